// Shadow maps ("B" of Ropinski et al.), CPU twin: per texel the depth of the first occluder
// along its ray (OccluderTest: by default where the accumulated opacity first exceeds the
// threshold; or the first sample above it); a point is lit where its depth minus the bias is
// not behind it, percentage-closer filtered. GLSL twins: Shaders/Shadows/ShadowMap.glsl (lookup) and
// Shaders/Shadows/ShadowMapBuild.glsl (build).
#ifndef deepshadow_ShadowMap_h
#define deepshadow_ShadowMap_h

#include "Core/Shadows/LightSpace.h"
#include "vtkDeepShadowCoreModule.h"

#include <glm/vec2.hpp>

#include <vector>

namespace deepshadow
{

/** The Poisson disc of the Poisson filter, in texels (the GLSL twin is generated from it). */
VTKDEEPSHADOWCORE_EXPORT const std::vector<glm::dvec2>& PoissonDisc();

/**
 * Percentage-closer filtering of depth comparisons on a size x size map at continuous texel
 * position (x, y) (texel centres at integers): the twin of the GLSL lookup. Each texel is
 * compared with `depth` plus `slope` times its offset from (x, y) (a receiver's plane,
 * MapPoint::Slope).
 */
VTKDEEPSHADOWCORE_EXPORT double FilterShadowMap(const float* depths, int size, double x,
  double y, double depth, ShadowFilter filter, const glm::dvec2& slope = glm::dvec2(0.0));

/**
 * The shadow map's occluder along a ray (MarchTexelRay, OccluderTest): the depth of the
 * first sample or casting-surface crossing that blocks it, NoHit if none does. `empty`
 * blocks are skipped (not with the threshold on the scalar).
 */
VTKDEEPSHADOWCORE_EXPORT float FirstOccluder(const ShadowCaster& caster, const ShadowParameters& parameters,
  double step, const EmptySpaceMap* empty, const glm::dvec3& origin, const glm::dvec3& direction);

class VTKDEEPSHADOWCORE_EXPORT ShadowMapShadow : public LightSpaceShadow
{
public:
  ShadowMapShadow(const ShadowParameters& parameters, const ShadowCaster& caster,
    const Light& light, double step, int threads);
  size_t Bytes() const override { return this->Depths.size() * sizeof(float); }

protected:
  glm::dvec3 MapVisibility(const MapPoint& point) const override;

private:
  std::vector<float> Depths; // per face, size x size; NoHit where no sample is above
};

}
#endif
