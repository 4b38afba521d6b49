// Independent components' own gradient opacities (Core/Components.h) against closed forms:
// on linear fields the gradient is constant, so each component's factor is its own function
// at its own slope, whatever the other components hold.
#include "Core/Components.h"

#include <gtest/gtest.h>

#include <memory>

using namespace deepshadow;

namespace
{
// f(i, j, k) = base + slope . (i, j, k) on an 8^3 grid of unit spacing.
std::shared_ptr<VolumeGrid> Ramp(const glm::dvec3& slope, double base = 100.0)
{
  std::vector<float> values;
  for (int k = 0; k < 8; ++k)
    for (int j = 0; j < 8; ++j)
      for (int i = 0; i < 8; ++i)
        values.push_back(static_cast<float>(base + glm::dot(slope, glm::dvec3(i, j, k))));
  return std::make_shared<VolumeGrid>(glm::ivec3(8), std::move(values), glm::dmat4(1.0));
}

// A function that rises from 0.1 at magnitude 0 to 1 at 10.
PiecewiseLinear Rising()
{
  return PiecewiseLinear({ { 0.0, 0.1 }, { 10.0, 1.0 } });
}
}

TEST(ComponentGradients, EachComponentTakesItsOwnFunctionAtItsOwnSlope)
{
  const auto first = Ramp({ 2.0, 0.0, 0.0 });  // |gradient| 2
  ComponentSet set;
  set.Others = { Ramp({ 0.0, 3.0, 4.0 }), Ramp({ 0.0, 0.0, 1.0 }) }; // 5, and 1 (no function)
  const glm::dvec2 range(0.0, 400.0); // a quarter is 100: nothing is clamped
  set.Gradients = { GradientOpacity::For(Rising(), range, glm::dvec3(1.0)),
    GradientOpacity::For(PiecewiseLinear({ { 0.0, 1.0 }, { 10.0, 0.0 } }), range, glm::dvec3(1.0)),
    std::nullopt };
  ASSERT_TRUE(set.HasGradients());
  const glm::dvec4 factors = set.GradientFactors(*first, glm::dvec3(3.5, 3.5, 3.5), Interpolation::Linear);
  EXPECT_NEAR(factors[0], 0.1 + 0.9 * 2.0 / 10.0, 1e-12); // its own function at 2
  EXPECT_NEAR(factors[1], 1.0 - 5.0 / 10.0, 1e-12);       // its own at 5
  EXPECT_EQ(factors[2], 1.0);                              // none
  EXPECT_EQ(factors[3], 1.0);                              // no such component

  // Applied to the opacities of the visible components only, before they combine.
  ComponentColors colors{};
  colors[0] = { 1.0, 0.0, 0.0, 0.5 };
  colors[1] = { 0.0, 1.0, 0.0, 0.0 };
  colors[2] = { 0.0, 0.0, 1.0, 0.4 };
  set.ApplyGradients(colors, *first, glm::dvec3(3.5), Interpolation::Linear);
  EXPECT_NEAR(colors[0].a, 0.5 * factors[0], 1e-12);
  EXPECT_EQ(colors[1].a, 0.0);
  EXPECT_EQ(colors[2].a, 0.4);
}

TEST(ComponentGradients, MagnitudesAreClampedToAQuarterOfEachComponentsRange)
{
  const auto first = Ramp({ 8.0, 0.0, 0.0 });
  ComponentSet set;
  set.Others = { Ramp({ 8.0, 0.0, 0.0 }) };
  // Component 0's range is 16 (a quarter: 4), component 1's 400 (100): the same slope of 8
  // reads its function at 4 in one and at 8 in the other.
  set.Gradients = { GradientOpacity::For(Rising(), { 0.0, 16.0 }, glm::dvec3(1.0)),
    GradientOpacity::For(Rising(), { 0.0, 400.0 }, glm::dvec3(1.0)) };
  const glm::dvec4 factors = set.GradientFactors(*first, glm::dvec3(3.5), Interpolation::Linear);
  EXPECT_NEAR(factors[0], 0.1 + 0.9 * 4.0 / 10.0, 1e-12);
  EXPECT_NEAR(factors[1], 0.1 + 0.9 * 8.0 / 10.0, 1e-12);
}

TEST(ComponentGradients, NoneLeaveTheCombinedSampleAsItWas)
{
  ComponentSet set;
  set.Others = { Ramp({ 1.0, 0.0, 0.0 }) };
  EXPECT_FALSE(set.HasGradients());
  set.Gradients = { std::nullopt, std::nullopt };
  EXPECT_FALSE(set.HasGradients());
  const auto first = Ramp({ 0.0, 1.0, 0.0 });
  EXPECT_EQ(set.GradientFactors(*first, glm::dvec3(2.0), Interpolation::Linear), glm::dvec4(1.0));
}
