// Isosurface crossings (VTK's ISOSURFACE_BLEND rules) and the light a translucent surface lets
// through, on the CPU.
#include "Core/Isosurface.h"
#include "Core/Shadows.h"
#include "SlabScene.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace deepshadow;

namespace
{
// The crossing a ray reports at each of `scalars`, NaN as -1 (none).
std::vector<double> Crossings(const std::vector<double>& values, const std::vector<double>& scalars)
{
  IsoCrossings crossings(&values);
  std::vector<double> out;
  for (double s : scalars)
  {
    const double c = crossings.Next(s);
    out.push_back(IsoCrossings::IsCrossing(c) ? c : -1.0);
  }
  return out;
}
}

TEST(Isosurface, TheFirstSampleOnlyFindsWhereTheRayStarts)
{
  // Starting inside (above 50) shows no surface at the entry; leaving shows one.
  EXPECT_EQ(Crossings({ 50.0 }, { 80.0, 70.0, 40.0, 30.0 }), (std::vector<double>{ -1, -1, 50, -1 }));
}

TEST(Isosurface, CrossingsCountBothWaysOncePerStep)
{
  // Up through 10 and 20 in one step: 10 now, 20 at the next sample (still beyond it).
  EXPECT_EQ(Crossings({ 10.0, 20.0 }, { 0.0, 25.0, 25.0, 15.0, 5.0 }),
    (std::vector<double>{ -1, 10, 20, 20, 10 }));
  // Past both and straight back: the lower one up, then down; the upper one never shows.
  EXPECT_EQ(Crossings({ 10.0, 20.0 }, { 0.0, 25.0, 5.0 }), (std::vector<double>{ -1, 10, 10 }));
}

TEST(Isosurface, WithoutValuesScalarsPassThrough)
{
  IsoCrossings crossings(nullptr);
  EXPECT_EQ(crossings.Next(3.5), 3.5);
  EXPECT_EQ(crossings.Next(-2.0), -2.0);
}

TEST(Isosurface, EachCrossingLetsThroughOneMinusItsOpacity)
{
  // The slab (scalar 1 for z in [8, 12]) as the contour 0.5, of opacity 0.4: a feeler from
  // below through it crosses twice and lets through 0.6^2, whatever the step; one that ends
  // inside it, 0.6; coloured (surface colour 0.25 grey), (1 - 0.4 x 0.75)^2.
  const deepshadow::testing::SlabScene scene(0.4);
  const TransferFunction transfer = TransferFunction::Grey({ { 0.0, 0.4 }, { 1.0, 0.4 } });
  TransferFunction colored = transfer;
  colored.Red = colored.Green = colored.Blue = PiecewiseLinear({ { 0.0, 0.25 }, { 1.0, 0.25 } });
  const std::vector<double> values{ 0.5 };
  ShadowCaster caster = scene.Caster;
  caster.Sampling = Interpolation::Linear;
  caster.Transfer = &transfer;
  caster.IsoValues = &values;
  const glm::dvec3 from(10.0, 10.0, 2.0), up(0.0, 0.0, 1.0);
  for (double step : { 0.25, 0.5, 0.7 })
  {
    const ShadowParameters parameters = ShadowParameters::GroundTruth(false, 1.0);
    EXPECT_NEAR(FeelerVisibility(caster, from, up, 1e9, step, parameters).x, 0.36, 1e-12) << "step " << step;
    EXPECT_NEAR(FeelerVisibility(caster, from, up, 8.0, step, parameters).x, 0.6, 1e-12) << "step " << step;
  }
  caster.Transfer = &colored;
  const ShadowParameters coloredRays = ShadowParameters::GroundTruth(true, 1.0);
  EXPECT_NEAR(FeelerVisibility(caster, from, up, 1e9, 0.5, coloredRays).x, 0.7 * 0.7, 1e-12);
}
