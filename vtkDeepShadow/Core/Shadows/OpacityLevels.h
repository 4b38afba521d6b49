// Opacity levels: the low-memory deep shadow map of "Deep Shadow Maps from Volumetric Data
// on the GPU" (paper 001), CPU twin. One RGBA texel per light-space texel: the depths at
// which the accumulated opacity 1 - V along the texel's ray crosses three levels (10, 50 and
// 90 % by default) and the maximum opacity reached. Both directions follow the paper's rule:
// a crossing's depth between two samples is placed by a smoothstep of where the level lies
// between their opacities; a lookup is 0 before the first depth, moves from one level to the
// next along a smoothstep of depth between their depths, and is the maximum opacity from the
// last depth on. Where a level is never reached its depth is that of the maximum, and the
// lookup never exceeds the maximum. Grey only; bilinear across the four nearest texels.
//
// Casting meshes are not volumes: each crossing is a step, which the smooth interpolation
// between levels would spread from the volume to the mesh (a ground under a ball read the
// last level). The levels hold the volume's opacity only; the meshes' crossings go into a
// second texel (Core/Shadows/SurfaceSteps.h).
// GLSL twins: Shaders/Shadows/OpacityLevelsBuild.glsl and Shaders/Shadows/OpacityLevels.glsl.
#ifndef deepshadow_OpacityLevels_h
#define deepshadow_OpacityLevels_h

#include "Core/Shadows/DeepShadowMap.h"
#include "Core/Shadows/SurfaceSteps.h"
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
  /** As the GPU stores it: one RGBA 32-bit float texel, two with casting meshes. */
  size_t Bytes() const override { return (this->Texels.size() + this->Steps.size()) * 4 * sizeof(float); }

protected:
  glm::dvec3 MapVisibility(const MapPoint& point) const override;

private:
  std::vector<OpacityLevelsTexel> Texels;
  std::vector<SurfaceSteps> Steps; // per texel, when meshes cast; else empty
};

}
#endif
