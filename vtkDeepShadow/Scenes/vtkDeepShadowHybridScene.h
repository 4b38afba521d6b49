/**
 * @class   vtkDeepShadowHybridScene
 * @brief   Standard hybrid scenes: a standard scene's volume with meshes that cast and receive.
 *
 * For vtkDeepShadowPolyDataMapper actors under a vtkDeepShadowPass. The meshes are placed from
 * the volume's data bounds and the direction towards the key light (their axis-aligned boxes
 * face the axis the light comes most along):
 *
 * - "hybrid-ground": the spheres scene over a ground plane on the far side from the light.
 * - "hybrid-glass":  the box scene over a ground, with a translucent blue glass slab between
 *                    the light and half of the volume: the shadow it casts through the volume
 *                    is tinted (coloured techniques) and lighter.
 * - "hybrid-rod":    the head with an opaque rod (a surgical tool) through it: the rod is
 *                    shadowed by the skull and shadows the brain, over a ground.
 * - "hybrid-smoke":  the composition of the hybrid deep-shadow-map paper: a smoking cup of
 *                    coffee beside the head, over a ground. The smoke is a second volume
 *                    (MakeSmoke) rising from the cup on the light's side, so that its shadow
 *                    falls over the head; the head shadows the cup, the cup the ground.
 * - "hybrid-sparse": the sparse scene's 19 objects over a ground, with an opaque box and a
 *                    translucent blue octagonal prism standing in two of its free cells: 22
 *                    objects.
 */
#ifndef vtkDeepShadowHybridScene_h
#define vtkDeepShadowHybridScene_h

#include "vtkDeepShadowScenesModule.h" // For export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // For the meshes

#include <array>  // For colours
#include <string> // For scene names
#include <vector> // For scene names

class vtkImageData;
class vtkPolyData;
class vtkVolumeProperty;

class VTKDEEPSHADOWSCENES_EXPORT vtkDeepShadowHybridScene : public vtkObject
{
public:
  static vtkDeepShadowHybridScene* New();
  vtkTypeMacro(vtkDeepShadowHybridScene, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** hybrid-ground, hybrid-glass, hybrid-rod, hybrid-smoke, hybrid-sparse. */
  static std::vector<std::string> GetSceneNames();
  static bool IsSceneName(const std::string& name);
  static std::string GetSceneDescription(const std::string& name);
  /** The standard scene whose volume a hybrid scene shows ("head" for "hybrid-rod"). */
  static std::string GetVolumeSceneName(const std::string& name);

  /** A mesh of a scene and how it looks. */
  struct Mesh
  {
    vtkSmartPointer<vtkPolyData> PolyData;
    double Opacity = 1.0;
    std::array<double, 3> Color{ { 0.8, 0.8, 0.8 } };
  };
  /**
   * The meshes of scene `name` (world coordinates) for a volume of the given bounds lit from
   * `toLight` (a direction towards the light). Empty for unknown names.
   */
  static std::vector<Mesh> MakeMeshes(const std::string& name, const double volumeBounds[6], const double toLight[3]);
  /** A ground square under the volume, on the far side from the light (deepshadow --ground). */
  static Mesh MakeGround(const double volumeBounds[6], const double toLight[3]);
  /**
   * The second volume of scene `name` (the smoke of "hybrid-smoke": a plume of unsigned char
   * density, 0 outside it), placed as MakeMeshes places its cup; null for scenes without one.
   */
  static vtkSmartPointer<vtkImageData> MakeSmoke(const std::string& name, const double volumeBounds[6],
    const double toLight[3]);
  /** How the smoke looks and casts: grey-white, faint where thin (unshaded). */
  static vtkSmartPointer<vtkVolumeProperty> MakeSmokeProperty();

protected:
  vtkDeepShadowHybridScene() = default;
  ~vtkDeepShadowHybridScene() override = default;

private:
  vtkDeepShadowHybridScene(const vtkDeepShadowHybridScene&) = delete;
  void operator=(const vtkDeepShadowHybridScene&) = delete;
};

#endif
