// Uniform opacity slices, CPU side: the lookup is linear between slices (1 at depth 0, the
// last beyond); through a homogeneous slab the slices are the sampled transmittance within
// 8 bits, exact behind the slab and in front of it beyond one slice's width, and the error
// inside falls as the slices multiply (linear interpolation of Beer-Lambert).
#include "Core/Shadows/DeepShadowMap.h"
#include "Core/Shadows/OpacitySlices.h"
#include "Core/ShadowTechniques.h"
#include "Core/Shadows.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <vector>

using namespace deepshadow;

TEST(OpacitySlices, LookupIsLinearBetweenSlicesOneAtZeroAndLastBeyond)
{
  // Four slices at 0.25, 0.5, 0.75, 1 of the range.
  const std::vector<std::uint8_t> slices{ 255, 102, 51, 51 };
  EXPECT_EQ(EvaluateSlices(slices.data(), 4, -1.0), 1.0);
  EXPECT_EQ(EvaluateSlices(slices.data(), 4, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(EvaluateSlices(slices.data(), 4, 0.125), 1.0);
  EXPECT_DOUBLE_EQ(EvaluateSlices(slices.data(), 4, 0.375), 0.7);
  EXPECT_DOUBLE_EQ(EvaluateSlices(slices.data(), 4, 0.625), 0.3);
  EXPECT_DOUBLE_EQ(EvaluateSlices(slices.data(), 4, 3.0), 0.2);
}

namespace
{
// A 33^3 volume, value 1 for z in [12, 20] (opacity 0.2 a voxel), lit from +z.
struct Slab
{
  std::shared_ptr<VolumeGrid> Grid;
  TransferFunction Transfer;
  ShadowCaster Caster;
  Slab()
  {
    std::vector<float> values(33 * 33 * 33, 0.0f);
    for (int k = 12; k <= 20; ++k)
      for (int j = 0; j < 33; ++j)
        for (int i = 0; i < 33; ++i)
          values[i + 33 * (j + 33 * k)] = 1.0f;
    this->Grid = std::make_shared<VolumeGrid>(glm::ivec3(33), values, glm::dmat4(1.0));
    this->Transfer = TransferFunction::Grey({ { 0.0, 0.0 }, { 0.999, 0.0 }, { 1.0, 0.2 } });
    this->Caster.Grid = this->Grid.get();
    this->Caster.Transfer = &this->Transfer;
    this->Caster.Sampling = Interpolation::Nearest;
  }
};

// The sampled transmittance (linear between the samples' ends) at `depth`.
double Sampled(const VisibilitySamples& samples, double depth)
{
  size_t k = 0;
  while (k < samples.Depths.size() && samples.Depths[k] < depth)
  {
    ++k;
  }
  if (k == 0)
  {
    return 1.0;
  }
  if (k == samples.Depths.size())
  {
    return samples.Values.back().r;
  }
  const double d0 = samples.Depths[k - 1], d1 = samples.Depths[k];
  return samples.Values[k - 1].r + (depth - d0) / (d1 - d0) * (samples.Values[k].r - samples.Values[k - 1].r);
}
}

TEST(OpacitySlices, ThroughASlabTheErrorFallsAsTheSlicesMultiply)
{
  const Slab slab;
  const double range = LightDepthRange(CasterBoundsOf(slab.Grid->GetIndexToWorld(), slab.Grid->GetDims(), nullptr).Radius);
  const glm::dvec3 origin(16.0, 16.0, 40.0), down(0.0, 0.0, -1.0);
  const VisibilitySamples samples = SampleVisibility(slab.Caster, origin, down, 0.5, false, 1.0 / 512.0);
  double previous = 1.0;
  for (int count : { 8, 16, 32, 64 })
  {
    const std::vector<std::uint8_t> slices = SliceTexel(slab.Caster, origin, down, 0.5, count, range);
    double atSlices = 0.0, between = 0.0;
    for (int i = 0; i < count; ++i)
    {
      atSlices = std::max(atSlices, std::abs(slices[i] / 255.0 - Sampled(samples, (i + 1) * range / count)));
    }
    for (double depth = 0.0; depth < range; depth += 0.05)
    {
      between = std::max(between, std::abs(EvaluateSlices(slices.data(), count, depth / range) - Sampled(samples, depth)));
    }
    std::printf("%2d slices: largest error at the slices %.4f, between them %.4f\n", count, atSlices, between);
    EXPECT_LE(atSlices, 0.5 / 255.0 + 1e-9) << count;
    EXPECT_LT(between, previous) << count;
    previous = between;
  }
  EXPECT_LT(previous, 0.06) << "64 slices";
}

TEST(OpacitySlices, MapIsExactBehindTheSlabAndInFrontBeyondASlice)
{
  const Slab slab;
  Light light;
  light.Position = { 0.0, 0.0, 1.0 };
  ShadowParameters p = FindShadowTechnique("slices")->DefaultParameters();
  p.MapSize = 32;
  const auto map = MakeLightShadow(p, slab.Caster, light, 0.5, 2);
  const auto truth = MakeLightShadow(ShadowParameters::GroundTruth(false, 1.0), slab.Caster, light, 0.5);
  EXPECT_EQ(map->Bytes(), 32u * 32 * 32);
  const double range = LightDepthRange(CasterBoundsOf(slab.Grid->GetIndexToWorld(), slab.Grid->GetDims(), nullptr).Radius);
  const double width = range / 32;
  EXPECT_EQ(map->Visibility({ 16.0, 16.0, 20.5 + width + 0.5 }).r, 1.0);
  for (double z : { 4.0, 8.0 })
  {
    EXPECT_NEAR(map->Visibility({ 16.0, 16.0, z }).r, truth->Visibility({ 16.0, 16.0, z }).r, 1.0 / 255 + 1.0 / 512);
  }
}
