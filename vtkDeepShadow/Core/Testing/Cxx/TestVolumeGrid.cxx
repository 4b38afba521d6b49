// Volume sampling follows OpenGL's 3D texture rules; gradients and transforms are exact.
#include "Core/Camera.h"
#include "Core/VolumeGrid.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <limits>

using namespace deepshadow;

namespace
{
// f(i, j, k) = a + b i + c j + d k on a grid.
VolumeGrid LinearGrid(glm::ivec3 dims, const glm::dmat4& indexToWorld)
{
  std::vector<float> values;
  for (int k = 0; k < dims.z; ++k)
    for (int j = 0; j < dims.y; ++j)
      for (int i = 0; i < dims.x; ++i)
        values.push_back(static_cast<float>(3.0 + 2.0 * i - 1.0 * j + 0.5 * k));
  return VolumeGrid(dims, std::move(values), indexToWorld);
}
}

TEST(VolumeGrid, TrilinearSamplingReproducesLinearFieldsInside)
{
  const VolumeGrid grid = LinearGrid({ 5, 6, 7 }, glm::dmat4(1.0));
  for (glm::dvec3 p : { glm::dvec3(0.0), glm::dvec3(1.25, 2.5, 3.75), glm::dvec3(4.0, 5.0, 6.0),
         glm::dvec3(3.999, 0.001, 5.5) })
  {
    EXPECT_NEAR(grid.Sample(p, Interpolation::Linear), 3.0 + 2.0 * p.x - p.y + 0.5 * p.z, 1e-12);
  }
}

TEST(VolumeGrid, SamplingClampsToTheEdgeLikeGL)
{
  const VolumeGrid grid = LinearGrid({ 4, 4, 4 }, glm::dmat4(1.0));
  EXPECT_DOUBLE_EQ(grid.Sample({ -3.0, 0.0, 0.0 }, Interpolation::Linear), grid.At(0, 0, 0));
  EXPECT_DOUBLE_EQ(grid.Sample({ 9.0, 3.0, 3.0 }, Interpolation::Linear), grid.At(3, 3, 3));
}

TEST(VolumeGrid, NearestRoundsHalfUpLikeGL)
{
  const VolumeGrid grid = LinearGrid({ 4, 4, 4 }, glm::dmat4(1.0));
  EXPECT_DOUBLE_EQ(grid.Sample({ 1.49, 0.0, 0.0 }, Interpolation::Nearest), grid.At(1, 0, 0));
  EXPECT_DOUBLE_EQ(grid.Sample({ 1.5, 0.0, 0.0 }, Interpolation::Nearest), grid.At(2, 0, 0));
}

TEST(VolumeGrid, WorldGradientAccountsForSpacingAndRotation)
{
  // index -> world: spacing (2, 1, 0.5), then a rotation about z, then a translation.
  glm::dmat4 m = glm::translate(glm::dmat4(1.0), glm::dvec3(10.0, -3.0, 2.0));
  m = glm::rotate(m, 0.7, glm::dvec3(0.0, 0.0, 1.0));
  m = glm::scale(m, glm::dvec3(2.0, 1.0, 0.5));
  const VolumeGrid grid = LinearGrid({ 6, 6, 6 }, m);
  // f = 3 + 2i - j + 0.5k: the world gradient satisfies grad_world . (M e_axis) = df/d(axis).
  const glm::dvec3 g = grid.WorldGradient({ 2.5, 2.5, 2.5 }, Interpolation::Linear);
  EXPECT_NEAR(glm::dot(g, glm::dvec3(m[0])), 2.0, 1e-9);
  EXPECT_NEAR(glm::dot(g, glm::dvec3(m[1])), -1.0, 1e-9);
  EXPECT_NEAR(glm::dot(g, glm::dvec3(m[2])), 0.5, 1e-9);
}

