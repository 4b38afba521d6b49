// Shadow techniques, CPU side: the twins of the GPU techniques and the ground truth.
//
// A LightShadow answers one question, "how much of this light reaches world point p?", in
// [0, 1]. Each technique builds one per light from the volume that casts (issue scope: a
// volume shadows itself) and the light:
//   - Rays, translucent ("A"): march a feeler from p to the light and multiply (1 - alpha) of
//     its samples, alpha corrected for the feeler's step exactly as on the view ray. With exact
//     transfer functions, a fine step and no early termination this is the ground truth.
//   - Rays, opaque ("B"): 0 as soon as a feeler sample exceeds the threshold, else 1.
//   - Cached ("PP"): either of the above evaluated once on a grid over the volume's box and
//     interpolated trilinearly, as the GPU's 3D shadow texture is.
//   - Shadow map ("B"): per light-space texel, the depth of the first sample above the
//     threshold along the texel's ray; p is lit if its depth minus the bias is not behind it,
//     filtered by percentage-closer filtering (none, 2x2 bilinear, 3x3 box, Poisson disc).
// Feelers use the volume's samples at (j + 0.5) * step from p, like the view ray.
#ifndef deepshadow_Shadows_h
#define deepshadow_Shadows_h

#include "EmptySpace.h"
#include "Light.h"
#include "TransferFunction.h"
#include "VolumeGrid.h"
#include "vtkDeepShadowCoreModule.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <memory>
#include <string>
#include <vector>

namespace deepshadow
{

enum class ShadowKind
{
  None,
  Rays,
  ShadowMap
};

enum class ShadowFilter
{
  None,    // the texel the point falls in
  PCF2x2,  // the four nearest texels, bilinear weights
  PCF3x3,  // the 3x3 texels around the nearest one, equal weights
  Poisson  // 12 taps of a Poisson disc of radius 2 texels, equal weights
};

enum class ThresholdMode
{
  Opacity, // the transfer function's opacity (per unit distance) exceeds the threshold
  Scalar   // the scalar, normalized to [0, 1] over the data range, exceeds it
};

/** Everything a technique's result depends on besides the volume and the light. */
struct VTKDEEPSHADOWCORE_EXPORT ShadowParameters
{
  ShadowKind Kind = ShadowKind::None;
  bool Opaque = false;      // rays: binary at the first sample above the threshold
  bool Cached = false;      // rays: evaluated once into a shadow volume
  double Threshold = 0.5;   // opaque rays and shadow maps, in [0, 1]
  ThresholdMode Mode = ThresholdMode::Opacity;
  double StepFactor = 1.0;  // feeler (and light-ray) step / view step
  int VolumeSize = 128;     // cached: shadow nodes along the longest axis (at most the data's)
  int MapSize = 512;        // shadow map: texels per side
  double Bias = 2.0;        // shadow map: depth bias, in feeler steps
  ShadowFilter Filter = ShadowFilter::PCF3x3;
  /** Stop a feeler once its transmittance is below ShadowTerminationTransmittance. */
  bool EarlyTermination = true;

