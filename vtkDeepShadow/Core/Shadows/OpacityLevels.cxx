#include "Core/Shadows/OpacityLevels.h"

#include "Core/Geometry/SurfaceSet.h"

#include <algorithm>
#include <cmath>

namespace deepshadow
{

double SmoothStep(double a, double b, double x)
{
  if (!(b > a))
  {
    return x < a ? 0.0 : 1.0;
  }
  const double h = std::clamp((x - a) / (b - a), 0.0, 1.0);
  return h * h * (3.0 - 2.0 * h);
}

OpacityLevelsTexel BuildOpacityLevels(
  const VisibilitySamples& samples, const std::array<double, 3>& levels)
{
  OpacityLevelsTexel texel;
  if (samples.Depths.empty())
  {
    return texel;
  }
  const size_t count = samples.Depths.size();
  double maxOpacity = 0.0, maxDepth = samples.Depths.front();
  for (size_t s = 1; s < count; ++s)
  {
    const double a0 = 1.0 - samples.Values[s - 1].r, a1 = 1.0 - samples.Values[s].r;
    if (a1 > maxOpacity)
    {
      maxOpacity = a1;
      maxDepth = samples.Depths[s];
    }
    for (int level = 0; level < 3; ++level)
    {
      if (texel.Depths[level] == NoHit && a0 < levels[level] && a1 >= levels[level])
      {
        const double f = SmoothStep(a0, a1, levels[level]);
        texel.Depths[level] =
          static_cast<float>(samples.Depths[s - 1] + f * (samples.Depths[s] - samples.Depths[s - 1]));
      }
    }
  }
  if (maxOpacity <= 0.0)
  {
    return texel; // nothing absorbs along this ray
  }
  for (float& depth : texel.Depths)
  {
    if (depth == NoHit)
    {
      depth = static_cast<float>(maxDepth);
    }
  }
  texel.MaxOpacity = static_cast<float>(maxOpacity);
  return texel;
}

double EvaluateOpacityLevels(
  const OpacityLevelsTexel& texel, const std::array<double, 3>& levels, double depth)
{
  const std::array<double, 3> d{ { texel.Depths[0], texel.Depths[1], texel.Depths[2] } };
  double opacity;
  if (depth < d[0])
  {
    opacity = 0.0;
  }
  else if (depth < d[1])
  {
    opacity = levels[0] + SmoothStep(d[0], d[1], depth) * (levels[1] - levels[0]);
  }
  else if (depth < d[2])
  {
    opacity = levels[1] + SmoothStep(d[1], d[2], depth) * (levels[2] - levels[1]);
  }
  else
  {
    opacity = texel.MaxOpacity;
  }
  return std::min(opacity, static_cast<double>(texel.MaxOpacity));
}

OpacityLevelsShadow::OpacityLevelsShadow(const ShadowParameters& parameters,
  const ShadowCaster& caster, const Light& light, double step, int threads)
  : LightSpaceShadow(parameters, caster, light, step)
{
  const bool meshes = caster.Surfaces && !caster.Surfaces->Empty();
  this->Texels.assign(this->TexelCount(), OpacityLevelsTexel());
  if (meshes)
  {
    this->Steps.assign(this->TexelCount(), SurfaceSteps());
  }
  this->ForEachTexel(threads, [&](int f, int x, int y, const glm::dvec3& origin, const glm::dvec3& direction) {
    // The volume's visibility: its entry, then the end of every sample (SampleVisibility
    // without the meshes, which go into the steps).
    VisibilitySamples samples;
    SurfaceStepsBuilder steps;
    MarchBesideSurfaceSteps(this->FaceCaster(f), caster, origin, direction, step, steps,
      [&](double t, double, bool, double volume) {
        if (samples.Depths.empty())
        {
          samples.Depths.push_back(t - 0.5 * step);
          samples.Values.emplace_back(1.0);
        }
        samples.Depths.push_back(t + 0.5 * step);
        samples.Values.emplace_back(volume);
      });
    const size_t texel = this->Texel(f, x, y);
    this->Texels[texel] = BuildOpacityLevels(samples, parameters.Levels);
    if (meshes)
    {
      this->Steps[texel] = steps.Finish();
    }
  });
}

glm::dvec3 OpacityLevelsShadow::MapVisibility(const MapPoint& point) const
{
  return this->Bilinear(point, [&](size_t texel, double depth) {
    const double volume = 1.0 - EvaluateOpacityLevels(this->Texels[texel], this->Parameters.Levels, depth);
    return glm::dvec3(this->Steps.empty() ? volume : volume * EvaluateSurfaceSteps(this->Steps[texel], depth));
  });
}

}
