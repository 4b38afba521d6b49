/**
 * @class   vtkDeepShadowStandardScene
 * @brief   Procedural standard scenes named after the papers, with a recommended look.
 *
 * Each scene is a volume generated on the CPU from a fixed recipe (no medical data set is
 * reachable here), plus the transfer function, camera, key-light direction and sample distance
 * that make it look right. The scenes:
 *
 * - "box":     64^3 uchar, a cube that gets more opaque towards its centre (DSM from 3D textures).
 * - "bucky":   32^3 uchar, C60 buckminsterfullerene: 60 Gaussian atoms and faint bonds.
 * - "rods":    64^3 uchar, thin opaque rods crossing along x, y and z (thin occluders).
 * - "clouds":  512x512x32 uchar, fBm value-noise cloud puffs in a flat slab.
 * - "spheres": 128^3 uchar, translucent spheres of different sizes and scalar values (CSSM).
 * - "head":    256x256x160 short, a CT-like head phantom in Hounsfield units, anisotropic spacing.
 * - "sparse":  256x256x48 uchar, 19 small objects (balls, shells, molecules, rings, cubes,
 *              crosses) far apart in a wide flat slab, the camera close to one of them near a
 *              corner, far from the centre of the light's view (clustered deep shadow maps).
 *
 * Generation is deterministic: integer hashes for randomness, only correctly rounded IEEE
 * operations (no libm transcendental functions, no std:: random distributions), compiled without
 * FMA contraction, and each voxel computed independently of the thread that computes it. The
 * same scene and scale give the same bytes on every run and machine.
 *
 * The volume is centred on the world origin. SetResolutionScale() changes the number of
 * voxels but not the world-space size of the volume.
 *
 * Coordinates of the head (DICOM LPS-like): +x is the patient's left, +y posterior (the face
 * looks towards -y), +z superior. Slices run along z.
 */
#ifndef vtkDeepShadowStandardScene_h
#define vtkDeepShadowStandardScene_h

#include "vtkDeepShadowScenesModule.h" // For export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // For cached data

#include <string> // For scene names
#include <vector> // For scene names

class vtkCamera;
class vtkImageData;
class vtkVolumeProperty;

class VTKDEEPSHADOWSCENES_EXPORT vtkDeepShadowStandardScene : public vtkObject
{
public:
  static vtkDeepShadowStandardScene* New();
  vtkTypeMacro(vtkDeepShadowStandardScene, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The scene names, in a fixed order: box, bucky, rods, clouds, spheres, head, sparse. */
  static std::vector<std::string> GetSceneNames();

  /** One line describing the scene; "" if the name is unknown. */
  static std::string GetSceneDescription(const std::string& name);

  /** True if `name` is one of GetSceneNames(). */
  static bool IsSceneName(const std::string& name);

  ///@{
  /**
   * Chooses the scene (default "box"). Unknown names are rejected with an error that lists the
   * valid ones, and the current scene is kept. Success drops the cached volume and property.
   */
  bool SetScene(const std::string& name);
  const std::string& GetScene() const;
  ///@}

  ///@{
  /**
   * Scales the number of voxels along each axis (default 1; at least 2 per axis). The spacing
   * grows accordingly, so the world-space size of the volume stays the same. Clamped to
   * [0.01, 2]. A change drops the cached volume and property.
   */
  void SetResolutionScale(double scale);
  vtkGetMacro(ResolutionScale, double);
  ///@}

  ///@{
  /**
   * "sparse" only: how many of its objects (0, the default: its 19). Fewer keep the first
   * (the object the camera looks at, the ring that shadows it, then cell by cell); up to
   * GetMaxObjectCount() (24) adds smaller ones between the cells. For scaling studies
   * against the object count; other scenes ignore it. A change drops the cached volume.
   */
  void SetObjectCount(int count);
  vtkGetMacro(ObjectCount, int);
  static int GetMaxObjectCount();
  ///@}

  /** Dimensions, spacing and origin of the volume at the current scale (no generation). */
  void GetDimensions(int dims[3]) const;
  void GetSpacing(double spacing[3]) const;
  void GetOrigin(double origin[3]) const;

  /** VTK scalar type of the volume (VTK_UNSIGNED_CHAR or VTK_SHORT). */
  int GetScalarType() const;

  /** Scalar value of empty space (0, or -1000 HU for the head); its opacity is exactly 0. */
  double GetBackgroundValue() const;

  /**
   * The volume: one-component point scalars named "scalars", generated on the first call and
   * cached until the scene or scale changes.
   */
  vtkImageData* GetVolume();

  /** Wall-clock seconds the last generation took (0 before the first). */
  vtkGetMacro(LastGenerationTime, double);

  /**
   * The recommended look: colour and scalar-opacity transfer functions (opacity 0 at the
   * background value), shading on, linear interpolation, unit distance one voxel.
   */
  vtkVolumeProperty* GetVolumeProperty();

  /**
   * Sets a 3/4 view of the volume: focal point at its centre, view angle 30 degrees, view-up,
   * and a distance at which the whole bounding box is in view with some margin. "sparse" is
   * seen from close to one of its objects instead (the rest recedes behind it). The caller
   * resets the clipping range.
   */
  void ApplyCamera(vtkCamera* camera);

  /**
   * Suggested key-light direction (unit, world, pointing from the scene towards the light),
   * far enough from the view direction of ApplyCamera that shadows are visible.
   */
  void GetLightDirection(double dir[3]);
  /** The same, returned (for Python: `scene.GetLightDirection()`). */
  double* GetLightDirection() VTK_SIZEHINT(3);

  /** About half the smallest spacing, in world units. */
  double GetSuggestedSampleDistance();

protected:
  vtkDeepShadowStandardScene();
  ~vtkDeepShadowStandardScene() override;

  void Invalidate();

  std::string Scene;
  double ResolutionScale = 1.0;
  int ObjectCount = 0;
  double LastGenerationTime = 0.0;
  double LightDirection[3] = { 0.0, 0.0, 1.0 };
  vtkSmartPointer<vtkImageData> Volume;
  vtkSmartPointer<vtkVolumeProperty> Property;

private:
  vtkDeepShadowStandardScene(const vtkDeepShadowStandardScene&) = delete;
  void operator=(const vtkDeepShadowStandardScene&) = delete;
};

#endif