  /** The ground truth: translucent rays, no early termination, at `stepFactor`. */
  static ShadowParameters GroundTruth(double stepFactor = 0.25);
  /** A short name: none, rays, rays-opaque, rays-cached, rays-opaque-cached, shadowmap. */
  std::string Name() const;
};

/** Feelers stop below this transmittance (GPU and twin alike) unless told not to. */
constexpr double ShadowTerminationTransmittance = 1.0 / 512.0;

/** The Poisson disc of the Poisson filter, in texels (the GLSL twin is generated from it). */
VTKDEEPSHADOWCORE_EXPORT const std::vector<glm::dvec2>& PoissonDisc();

/**
 * Dimensions of the cached shadow volume for a data grid: aspect kept, `size` nodes along
 * the longest axis but never more than the data has.
 */
VTKDEEPSHADOWCORE_EXPORT glm::ivec3 ShadowVolumeDims(const glm::ivec3& dataDims, int size);

/** The volume that casts shadows, as the techniques read it. */
struct ShadowCaster
{
  const VolumeGrid* Grid = nullptr;
  const TransferFunction* Transfer = nullptr;
  Interpolation Sampling = Interpolation::Linear;
  /** GPU twin: the feeler's corrected opacity from this table (sampled for the feeler step). */
  const TransferTable* FeelerTable = nullptr;
  /** Optional: blocks of zero opacity that feelers may skip (exactly; see EmptySpace.h). */
  const EmptySpaceMap* Empty = nullptr;
};

/** How much of one light reaches a point. */
class VTKDEEPSHADOWCORE_EXPORT LightShadow
{
public:
  virtual ~LightShadow() = default;
  /** Visibility of the light from world point p, in [0, 1]. */
  virtual double Visibility(const glm::dvec3& p) const = 0;
  /** Memory of the structure (0 for techniques without one). */
  virtual size_t Bytes() const { return 0; }
};

/**
 * Builds the technique's shadow of `light` cast by `caster`. `viewStep` is the view ray's
 * sample distance (the feeler step is StepFactor times it). Returns null for ShadowKind::None.
 */
VTKDEEPSHADOWCORE_EXPORT std::unique_ptr<LightShadow> MakeLightShadow(
  const ShadowParameters& parameters, const ShadowCaster& caster, const Light& light,
  double viewStep, int threads = 0);

/**
 * The feeler itself: transmittance from world point `from` towards the light (unit direction
 * `toLight`) up to `maxDistance` or the volume's box, samples every `step`.
 */
VTKDEEPSHADOWCORE_EXPORT double FeelerVisibility(const ShadowCaster& caster,
  const glm::dvec3& from, const glm::dvec3& toLight, double maxDistance, double step,
  const ShadowParameters& parameters);

/** One face of a shadow map: a light-space projection whose texels cast rays into the scene. */
struct VTKDEEPSHADOWCORE_EXPORT ShadowMapFace
{
  bool Perspective = false;
  glm::dvec3 Origin{ 0.0 };  // light position (perspective) or centre of the near plane
  glm::dvec3 Forward{ 0.0, 0.0, -1.0 };
  glm::dvec3 Right{ 1.0, 0.0, 0.0 };
  glm::dvec3 Up{ 0.0, 1.0, 0.0 };
  double Extent = 1.0;       // half-width of the near plane (ortho) or tan(half angle)

  /** Texel ray through normalized face coordinates (u, v) in [-1, 1]. */
  void TexelRay(double u, double v, glm::dvec3& origin, glm::dvec3& direction) const;
  /** Face coordinates and depth of world point p; false if p is behind the face. */
  bool Project(const glm::dvec3& p, double& u, double& v, double& depth) const;
};

/** Bounding sphere (world) of the box [0, dims - 1] of index space mapped by indexToWorld. */
VTKDEEPSHADOWCORE_EXPORT void VolumeBoundingSphere(
  const glm::dmat4& indexToWorld, const glm::ivec3& dims, glm::dvec3& centre, double& radius);

/**
 * The faces a light needs to see a bounding sphere (centre, radius): one orthographic face
 * for a directional light, one perspective face for a positional light outside the sphere,
 * six (a cube) for one inside it.
 */
VTKDEEPSHADOWCORE_EXPORT std::vector<ShadowMapFace> ShadowMapFaces(
  const Light& light, const glm::dvec3& centre, double radius);

/** For a cube of faces, the face that sees direction d (major axis); 0 otherwise. */
VTKDEEPSHADOWCORE_EXPORT int ShadowMapFaceFor(const std::vector<ShadowMapFace>& faces,
  const glm::dvec3& fromLight);

/**
 * Percentage-closer filtering of depth comparisons on a size x size map at continuous texel
 * position (x, y) (texel centres at integers): the twin of the GLSL lookup.
 */
VTKDEEPSHADOWCORE_EXPORT double FilterShadowMap(const float* depths, int size, double x,
  double y, double depth, ShadowFilter filter);

}
#endif
