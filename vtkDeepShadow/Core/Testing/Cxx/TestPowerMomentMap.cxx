// Power-moment maps, CPU side: the stored moments are those of the piecewise-constant
// extinction the samples make, a distribution of N = M / 2 atoms is reconstructed exactly
// away from its atoms (it is the one its M moments determine), and through a homogeneous
// body the optical depth approaches Beer-Lambert's as moments are added.
#include "Core/Shadows/FourierOpacityMap.h"
#include "Core/Shadows/PowerMomentMap.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

using namespace deepshadow;

namespace
{
// A homogeneous body from depth a to b, of optical depth `tau`, as samples `step` long.
std::vector<float> Body(int moments, double end, double a, double b, double tau, double step)
{
  PowerMomentBuilder builder(moments, end, step);
  const int samples = static_cast<int>(std::lround((b - a) / step));
  for (int j = 0; j < samples; ++j)
  {
    builder.Add(a + (j + 0.5) * step, tau / samples);
  }
  return builder.Finish();
}
}

// The uniform distribution on [za, zb]: b_k = (zb^(k+1) - za^(k+1)) / ((k + 1) (zb - za)),
// whatever the step (a sample is a box, not a point).
TEST(PowerMomentMap, MomentsAreThoseOfTheSamplesPiecewiseConstantExtinction)
{
  const double end = FourierEnd(40.0), a = 10.0, b = 22.0, tau = 3.0;
  for (double step : { 0.25, 1.0, 4.0 })
  {
    const std::vector<float> texel = Body(6, end, a, b, tau, step);
    EXPECT_FLOAT_EQ(texel[1], tau);
    const double za = 2.0 * a / end - 1.0, zb = 2.0 * b / end - 1.0;
    for (int k = 1; k <= 6; ++k)
    {
      const double exact = (std::pow(zb, k + 1) - std::pow(za, k + 1)) / ((k + 1) * (zb - za));
      EXPECT_NEAR(texel[1 + k], exact, 1e-6) << "b_" << k << ", step " << step;
    }
  }
}

// N atoms are what M = 2N moments determine: the fraction in front of z is exact everywhere
// but near the atoms, which the bias towards the uniform distribution smears (more of it at
// 6 moments: 0.035 off 0.02 from an atom, 0.007 off at 0.05).
TEST(PowerMomentMap, AtomsAreReconstructedExactly)
{
  const std::vector<std::vector<double>> positions = { { -0.3 }, { -0.6, 0.4 }, { -0.7, 0.1, 0.5 } };
  const std::vector<std::vector<double>> weights = { { 1.0 }, { 0.3, 0.7 }, { 0.5, 0.2, 0.3 } };
  for (int n = 1; n <= 3; ++n)
  {
    std::vector<double> b(2 * n, 0.0);
    for (int k = 1; k <= 2 * n; ++k)
    {
      for (int i = 0; i < n; ++i)
      {
        b[k - 1] += weights[n - 1][i] * std::pow(positions[n - 1][i], k);
      }
    }
    for (double z = -0.95; z < 0.95; z += 0.01)
    {
      double exact = 0.0, nearest = 1.0;
      for (int i = 0; i < n; ++i)
      {
        exact += positions[n - 1][i] < z ? weights[n - 1][i] : 0.0;
        nearest = std::min(nearest, std::abs(positions[n - 1][i] - z));
      }
      if (nearest > 0.02 * n)
      {
        EXPECT_NEAR(PowerMomentFractionBefore(b.data(), 2 * n, z), exact, 0.01) << n << " atoms, z " << z;
      }
    }
  }
}

// Beer-Lambert through the body: 0 before it, the total past End, within [0, total] between,
// and the error shrinks as moments are added.
TEST(PowerMomentMap, OpticalDepthConvergesAsMomentsAreAdded)
{
  const double end = FourierEnd(40.0), a = 10.0, b = 22.0, tau = 3.0;
  double previous = 1e9;
  for (int moments : { 2, 4, 6 })
  {
    const std::vector<float> texel = Body(moments, end, a, b, tau, 0.25);
    EXPECT_EQ(PowerMomentOpticalDepth(texel.data(), moments, 9.99), 0.0) << "before the body, " << moments;
    EXPECT_FLOAT_EQ(PowerMomentOpticalDepth(texel.data(), moments, end + 1.0), tau) << "past End, " << moments;
    double worst = 0.0, squares = 0.0;
    int count = 0;
    for (double depth = 0.0; depth < end; depth += 0.1)
    {
      const double got = PowerMomentOpticalDepth(texel.data(), moments, depth);
      EXPECT_GE(got, 0.0);
      EXPECT_LE(got, tau + 1e-6);
      const double exact = tau * std::clamp((depth - a) / (b - a), 0.0, 1.0);
      worst = std::max(worst, std::abs(got - exact));
      squares += (got - exact) * (got - exact);
      ++count;
    }
    const double rms = std::sqrt(squares / count);
    EXPECT_LT(rms, previous) << moments << " moments";
    previous = rms;
    std::printf("%d moments: optical depth rms error %.4f, max %.4f\n", moments, rms, worst);
  }
  EXPECT_LT(previous, 0.3); // 6 moments
}
