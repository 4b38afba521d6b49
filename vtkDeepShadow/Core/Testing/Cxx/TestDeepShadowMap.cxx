// Deep shadow maps and opacity levels, CPU side: the compression bound checked exactly on
// random and adversarial visibility functions, the overflow rule, and whole maps against the
// ground-truth feeler.
#include "Core/Shadows/DeepShadowMap.h"
#include "Core/Shadows/OpacityLevels.h"
#include "Core/Shadows.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

using namespace deepshadow;

namespace
{
// The largest |V' - V| over the samples, at their depths as stored (32-bit floats).
double MaxError(const std::vector<VisibilityNode>& nodes, int count, const VisibilitySamples& samples,
  int channels)
{
  double error = 0.0;
  for (size_t i = 0; i < samples.Depths.size(); ++i)
  {
    const double depth = static_cast<float>(samples.Depths[i]);
    const glm::dvec3 v = EvaluateVisibility(nodes.data(), count, depth);
    for (int c = 0; c < channels; ++c)
    {
      error = std::max(error, std::abs(v[c] - samples.Values[i][c]));
    }
  }
  return error;
}

VisibilitySamples FromValues(const std::vector<double>& depths, const std::vector<glm::dvec3>& values)
{
  VisibilitySamples samples;
  samples.Depths = depths;
  samples.Values = values;
  return samples;
}

// A random transmittance: multiplicative drops of random size at random depth steps, with
// occasional opaque runs, per channel when `channels` is 3.
VisibilitySamples RandomVisibility(std::mt19937& random, int count, int channels)
{
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  VisibilitySamples samples;
  double depth = 10.0 * unit(random);
  glm::dvec3 v(1.0);
  for (int i = 0; i < count; ++i)
  {
    samples.Depths.push_back(depth);
    samples.Values.push_back(v);
    depth += 0.01 + unit(random) * (unit(random) < 0.1 ? 5.0 : 0.2);
    const double kind = unit(random);
    for (int c = 0; c < 3; ++c)
    {
      const double alpha = kind < 0.6 ? 0.05 * unit(random) : (kind < 0.9 ? unit(random) : 0.0);
      v[c] *= 1.0 - (channels == 3 ? alpha * unit(random) : alpha);
    }
    if (channels == 1)
    {
      v = glm::dvec3(v.r);
    }
  }
  return samples;
}
}

TEST(DeepShadowMap, CompressionStaysWithinEpsilonOnRandomFunctions)
{
  std::mt19937 random(42);
  for (int trial = 0; trial < 300; ++trial)
  {
    const int channels = trial % 2 ? 3 : 1;
    const VisibilitySamples samples = RandomVisibility(random, 2 + trial % 200, channels);
    for (double epsilon : { 0.2, 0.05, 0.01, 1e-3, 1e-5 })
    {
      const CompressedVisibility c = CompressVisibility(samples, channels, epsilon, 1 << 20);
      ASSERT_EQ(c.Epsilon, epsilon);
      ASSERT_EQ(static_cast<int>(c.Nodes.size()), c.NodesNeeded);
      ASSERT_LE(MaxError(c.Nodes, static_cast<int>(c.Nodes.size()), samples, channels), epsilon + 1e-12)
        << "trial " << trial << " epsilon " << epsilon;
      ASSERT_EQ(c.Nodes.front().Depth, static_cast<float>(samples.Depths.front()));
    }
  }
}

