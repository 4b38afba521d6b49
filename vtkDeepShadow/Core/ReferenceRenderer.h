// The CPU reference renderer: the ground truth of every error this project reports.
//
// Double precision, multi-threaded, and the same optical model as the GPU mapper
// (OpticalModel.h): per pixel, a ray through the pixel centre is marched through each
// volume's box [0, Dims - 1] from its entry point, samples at t0 + (k + offset) * dt with
// offset 0.5 (or the pixel's jitter), opacity corrected for dt, Phong-shaded if asked,
// composited front to back, and the volumes blended over the background in scene order.
//
// Lighting: a shaded volume is Phong-lit (ambient + per light diffuse and specular of the
// gradient normal, in the volume's VolumeShading: VTK's or Blinn-Phong); an unshaded volume with a shadow technique scatters light isotropically
// (ambient + per light diffuse without the normal), so that it can receive shadows; an
// unshaded volume without shadows just emits its colour. Each light's diffuse and specular
// part is multiplied by its visibility 1 - ShadowAttenuation * (1 - V(p)), per colour
// channel (coloured techniques give each channel its own V); ambient never is.
//
// Hybrid scenes and several volumes: along a view ray, every volume's samples and the meshes'
// crossings are composited in depth order (an opaque mesh ends the ray): volumes that overlap
// interleave sample by sample, and a translucent mesh inside a volume sits between the samples
// around it. A mesh point is Phong-lit with its interpolated normal and colour, each light
// scaled by its visibility, looked up deepshadow::ReceiverOffset towards the light.
// (Scene::VolumeSegments > 0 reproduces the GPU instead, see there.)
//
// Several volumes: every volume with a shadow technique casts shadows onto the others and
// onto the meshes. A light's visibility at a point is the product of every shadowing volume's
// answer there (optical depths add along a light ray, whatever the order of the volumes).
// The casting meshes are held by the first shadowing volume's technique only, so that they
// count once; meshes look that technique up directly and multiply in the other volumes'.
//
// With the default MarchSettings it is the exact model (transfer functions evaluated exactly,
// no early termination). `GpuTwin()` settings reproduce what the GPU computes instead (table
// lookups, early termination), so GPU and CPU can be compared formula by formula.
#ifndef deepshadow_ReferenceRenderer_h
#define deepshadow_ReferenceRenderer_h

#include "Core/Bound/BoundRegion.h"
#include "Core/Camera.h"
#include "Core/Components.h"
#include "Core/Image.h"
#include "Core/Light.h"
#include "Core/OpticalModel.h"
#include "Core/GradientOpacity.h"
#include "Core/Isosurface.h"
#include "Core/Projection.h"
#include "Core/Transfer2D.h"
#include "Core/Shadows.h"
#include "Core/Geometry/SurfaceSet.h"
#include "Core/EmptySpace.h"
#include "Core/TransferFunction.h"
#include "Core/VolumeGrid.h"
#include "Core/VolumeShading.h"
#include "vtkDeepShadowCoreModule.h"

