// Shadow techniques, CPU side: the twins of the GPU techniques and the ground truth.
//
// A LightShadow answers one question, "how much of this light reaches world point p?", in
// [0, 1] per colour channel. Each technique builds one per light from the volume that casts
// (a volume shadows itself) and the light:
//   - Rays, translucent ("A"): march a feeler from p to the light and multiply (1 - alpha) of
//     its samples, alpha corrected for the feeler's step exactly as on the view ray; coloured,
//     (1 - alpha (1 - c)) per channel with c the sample's colour (its transmission). With exact
//     transfer functions, a fine step and no early termination this is the ground truth.
//   - Rays, opaque ("B"): 0 as soon as the feeler meets an occluder (OccluderTest: by default
//     once its accumulated opacity exceeds the threshold), else 1.
//   - Casting surfaces (ShadowCaster::Surfaces) are steps on every technique's light rays.
//   - Light-space maps (Shadows/LightSpace.h), one file each in Shadows/: shadow map ("B"),
//     deep shadow map (a visibility function per texel compressed within epsilon), opacity
//     levels (depths at 10/50/90 % opacity) and coloured stochastic shadow maps (CSSM).
//   - Cached ("PP"): any of the above evaluated once per node of a grid over the volume's box
//     and interpolated trilinearly, as the GPU's 3D shadow texture is (Shadows/ShadowGrid.h).
// Feelers and light rays take samples at (j + 0.5) * step, like the view ray.
#ifndef deepshadow_Shadows_h
#define deepshadow_Shadows_h

#include "Core/EmptySpace.h"
#include "Core/Light.h"
#include "Core/TransferFunction.h"
#include "Core/VolumeGrid.h"
#include "vtkDeepShadowCoreModule.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <map>
#include <optional>
#include <memory>
#include <string>
#include <vector>

namespace deepshadow
{
class BoundRegion;
class Camera;
class ComponentLookup;
class IsoCrossings;
struct LabelMap;
struct Transfer2D;
class SurfaceSet;
struct GradientOpacity;

/**
 * The technique family a ShadowParameters describes; the registry (ShadowTechniques.h) maps
 * each to its names, CPU twin and GPU class. A technique added outside this list may use a
 * kind of its own, e.g. `constexpr ShadowKind MyKind = ShadowKind(100);` in its twin's header.
 */
enum class ShadowKind : int
{
  None,
  Rays,
  ShadowMap,
  DeepShadowMap,
  OpacityLevels,
  Stochastic,
  ResolutionMatched
};

enum class ShadowFilter
{
  None,    // the texel the point falls in
  PCF2x2,  // the four nearest texels, bilinear weights
  PCF3x3,  // the 3x3 texels around the nearest one, equal weights
  Poisson  // 12 taps of a Poisson disc of radius 2 texels, equal weights
};

/** Where binary techniques (opaque rays, shadow maps) put an occluder along a light ray. */
enum class ThresholdMode
{
  /**
   * Where the opacity accumulated along the light ray, 1 - transmittance (meshes included),
   * first exceeds the threshold: a thick translucent body casts the hard shadow of its
   * bulk, whatever opacity each of its samples has (the default).
   */
  Accumulated,
  Opacity, // a sample whose transfer-function opacity (per unit distance) exceeds it
  Scalar   // a sample whose scalar, normalized to [0, 1] over the data range, exceeds it
};

/** Everything a technique's result depends on besides the volume and the light. */
struct VTKDEEPSHADOWCORE_EXPORT ShadowParameters
{
  ShadowKind Kind = ShadowKind::None;
  double StepFactor = 1.0;  // feeler (and light-ray) step / view step
  double Threshold = 0.5;   // opaque rays and shadow maps, in [0, 1]
  ThresholdMode Mode = ThresholdMode::Accumulated;
  /** One visibility per colour channel (rays, deep shadow maps; CSSM always is). */
  bool Colored = false;
  /** Evaluated once per node of a shadow volume over the box, then trilinear ("PP"). */
  bool Cached = false;
  int VolumeSize = 128;     // cached: shadow nodes along the longest axis (at most the data's)
  int MapSize = 512;        // light-space maps: texels per side
  /**
   * Light-space maps: at most this many clustered faces per light, each fitted to a cluster
   * of the volume's objects (Core/Shadows/Clusters.h); 0: one face over the whole box.
   */
  int Clusters = 0;
  double ClusterDistance = 0.25; // clustering's d0, in half-widths of the unclustered face

