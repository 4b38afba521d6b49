#include "Core/Shadows/OpacitySlices.h"

#include "Core/ShadowTechniques.h"
#include "Core/Shadows/DeepShadowMap.h"

#include <algorithm>
#include <cmath>

namespace deepshadow
{

int OpacitySliceCount(const ShadowParameters& parameters)
{
  return static_cast<int>(FindShadowParameter("slices")->Get(parameters).at(0));
}

std::vector<std::uint8_t> SliceTexel(const ShadowCaster& caster, const glm::dvec3& origin,
  const glm::dvec3& direction, double step, int count, double depthRange)
{
  const VisibilitySamples samples = SampleVisibility(caster, origin, direction, step, false, 1.0 / 512.0);
  const size_t points = samples.Depths.size();
  std::vector<std::uint8_t> slices(static_cast<size_t>(count), 255);
  size_t k = 0; // the first point at or beyond the slice
  for (int i = 0; i < count; ++i)
  {
    const double depth = (i + 1) * depthRange / count;
    while (k < points && samples.Depths[k] < depth)
    {
      ++k;
    }
    double value = 1.0; // in front of the ray's first point
    if (k == points && points > 0)
    {
      value = samples.Values.back().r;
    }
    else if (k > 0)
    {
      // At a step (two points at one depth) the first of them: the value before it.
      const double d0 = samples.Depths[k - 1], d1 = samples.Depths[k];
      const double v0 = samples.Values[k - 1].r, v1 = samples.Values[k].r;
      value = v0 + (depth - d0) / (d1 - d0) * (v1 - v0);
    }
    slices[static_cast<size_t>(i)] = static_cast<std::uint8_t>(std::lround(std::clamp(value, 0.0, 1.0) * 255.0));
  }
  return slices;
}

double EvaluateSlices(const std::uint8_t* slices, int count, double depth)
{
  const double f = depth * count;
  if (!(f > 0.0))
  {
    return 1.0;
  }
  if (f >= count)
  {
    return slices[count - 1] / 255.0;
  }
  const int j = static_cast<int>(std::floor(f));
  const double before = j == 0 ? 1.0 : slices[j - 1] / 255.0, after = slices[j] / 255.0;
  return before + (f - j) * (after - before);
}

OpacitySlicesShadow::OpacitySlicesShadow(const ShadowParameters& parameters, const ShadowCaster& caster,
  const Light& light, double step, int threads)
  : LightSpaceShadow(parameters, caster, light, step)
  , Count(OpacitySliceCount(parameters))
  , DepthRange(LightDepthRange(
      CasterBoundsOf(caster.Grid->GetIndexToWorld(), caster.Grid->GetDims(), caster.Surfaces).Radius))
{
  this->Slices.assign(this->TexelCount() * this->Count, 255);
  this->ForEachTexel(threads, [&](int f, int x, int y, const glm::dvec3& origin, const glm::dvec3& direction) {
    const std::vector<std::uint8_t> texel =
      SliceTexel(this->FaceCaster(f), origin, direction, step, this->Count, this->DepthRange);
    std::copy(texel.begin(), texel.end(), this->Slices.begin() + this->Texel(f, x, y) * this->Count);
  });
}

glm::dvec3 OpacitySlicesShadow::MapVisibility(const MapPoint& point) const
{
  return this->Bilinear(point, [&](size_t texel, double depth) {
    // One slice towards the light: a surface does not shadow itself (see the header).
    return glm::dvec3(EvaluateSlices(
      &this->Slices[texel * this->Count], this->Count, depth / this->DepthRange - 1.0 / this->Count));
  });
}

}