TEST(DeepShadowMap, CompressionStaysWithinEpsilonOnAdversarialFunctions)
{
  std::vector<std::pair<const char*, VisibilitySamples>> cases;
  {
    // Steps: flat runs with sudden drops between adjacent samples.
    std::vector<double> d;
    std::vector<glm::dvec3> v;
    double value = 1.0;
    for (int i = 0; i < 400; ++i)
    {
      d.push_back(i * 0.25);
      v.emplace_back(value);
      if (i % 40 == 39)
      {
        value *= 0.5;
      }
    }
    cases.emplace_back("steps", FromValues(d, v));
  }
  {
    // Thin spikes: one sample of high opacity among many of none, in every channel apart.
    std::vector<double> d;
    std::vector<glm::dvec3> v;
    glm::dvec3 value(1.0);
    for (int i = 0; i < 300; ++i)
    {
      d.push_back(100.0 + i * 1e-3);
      v.push_back(value);
      if (i % 50 == 7)
      {
        value[(i / 50) % 3] *= 0.05;
      }
    }
    cases.emplace_back("spikes", FromValues(d, v));
  }
  {
    // Opacity to 1: transmittance underflows towards 0 through 1e-300.
    std::vector<double> d;
    std::vector<glm::dvec3> v;
    double value = 1.0;
    for (int i = 0; i < 200; ++i)
    {
      d.push_back(i);
      v.emplace_back(value);
      value *= 0.02;
    }
    cases.emplace_back("opaque", FromValues(d, v));
  }
  {
    // Far from the origin with tiny spacing: depths 1e6 apart by 0.5 (float spacing 0.0625).
    std::vector<double> d;
    std::vector<glm::dvec3> v;
    for (int i = 0; i < 200; ++i)
    {
      d.push_back(1e6 + 0.5 * i);
      v.emplace_back(std::exp(-0.03 * i));
    }
    cases.emplace_back("far", FromValues(d, v));
  }
  {
    // Depths closer than a float apart: stored strictly increasing, still within the bound.
    std::vector<double> d{ 1.0, 1.0 + 1e-9, 1.0 + 2e-9, 2.0 };
    std::vector<glm::dvec3> v{ glm::dvec3(1.0), glm::dvec3(0.5), glm::dvec3(0.5), glm::dvec3(0.4) };
    cases.emplace_back("coincident", FromValues(d, v));
  }
  cases.emplace_back("single", FromValues({ 3.0 }, { glm::dvec3(1.0) }));
  for (const auto& [name, samples] : cases)
  {
    for (double epsilon : { 0.1, 0.01, 1e-4 })
    {
      const CompressedVisibility c = CompressVisibility(samples, 3, epsilon, 1 << 20);
      // The coincident case stores its depths one float apart; its samples are checked there.
      VisibilitySamples stored = samples;
      for (size_t i = 1; i < stored.Depths.size(); ++i)
      {
        const float previous = static_cast<float>(stored.Depths[i - 1]);
        if (!(static_cast<float>(stored.Depths[i]) > previous))
        {
          stored.Depths[i] = std::nextafter(previous, 1e30f);
        }
      }
      EXPECT_LE(MaxError(c.Nodes, static_cast<int>(c.Nodes.size()), stored, 3), epsilon + 1e-12)
        << name << " epsilon " << epsilon;
    }
  }
}

TEST(DeepShadowMap, EpsilonZeroKeepsEverySampleToFloatPrecision)
{
  std::mt19937 random(7);
  const VisibilitySamples samples = RandomVisibility(random, 150, 1);
  const CompressedVisibility c = CompressVisibility(samples, 1, 0.0, 1 << 20);
  EXPECT_LE(MaxError(c.Nodes, static_cast<int>(c.Nodes.size()), samples, 1), 6e-8);
  EXPECT_LE(c.Nodes.size(), samples.Depths.size());
  // A linear function needs two nodes even at epsilon 0.
  const VisibilitySamples line = FromValues({ 0.0, 1.0, 2.0, 3.0, 4.0 },
    { glm::dvec3(1.0), glm::dvec3(0.75), glm::dvec3(0.5), glm::dvec3(0.25), glm::dvec3(0.0) });
  EXPECT_EQ(CompressVisibility(line, 1, 0.0, 8).Nodes.size(), 2u);
}

