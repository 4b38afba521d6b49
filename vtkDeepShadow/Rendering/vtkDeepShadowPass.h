/**
 * @class   vtkDeepShadowPass
 * @brief   One shadowing system for a renderer's volumes and meshes.
 *
 * Set it on a renderer (renderer->SetPass(pass)) as VTK's render passes are. Each frame it
 * gathers the visible casters: volumes drawn by vtkDeepShadowVolumeMapper and meshes drawn by
 * vtkDeepShadowPolyDataMapper with CastShadows on. The casting meshes, in world coordinates,
 * go to every such volume and into its technique's structure of each light; they are
 * gathered again only when a mesh, its property, its actor's placement or the set of casting
 * meshes changed (GetSurfaceSetBuilds).
 * Every visible volume with a shadow technique casts shadows onto the other volumes with a
 * technique and onto the meshes with ReceiveShadows on: a light's visibility is the product
 * of every caster's (optical depths add along a light ray). The first such volume is the
 * scene's shadow source: it holds the casting meshes (so that they count once) and meshes
 * look its structures up directly. What the other volumes cast reaches a receiver through a
 * grid over it (OtherVolumeShadowSize nodes along its longest side, one RGBA16F texel per
 * node and light), filled by each caster's own lookup and rebuilt only when a caster, its
 * structures, a light or the receiver's placement changed (GetOtherVolumeShadowBuilds). All
 * shadow structures are brought up to date before anything is drawn; then the props are
 * drawn as vtkDefaultPass draws them (opaque, translucent, volumes, overlay). What the pass
 * gives its mappers for a frame (casting surfaces, shadow source, other volumes' grids,
 * layers, segments) is one object (PassFrame.h), handed to each mapper when the frame starts
 * and taken back when it ends.
 *
 * Along each view ray, volumes and translucent meshes are composited in depth order: the
 * translucent meshes are peeled into TranslucentLayers layers (depth peeling); each visible
 * volume after the first is drawn into VolumeSegments segments (its march cut into pieces of
 * equal length along the ray, each kept at its opacity-weighted mean depth); and the first
 * visible volume merges layers and segments into its own march at their depths, as the CPU
 * reference does (deepshadow::Scene::TranslucentLayers and VolumeSegments). Pixels that volume
 * does not cover get the layers and segments by a full-screen pass. Volumes that do not
 * overlap along a ray come out exact; where they do, they interleave at a segment's grain.
 * Fragments behind the last layer are left out (GetTranslucentLayersOverflowed says when).
 * With TranslucentLayers 0, or with no volume, translucent meshes are blended as VTK blends
 * them; with VolumeSegments 0, volumes are blended in the renderer's order, as VTK does.
 *
 * Limit of this version: mesh shadows reach the volumes after the first at the grid's
 * resolution.
 */
#ifndef vtkDeepShadowPass_h
#define vtkDeepShadowPass_h

#include "vtkDeepShadowRenderingModule.h" // For export macro
#include "vtkDefaultPass.h"

#include <memory>  // For std::unique_ptr
#include <string>  // For std::string
#include <utility> // For std::pair
#include <vector>  // For std::vector

class vtkActor;
class vtkDeepShadowPolyDataMapper;
class vtkDeepShadowVolumeMapper;
class vtkRenderer;
class vtkVolume;
namespace deepshadow
{
struct VolumeCaster;
}

