// Coloured stochastic shadow maps (CSSM, paper 003, after McGuire and Enderton), CPU twin.
//
// Build: from each texel a photon is traced through the volume in segments (the samples of
// the texel's ray). In segment i it is stopped in channel c with probability
// rho = alpha (1 - t_c) (alpha corrected for the step, t_c the colour: its transmission),
// decided by comparing rho with one random threshold r_i in [0, 1) per segment; per channel
// the texel stores the depth of the segment that stopped the photon (NoHit if none did).
// With `Photons` > 1 each texel traces that many independent photons (one layer each).
// Thresholds come from an integer hash of (texel, layer, segment, seed), so maps are
// reproducible and the GPU draws the same numbers.
//
// Lookup: the fraction of tests, over the m offsets of the nearest texel and the photons,
// whose stored depth lies beyond the point (on a receiving surface, beyond its plane at that
// texel: MapPoint::DepthAt): an unbiased estimate of the coloured
// transmittance prod (1 - rho_i) over the segments before the point (TestStochastic checks
// it). GLSL twins: Shaders/Shadows/StochasticShadowMapBuild.glsl and
// Shaders/Shadows/StochasticShadowMap.glsl.
#ifndef deepshadow_StochasticShadowMap_h
#define deepshadow_StochasticShadowMap_h

#include "Core/Shadows/LightSpace.h"
#include "vtkDeepShadowCoreModule.h"

#include <glm/vec2.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace deepshadow
{

/**
 * The texel offsets of the lookup: 13 are the paper's, {(0,0), (+-3,+-3), (+-4,0), (0,+-4),
 * (+-7,0), (0,+-7)}; 7 are its seven smallest, {(0,0), (+-4,0), (0,+-4), (3,3), (-3,-3)};
 * 21 add {(+-7,+-7), (+-10,0), (0,+-10)}. Other counts throw std::invalid_argument.
 */
VTKDEEPSHADOWCORE_EXPORT const std::vector<glm::ivec2>& StochasticOffsets(int count);

/**
 * Segment numbers of surface crossings: the k-th crossing of a photon's ray is segment
 * SurfaceSegmentBase + k (volume samples are segments 0, 1, ...).
 */
constexpr uint32_t SurfaceSegmentBase = 0x80000000u;

/** The random threshold of a segment, in [0, 1): PCG hashes, the same on GPU and CPU. */
VTKDEEPSHADOWCORE_EXPORT double StochasticThreshold(
  uint32_t x, uint32_t y, uint32_t layer, uint32_t segment, uint32_t seed);

/**
 * Traces the photon of texel (x, y), layer `layer`: per channel the depth of the segment
 * that stopped it, NoHit where none did.
 */
VTKDEEPSHADOWCORE_EXPORT std::array<float, 3> TraceStochasticPhoton(const ShadowCaster& caster,
  const glm::dvec3& origin, const glm::dvec3& direction, double step, uint32_t x, uint32_t y,
  uint32_t layer, uint32_t seed);

class VTKDEEPSHADOWCORE_EXPORT StochasticShadowMap : public LightSpaceShadow
{
public:
  StochasticShadowMap(const ShadowParameters& parameters, const ShadowCaster& caster,
    const Light& light, double step, int threads);
  /** As the GPU stores it: one RGBA 32-bit float texel per texel and photon. */
  size_t Bytes() const override { return this->Stops.size() * 4 * sizeof(float); }

protected:
  glm::dvec3 MapVisibility(const MapPoint& point) const override;

private:
  int Photons;
  std::vector<std::array<float, 3>> Stops; // per texel, per photon
};

}
#endif