TEST(DeepShadowMap, OverflowDoublesTheBoundUntilTheNodesFit)
{
  std::mt19937 random(3);
  for (int trial = 0; trial < 100; ++trial)
  {
    const VisibilitySamples samples = RandomVisibility(random, 100, 3);
    const CompressedVisibility free = CompressVisibility(samples, 3, 0.01, 1 << 20);
    for (int layers : { 1, 2, 4, 8 })
    {
      const CompressedVisibility c = CompressVisibility(samples, 3, 0.01, layers);
      EXPECT_LE(static_cast<int>(c.Nodes.size()), layers);
      EXPECT_EQ(c.NodesNeeded, free.NodesNeeded);
      if (free.NodesNeeded <= layers)
      {
        EXPECT_EQ(c.Epsilon, 0.01);
      }
      else
      {
        EXPECT_GT(c.Epsilon, 0.01);
        // The doubling sequence 0.02, 0.04, ...: the first that fits.
        EXPECT_GT(CompressVisibility(samples, 3, c.Epsilon / 2, 1 << 20).Nodes.size(),
          static_cast<size_t>(layers));
      }
      EXPECT_LE(MaxError(c.Nodes, static_cast<int>(c.Nodes.size()), samples, 3), c.Epsilon + 1e-12);
    }
  }
  // One layer: a single node at the entry, V' = 1, the bound covering the deepest shadow.
  const VisibilitySamples dark = FromValues({ 0.0, 1.0, 2.0 }, { glm::dvec3(1.0), glm::dvec3(0.5), glm::dvec3(0.1) });
  const CompressedVisibility one = CompressVisibility(dark, 1, 0.0, 1);
  ASSERT_EQ(one.Nodes.size(), 1u);
  EXPECT_EQ(one.Nodes[0].Value[0], 1.0f);
  EXPECT_GE(one.Epsilon, 0.9);
  EXPECT_EQ(one.NodesNeeded, 3);
}

TEST(DeepShadowMap, TruncatedFunctionsEndWithinTheBoundOfEverythingBeyond)
{
  VisibilitySamples samples = FromValues({ 0.0, 1.0, 2.0 }, { glm::dvec3(1.0), glm::dvec3(0.3), glm::dvec3(0.008) });
  samples.Truncated = true;
  const CompressedVisibility c = CompressVisibility(samples, 1, 0.01, 8);
  // Beyond the last sample V may be anything in [0, 0.008]: V' must be within 0.01 of both ends.
  const double after = EvaluateVisibility(c.Nodes.data(), static_cast<int>(c.Nodes.size()), 1e9).r;
  EXPECT_LE(after, 0.01);
  EXPECT_GE(after, 0.008 - 0.01);
  EXPECT_THROW(CompressVisibility(samples, 1, 0.001, 8), std::invalid_argument);
  EXPECT_THROW(CompressVisibility(samples, 1, 0.01, 0), std::invalid_argument);
}

TEST(DeepShadowMap, LookupIsLinearBetweenNodesOneBeforeAndLastAfter)
{
  const std::vector<VisibilityNode> nodes{ { 2.0f, { 1.0f, 1.0f, 1.0f } },
    { 4.0f, { 0.5f, 0.6f, 0.7f } }, { 8.0f, { 0.1f, 0.2f, 0.3f } }, { NoHit, { 0.1f, 0.2f, 0.3f } } };
  EXPECT_EQ(EvaluateVisibility(nodes.data(), 4, 1.0), glm::dvec3(1.0));
  EXPECT_NEAR(EvaluateVisibility(nodes.data(), 4, 3.0).g, 0.8, 1e-7);
  EXPECT_NEAR(EvaluateVisibility(nodes.data(), 4, 6.0).b, 0.5, 1e-7);
  EXPECT_NEAR(EvaluateVisibility(nodes.data(), 4, 1e20).r, 0.1, 1e-7);
  EXPECT_NEAR(EvaluateVisibility(nodes.data(), 3, 1e20).r, 0.1, 1e-7);
  EXPECT_EQ(EvaluateVisibility(nodes.data(), 0, 5.0), glm::dvec3(1.0));
}