class VTKDEEPSHADOWRENDERING_EXPORT vtkDeepShadowPass : public vtkDefaultPass
{
public:
  static vtkDeepShadowPass* New();
  vtkTypeMacro(vtkDeepShadowPass, vtkDefaultPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  void Render(const vtkRenderState* state) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

  /** Times the casting meshes were gathered into a new set (observability). */
  vtkGetMacro(SurfaceSetBuilds, int);
  /** Casting meshes in the last set. */
  vtkGetMacro(CastingMeshes, int);
  ///@{
  /**
   * Layers the translucent meshes are peeled into when a volume is in the scene (default 4;
   * 0 turns the merging off). Each layer costs 8 bytes a pixel and one more drawing of the
   * translucent meshes.
   */
  vtkSetClampMacro(TranslucentLayers, int, 0, 8);
  vtkGetMacro(TranslucentLayers, int);
  ///@}
  /** Layers peeled in the last frame (0: nothing was peeled). */
  vtkGetMacro(PeeledLayers, int);
  /** Whether translucent fragments were left behind the last layer in the last frame. */
  vtkGetMacro(TranslucentLayersOverflowed, bool);
  /** GPU memory of the layers (and the opaque image copy they need), in bytes. */
  vtkGetMacro(TranslucentLayerBytes, long long);
  ///@{
  /**
   * Segments each volume after the first is cut into along a view ray, to be merged into the
   * first volume's march (default 8, at most 8; 0 turns the merging off). Each costs 16 bytes a
   * pixel a volume.
   */
  vtkSetClampMacro(VolumeSegments, int, 0, 8);
  vtkGetMacro(VolumeSegments, int);
  ///@}
  /** Volumes merged into the first volume's march in the last frame. */
  vtkGetMacro(MergedVolumes, int);
  /** GPU memory of the segments in the last frame, in bytes. */
  vtkGetMacro(VolumeSegmentBytes, long long);

  ///@{
  /**
   * Nodes along a receiver's longest side of the grid that carries the other volumes'
   * shadows to it (default 64; a volume's grid is never finer than its data).
   */
  vtkSetClampMacro(OtherVolumeShadowSize, int, 2, 256);
  vtkGetMacro(OtherVolumeShadowSize, int);
  ///@}
  /** Grids of other volumes' shadows built so far (observability). */
  vtkGetMacro(OtherVolumeShadowBuilds, int);
  /** GPU memory of those grids in the last frame, in bytes. */
  vtkGetMacro(OtherVolumeShadowBytes, long long);

  /** Why the last frame's meshes cast no shadows (e.g. a mesh with NaN points); "" if none. */
  const std::string& GetLastError() const { return this->LastError; }

protected:
  vtkDeepShadowPass();
  ~vtkDeepShadowPass() override;

  int SurfaceSetBuilds = 0;
  int CastingMeshes = 0;
  int TranslucentLayers = 4;
  int PeeledLayers = 0;
  bool TranslucentLayersOverflowed = false;
  long long TranslucentLayerBytes = 0;
  int VolumeSegments = 8;
  int MergedVolumes = 0;
  long long VolumeSegmentBytes = 0;
  int OtherVolumeShadowSize = 64;
  int OtherVolumeShadowBuilds = 0;
  long long OtherVolumeShadowBytes = 0;
  std::string LastError;

  /**
   * Opaque; translucent meshes peeled and the other volumes drawn into segments; the first
   * volume merging them; other volumes not ours; overlay.
   */
  void RenderMerged(const vtkRenderState* state, vtkDeepShadowVolumeMapper* merging,
    const std::vector<std::pair<vtkVolume*, vtkDeepShadowVolumeMapper*>>& guests,
    const std::vector<std::pair<vtkActor*, vtkDeepShadowPolyDataMapper*>>& peeled);
  /** Brings each receiver's grid of the other volumes' shadows up to date and hands it over. */
  void UpdateOtherVolumeShadows(vtkRenderer* renderer,
    const std::vector<std::pair<vtkVolume*, vtkDeepShadowVolumeMapper*>>& shadowing,
    const std::vector<deepshadow::VolumeCaster>& casters,
    const std::vector<std::pair<vtkActor*, vtkDeepShadowPolyDataMapper*>>& meshes);

private:
  vtkDeepShadowPass(const vtkDeepShadowPass&) = delete;
  void operator=(const vtkDeepShadowPass&) = delete;

  class Internals;
  std::unique_ptr<Internals> Impl;
};

#endif
