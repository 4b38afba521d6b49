#include "Core/Shadows/ShadowMap.h"

#include "Core/Geometry/SurfaceSet.h"

#include <algorithm>
#include <cmath>

namespace deepshadow
{

const std::vector<glm::dvec2>& PoissonDisc()
{
  // A 12-point Poisson disc in the unit circle, scaled to a radius of 2 texels.
  static const std::vector<glm::dvec2> disc = [] {
    const double unit[12][2] = { { -0.326212, -0.405805 }, { -0.840144, -0.073580 },
      { -0.695914, 0.457137 }, { -0.203345, 0.620716 }, { 0.962340, -0.194983 },
      { 0.473434, -0.480026 }, { 0.519456, 0.767022 }, { 0.185461, -0.893124 },
      { 0.507431, 0.064425 }, { 0.896420, 0.412458 }, { -0.321940, -0.932615 },
      { -0.791559, -0.597705 } };
    std::vector<glm::dvec2> points;
    for (const auto& p : unit)
    {
      points.emplace_back(2.0 * p[0], 2.0 * p[1]);
    }
    return points;
  }();
  return disc;
}

double FilterShadowMap(const float* depths, int size, double x, double y, double depth,
  ShadowFilter filter, const glm::dvec2& slope)
{
  x = ClampTexelPosition(x, size);
  y = ClampTexelPosition(y, size);
  auto lit = [&](int i, int j) {
    const double planeDepth = depth + slope.x * (i - x) + slope.y * (j - y);
    i = std::clamp(i, 0, size - 1);
    j = std::clamp(j, 0, size - 1);
    return planeDepth <= static_cast<double>(depths[static_cast<size_t>(j) * size + i]) ? 1.0 : 0.0;
  };
  const int nx = static_cast<int>(std::floor(x + 0.5));
  const int ny = static_cast<int>(std::floor(y + 0.5));
  switch (filter)
  {
    case ShadowFilter::None:
      return lit(nx, ny);
    case ShadowFilter::PCF2x2:
    {
      const int i = static_cast<int>(std::floor(x)), j = static_cast<int>(std::floor(y));
      const double fx = x - i, fy = y - j;
      return (1 - fx) * (1 - fy) * lit(i, j) + fx * (1 - fy) * lit(i + 1, j) +
        (1 - fx) * fy * lit(i, j + 1) + fx * fy * lit(i + 1, j + 1);
    }
    case ShadowFilter::PCF3x3:
    {
      double sum = 0.0;
      for (int dj = -1; dj <= 1; ++dj)
      {
        for (int di = -1; di <= 1; ++di)
        {
          sum += lit(nx + di, ny + dj);
        }
      }
      return sum / 9.0;
    }
    case ShadowFilter::Poisson:
    {
      double sum = 0.0;
      for (const glm::dvec2& o : PoissonDisc())
      {
        sum += lit(static_cast<int>(std::floor(x + o.x + 0.5)), static_cast<int>(std::floor(y + o.y + 0.5)));
      }
      return sum / static_cast<double>(PoissonDisc().size());
    }
  }
  return 1.0;
}

ShadowMapShadow::ShadowMapShadow(const ShadowParameters& parameters, const ShadowCaster& caster,
  const Light& light, double step, int threads)
  : LightSpaceShadow(parameters, caster, light, step)
{
  this->Depths.assign(this->TexelCount(), NoHit);
  this->ForEachTexel(threads, [&](int f, int x, int y, const glm::dvec3& origin, const glm::dvec3& direction) {
    this->Depths[this->Texel(f, x, y)] =
      FirstOccluder(this->FaceCaster(f), parameters, step, this->FaceCaster(f).Empty, origin, direction);
  });
}

float FirstOccluder(const ShadowCaster& caster, const ShadowParameters& parameters, double step,
  const EmptySpaceMap* empty, const glm::dvec3& origin, const glm::dvec3& direction)
{
  // Zero-opacity blocks hold no occluder, unless the threshold is on the scalar.
  if (parameters.Mode == ThresholdMode::Scalar)
  {
    empty = nullptr;
  }
  float depth = NoHit;
  OccluderTest occluder(caster, parameters, step);
  MarchTexelRay(
    caster, origin, direction, step, empty,
    [&](long, double t, const CastSample& scalar, bool skipped) {
      if (!skipped && occluder.Sample(scalar))
      {
        depth = static_cast<float>(t);
        return false;
      }
      return true;
    },
    [&](double t, int surface) {
      if (occluder.Surface(surface))
      {
        depth = static_cast<float>(t);
        return false;
      }
      return true;
    });
  return depth;
}

glm::dvec3 ShadowMapShadow::MapVisibility(const MapPoint& point) const
{
  return glm::dvec3(FilterShadowMap(&this->Depths[this->Texel(point.Face, 0, 0)], this->Size, point.X,
    point.Y, point.Depth - this->Parameters.Bias * this->Step, this->Parameters.Filter, point.Slope));
}

}
