/**
 * @class   vtkDeepShadowBoundedScene
 * @brief   Standard scenes of volumes bounded by closed meshes, and the meshes themselves.
 *
 * Each scene is a standard scene's volume (vtkDeepShadowStandardScene) with polyhedral bounds
 * and a CSG expression for vtkDeepShadowVolumeMapper::AddBound / SetBoundExpression (or for
 * vtkDeepShadowCSGFilter). Bounds are in the volume's data coordinates:
 *
 * - "head-cut":     the head, minus a sphere biting into its upper front-left: diff(A,B) of a
 *                   box around the head (A) and the sphere (B). The cut shows the skull's
 *                   thickness and the brain, and the rim shadows the inside.
 * - "box-torus":    the box scene inside a torus about z (a bound with a hole).
 * - "spheres-half": the spheres scene bounded by a box on five of the volume's faces that
 *                   ends at its mid-plane z = 0 (a bound touching the volume's faces).
 *
 * The meshes are built here, closed and oriented outward (counter-clockwise seen from
 * outside), with shared points: MakeBox, MakeSphere and MakeTorus.
 */
#ifndef vtkDeepShadowBoundedScene_h
#define vtkDeepShadowBoundedScene_h

#include "vtkDeepShadowScenesModule.h" // For export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // For the bounds

#include <string> // For scene names
#include <vector> // For scene names

class vtkPolyData;

class VTKDEEPSHADOWSCENES_EXPORT vtkDeepShadowBoundedScene : public vtkObject
{
public:
  static vtkDeepShadowBoundedScene* New();
  vtkTypeMacro(vtkDeepShadowBoundedScene, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** head-cut, box-torus, spheres-half. */
  static std::vector<std::string> GetSceneNames();
  static bool IsSceneName(const std::string& name);
  static std::string GetSceneDescription(const std::string& name);
  /** The standard scene whose volume a bounded scene shows ("head" for "head-cut"). */
  static std::string GetVolumeSceneName(const std::string& name);

  /**
   * The bounds of scene `name` for a volume of the given data bounds (xmin, xmax, ymin, ...),
   * named A, B, ... in order, and the expression that combines them. Empty for unknown names.
   */
  static std::vector<vtkSmartPointer<vtkPolyData>> MakeBounds(const std::string& name, const double volumeBounds[6]);
  static std::string GetBoundExpression(const std::string& name);

  ///@{
  /** Closed, outward-oriented triangle meshes. */
  static vtkSmartPointer<vtkPolyData> MakeBox(const double bounds[6]);
  static vtkSmartPointer<vtkPolyData> MakeSphere(const double centre[3], double radius, int resolution = 48);
  /** About the z axis through `centre`: tube radius `minor` around a circle of radius `major`. */
  static vtkSmartPointer<vtkPolyData> MakeTorus(const double centre[3], double major, double minor, int resolution = 64);
  ///@}

protected:
  vtkDeepShadowBoundedScene() = default;
  ~vtkDeepShadowBoundedScene() override = default;

private:
  vtkDeepShadowBoundedScene(const vtkDeepShadowBoundedScene&) = delete;
  void operator=(const vtkDeepShadowBoundedScene&) = delete;
};

#endif