namespace
{
// A 33^3 volume: value 1 in a slab z in [12, 20], 0 elsewhere, opacity `alpha` and colour
// `color` for 1.
struct Slab
{
  std::shared_ptr<VolumeGrid> Grid;
  TransferFunction Transfer;
  ShadowCaster Caster;
  Slab(double alpha, const glm::dvec3& color)
  {
    std::vector<float> values(33 * 33 * 33, 0.0f);
    for (int k = 12; k <= 20; ++k)
      for (int j = 0; j < 33; ++j)
        for (int i = 0; i < 33; ++i)
          values[i + 33 * (j + 33 * k)] = 1.0f;
    this->Grid = std::make_shared<VolumeGrid>(glm::ivec3(33), values, glm::dmat4(1.0));
    this->Transfer = TransferFunction::Grey({ { 0.0, 0.0 }, { 0.999, 0.0 }, { 1.0, alpha } });
    this->Transfer.Red = PiecewiseLinear({ { 0.0, 1.0 }, { 1.0, color.r } });
    this->Transfer.Green = PiecewiseLinear({ { 0.0, 1.0 }, { 1.0, color.g } });
    this->Transfer.Blue = PiecewiseLinear({ { 0.0, 1.0 }, { 1.0, color.b } });
    this->Caster.Grid = this->Grid.get();
    this->Caster.Transfer = &this->Transfer;
    this->Caster.Sampling = Interpolation::Nearest;
  }
};

Light Directional(const glm::dvec3& toLight)
{
  Light light;
  light.Position = toLight;
  return light;
}
}

TEST(DeepShadowMap, MapsMatchTheGroundTruthOutsideTheSlabWithinEpsilon)
{
  const Slab slab(0.2, glm::dvec3(1.0, 0.5, 0.0));
  for (bool colored : { false, true })
  {
    ShadowParameters p;
    p.Kind = ShadowKind::DeepShadowMap;
    p.Colored = colored;
    p.MapSize = 48;
    p.Epsilon = 0.01;
    const Light light = Directional({ 0.0, 0.0, 1.0 });
    const auto map = MakeLightShadow(p, slab.Caster, light, 0.5, 2);
    const auto truth = MakeLightShadow(ShadowParameters::GroundTruth(colored, 1.0), slab.Caster, light, 0.5);
    for (const glm::dvec3& point : { glm::dvec3(16, 16, 4), glm::dvec3(5, 20, 9), glm::dvec3(16, 16, 28) })
    {
      const glm::dvec3 expected = truth->Visibility(point), actual = map->Visibility(point);
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_NEAR(actual[c], expected[c], p.Epsilon + 1e-6) << "colored " << colored << " c " << c;
      }
    }
    const glm::dvec3 below = map->Visibility({ 16, 16, 4 });
    if (colored)
    {
      // Red passes a red medium; blue is stopped by all of its opacity.
      EXPECT_NEAR(below.r, 1.0, 0.01);
      EXPECT_LT(below.b, below.g);
    }
    EXPECT_EQ(map->Bytes(), 48u * 48 * 8 * (colored ? 16 : 8));
    const DeepShadowMapStatistics& stats = dynamic_cast<const DeepShadowMap&>(*map).GetStatistics();
    EXPECT_GT(stats.TexelsHit, 0);
    EXPECT_GE(stats.NodesAverage, 1.0);
    EXPECT_LE(stats.NodesMax, 8);
    EXPECT_EQ(stats.EpsilonMax, 0.01);
  }
}

TEST(DeepShadowMap, OpaqueStructuresStayOpaqueAtTheDefaults)
{
  // A thin opaque sheet (three voxels) under a directional light: V' drops from 1 to 0 within
  // two samples, and the default bound keeps it dark behind (no light leaking through).
  std::vector<float> values(33 * 33 * 33, 0.0f);
  for (int k = 15; k <= 17; ++k)
    for (int j = 0; j < 33; ++j)
      for (int i = 0; i < 33; ++i)
        values[i + 33 * (j + 33 * k)] = 1.0f;
  auto grid = std::make_shared<VolumeGrid>(glm::ivec3(33), values, glm::dmat4(1.0));
  TransferFunction tf = TransferFunction::Grey({ { 0.0, 0.0 }, { 0.5, 0.0 }, { 1.0, 1.0 } });
  ShadowCaster caster;
  caster.Grid = grid.get();
  caster.Transfer = &tf;
  ShadowParameters p;
  p.Kind = ShadowKind::DeepShadowMap;
  p.MapSize = 32;
  const auto map = MakeLightShadow(p, caster, Directional({ 0.0, 0.0, 1.0 }), 0.5, 2);
  const auto truth = MakeLightShadow(ShadowParameters::GroundTruth(false, 1.0), caster, Directional({ 0.0, 0.0, 1.0 }), 0.5);
  EXPECT_EQ(truth->Visibility({ 16, 16, 8 }).r, 0.0);
  EXPECT_NEAR(map->Visibility({ 16, 16, 8 }).r, truth->Visibility({ 16, 16, 8 }).r, p.Epsilon + 1e-6);
  EXPECT_EQ(map->Visibility({ 16, 16, 24 }).r, 1.0);
}

