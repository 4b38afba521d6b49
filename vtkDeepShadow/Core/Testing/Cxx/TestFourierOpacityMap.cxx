// Fourier opacity maps, CPU side: the stored coefficients are the closed-form Fourier
// coefficients of the piecewise-constant extinction the samples make (not of points), the
// optical depth converges to Beer-Lambert's as pairs are added, and End carries First.
#include "Core/Shadows/FourierOpacityMap.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace deepshadow;

namespace
{
constexpr double Pi = 3.14159265358979323846;

// A homogeneous body from depth a to b, of optical depth `tau`, as samples `step` long.
std::vector<float> Body(int terms, double end, double a, double b, double tau, double step)
{
  FourierSeriesBuilder builder(terms, end, step);
  const int samples = static_cast<int>(std::lround((b - a) / step));
  for (int j = 0; j < samples; ++j)
  {
    builder.Add(a + (j + 0.5) * step, tau / samples);
  }
  return builder.Finish();
}
}

// Extinction c on [a, b] (x = depth / End): a_k = 2 c (sin 2 pi k xb - sin 2 pi k xa) / (2 pi k),
// b_k = 2 c (cos 2 pi k xa - cos 2 pi k xb) / (2 pi k); stored divided by 2 pi k once more.
TEST(FourierOpacityMap, CoefficientsAreThoseOfTheSamplesPiecewiseConstantExtinction)
{
  const double end = FourierEnd(40.0), a = 10.0, b = 22.0, tau = 3.0;
  for (double step : { 0.25, 1.0, 4.0 })
  {
    const std::vector<float> series = Body(15, end, a, b, tau, step);
    EXPECT_FLOAT_EQ(series[1], tau);
    const double xa = a / end, xb = b / end, c = tau / (xb - xa);
    for (int k = 1; k <= 15; ++k)
    {
      const double scale = c / (2.0 * Pi * Pi * k * k);
      const double ak = scale * (std::sin(2.0 * Pi * k * xb) - std::sin(2.0 * Pi * k * xa));
      const double bk = scale * (std::cos(2.0 * Pi * k * xa) - std::cos(2.0 * Pi * k * xb));
      EXPECT_NEAR(series[2 * k], ak, 1e-5) << "A_" << k << ", step " << step;
      EXPECT_NEAR(series[2 * k + 1], bk, 1e-5) << "B_" << k << ", step " << step;
    }
  }
}

// Beer-Lambert through the body: 0 before it, Total behind End, and between, the series'
// error shrinks as pairs are added (it rings around the two fronts, as a truncated series
// of a step does), and never leaves [0, Total].
TEST(FourierOpacityMap, OpticalDepthConvergesAsPairsAreAdded)
{
  const double end = FourierEnd(40.0), a = 10.0, b = 22.0, tau = 3.0;
  double previous = 1e9;
  for (int terms : { 1, 3, 7, 15 })
  {
    const std::vector<float> series = Body(terms, end, a, b, tau, 0.25);
    EXPECT_EQ(FourierOpticalDepth(series.data(), terms, 9.99), 0.0) << "before the body, " << terms;
    EXPECT_FLOAT_EQ(FourierOpticalDepth(series.data(), terms, end + 1.0), tau) << "past End, " << terms;
    double worst = 0.0, squares = 0.0;
    int count = 0;
    for (double depth = 0.0; depth < end; depth += 0.1)
    {
      const double got = FourierOpticalDepth(series.data(), terms, depth);
      EXPECT_GE(got, 0.0);
      EXPECT_LE(got, tau + 1e-6);
      const double exact = tau * std::clamp((depth - a) / (b - a), 0.0, 1.0);
      worst = std::max(worst, std::abs(got - exact));
      squares += (got - exact) * (got - exact);
      ++count;
    }
    const double rms = std::sqrt(squares / count);
    EXPECT_LT(rms, previous) << terms << " pairs";
    previous = rms;
    std::printf("%2d pairs: optical depth rms error %.4f, max %.4f\n", terms, rms, worst);
  }
  EXPECT_LT(previous, 0.05); // 15 pairs
}

// First rides in End's lowest bits: End is not below what was asked, First never after the
// true one and at most End / 4095 before it.
TEST(FourierOpacityMap, EndCarriesTheFirstDepth)
{
  for (double asked : { 1e-3, 0.7, 40.0, 12345.6 })
  {
    const float end = FourierEnd(asked);
    EXPECT_GE(end, asked);
    EXPECT_LE(end, asked * (1.0 + 1e-3));
    for (double first : { 0.0, 0.3 * asked, 0.999 * asked })
    {
      double unpackedEnd = 0.0, unpackedFirst = 0.0;
      UnpackFourierEnd(PackFourierEnd(end, first), unpackedEnd, unpackedFirst);
      EXPECT_EQ(unpackedEnd, static_cast<double>(end));
      EXPECT_LE(unpackedFirst, first * (1.0 + 1e-6));
      EXPECT_GE(unpackedFirst, first - end / 4095.0 - 1e-6 * end);
    }
  }
}
