// Empty-space skipping must be exact: a block marked empty has zero opacity everywhere a
// sample in it can read, and skipping lands exactly on the samples an unskipping ray takes.
#include "Core/EmptySpace.h"
#include "Core/Jitter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace deepshadow;

namespace
{
VolumeGrid SparseRandomGrid(glm::ivec3 dims, uint32_t seed)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<float> values(static_cast<size_t>(dims.x) * dims.y * dims.z, 0.0f);
  // A few dense blobs in an empty volume.
  for (int blob = 0; blob < 4; ++blob)
  {
    const glm::dvec3 c(unit(random) * dims.x, unit(random) * dims.y, unit(random) * dims.z);
    const double r = 2.0 + 4.0 * unit(random);
    for (int k = 0; k < dims.z; ++k)
      for (int j = 0; j < dims.y; ++j)
        for (int i = 0; i < dims.x; ++i)
          if (glm::length(glm::dvec3(i, j, k) - c) < r)
            values[i + dims.x * (j + static_cast<size_t>(dims.y) * k)] = 50.0f + 200.0f * unit(random);
  }
  return VolumeGrid(dims, std::move(values), glm::dmat4(1.0));
}
}

TEST(EmptySpace, BlocksMarkedEmptyHaveZeroOpacityEverywhereInside)
{
  const VolumeGrid grid = SparseRandomGrid({ 37, 29, 41 }, 3);
  const PiecewiseLinear opacity({ { 0.0, 0.0 }, { 20.0, 0.0 }, { 255.0, 0.8 } });
  const BlockRanges ranges = BlockRanges::Compute(grid, 8);
  const std::vector<uint8_t> occupied = ranges.Occupancy(opacity);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  size_t empty = 0;
  for (int bz = 0; bz < ranges.BlockCount.z; ++bz)
    for (int by = 0; by < ranges.BlockCount.y; ++by)
      for (int bx = 0; bx < ranges.BlockCount.x; ++bx)
      {
        const size_t b = bx + ranges.BlockCount.x * (by + static_cast<size_t>(ranges.BlockCount.y) * bz);
        if (occupied[b])
        {
          continue;
        }
        ++empty;
        for (int n = 0; n < 300; ++n)
        {
          const glm::dvec3 p = 8.0 * (glm::dvec3(bx, by, bz) + glm::dvec3(unit(random), unit(random), unit(random)));
          for (auto mode : { Interpolation::Linear, Interpolation::Nearest })
          {
            ASSERT_EQ(opacity.Evaluate(grid.Sample(p, mode)), 0.0) << "block " << bx << "," << by << "," << bz;
          }
        }
      }
  EXPECT_GT(empty, 0u);
  EXPECT_LT(empty, occupied.size());
}

TEST(EmptySpace, SkippingLandsOnTheSamplesOfAnUnskippingRay)
{
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 2000; ++trial)
  {
    const glm::dvec3 start = glm::dvec3(8.0) + 8.0 * glm::dvec3(unit(random), unit(random), unit(random)) * 0.99;
    glm::dvec3 step(unit(random), unit(random), unit(random));
    step *= (0.05 + std::abs(unit(random))) / glm::length(step);
    if (trial % 7 == 0)
    {
      step.y = 0.0; // axis-parallel components
    }
    const glm::ivec3 block = glm::ivec3(glm::floor(start / 8.0));
    const int n = StepsToLeaveBlock(start, step, block, 8);
    ASSERT_GE(n, 1);
    // Every sample skipped is still in the block; the one landed on is not inside it.
    for (int s = 1; s < n; ++s)
    {
      const glm::dvec3 p = start + double(s) * step;
      EXPECT_EQ(glm::ivec3(glm::floor(p / 8.0 + 1e-9)) == block ||
          glm::ivec3(glm::floor(p / 8.0 - 1e-9)) == block, true);
    }
    const glm::dvec3 landed = start + double(n) * step;
    const glm::dvec3 lo = glm::dvec3(block) * 8.0, hi = lo + 8.0;
    const bool strictlyInside = glm::all(glm::greaterThan(landed, lo + 1e-9)) &&
      glm::all(glm::lessThan(landed, hi - 1e-9));
    EXPECT_FALSE(strictlyInside);
  }
}

TEST(Jitter, IsDeterministicUniformAndMatchesTheGLSLConstants)
{
  // Fixed values pin the hash: the GLSL twin (Shaders/Features/Jitter.glsl) must agree.
  EXPECT_EQ(PcgHash(0u), 129708002u);
  EXPECT_EQ(PcgHash(1u), 2831084092u);
  double sum = 0.0;
  for (uint32_t y = 0; y < 64; ++y)
    for (uint32_t x = 0; x < 64; ++x)
    {
      const double j = JitterOffset(x, y, 42);
      ASSERT_GE(j, 0.0);
      ASSERT_LT(j, 1.0);
      EXPECT_EQ(j, JitterOffset(x, y, 42));
      sum += j;
    }
  EXPECT_NEAR(sum / 4096.0, 0.5, 0.02);
  EXPECT_NE(JitterOffset(3, 4, 1), JitterOffset(3, 4, 2));
}