TEST(OpacityLevels, BuildPlacesCrossingsByTheSmoothstepRule)
{
  // Opacity 0, 0.2, 0.6, 0.95 at depths 0, 1, 2, 3.
  const VisibilitySamples samples = FromValues({ 0.0, 1.0, 2.0, 3.0 },
    { glm::dvec3(1.0), glm::dvec3(0.8), glm::dvec3(0.4), glm::dvec3(0.05) });
  const std::array<double, 3> levels{ { 0.1, 0.5, 0.9 } };
  const OpacityLevelsTexel texel = BuildOpacityLevels(samples, levels);
  EXPECT_NEAR(texel.Depths[0], 0.0 + SmoothStep(0.0, 0.2, 0.1), 1e-6);
  EXPECT_NEAR(texel.Depths[1], 1.0 + SmoothStep(0.2, 0.6, 0.5), 1e-6);
  EXPECT_NEAR(texel.Depths[2], 2.0 + SmoothStep(0.6, 0.95, 0.9), 1e-6);
  EXPECT_NEAR(texel.MaxOpacity, 0.95, 1e-6);
  // Lookup: 0 before, the levels at their depths, the maximum after, monotone between.
  EXPECT_EQ(EvaluateOpacityLevels(texel, levels, texel.Depths[0] - 1e-3), 0.0);
  EXPECT_NEAR(EvaluateOpacityLevels(texel, levels, texel.Depths[0]), 0.1, 1e-9);
  EXPECT_NEAR(EvaluateOpacityLevels(texel, levels, texel.Depths[1]), 0.5, 1e-9);
  EXPECT_NEAR(EvaluateOpacityLevels(texel, levels, 10.0), 0.95, 1e-6);
  double previous = 0.0;
  for (double z = 0.0; z < 4.0; z += 0.01)
  {
    const double a = EvaluateOpacityLevels(texel, levels, z);
    EXPECT_GE(a, previous);
    EXPECT_LE(a, texel.MaxOpacity);
    previous = a;
  }
}

TEST(OpacityLevels, UnreachedLevelsSitAtTheMaximumAndNeverExceedIt)
{
  const VisibilitySamples samples = FromValues({ 0.0, 1.0, 2.0, 3.0 },
    { glm::dvec3(1.0), glm::dvec3(0.8), glm::dvec3(0.7), glm::dvec3(0.7) });
  const std::array<double, 3> levels{ { 0.1, 0.5, 0.9 } };
  const OpacityLevelsTexel texel = BuildOpacityLevels(samples, levels);
  EXPECT_EQ(texel.Depths[1], 2.0f); // where the maximum 0.3 was reached
  EXPECT_EQ(texel.Depths[2], 2.0f);
  EXPECT_NEAR(EvaluateOpacityLevels(texel, levels, 1.9), 0.3, 1e-6);
  EXPECT_NEAR(EvaluateOpacityLevels(texel, levels, 50.0), 0.3, 1e-6);
  // Nothing absorbs: no depths, zero opacity everywhere.
  const OpacityLevelsTexel clear = BuildOpacityLevels(
    FromValues({ 0.0, 1.0 }, { glm::dvec3(1.0), glm::dvec3(1.0) }), levels);
  EXPECT_EQ(clear.Depths[0], NoHit);
  EXPECT_EQ(EvaluateOpacityLevels(clear, levels, 1e30), 0.0);
}