#include <glm/mat3x3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace deepshadow
{

struct VolumeInstance
{
  std::shared_ptr<const VolumeGrid> Grid;
  TransferFunction Transfer;
  Material Surface;
  bool Shade = false;
  /** How the lights shade it when Shade (VTK's shading or Blinn-Phong, VolumeShading.h). */
  VolumeShading Shading;
  Interpolation Sampling = Interpolation::Linear;
  /** How the volume shadows itself (ShadowKind::None: not at all). */
  ShadowParameters Shadows;
  /** The transfer function that casts shadows, if not the one that is drawn. */
  std::optional<TransferFunction> ShadowTransfer;
  /**
   * Where the volume exists, in voxel-index space (null: its whole box). Outside it the
   * volume is empty: it neither shows nor casts shadows.
   */
  std::shared_ptr<const BoundRegion> Bound;
  /** Projection blend modes (maximum, minimum, average, additive): drawn unlit, unshadowed. */
  ProjectionSettings Projection;
  /**
   * Isosurface blending (Isosurface.h): the contour values, sorted; empty: composite (or the
   * projection). The surfaces are lit and shadowed, and are what casts the shadows.
   */
  std::vector<double> IsoValues;
  /** Gradient opacity (composite blending only, as VTK's); drawn and cast. */
  std::optional<GradientOpacity> Gradient;
  /** A binary mask (Mask.h) of the grid's dimensions, or null; what it clears neither shows nor casts. */
  std::shared_ptr<const VolumeGrid> Mask;
  /** With Mask: Mask is a label map (Mask.h), whose labels' colours and opacities show and cast. */
  std::shared_ptr<const LabelMap> Labels;
  /**
   * A prop scaled differently along its axes, composited: its linear part undone (world ->
   * dataset) and its mean scale (the tables' unit), so that opacity is integrated per dataset
   * unit as VTK's mapper does (Features/DatasetOpacity.glsl); empty otherwise.
   */
  std::optional<glm::dmat3> WorldToDataset;
  double DatasetScale = 1.0;
  /** A 2D transfer function (Transfer2D.h; composite, one component) replacing Transfer's looks. */
  std::shared_ptr<const Transfer2D> Function2D;
  /** Several components per voxel (Components.h; composite only): Grid is component 0. */
  std::optional<ComponentSet> Components;
};

struct Scene
{
  Camera View;
  std::vector<Light> Lights;
  glm::dvec3 Background{ 0.0 };
  glm::dvec3 AmbientLight{ 1.0 }; // vtkRenderer::GetAmbient()
  bool TwoSidedLighting = true;
  std::vector<VolumeInstance> Volumes;
  /**
   * Hybrid scenes: the meshes drawn (lit; shadowed by the first shadowing volume's technique
   * when they receive), and the meshes that cast shadows into every volume's technique.
   */
  std::shared_ptr<const SurfaceSet> Surfaces;
  std::shared_ptr<const SurfaceSet> CastingSurfaces;
  /** World distance of a mesh receiver's shadow lookup towards the light (0: the default). */
  double ReceiverBias = 0.0;
  /**
   * 0: every translucent mesh crossing along a view ray is composited (exact). n > 0: the
   * twin of the GPU's depth peeling into n layers: only the n nearest translucent crossings
   * (opaque meshes still end the ray).
   */
  int TranslucentLayers = 0;
  /**
   * 0: what other volumes cast onto a receiver is their product evaluated at each point
   * (exact). n > 0: the twin of vtkDeepShadowPass, which stores that product per light on a
   * grid of n nodes along the receiver's longest side (GridFrame::OverVolume for a volume,
   * GridFrame::OverBox over a mesh's points) and interpolates it trilinearly.
   */
  int OtherVolumeShadowSize = 0;
  /**
   * 0: the samples of all volumes along a view ray interleave in depth order (exact). n > 0:
   * the twin of vtkDeepShadowPass, where each volume after the first is cut, along each view
   * ray, into n segments of equal length between its entry and its exit (or the first opaque
   * mesh); a segment is composited on its own and takes its place among the first volume's
   * samples and the meshes' crossings at its opacity-weighted mean depth. Volumes that do not
   * overlap along a ray come out exact; where they do, the error shrinks as n grows.
   */
  int VolumeSegments = 0;
};

/** One sample of a volume along a view ray, premultiplied (colour x alpha, alpha). */
struct RaySample
{
  double T = 0.0;
  glm::dvec4 Color{ 0.0 };
  glm::dvec4 Term{ 0.0 }; // the shadow term, composited as the colour is
};

/**
 * What an image shows: the lit colour, or the shadow term alone: each sample's colour
 * replaced by the product, over the lights that reach it and cast shadows, of
 * 1 - attenuation (1 - visibility) (1 where nothing shadows it), composited with the
 * volume's opacity as colours are. Comparing shadow-term images measures a technique's
 * error in the light-attenuation term without shading or colour mixed in.
 */
enum class RenderOutput
{
  Color,
  ShadowTerm
};

struct MarchSettings
{
  RenderOutput Output = RenderOutput::Color;
  double SampleDistance = 1.0; // world units between samples
  bool Jitter = false;
  uint32_t JitterSeed = 0;
  /** Stop once accumulated opacity exceeds this; 1 never stops early (exact). */
  double TerminationOpacity = 1.0;
  /** 0: evaluate transfer functions exactly. N: look them up in an N-texel TransferTable. */
  int TransferTableSize = 0;
  /** Skip blocks of zero opacity (exact: the same samples count; only faster). */
  bool EmptySpaceSkipping = true;

  /** What the GPU mapper computes with the same parameters. */
  static MarchSettings GpuTwin(double sampleDistance, int tableSize, bool jitter = false,
    uint32_t seed = 0, double terminationOpacity = DefaultTerminationOpacity);
};

class VTKDEEPSHADOWCORE_EXPORT ReferenceRenderer
{
public:
  /**
   * Renders the scene; `threads` 0 uses DefaultThreadCount(). With `shadowTerm`, also its
   * shadow-term image (RenderOutput::ShadowTerm) from the same march: the visibilities,
   * which cost the most, are evaluated once for both. With `surfaceTerm`, also the shadow
   * term at each pixel's first receiver: that of the fragment (sample or mesh crossing) at
   * which the view ray's opacity first reaches ReceiverOpacity, not composited; -1 where it
   * never does. Throws std::invalid_argument when a sample distance (or a shadow step)
   * would take more samples across a volume than a ray may (CheckRaySamples), as the GPU
   * mapper refuses it.
   */
  static Image Render(const Scene& scene, const MarchSettings& settings, int threads = 0,
    Image* shadowTerm = nullptr, Image* surfaceTerm = nullptr);
  /** Where a view ray meets its first receiver: the opacity it has reached there. */
  static constexpr double ReceiverOpacity = 0.5;

  /** What rendering a volume needs beyond its description, computed once per image. */
  struct PreparedVolume
  {
    std::unique_ptr<TransferTable> Table;       // GPU twin only
    std::unique_ptr<TransferTable> FeelerTable; // GPU twin with shadows only
    std::unique_ptr<ComponentLookup> Components;       // several components: the view's step
    std::unique_ptr<ComponentLookup> FeelerComponents; // and the light rays'
    // GPU twin with a label map: label k's table at [k - 1] (held apart: casters point at it)
    std::unique_ptr<std::vector<TransferTable>> LabelTables;
    std::unique_ptr<EmptySpaceMap> Empty;       // blocks rays may skip (exact)
    std::unique_ptr<EmptySpaceMap> ShadowEmpty; // the same for a separate shadow transfer
    std::vector<std::unique_ptr<LightShadow>> Shadows; // per scene light; null: no shadow
    /** What mesh receivers look up: Shadows, or uncached when they are cached (a cache's grid
     * covers the volume's box only). Empty: the same as Shadows. */
    std::vector<std::unique_ptr<LightShadow>> DirectShadows;
    /** Per scene light: what the other shadowing volumes cast onto this one (null: none). */
    std::vector<std::unique_ptr<LightShadow>> OtherShadows;
    /** What receivers elsewhere look up: DirectShadows if there are any, else Shadows. */
    const LightShadow* ReceiverLookup(size_t light) const;
  };
  /**
   * `castSurfaces`: whether the scene's casting meshes go into this volume's technique (the
   * first shadowing volume's only; see above). OtherShadows is left to Render().
   */
  static PreparedVolume Prepare(const Scene& scene, const VolumeInstance& volume,
    const MarchSettings& settings, int threads = 0, bool castSurfaces = true);

  /**
   * Premultiplied RGBA of one volume along `ray` up to world distance `tLimit`, with the
   * first sample `offset` steps (in [0, 1)) past the entry; with `shadowTerm`, also the
   * premultiplied shadow term along the same ray. With `samples`, every sample is also
   * appended there, premultiplied, to be composited in depth order with others.
   */
  static glm::dvec4 MarchRay(const Scene& scene, const VolumeInstance& volume,
    const PreparedVolume& prepared, const Ray& ray, double tLimit, double offset,
    const MarchSettings& settings, glm::dvec4* shadowTerm = nullptr, std::vector<RaySample>* samples = nullptr);

  /** A volume sample as the ray caster looks it up, before it is lit. */
  struct ClassifiedSample
  {
    glm::dvec3 Color{ 0.0 };
    double Alpha = 0.0;                // for the view step (and the prop's stretch)
    glm::dvec3 Unlit{ 0.0 };           // a label map's colour, added unlit (Mask.h)
    glm::dvec4 ComponentValues{ 0.0 }; // several components: their values,
    ComponentColors Colors{};          // and each one's colour and opacity (lit apart later)
  };
  /**
   * The sample at continuous index `index` (of scalar `scalar`): transfer function or table,
   * components, 2D function, label map or mask, gradient opacity, the prop's stretch
   * (`datasetStretch`: this ray's world step in dataset units).
   */
  static ClassifiedSample Classify(const VolumeInstance& volume, const PreparedVolume& prepared,
    const glm::dvec3& index, double scalar, double dt, double datasetStretch);
  /**
   * The lit colour of `sample` at world `position` on `ray` (the shadow term alone under
   * RenderOutput::ShadowTerm), and in `term` the product of the lights' shadow factors, when
   * `wantTerm`. `factors`: each light's factor, looked up once (reused across samples).
   */
  static glm::dvec3 LitColor(const Scene& scene, const VolumeInstance& volume, const PreparedVolume& prepared,
    const Ray& ray, const glm::dvec3& position, const glm::dvec3& index, double dt, ClassifiedSample& sample,
    bool termOnly, bool wantTerm, std::vector<std::optional<glm::dvec3>>& factors, glm::dvec3& term);

  /**
   * Where a view ray marches a volume: from its entry (or the ray's start) to its exit or
   * `tLimit`; false if it misses the box.
   */
  static bool MarchInterval(const Ray& ray, const VolumeGrid& grid, double tLimit, double& t0, double& t1);

  /**
   * Lit colour of a mesh point, as vtkDeepShadowPolyDataMapper's shader computes it.
   * `shadows`: the first shadowing volume's lookups, per light, or null; `others`: what the
   * other volumes cast onto this mesh, per light, or null. `term`: also the point's shadow
   * term (see RenderOutput::ShadowTerm).
   */
  static glm::dvec3 ShadeSurface(const Scene& scene, const SurfaceSet& surfaces,
    const SurfaceHit& hit, const Ray& ray, const std::vector<const LightShadow*>& shadows,
    const std::vector<const LightShadow*>& others, double receiverBias, glm::dvec3* term = nullptr);
};

}
#endif