  // Rays.
  bool Opaque = false;      // binary: blocked at the first occluder (see ThresholdMode)
  /** Stop a feeler once its transmittance is below ShadowTerminationTransmittance. */
  bool EarlyTermination = true;

  // Shadow maps.
  double Bias = 2.0;        // depth bias, in feeler steps
  ShadowFilter Filter = ShadowFilter::PCF3x3;

  // Deep shadow maps.
  double Epsilon = 0.02;    // |V' - V| <= Epsilon at every sample depth (Documentation/Shadows.md)
  int Layers = 8;           // nodes per texel (and channel)
  /**
   * Chunked node memory (Core/Shadows/NodeChunks.h): nodes per chunk, taken from a pool as a
   * texel needs them, any number per texel; 0: Layers nodes per texel. Layers then only sizes
   * the automatic pool.
   */
  int ChunkNodes = 0;
  double PoolMegabytes = 0.0; // chunked: the pool per light; 0: the bytes Layers would take

  // Opacity levels: depths where the accumulated opacity crosses these.
  std::array<double, 3> Levels{ { 0.1, 0.5, 0.9 } };

  // Coloured stochastic shadow maps.
  int Offsets = 13;         // 7, 13 or 21 (StochasticOffsets)
  unsigned int Seed = 0;
  int Photons = 1;          // photons (independent depth triples) per texel

  // Resolution-matched shadow maps (Core/Shadows/ResolutionMatched.h); Bias and Filter too.
  int PageSize = 32;        // texels per page side
  int AtlasSize = 1024;     // texels per side of the atlas the pages live in
  int MaxResolution = 16384; // texels per side of the finest level (the virtual map)
  int AnalysisDownsample = 4; // every N-th pixel (each way) of the camera image asks for pages
  /** Keep built pages across frames while the light and casters stay (cached mode). */
  bool KeepPages = true;

  /**
   * Parameters of techniques that have no field above, by registry key (a technique added
   * later or outside the tree); ShadowParameterInfo::Get gives their defaults when absent.
   */
  std::map<std::string, std::vector<double>> Extra;

  /** Whether the result has a visibility per colour channel (CSSM always has). */
  bool IsColored() const { return this->Colored || this->Kind == ShadowKind::Stochastic; }
  /**
   * Empty if these parameters are usable, else what is wrong with them: every key checked
   * against its range in the technique registry (ShadowTechniques.h).
   */
  std::string Validate() const;