TEST(VolumeGrid, RangeIgnoresNonFiniteValues)
{
  std::vector<float> v = { 1.0f, std::numeric_limits<float>::quiet_NaN(), -2.0f,
    std::numeric_limits<float>::infinity(), 5.0f, 0.0f, 0.0f, 0.0f };
  const VolumeGrid grid({ 2, 2, 2 }, v, glm::dmat4(1.0));
  EXPECT_EQ(grid.GetRange(), glm::dvec2(-2.0, 5.0));
  const NonFiniteCount bad = CountNonFinite(v.data(), v.size());
  EXPECT_EQ(bad.NaN, 1u);
  EXPECT_EQ(bad.PositiveInfinity, 1u);
  ReplaceNonFinite(v.data(), v.size());
  EXPECT_EQ(v[1], -2.0f); // NaN -> smallest finite
  EXPECT_EQ(v[3], 5.0f);  // +Inf -> largest finite
}

TEST(VolumeGrid, ReplacingAnAllNonFiniteArrayGivesZeros)
{
  std::vector<float> v(8, std::numeric_limits<float>::quiet_NaN());
  ReplaceNonFinite(v.data(), v.size());
  for (float x : v)
  {
    EXPECT_EQ(x, 0.0f);
  }
}

TEST(DefaultSampleDistance, IsHalfTheShortestWorldVoxelEdge)
{
  glm::dmat4 m = glm::scale(glm::dmat4(1.0), glm::dvec3(0.9, 0.9, 1.5));
  EXPECT_DOUBLE_EQ(DefaultSampleDistance(m), 0.45);
  m = glm::rotate(glm::dmat4(1.0), 1.0, glm::dvec3(1.0, 1.0, 0.0)) * m;
  EXPECT_NEAR(DefaultSampleDistance(m), 0.45, 1e-12);
}

TEST(Camera, PixelRaysStartOnTheNearPlaneAndHitThePixelCentre)
{
  const glm::dmat4 view = glm::lookAt(glm::dvec3(0, 0, 10), glm::dvec3(0.0), glm::dvec3(0, 1, 0));
  const glm::dmat4 projection = glm::perspective(glm::radians(30.0), 1.0, 1.0, 100.0);
  const Camera camera(projection * view, 100, 100);
  const Ray centre = camera.RayThrough(50.0, 50.0);
  EXPECT_NEAR(glm::length(centre.Direction - glm::dvec3(0, 0, -1)), 0.0, 1e-12);
  EXPECT_NEAR(centre.Origin.z, 9.0, 1e-9); // near plane at distance 1
  const Ray corner = camera.PixelRay(99, 99);
  const glm::dvec4 clip = camera.GetViewProjection() * glm::dvec4(corner.Origin + 5.0 * corner.Direction, 1.0);
  EXPECT_NEAR((clip.x / clip.w + 1.0) * 50.0, 99.5, 1e-9);
  EXPECT_NEAR((clip.y / clip.w + 1.0) * 50.0, 99.5, 1e-9);
}

TEST(IntersectBox, HitsMissesAndParallelRays)
{
  double t0 = 0, t1 = 0;
  const Ray hit{ { -5.0, 0.5, 0.5 }, { 1.0, 0.0, 0.0 } };
  ASSERT_TRUE(IntersectBox(hit, glm::dmat4(1.0), glm::dvec3(0.0), glm::dvec3(1.0), t0, t1));
  EXPECT_DOUBLE_EQ(t0, 5.0);
  EXPECT_DOUBLE_EQ(t1, 6.0);
  const Ray parallelOutside{ { -5.0, 2.0, 0.5 }, { 1.0, 0.0, 0.0 } };
  EXPECT_FALSE(IntersectBox(parallelOutside, glm::dmat4(1.0), glm::dvec3(0.0), glm::dvec3(1.0), t0, t1));
  // t stays world distance when the box lives in a scaled space.
  const glm::dmat4 worldToBox = glm::scale(glm::dmat4(1.0), glm::dvec3(0.5));
  ASSERT_TRUE(IntersectBox(hit, worldToBox, glm::dvec3(0.0), glm::dvec3(1.0), t0, t1));
  EXPECT_DOUBLE_EQ(t0, 5.0);
  EXPECT_DOUBLE_EQ(t1, 7.0);
}