TEST(OpacityLevels, MapsShadowBehindTheSlab)
{
  const Slab slab(0.3, glm::dvec3(1.0));
  ShadowParameters p;
  p.Kind = ShadowKind::OpacityLevels;
  p.MapSize = 32;
  const auto map = MakeLightShadow(p, slab.Caster, Directional({ 0.0, 0.0, 1.0 }), 0.5, 2);
  const auto truth = MakeLightShadow(ShadowParameters::GroundTruth(false, 1.0), slab.Caster, Directional({ 0.0, 0.0, 1.0 }), 0.5);
  EXPECT_EQ(map->Visibility({ 16, 16, 28 }).r, 1.0);
  // Behind it, the maximum opacity: exact up to the 1/512 at which the march stops.
  EXPECT_NEAR(map->Visibility({ 16, 16, 4 }).r, truth->Visibility({ 16, 16, 4 }).r, 1.0 / 512);
  EXPECT_EQ(map->Bytes(), 32u * 32 * 16);
}

TEST(OpacityLevels, MeshStepsKeepTheMostOpaqueWhereItIs)
{
  // No step: 1 everywhere.
  EXPECT_EQ(EvaluateSurfaceSteps(SurfaceStepsBuilder().Finish(), 1e30), 1.0);
  // A glass's two faces (0.6 each) and an opaque ground: the back face folds into the front,
  // the ground keeps its depth, so the ground itself reads the glass's 0.36.
  SurfaceStepsBuilder glass;
  glass.Add(10.0, 0.6);
  glass.Add(11.0, 0.6);
  glass.Add(30.0, 0.0);
  const SurfaceSteps steps = glass.Finish();
  EXPECT_EQ(EvaluateSurfaceSteps(steps, 9.0), 1.0);
  EXPECT_NEAR(EvaluateSurfaceSteps(steps, 10.5), 0.36, 1e-6); // inside the glass: 0.6 exact
  EXPECT_NEAR(EvaluateSurfaceSteps(steps, 29.0), 0.36, 1e-6);
  EXPECT_EQ(EvaluateSurfaceSteps(steps, 30.0), 0.0);
  EXPECT_EQ(glass.Transmittance(), 0.0);
  // Two glasses (0.6 and 0.8 a face) over an opaque ground: the ground reads all four faces.
  SurfaceStepsBuilder two;
  for (const auto& [depth, transmission] : { std::pair{ 1.0, 0.6 }, { 2.0, 0.6 }, { 5.0, 0.8 }, { 6.0, 0.8 }, { 9.0, 0.0 } })
  {
    two.Add(depth, transmission);
  }
  EXPECT_NEAR(EvaluateSurfaceSteps(two.Finish(), 8.9), 0.6 * 0.6 * 0.8 * 0.8, 1e-6);
  EXPECT_EQ(EvaluateSurfaceSteps(two.Finish(), 9.0), 0.0);
  EXPECT_EQ(EvaluateSurfaceSteps(two.Finish(), 0.5), 1.0);
  // An opaque mesh first: nothing after it matters, and its depth stays exact.
  SurfaceStepsBuilder rod;
  rod.Add(4.0, 0.0);
  rod.Add(6.0, 0.0);
  rod.Add(8.0, 0.5);
  EXPECT_EQ(EvaluateSurfaceSteps(rod.Finish(), 3.9), 1.0);
  EXPECT_EQ(EvaluateSurfaceSteps(rod.Finish(), 4.0), 0.0);
}

TEST(ShadowParameters, UnusableParametersAreRefusedWithAReason)
{
  const Slab slab(0.3, glm::dvec3(1.0));
  ShadowParameters p;
  p.Kind = ShadowKind::DeepShadowMap;
  EXPECT_TRUE(p.Validate().empty());
  p.Epsilon = -1.0;
  EXPECT_THROW(MakeLightShadow(p, slab.Caster, Directional({ 0, 0, 1 }), 0.5), std::invalid_argument);
  p.Epsilon = std::nan("");
  EXPECT_FALSE(p.Validate().empty());
  p = ShadowParameters();
  p.Layers = 0;
  EXPECT_NE(p.Validate().find("layer"), std::string::npos);
  p = ShadowParameters();
  p.Offsets = 9;
  EXPECT_NE(p.Validate().find("7, 13 or 21"), std::string::npos);
  p = ShadowParameters();
  p.Levels = { { 0.5, 0.1, 0.9 } };
  EXPECT_FALSE(p.Validate().empty());
  p = ShadowParameters();
  p.Photons = 0;
  EXPECT_FALSE(p.Validate().empty());
}
