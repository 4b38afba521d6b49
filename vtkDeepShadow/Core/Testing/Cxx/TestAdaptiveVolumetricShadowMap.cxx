// Adaptive volumetric shadow maps, CPU side: nodes are the exact transmittance where there
// is room, AVSM's compression removes the node of the smallest triangle, and through a
// homogeneous body the greedy nodes do at least as well as evenly spaced ones, whose linear
// interpolation errs by at most h^2 max|f''| / 8 (Beer-Lambert and that bound computed here,
// not by the technique).
#include "Core/Shadows/AdaptiveVolumetricShadowMap.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace deepshadow;

// With room for every node, the curve passes through every sample's end: exact there.
TEST(AdaptiveVolumetricShadowMap, NodesAreTheTransmittanceWhileThereIsRoom)
{
  AdaptiveNodesBuilder builder(8);
  builder.Add(1.0, 2.0, 0.5);
  builder.AddClear();
  builder.Add(5.0, 6.0, 0.5);
  const std::vector<float> nodes = builder.Finish();
  EXPECT_EQ(EvaluateAdaptiveNodes(nodes.data(), 8, 0.5), 1.0);
  EXPECT_EQ(EvaluateAdaptiveNodes(nodes.data(), 8, 1.0), 1.0);
  EXPECT_DOUBLE_EQ(EvaluateAdaptiveNodes(nodes.data(), 8, 1.5), 0.75);
  EXPECT_EQ(EvaluateAdaptiveNodes(nodes.data(), 8, 2.0), 0.5);
  EXPECT_EQ(EvaluateAdaptiveNodes(nodes.data(), 8, 4.0), 0.5) << "flat where nothing absorbs";
  EXPECT_EQ(EvaluateAdaptiveNodes(nodes.data(), 8, 6.0), 0.25);
  EXPECT_EQ(EvaluateAdaptiveNodes(nodes.data(), 8, 100.0), 0.25);
  EXPECT_EQ(nodes[8], NoHit) << "unused nodes sit at the largest float";
}

// One too many: of (0, 1), (1, 0.5), (1.1, 0.475), (2, 0.4) the node at 1.1 makes the
// smallest triangle with its neighbours (0.015 against 0.025, in doubled area) and goes;
// first and newest stay.
TEST(AdaptiveVolumetricShadowMap, CompressionDropsTheSmallestTriangle)
{
  AdaptiveNodesBuilder builder(3);
  builder.Add(0.0, 1.0, 0.5);
  builder.Add(1.0, 1.1, 0.95);
  builder.Add(1.1, 2.0, 0.4 / 0.475);
  const std::vector<float> nodes = builder.Finish();
  ASSERT_EQ(nodes.size(), 6u);
  EXPECT_EQ(nodes[0], 0.0f);
  EXPECT_EQ(nodes[2], 1.0f);
  EXPECT_EQ(nodes[4], 2.0f);
  EXPECT_FLOAT_EQ(nodes[5], 0.4f);
}

// Beer-Lambert through a homogeneous body of optical depth 4 in 64 samples, T(x) = exp(-4 x)
// over x in [0, 1]: N evenly spaced nodes err by at most (1 / (N - 1))^2 16 / 8; AVSM's
// adaptive ones must not do worse, and from 4 nodes on the error shrinks by more than three
// as the nodes double (second order).
TEST(AdaptiveVolumetricShadowMap, ErrorThroughAHomogeneousBodyShrinksAsTheNodesDouble)
{
  const double a = 10.0, b = 26.0, tau = 4.0;
  const int samples = 64;
  const double step = (b - a) / samples, each = std::exp(-tau / samples);
  double previous = 1.0;
  for (int count : { 2, 4, 8, 16 })
  {
    AdaptiveNodesBuilder builder(count);
    for (int j = 0; j < samples; ++j)
    {
      builder.Add(a + j * step, a + (j + 1) * step, each);
    }
    const std::vector<float> nodes = builder.Finish();
    double worst = 0.0;
    for (double depth = a; depth <= b; depth += 0.05)
    {
      const double exact = std::exp(-tau * (depth - a) / (b - a));
      worst = std::max(worst, std::abs(EvaluateAdaptiveNodes(nodes.data(), count, depth) - exact));
    }
    std::printf("%2d nodes: largest error %.4f\n", count, worst);
    const double spacing = 1.0 / (count - 1);
    EXPECT_LE(worst, spacing * spacing * tau * tau / 8.0) << count << " nodes";
    if (count > 4)
    {
      EXPECT_LT(worst, previous / 3.0) << count << " nodes";
    }
    previous = worst;
  }
}
