// Deep shadow maps at a fixed budget, CPU side: the lookup's fixed loop is the piecewise-
// linear function of its nodes; a map stays within the bound each texel reached of the
// ground truth, the bound shrinks as the budget grows, and the first node is exact (two
// nodes keep an empty box in front of an opaque sheet fully lit, where the variable-node
// map at two layers draws a line from the box's entry).
#include "Core/Shadows/DeepShadowMap.h"
#include "Core/Shadows/FixedBudgetDeepShadowMap.h"
#include "Core/ShadowTechniques.h"
#include "Core/Shadows.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <vector>

using namespace deepshadow;

namespace
{
constexpr double Unorm = 65535.0;

// A 33^3 volume, value 1 for z in [first, last], opacity `alpha` there.
struct Layer
{
  std::shared_ptr<VolumeGrid> Grid;
  TransferFunction Transfer;
  ShadowCaster Caster;
  Layer(int first, int last, double alpha)
  {
    std::vector<float> values(33 * 33 * 33, 0.0f);
    for (int k = first; k <= last; ++k)
      for (int j = 0; j < 33; ++j)
        for (int i = 0; i < 33; ++i)
          values[i + 33 * (j + 33 * k)] = 1.0f;
    this->Grid = std::make_shared<VolumeGrid>(glm::ivec3(33), values, glm::dmat4(1.0));
    this->Transfer = TransferFunction::Grey({ { 0.0, 0.0 }, { 0.999, 0.0 }, { 1.0, alpha } });
    this->Caster.Grid = this->Grid.get();
    this->Caster.Transfer = &this->Transfer;
    this->Caster.Sampling = Interpolation::Nearest;
  }
};

Light FromAbove()
{
  Light light;
  light.Position = { 0.0, 0.0, 1.0 };
  return light;
}

ShadowParameters Fixed(int bits)
{
  ShadowParameters p = FindShadowTechnique("dsm-fixed")->DefaultParameters();
  p.MapSize = 32;
  FindShadowParameter("dsm-bits")->Set(p, { static_cast<double>(bits) });
  return p;
}
}

TEST(FixedBudgetDeepShadowMap, LookupIsOneBeforeLinearBetweenAndLastAfter)
{
  // (0.2, 1), (0.4, 0.5), (0.6, 0.25), then an unused node at the end with 0.25.
  const std::vector<std::uint16_t> nodes{ 13107, 65535, 26214, 32768, 39321, 16384, 65535, 16384 };
  EXPECT_EQ(EvaluateFixedNodes(nodes.data(), 4, 0.1), 1.0);
  EXPECT_EQ(EvaluateFixedNodes(nodes.data(), 4, 0.2), 1.0);
  EXPECT_NEAR(EvaluateFixedNodes(nodes.data(), 4, 0.3), 0.75, 1e-4);
  EXPECT_NEAR(EvaluateFixedNodes(nodes.data(), 4, 0.5), 0.375, 1e-4);
  EXPECT_NEAR(EvaluateFixedNodes(nodes.data(), 4, 0.9), 0.25, 1e-4);
  EXPECT_NEAR(EvaluateFixedNodes(nodes.data(), 4, 7.0), 0.25, 1e-4) << "beyond the range";
  // A ray that absorbs nothing: every node at the end with 1.
  const std::vector<std::uint16_t> clear(8, 65535);
  EXPECT_EQ(EvaluateFixedNodes(clear.data(), 4, 0.5), 1.0);
  EXPECT_EQ(EvaluateFixedNodes(clear.data(), 4, 2.0), 1.0);
}

