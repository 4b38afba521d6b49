// Uniform opacity slices ("slices"; opacity shadow maps, Kim and Neumann 2001), CPU twin: a
// rival of the deep shadow map at a fixed number of bits per texel, the simplest one. Each
// texel keeps the transmittance of its ray at N depths evenly spaced over the light's depth
// range (LightDepthRange: slice i at (i + 1) / N of it), 8 bits each; the lookup is linear
// between them, 1 at depth 0 and the last slice's value beyond, at the point's depth less one
// slice: interpolated at its own depth, an opaque surface between two slices would read part
// of its own front (bands across a lit skin, the ground under a lit sky reading 0.34 at 32
// slices); one slice towards the light, the surface is lit and the shadow inside a medium
// lags by a slice, as a shadow map's bias. No search and no bound; slices outside the volume
// are spent on nothing; smooth media are where it does well.
//
// The ray is sampled as the deep shadow map samples it (SampleVisibility: the transmittance
// at every sample's end, linear between, a casting mesh a step), and a slice takes that
// curve's value at its depth (at a step, the value before it); rays stop below 1/512, like
// feelers. N = 8, 16, 32 or 64 slices are 64 to 512 bits, four slices per RGBA8 layer. Grey
// only; bilinear across the four nearest texels.
// GLSL twins: Shaders/Shadows/OpacitySlicesBuild.glsl and OpacitySlices.glsl.
#ifndef deepshadow_OpacitySlices_h
#define deepshadow_OpacitySlices_h

#include "Core/Shadows/LightSpace.h"
#include "vtkDeepShadowCoreModule.h"

#include <cstdint>
#include <vector>

namespace deepshadow
{

/** The registry's kind of uniform opacity slices ("slices"). */
constexpr ShadowKind OpacitySlicesKind = ShadowKind(10);

/** The slices parameter: slices per texel, 8 bits each (ShadowParameters::Extra). */
VTKDEEPSHADOWCORE_EXPORT int OpacitySliceCount(const ShadowParameters& parameters);

/**
 * The transmittance of one texel's ray at `count` slices evenly spaced over `depthRange`,
 * as stored (8-bit unorms).
 */
VTKDEEPSHADOWCORE_EXPORT std::vector<std::uint8_t> SliceTexel(const ShadowCaster& caster,
  const glm::dvec3& origin, const glm::dvec3& direction, double step, int count, double depthRange);

/** The lookup: V at `depth` (normalized by the depth range) from `count` stored slices. */
VTKDEEPSHADOWCORE_EXPORT double EvaluateSlices(const std::uint8_t* slices, int count, double depth);

class VTKDEEPSHADOWCORE_EXPORT OpacitySlicesShadow : public LightSpaceShadow
{
public:
  OpacitySlicesShadow(const ShadowParameters& parameters, const ShadowCaster& caster,
    const Light& light, double step, int threads);
  /** As the GPU stores it: a byte per slice. */
  size_t Bytes() const override { return this->Slices.size(); }

protected:
  glm::dvec3 MapVisibility(const MapPoint& point) const override;

private:
  int Count;         // slices per texel
  double DepthRange; // world depth of the last slice
  std::vector<std::uint8_t> Slices;
};

}
#endif