  /** The ground truth: translucent rays, no early termination, at `stepFactor`. */
  static ShadowParameters GroundTruth(bool colored = false, double stepFactor = 0.25);
  /**
   * The registry's name of the technique (ShadowTechniques.h): none, rays, rays-opaque,
   * shadowmap, dsm, dsm-color, dsm3, cssm, each with "-cached" when cached (dsm-cached, ...).
   */
  std::string Name() const;
};

/** Feelers stop below this transmittance (GPU and twin alike) unless told not to. */
constexpr double ShadowTerminationTransmittance = 1.0 / 512.0;

/**
 * Dimensions of the cached shadow volume for a data grid: aspect kept, `size` nodes along
 * the longest axis but never more than the data has.
 */
VTKDEEPSHADOWCORE_EXPORT glm::ivec3 ShadowVolumeDims(const glm::ivec3& dataDims, int size);

/**
 * One sample as the light's rays read it: its scalar (under isosurface blending, the contour
 * crossed since the sample before, or none: IsoCrossings) and what its opacity is multiplied
 * by (gradient opacity; 1 without).
 */
struct CastSample
{
  CastSample(double scalar, double opacityScale = 1.0)
    : Scalar(scalar)
    , OpacityScale(opacityScale)
  {
  }
  double Scalar;
  double OpacityScale;
  glm::dvec4 Values{ 0.0 }; // every component's value (Components.h), when there are several
  glm::dvec4 ComponentGradientFactors{ 1.0 }; // each component's gradient opacity (Components.h)
  int Label = 0;            // its label under a label map (Mask.h)
  double Magnitude = 0.0;   // its gradient magnitude under a 2D transfer function (Transfer2D.h)
};

/** A box in a volume's continuous index space, corners included. */
struct IndexBox
{
  glm::dvec3 Lo{ 0.0 };
  glm::dvec3 Hi{ 0.0 };
};

/** The volume that casts shadows, as the techniques read it. */
struct ShadowCaster
{
  const VolumeGrid* Grid = nullptr;
  /** The transfer function that casts (the volume's, or a separate one for shadows). */
  const TransferFunction* Transfer = nullptr;
  Interpolation Sampling = Interpolation::Linear;
  /** GPU twin: colour and corrected opacity from this table (sampled for the feeler step). */
  const TransferTable* FeelerTable = nullptr;
  /** Optional: blocks of zero opacity that feelers may skip (exactly; see EmptySpace.h). */
  const EmptySpaceMap* Empty = nullptr;
  /** Optional: where the volume exists (BoundRegion.h); outside, it casts nothing. */
  const BoundRegion* Bound = nullptr;
  /**
   * Optional: surfaces (world coordinates) that cast shadows too (SurfaceSet.h). Every
   * technique meets them on its light rays: a step of their transmission; binary techniques
   * (opaque rays, shadow maps) stop at a surface whose opacity exceeds the threshold.
   */
  const SurfaceSet* Surfaces = nullptr;
  /**
   * Optional: isosurface blending's contour values, sorted (Isosurface.h). The light's rays
   * then read, at each sample, the contour crossed since the one before (IsoCrossings), and
   * a crossing's opacity is the transfer function's, uncorrected; no crossing casts nothing.
   */
  const std::vector<double>* IsoValues = nullptr;
  /** Optional: gradient opacity (GradientOpacity.h), which light rays see as the view does. */
  const GradientOpacity* Gradient = nullptr;
  /** Optional: a binary mask (Mask.h, the data's dimensions); what it clears casts nothing. */
  const VolumeGrid* Mask = nullptr;
  /**
   * Optional, with Mask: Mask is a label map, whose labels' colours and opacities cast (from
   * LabelTables, GPU twin, or the functions), their opacities holding for a step of ViewStep.
   */
  const LabelMap* Labels = nullptr;
  const std::vector<TransferTable>* LabelTables = nullptr;
  /** The view's step: what a label's or a 2D function's opacity holds for (uncorrected, as VTK's). */
  double ViewStep = 1.0;
  /** Optional: a 2D transfer function (Transfer2D.h) replacing Transfer's colour and opacity,
   * its opacities holding for a step of ViewStep. */
  const Transfer2D* Function2D = nullptr;
  /** Several components (Components.h): their colours and opacities replace Transfer's. */
  const ComponentLookup* Components = nullptr;
  /**
   * Optional: the part of index space a light-space face's rays march (a cluster's box,
   * Core/Shadows/Clusters.h); null: all of it.
   */
  const IndexBox* Clip = nullptr;
  /**
   * Optional: the centre of the camera's near plane (world). Clustered light-space maps give
   * objects that look larger from there clusters of their own (Core/Shadows/Clusters.h).
   */
  std::optional<glm::dvec3> Eye;
  /**
   * Optional: the camera whose pixels resolution-matched maps serve
   * (Core/Shadows/ResolutionMatched.h); without it they build their base level alone.
   */
  const Camera* View = nullptr;

  /**
   * The sample at continuous voxel index `index` of a light ray whose crossings `crossings`
   * follows (IsoCrossings(IsoValues), one per ray).
   */
  CastSample Read(const glm::dvec3& index, IsoCrossings& crossings) const;

