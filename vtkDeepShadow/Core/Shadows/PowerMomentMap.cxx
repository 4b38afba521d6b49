#include "Core/Shadows/PowerMomentMap.h"

#include "Core/Geometry/SurfaceSet.h"
#include "Core/ShadowTechniques.h"
#include "Core/Shadows/FourierOpacityMap.h" // End and First in one float

#include <algorithm>
#include <array>
#include <cmath>

namespace deepshadow
{
namespace
{
constexpr int MaxOrder = 3; // moments / 2

// The k-th moment of the uniform distribution on [x - h, x + h]:
// sum over even j of C(k, j) x^(k - j) h^j / (j + 1).
double BoxMoment(int k, double x, double h)
{
  double sum = 0.0, binomial = 1.0;
  for (int j = 0; j <= k; ++j)
  {
    if (j % 2 == 0)
    {
      sum += binomial * std::pow(x, k - j) * std::pow(h, j) / (j + 1);
    }
    binomial = binomial * (k - j) / (j + 1);
  }
  return sum;
}

// The real roots of c[0] + c[1] x + ... + c[n] x^n, n = 1, 2 or 3, each clamped to [-4, 4]:
// the kernel polynomial's roots are real; far ones (a leading coefficient near 0) carry
// almost no weight, and the clamp keeps their side of the point.
std::array<double, MaxOrder> Roots(const double* c, int n)
{
  std::array<double, MaxOrder> r{};
  if (n == 1)
  {
    r[0] = -c[0] / c[1];
  }
  else if (n == 2)
  {
    const double discriminant = std::max(c[1] * c[1] - 4.0 * c[2] * c[0], 0.0);
    const double q = -0.5 * (c[1] + std::copysign(std::sqrt(discriminant), c[1]));
    r[0] = q / c[2];
    r[1] = c[0] / q;
  }
  else
  {
    // Monic x^3 + a x^2 + b x + d, depressed t^3 + p t + q at x = t - a / 3; three real roots
    // by the trigonometric method (p < 0 for three distinct ones; held below 0).
    const double a = c[2] / c[3], b = c[1] / c[3], d = c[0] / c[3];
    const double p = std::min(b - a * a / 3.0, -1e-12);
    const double q = 2.0 * a * a * a / 27.0 - a * b / 3.0 + d;
    const double m = 2.0 * std::sqrt(-p / 3.0);
    const double theta = std::acos(std::clamp(3.0 * q / (p * m), -1.0, 1.0)) / 3.0;
    for (int k = 0; k < 3; ++k)
    {
      r[k] = m * std::cos(theta - 2.0943951023931957 * k) - a / 3.0;
    }
  }
  for (int k = 0; k < n; ++k)
  {
    r[k] = std::isfinite(r[k]) ? std::clamp(r[k], -4.0, 4.0) : (r[k] < 0.0 ? -4.0 : 4.0);
  }
  return r;
}
}

int PowerMomentCount(const ShadowParameters& parameters)
{
  return static_cast<int>(FindShadowParameter("moments")->Get(parameters).at(0));
}

double PowerMomentBias(int moments)
{
  return moments <= 2 ? 1e-6 : (moments <= 4 ? 5e-6 : 5e-5);
}

PowerMomentBuilder::PowerMomentBuilder(int moments, double end, double step)
  : Moments(moments)
  , End(end)
  , Step(step)
  , Sums(static_cast<size_t>(moments), 0.0)
{
}

void PowerMomentBuilder::Add(double depth, double tau)
{
  if (this->Total == 0.0)
  {
    this->First = depth - 0.5 * this->Step;
  }
  this->Total += tau;
  const double z = 2.0 * depth / this->End - 1.0, h = this->Step / this->End;
  for (int k = 1; k <= this->Moments; ++k)
  {
    this->Sums[k - 1] += tau * BoxMoment(k, z, h);
  }
}

std::vector<float> PowerMomentBuilder::Finish() const
{
  std::vector<float> texel(4 * static_cast<size_t>(PowerMomentLayers(this->Moments)), 0.0f);
  texel[0] = PackFourierEnd(static_cast<float>(this->End), this->First);
  texel[1] = static_cast<float>(this->Total);
  for (int k = 1; k <= this->Moments && this->Total > 0.0; ++k)
  {
    texel[1 + k] = static_cast<float>(this->Sums[k - 1] / this->Total);
  }
  return texel;
}

double PowerMomentFractionBefore(const double* b, int moments, double z)
{
  const int n = moments / 2;
  const double alpha = PowerMomentBias(moments);
  std::array<double, 2 * MaxOrder + 1> biased{};
  biased[0] = 1.0;
  for (int k = 1; k <= moments; ++k)
  {
    biased[k] = (1.0 - alpha) * b[k - 1] + alpha * (k % 2 == 0 ? 1.0 / (k + 1) : 0.0);
  }
  // H c = (1, z, ..., z^n), H[i][j] = b_(i+j), by Cholesky.
  std::array<std::array<double, MaxOrder + 1>, MaxOrder + 1> L{};
  for (int i = 0; i <= n; ++i)
  {
    for (int j = 0; j <= i; ++j)
    {
      double sum = biased[i + j];
      for (int k = 0; k < j; ++k)
      {
        sum -= L[i][k] * L[j][k];
      }
      L[i][j] = i == j ? std::sqrt(std::max(sum, 1e-30)) : sum / L[j][j];
    }
  }
  std::array<double, MaxOrder + 1> c{};
  double power = 1.0;
  for (int i = 0; i <= n; ++i, power *= z)
  {
    double sum = power;
    for (int k = 0; k < i; ++k)
    {
      sum -= L[i][k] * c[k];
    }
    c[i] = sum / L[i][i];
  }
  for (int i = n; i >= 0; --i)
  {
    double sum = c[i];
    for (int k = i + 1; k <= n; ++k)
    {
      sum -= L[k][i] * c[k];
    }
    c[i] = sum / L[i][i];
  }
  // The support: z and the kernel's roots, apart by at least 1e-6; the polynomial through
  // Overestimation at z and the indicator of "in front of z" at the roots, by divided
  // differences; the fraction is its integral against the (biased) moments.
  const std::array<double, MaxOrder> roots = Roots(c.data(), n);
  std::array<double, MaxOrder + 1> x{}, d{};
  x[0] = z;
  d[0] = PowerMomentOverestimation;
  for (int i = 1; i <= n; ++i)
  {
    x[i] = roots[i - 1];
    for (int j = 0; j < i; ++j)
    {
      if (std::abs(x[i] - x[j]) < 1e-6)
      {
        x[i] = x[j] + (x[i] < x[j] ? -1e-6 : 1e-6);
      }
    }
    d[i] = x[i] < z ? 1.0 : 0.0;
  }
  for (int j = 1; j <= n; ++j)
  {
    for (int i = n; i >= j; --i)
    {
      d[i] = (d[i] - d[i - 1]) / (x[i] - x[i - j]);
    }
  }
  // The Newton form's integral: d[j] times that of prod_(i < j) (x - x_i), expanded in powers
  // of x as it grows (ascending, with the coefficient below carried along).
  std::array<double, MaxOrder + 1> product{};
  product[0] = 1.0;
  double fraction = d[0];
  for (int j = 1; j <= n; ++j)
  {
    double below = 0.0, integral = 0.0;
    for (int k = 0; k <= j; ++k)
    {
      const double coefficient = product[k];
      product[k] = below - x[j - 1] * coefficient;
      below = coefficient;
      integral += product[k] * biased[k];
    }
    fraction += d[j] * integral;
  }
  return std::isfinite(fraction) ? std::clamp(fraction, 0.0, 1.0) : 0.0;
}

double PowerMomentOpticalDepth(const float* texel, int moments, double depth)
{
  double end = 0.0, first = 0.0;
  UnpackFourierEnd(texel[0], end, first);
  const double total = texel[1];
  if (!(total > 0.0) || depth <= first)
  {
    return 0.0;
  }
  if (depth >= end)
  {
    return total;
  }
  std::array<double, 2 * MaxOrder> b{};
  for (int k = 0; k < moments; ++k)
  {
    b[k] = texel[2 + k];
  }
  return total * PowerMomentFractionBefore(b.data(), moments, 2.0 * depth / end - 1.0);
}

PowerMomentMap::PowerMomentMap(const ShadowParameters& parameters, const ShadowCaster& caster,
  const Light& light, double step, int threads)
  : LightSpaceShadow(parameters, caster, light, step)
  , Moments(PowerMomentCount(parameters))
  , Floats(4 * PowerMomentLayers(PowerMomentCount(parameters)))
{
  const bool meshes = caster.Surfaces && !caster.Surfaces->Empty();
  this->Texels.assign(this->TexelCount() * this->Floats, 0.0f);
  if (meshes)
  {
    this->Steps.assign(this->TexelCount(), SurfaceSteps());
  }
  this->ForEachTexel(threads, [&](int f, int x, int y, const glm::dvec3& origin, const glm::dvec3& direction) {
    const ShadowCaster& faceCaster = this->FaceCaster(f);
    double t0 = 0.0, tExit = 0.0;
    // No box: no moments (End 1, b0 0) that let everything through.
    const double end = FourierEnd(TexelRaySpan(faceCaster, origin, direction, t0, tExit) ? tExit + step : 1.0);
    PowerMomentBuilder moments(this->Moments, end, step);
    SurfaceStepsBuilder steps;
    MarchBesideSurfaceSteps(faceCaster, caster, origin, direction, step, steps,
      [&](double t, double opacity, bool skipped, double) {
        if (!skipped)
        {
          moments.Add(t, SampleOpticalDepth(opacity));
        }
      });
    const size_t texel = this->Texel(f, x, y);
    const std::vector<float> stored = moments.Finish();
    std::copy(stored.begin(), stored.end(), this->Texels.begin() + texel * this->Floats);
    if (meshes)
    {
      this->Steps[texel] = steps.Finish();
    }
  });
}

glm::dvec3 PowerMomentMap::MapVisibility(const MapPoint& point) const
{
  return this->Bilinear(point, [&](size_t texel, double depth) {
    const double volume =
      std::exp(-PowerMomentOpticalDepth(&this->Texels[texel * this->Floats], this->Moments, depth));
    return glm::dvec3(this->Steps.empty() ? volume : volume * EvaluateSurfaceSteps(this->Steps[texel], depth));
  });
}

}
