/**
 * @class   vtkDeepShadowCastingMeshes
 * @brief   The meshes that cast shadows into a volume's structures, gathered in world space.
 *
 * One set of casting meshes (deepshadow::SurfaceSet: every mesh drawn by a
 * vtkDeepShadowPolyDataMapper with CastShadows on, in world coordinates, one triangle
 * hierarchy), gathered again only when a mesh, its mapper, its property, its actor's placement
 * or the list of meshes changed (GetBuilds). vtkDeepShadowPass keeps one for its renderer;
 * ParaView's Shadowed Volume keeps one for the view's Shadowed Surfaces, and gives it to its
 * volume mapper (vtkDeepShadowVolumeMapper::SetPassFrame: the set stays with the mapper).
 * A mesh that cannot cast (no triangles, NaN points) is left out with a warning; a set that
 * cannot be made is GetLastError().
 */
#ifndef vtkDeepShadowCastingMeshes_h
#define vtkDeepShadowCastingMeshes_h

#include "vtkDeepShadowRenderingModule.h" // For export macro
#include "vtkObject.h"

#include <memory>  // For std::shared_ptr
#include <string>  // For std::string
#include <utility> // For std::pair
#include <vector>  // For std::vector

class vtkActor;
class vtkDeepShadowPolyDataMapper;
namespace deepshadow
{
class SurfaceSet;
}

class VTKDEEPSHADOWRENDERING_EXPORT vtkDeepShadowCastingMeshes : public vtkObject
{
public:
  static vtkDeepShadowCastingMeshes* New();
  vtkTypeMacro(vtkDeepShadowCastingMeshes, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

#ifndef __VTK_WRAP__
  /**
   * Gathers the meshes of `meshes` whose mapper casts, if any of them changed since the last
   * call; true when the set was made anew.
   */
  bool Update(const std::vector<std::pair<vtkActor*, vtkDeepShadowPolyDataMapper*>>& meshes);
  /** The set; null when no mesh casts. */
  std::shared_ptr<const deepshadow::SurfaceSet> GetSurfaces() const { return this->Surfaces; }
#endif

  /** Sets made so far (observability: once per change). */
  vtkGetMacro(Builds, int);
  /** Meshes in the current set. */
  vtkGetMacro(Count, int);
  /** Why the last set could not be made; "" if it was. */
  const std::string& GetLastError() const { return this->LastError; }

protected:
  vtkDeepShadowCastingMeshes();
  ~vtkDeepShadowCastingMeshes() override;

private:
  vtkDeepShadowCastingMeshes(const vtkDeepShadowCastingMeshes&) = delete;
  void operator=(const vtkDeepShadowCastingMeshes&) = delete;

  std::vector<double> Key; // what the set was made from
  std::shared_ptr<const deepshadow::SurfaceSet> Surfaces;
  int Builds = 0;
  int Count = 0;
  std::string LastError;
};

#endif