// Beer-Lambert through a homogeneous slab (opacity 0.2 a voxel, 9 voxels). Along a ray, the
// nodes stay within the bound the texel reached of every sample from the first absorbing one
// on (and the 16-bit depth grid's share, 5e-4); the bound falls as the budget grows. The
// map is 1 in front of the slab and within that bound (and the bilinear blend's share) of
// the ground truth behind it.
TEST(FixedBudgetDeepShadowMap, NodesStayWithinTheBoundReached)
{
  const Layer slab(12, 20, 0.2);
  const double range = LightDepthRange(CasterBoundsOf(slab.Grid->GetIndexToWorld(), slab.Grid->GetDims(), nullptr).Radius);
  const glm::dvec3 origin(16.0, 16.0, 40.0), down(0.0, 0.0, -1.0);
  const auto truth = MakeLightShadow(ShadowParameters::GroundTruth(false, 1.0), slab.Caster, FromAbove(), 0.5);
  double previous = 1.0;
  for (int bits : { 64, 128, 256, 512 })
  {
    const int nodes = bits / 32;
    const FixedBudgetTexel texel = FitFixedBudget(slab.Caster, origin, down, 0.5, nodes, range);
    ASSERT_TRUE(texel.Hit);
    const VisibilitySamples samples = SampleVisibility(slab.Caster, origin, down, 0.5, false, texel.Epsilon);
    double worst = 0.0;
    for (size_t i = 0; i < samples.Depths.size(); ++i)
    {
      const double stored = EvaluateFixedNodes(texel.Nodes.data(), nodes, samples.Depths[i] / range);
      const double value = samples.Values[i].r;
      // Beyond a truncated march's last point V lies in [0, value].
      worst = std::max(worst, samples.Truncated && i + 1 == samples.Depths.size()
          ? std::max(stored - value, -stored) - texel.Epsilon
          : std::abs(stored - value));
    }
    std::printf("%3d bits: bound reached %.5f, largest error at the samples %.5f\n", bits, texel.Epsilon, worst);
    EXPECT_LE(worst, texel.Epsilon + 5e-4) << bits << " bits";
    EXPECT_LT(texel.Epsilon, previous) << bits << " bits";
    EXPECT_EQ(texel.Nodes[1], 65535) << "node 0 is 1";
    previous = texel.Epsilon;

    const auto map = MakeLightShadow(Fixed(bits), slab.Caster, FromAbove(), 0.5, 2);
    const FixedBudgetStatistics& stats = dynamic_cast<const FixedBudgetDeepShadowMap&>(*map).GetStatistics();
    EXPECT_GT(stats.TexelsHit, 0);
    EXPECT_EQ(map->Bytes(), 32u * 32 * bits / 8);
    EXPECT_EQ(map->Visibility({ 16.0, 16.0, 30.0 }).r, 1.0) << "lit in front of the slab";
    for (double z : { 9.0, 4.0 })
    {
      const glm::dvec3 behind(16.0, 16.0, z);
      EXPECT_NEAR(map->Visibility(behind).r, truth->Visibility(behind).r, stats.EpsilonMax + 2e-3) << bits << " bits";
    }
  }
  EXPECT_LT(previous, 0.01) << "512 bits";
}

// An opaque sheet (z in [15, 17]) after empty space: the first node sits where the sheet
// starts, so two nodes (64 bits) keep everything in front of it at 1 and behind it dark. The
// variable-node deep shadow map at two layers starts at the box's entry and doubles its
// bound until two nodes fit: in front of the sheet it is grey.
TEST(FixedBudgetDeepShadowMap, FirstNodeIsExactWhereTheRayFirstAbsorbs)
{
  const Layer sheet(15, 17, 1.0);
  const auto fixed = MakeLightShadow(Fixed(64), sheet.Caster, FromAbove(), 0.5, 2);
  ShadowParameters variable = FindShadowTechnique("dsm")->DefaultParameters();
  variable.MapSize = 32;
  variable.Layers = 2;
  const auto twoLayers = MakeLightShadow(variable, sheet.Caster, FromAbove(), 0.5, 2);
  double grey = 1.0;
  for (double z = 31.0; z >= 18.5; z -= 0.5)
  {
    EXPECT_EQ(fixed->Visibility({ 16.0, 16.0, z }).r, 1.0) << "z " << z;
    grey = std::min(grey, twoLayers->Visibility({ 16.0, 16.0, z }).r);
  }
  EXPECT_LT(grey, 0.9) << "the variable-node map at two layers leaks the sheet forward";
  EXPECT_NEAR(fixed->Visibility({ 16.0, 16.0, 8.0 }).r, 0.0, 1e-3);
}

