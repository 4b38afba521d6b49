// Opacity levels: the low-memory deep shadow map of "Deep Shadow Maps from Volumetric Data
// on the GPU" (paper 001), CPU twin. One RGBA texel per light-space texel: the depths at
// which the accumulated opacity 1 - V along the texel's ray crosses three levels (10, 50 and
// 90 % by default) and the maximum opacity reached. Both directions follow the paper's rule:
// a crossing's depth between two samples is placed by a smoothstep of where the level lies
// between their opacities; a lookup is 0 before the first depth, moves from one level to the
// next along a smoothstep of depth between their depths, and is the maximum opacity from the
// last depth on. Where a level is never reached its depth is that of the maximum, and the
// lookup never exceeds the maximum. Rays stop below 1/512 transmittance, like feelers. Grey
// only; bilinear across the four nearest texels.
// GLSL twins: Shaders/Shadows/OpacityLevelsBuild.glsl and Shaders/Shadows/OpacityLevels.glsl.
#ifndef deepshadow_OpacityLevels_h
#define deepshadow_OpacityLevels_h

#include "DeepShadowMap.h"
#include "vtkDeepShadowCoreModule.h"

#include <array>

namespace deepshadow
{

/** One texel: depths of the three levels and the maximum opacity (NoHit depths: no volume). */
struct OpacityLevelsTexel
{
  std::array<float, 3> Depths{ { NoHit, NoHit, NoHit } };
  float MaxOpacity = 0.0f;
};

/** The texel of sampled (grey) visibility. */
VTKDEEPSHADOWCORE_EXPORT OpacityLevelsTexel BuildOpacityLevels(
  const VisibilitySamples& samples, const std::array<double, 3>& levels);

/** Accumulated opacity at `depth` by the paper's interpolation rule. */
VTKDEEPSHADOWCORE_EXPORT double EvaluateOpacityLevels(
  const OpacityLevelsTexel& texel, const std::array<double, 3>& levels, double depth);

/** The paper's smoothstep: 0 at a, 1 at b, 3h^2 - 2h^3 between (GLSL smoothstep). */
VTKDEEPSHADOWCORE_EXPORT double SmoothStep(double a, double b, double x);

class VTKDEEPSHADOWCORE_EXPORT OpacityLevelsShadow : public LightSpaceShadow
{
public:
  OpacityLevelsShadow(const ShadowParameters& parameters, const ShadowCaster& caster,
    const Light& light, double step, int threads);
  size_t Bytes() const override { return this->Texels.size() * 4 * sizeof(float); }

protected:
  glm::dvec3 MapVisibility(const MapPoint& point) const override;

private:
  std::vector<OpacityLevelsTexel> Texels;
};

}
#endif
