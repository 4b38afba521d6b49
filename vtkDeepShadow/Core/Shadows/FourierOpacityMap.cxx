#include "Core/Shadows/FourierOpacityMap.h"

#include "Core/Geometry/SurfaceSet.h"
#include "Core/ShadowTechniques.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace deepshadow
{
namespace
{
constexpr double Pi = 3.14159265358979323846;

constexpr std::uint32_t FirstBits = 0xfffu;

std::uint32_t BitsOf(float value)
{
  std::uint32_t bits;
  std::memcpy(&bits, &value, sizeof(bits));
  return bits;
}

float FloatOf(std::uint32_t bits)
{
  float value;
  std::memcpy(&value, &bits, sizeof(value));
  return value;
}
}

float FourierEnd(double end)
{
  return FloatOf((BitsOf(static_cast<float>(end)) | FirstBits) + 1u);
}

float PackFourierEnd(float end, double first)
{
  // In float arithmetic, as the GLSL twin computes it.
  const float fraction = std::clamp(static_cast<float>(first) / end, 0.0f, 1.0f);
  return FloatOf(BitsOf(end) | static_cast<std::uint32_t>(std::floor(4095.0f * fraction)));
}

void UnpackFourierEnd(float stored, double& end, double& first)
{
  const std::uint32_t bits = BitsOf(stored);
  const float period = FloatOf(bits & ~FirstBits);
  end = period;
  first = static_cast<double>(static_cast<float>(bits & FirstBits) / 4095.0f * period);
}

double SampleOpticalDepth(double opacity)
{
  return -std::log(std::max(1.0 - opacity, 1.0 / 1024.0));
}

int FourierTerms(const ShadowParameters& parameters)
{
  return static_cast<int>(FindShadowParameter("fom-terms")->Get(parameters).at(0));
}

FourierSeriesBuilder::FourierSeriesBuilder(int terms, double end, double step)
  : Terms(terms)
  , End(end)
  , Step(step)
  , Sums(2 * static_cast<size_t>(terms), 0.0)
{
}

void FourierSeriesBuilder::Add(double depth, double tau)
{
  if (this->Total == 0.0)
  {
    this->First = depth - 0.5 * this->Step;
  }
  this->Total += tau;
  const double angle = 2.0 * Pi * depth / this->End;
  for (int k = 1; k <= this->Terms; ++k)
  {
    this->Sums[2 * (k - 1)] += tau * std::cos(k * angle);
    this->Sums[2 * (k - 1) + 1] += tau * std::sin(k * angle);
  }
}

std::vector<float> FourierSeriesBuilder::Finish() const
{
  std::vector<float> series(4 * static_cast<size_t>(FourierLayers(this->Terms)), 0.0f);
  series[0] = PackFourierEnd(static_cast<float>(this->End), this->First);
  series[1] = static_cast<float>(this->Total);
  const double width = this->Step / this->End;
  for (int k = 1; k <= this->Terms; ++k)
  {
    // A sample is a box `width` wide: a point's coefficients times sinc(k width); and the
    // integral's 1 / (2 pi k), with a_k = 2 sum tau cos: 1 / (pi k) in all.
    const double h = Pi * k * width;
    const double scale = (h > 0.0 ? std::sin(h) / h : 1.0) / (Pi * k);
    series[2 * k] = static_cast<float>(scale * this->Sums[2 * (k - 1)]);
    series[2 * k + 1] = static_cast<float>(scale * this->Sums[2 * (k - 1) + 1]);
  }
  return series;
}

double FourierOpticalDepth(const float* series, int terms, double depth)
{
  double end = 0.0, first = 0.0;
  UnpackFourierEnd(series[0], end, first);
  const double total = series[1];
  if (!(total > 0.0) || depth <= first)
  {
    return 0.0;
  }
  if (depth >= end)
  {
    return total;
  }
  const double x = depth / end;
  double tau = total * x;
  for (int k = 1; k <= terms; ++k)
  {
    const double angle = 2.0 * Pi * k * x;
    tau += series[2 * k] * std::sin(angle) + series[2 * k + 1] * (1.0 - std::cos(angle));
  }
  return std::clamp(tau, 0.0, total);
}

FourierOpacityMap::FourierOpacityMap(const ShadowParameters& parameters, const ShadowCaster& caster,
  const Light& light, double step, int threads)
  : LightSpaceShadow(parameters, caster, light, step)
  , Terms(FourierTerms(parameters))
  , Floats(4 * FourierLayers(FourierTerms(parameters)))
{
  const bool meshes = caster.Surfaces && !caster.Surfaces->Empty();
  this->Series.assign(this->TexelCount() * this->Floats, 0.0f);
  if (meshes)
  {
    this->Steps.assign(this->TexelCount(), SurfaceSteps());
  }
  this->ForEachTexel(threads, [&](int f, int x, int y, const glm::dvec3& origin, const glm::dvec3& direction) {
    const ShadowCaster& faceCaster = this->FaceCaster(f);
    double t0 = 0.0, tExit = 0.0;
    // No box: an empty series (End 1, Total 0) that lets everything through.
    const double end = FourierEnd(TexelRaySpan(faceCaster, origin, direction, t0, tExit) ? tExit + step : 1.0);
    FourierSeriesBuilder series(this->Terms, end, step);
    SurfaceStepsBuilder steps;
    MarchBesideSurfaceSteps(faceCaster, caster, origin, direction, step, steps,
      [&](double t, double opacity, bool skipped, double) {
        if (!skipped)
        {
          series.Add(t, SampleOpticalDepth(opacity));
        }
      });
    const size_t texel = this->Texel(f, x, y);
    const std::vector<float> stored = series.Finish();
    std::copy(stored.begin(), stored.end(), this->Series.begin() + texel * this->Floats);
    if (meshes)
    {
      this->Steps[texel] = steps.Finish();
    }
  });
}

glm::dvec3 FourierOpacityMap::MapVisibility(const MapPoint& point) const
{
  return this->Bilinear(point, [&](size_t texel, double depth) {
    const double volume = std::exp(-FourierOpticalDepth(&this->Series[texel * this->Floats], this->Terms, depth));
    return glm::dvec3(this->Steps.empty() ? volume : volume * EvaluateSurfaceSteps(this->Steps[texel], depth));
  });
}

}