// An error instead of a budget: the nodes are the 99th percentile of what the texels need,
// rounded up to even (two a layer), 2 to 32.
TEST(FixedBudgetDeepShadowMap, NodesForAnErrorAreThe99thPercentileRoundedUpToEven)
{
  std::vector<long long> histogram(MaxFixedNodes + 2, 0);
  EXPECT_EQ(FixedNodesForError(histogram), 2) << "no texel absorbs anything";
  histogram[4] = 990;
  histogram[20] = 10;
  EXPECT_EQ(FixedNodesForError(histogram), 4) << "99 % need 4";
  histogram[20] = 11;
  EXPECT_EQ(FixedNodesForError(histogram), 20) << "more than 1 % need 20";
  histogram[20] = 0;
  histogram[5] = 11;
  EXPECT_EQ(FixedNodesForError(histogram), 6) << "5, rounded up";
  histogram.assign(histogram.size(), 0);
  histogram.back() = 3;
  EXPECT_EQ(FixedNodesForError(histogram), MaxFixedNodes) << "more than the most";
}

// A slab that few nodes fit within the error, and a column of thin opaque layers that needs
// many: a column under 1 % of the texels is left beyond the error (the finest bound the
// slab's nodes fit), one over 1 % sizes every texel's nodes, and then no texel is beyond.
TEST(FixedBudgetDeepShadowMap, AnErrorSizesTheNodesSo99PercentKeepIt)
{
  auto volume = [](int columnTexels) {
    std::vector<float> values(33 * 33 * 33, 0.0f);
    for (int k = 0; k < 33; ++k)
      for (int j = 0; j < 33; ++j)
        for (int i = 0; i < 33; ++i)
        {
          const bool column = i < columnTexels && j < columnTexels && k >= 4 && k <= 28;
          values[i + 33 * (j + 33 * k)] = column ? (k % 3 == 0 ? 2.0f : 0.0f) : (k >= 12 && k <= 20 ? 1.0f : 0.0f);
        }
    return std::make_shared<VolumeGrid>(glm::ivec3(33), values, glm::dmat4(1.0));
  };
  const TransferFunction transfer = TransferFunction::Grey({ { 0.0, 0.0 }, { 0.999, 0.0 }, { 1.0, 0.2 }, { 2.0, 0.6 } });
  ShadowParameters p = Fixed(256);
  FindShadowParameter("dsm-fixed-error")->Set(p, { 0.01 });
  int narrow = 0, wide = 0;
  for (int columnTexels : { 2, 6 })
  {
    const auto grid = volume(columnTexels);
    ShadowCaster caster;
    caster.Grid = grid.get();
    caster.Transfer = &transfer;
    caster.Sampling = Interpolation::Nearest;
    const auto map = MakeLightShadow(p, caster, FromAbove(), 0.5, 2);
    const FixedBudgetStatistics& stats = dynamic_cast<const FixedBudgetDeepShadowMap&>(*map).GetStatistics();
    std::printf("column of %d^2 voxels: %d nodes, %.4f of %ld texels beyond the error, bound at most %.4f\n",
      columnTexels, stats.Nodes, stats.BeyondError, stats.TexelsHit, stats.EpsilonMax);
    EXPECT_LE(stats.BeyondError, 1.0 - FixedNodePercentile);
    EXPECT_EQ(map->Bytes(), 32u * 32 * stats.Nodes * 4);
    (columnTexels == 2 ? narrow : wide) = stats.Nodes;
    if (columnTexels == 2)
    {
      EXPECT_GT(stats.BeyondError, 0.0) << "the column's texels need more";
      EXPECT_GT(stats.EpsilonMax, 0.01) << "and get a coarser bound";
    }
    else
    {
      EXPECT_EQ(stats.BeyondError, 0.0);
      EXPECT_LE(stats.EpsilonMax, 0.01);
    }
  }
  EXPECT_GT(wide, narrow);
}
