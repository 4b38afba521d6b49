/**
 * @class   vtkDeepShadowPass
 * @brief   One shadowing system for a renderer's volumes and meshes.
 *
 * Set it on a renderer (renderer->SetPass(pass)) as VTK's render passes are. Each frame it
 * gathers the visible casters: volumes drawn by vtkDeepShadowVolumeMapper and meshes drawn by
 * vtkDeepShadowPolyDataMapper with CastShadows on. The casting meshes, in world coordinates,
 * go to every such volume (vtkDeepShadowVolumeMapper::SetCastingSurfaces) and into its
 * technique's structure of each light; they are gathered again only when a mesh, its
 * property, its actor's placement or the set of casting meshes changed (GetSurfaceSetBuilds).
 * The first visible volume with a shadow technique is the scene's shadow source: its
 * structures are brought up to date before any mesh is drawn, and every mesh with
 * ReceiveShadows on looks them up. Then the props are drawn as vtkDefaultPass draws them
 * (opaque, translucent, volumes, overlay).
 *
 * Limits of this version: meshes receive from one volume's structures (the first shadowing
 * one); a translucent mesh is blended in VTK's translucent pass, before volumes, so a volume
 * in front of it is composited correctly but one behind it is drawn over it too.
 */
#ifndef vtkDeepShadowPass_h
#define vtkDeepShadowPass_h

#include "vtkDeepShadowRenderingModule.h" // For export macro
#include "vtkDefaultPass.h"

#include <memory> // For std::unique_ptr
#include <string> // For std::string

class VTKDEEPSHADOWRENDERING_EXPORT vtkDeepShadowPass : public vtkDefaultPass
{
public:
  static vtkDeepShadowPass* New();
  vtkTypeMacro(vtkDeepShadowPass, vtkDefaultPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  void Render(const vtkRenderState* state) override;

  /** Times the casting meshes were gathered into a new set (observability). */
  vtkGetMacro(SurfaceSetBuilds, int);
  /** Casting meshes in the last set. */
  vtkGetMacro(CastingMeshes, int);
  /** Why the last frame's meshes cast no shadows (e.g. a mesh with NaN points); "" if none. */
  const std::string& GetLastError() const { return this->LastError; }

protected:
  vtkDeepShadowPass();
  ~vtkDeepShadowPass() override;

  int SurfaceSetBuilds = 0;
  int CastingMeshes = 0;
  std::string LastError;

private:
  vtkDeepShadowPass(const vtkDeepShadowPass&) = delete;
  void operator=(const vtkDeepShadowPass&) = delete;

  class Internals;
  std::unique_ptr<Internals> Impl;
};

#endif
