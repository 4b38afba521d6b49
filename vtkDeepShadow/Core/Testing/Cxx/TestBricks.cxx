// The order of bricks toward a light and the product of the bricks in front
// (Core/Shadows/Bricks.h): what a brick drawn by one MPI rank multiplies into its lookups.
#include "Core/Shadows/Bricks.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace deepshadow;

namespace
{
Light Directional(const glm::dvec3& travel)
{
  Light light;
  light.Positional = false;
  light.Position = -travel;
  light.FocalPoint = glm::dvec3(0.0);
  return light;
}

Light Positional(const glm::dvec3& at)
{
  Light light;
  light.Positional = true;
  light.Position = at;
  return light;
}

// Two bricks sharing the face z = 0: below [0,1]^2 x [-1, 0], above [0,1]^2 x [0, 1].
const BrickBox Below{ { 0.0, 0.0, -1.0 }, { 1.0, 1.0, 0.0 } };
const BrickBox Above{ { 0.0, 0.0, 0.0 }, { 1.0, 1.0, 1.0 } };
}

TEST(Bricks, DirectionalLightOrdersBricksAlongItsTravel)
{
  // Light from above (travelling -z): the upper brick is crossed first.
  EXPECT_EQ(OrderTowardLight(Above, Below, Directional({ 0.0, 0.0, -1.0 }), 1e-9), BrickOrder::First);
  EXPECT_EQ(OrderTowardLight(Below, Above, Directional({ 0.0, 0.0, -1.0 }), 1e-9), BrickOrder::Last);
  // From below, the other way; slanted rays still cross the shared face from above.
  EXPECT_EQ(OrderTowardLight(Above, Below, Directional({ 0.0, 0.0, 1.0 }), 1e-9), BrickOrder::Last);
  EXPECT_EQ(OrderTowardLight(Above, Below, Directional({ 0.7, -0.3, -0.2 }), 1e-9), BrickOrder::First);
  // Rays parallel to the shared face cross no brick after the other.
  EXPECT_EQ(OrderTowardLight(Above, Below, Directional({ 1.0, 0.0, 0.0 }), 1e-9), BrickOrder::Unordered);
}

TEST(Bricks, PositionalLightOrdersBricksBySideOfTheLight)
{
  EXPECT_EQ(OrderTowardLight(Above, Below, Positional({ 0.5, 0.5, 5.0 }), 1e-9), BrickOrder::First);
  EXPECT_EQ(OrderTowardLight(Above, Below, Positional({ 0.5, 0.5, -5.0 }), 1e-9), BrickOrder::Last);
  // A light inside the upper brick still lights the lower one through it.
  EXPECT_EQ(OrderTowardLight(Above, Below, Positional({ 0.5, 0.5, 0.5 }), 1e-9), BrickOrder::First);
  // On the shared plane: no ray passes from one into the other.
  EXPECT_EQ(OrderTowardLight(Above, Below, Positional({ 5.0, 0.5, 0.0 }), 1e-9), BrickOrder::Unordered);
}

TEST(Bricks, OverlapIsToleratedOnlyUpToTheTolerance)
{
  const BrickBox lower{ { 0.0, 0.0, -1.0 }, { 1.0, 1.0, 1e-7 } }; // float rounding of a shared face
  EXPECT_FALSE(BricksOverlap(lower, Above, 1e-6));
  EXPECT_EQ(OrderTowardLight(Above, lower, Directional({ 0.0, 0.0, -1.0 }), 1e-6), BrickOrder::First);
  const BrickBox ghost{ { 0.0, 0.0, -1.0 }, { 1.0, 1.0, 0.1 } }; // one ghost layer deep
  EXPECT_TRUE(BricksOverlap(ghost, Above, 1e-6));
  EXPECT_EQ(OrderTowardLight(Above, ghost, Directional({ 0.0, 0.0, -1.0 }), 1e-6), BrickOrder::Unordered);
}

TEST(Bricks, UpstreamIsTheProductOfTheBricksInFront)
{
  // Three bricks stacked along z, each a homogeneous slab: one texel, one channel. Light from
  // above: Beer-Lambert through the bricks above is the product of their transmittances.
  const std::vector<BrickBox> boxes{ { { 0, 0, 0 }, { 1, 1, 1 } }, { { 0, 0, 1 }, { 1, 1, 2 } },
    { { 0, 0, 2 }, { 1, 1, 3 } } };
  const double sigma[3] = { 0.5, 1.0, 2.0 };
  std::vector<float> totals;
  for (double s : sigma)
  {
    totals.push_back(static_cast<float>(std::exp(-s)));
  }
  const Light fromAbove = Directional({ 0.0, 0.0, -1.0 });
  bool overlapping = true;
  EXPECT_NEAR(UpstreamTransmittance(totals, 1, 0, boxes, fromAbove, 1e-9, overlapping)[0], std::exp(-3.0), 1e-6);
  EXPECT_FALSE(overlapping);
  EXPECT_NEAR(UpstreamTransmittance(totals, 1, 1, boxes, fromAbove, 1e-9, overlapping)[0], std::exp(-2.0), 1e-6);
  EXPECT_EQ(UpstreamTransmittance(totals, 1, 2, boxes, fromAbove, 1e-9, overlapping)[0], 1.0f);
  const Light fromBelow = Directional({ 0.0, 0.0, 1.0 });
  EXPECT_NEAR(UpstreamTransmittance(totals, 1, 2, boxes, fromBelow, 1e-9, overlapping)[0], std::exp(-1.5), 1e-6);
  // A brick that is not there (an empty rank: invalid box) is left out.
  std::vector<BrickBox> withEmpty = boxes;
  withEmpty[1] = BrickBox{};
  EXPECT_NEAR(UpstreamTransmittance(totals, 1, 0, withEmpty, fromAbove, 1e-9, overlapping)[0], std::exp(-2.0), 1e-6);
}

TEST(Bricks, UnionIgnoresMissingBricks)
{
  const BrickBox both = Below.Union(BrickBox{}).Union(Above);
  EXPECT_EQ(both.Min, glm::dvec3(0.0, 0.0, -1.0));
  EXPECT_EQ(both.Max, glm::dvec3(1.0, 1.0, 1.0));
  EXPECT_FALSE(BrickBox{}.IsValid());
}