  /**
   * Colour (transmission) and opacity corrected for `step` at `scalar`; under isosurface
   * blending, of the contour `scalar` crossed (uncorrected; none: opacity 0).
   */
  glm::dvec4 Sample(const CastSample& sample, double step) const;
  /** Whether the sample at `scalar` is above a per-sample threshold (Opacity, Scalar modes);
   * under isosurface blending, whether the contour it crossed is. */
  bool AboveThreshold(const CastSample& sample, double step, const ShadowParameters& parameters) const;
};

/**
 * The binary techniques' test along one light ray, in the ray's order: whether the light is
 * blocked once a sample or a mesh crossing counts (ThresholdMode). The twin of the GLSL
 * feeler's opaque branch and of ShadowMapBuild.glsl.
 */
class VTKDEEPSHADOWCORE_EXPORT OccluderTest
{
public:
  OccluderTest(const ShadowCaster& caster, const ShadowParameters& parameters, double step)
    : Caster(caster)
    , Parameters(parameters)
    , Step(step)
  {
  }
  bool Sample(const CastSample& sample);
  bool Surface(int surface);
  /** Counts what meshes let through at once (grey), for a ray that meets them first. */
  bool Transmission(double transmission);

private:
  const ShadowCaster& Caster;
  const ShadowParameters& Parameters;
  double Step;
  double Transmittance = 1.0;
};

/** How much of one light reaches a point. */
class VTKDEEPSHADOWCORE_EXPORT LightShadow
{
public:
  virtual ~LightShadow() = default;
  /** Visibility of the light from world point p, per colour channel, in [0, 1]. */
  virtual glm::dvec3 Visibility(const glm::dvec3& p) const = 0;
  /**
   * The same at a point of a receiving surface with unit normal `normal`. Lookups that read
   * neighbouring texels compare each at the depth of the receiver's plane there (a surface
   * that slopes away from the light is deeper at the texels beyond), so that a surface that
   * casts does not shadow itself through them; the rest ask Visibility().
   */
  virtual glm::dvec3 SurfaceVisibility(const glm::dvec3& p, const glm::dvec3& normal) const
  {
    (void)normal;
    return this->Visibility(p);
  }
  /** Memory of the structure (0 for techniques without one). */
  virtual size_t Bytes() const { return 0; }
};

/**
 * Builds the technique's shadow of `light` cast by `caster`. `viewStep` is the view ray's
 * sample distance (the feeler step is StepFactor times it). Returns null for ShadowKind::None;
 * throws std::invalid_argument with Validate()'s message for unusable parameters.
 */
VTKDEEPSHADOWCORE_EXPORT std::unique_ptr<LightShadow> MakeLightShadow(
  const ShadowParameters& parameters, const ShadowCaster& caster, const Light& light,
  double viewStep, int threads = 0);

/** The rays' twin (translucent, opaque or coloured feelers); `step` is the feeler step. */
VTKDEEPSHADOWCORE_EXPORT std::unique_ptr<LightShadow> MakeRayShadow(const ShadowParameters& parameters,
  const ShadowCaster& caster, const Light& light, double step, int threads = 0);

/**
 * The feeler itself: transmittance (per channel if Colored) from world point `from` towards
 * the light (unit direction `toLight`) up to `maxDistance` or the volume's box, samples every
 * `step` at (j + 0.5) * step, those outside the box left out (a point outside the volume
 * starts at its entry); times the transmission of every casting surface crossed before
 * `maxDistance`, inside the box or not.
 */
VTKDEEPSHADOWCORE_EXPORT glm::dvec3 FeelerVisibility(const ShadowCaster& caster,
  const glm::dvec3& from, const glm::dvec3& toLight, double maxDistance, double step,
  const ShadowParameters& parameters);

/** Distance from p to a positional light, infinity for a directional one. */
VTKDEEPSHADOWCORE_EXPORT double DistanceToLight(const Light& light, const glm::dvec3& p);

}
#endif
