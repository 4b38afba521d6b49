// Transfer functions: exact evaluation, exact maxima, and the GPU table's error bound.
#include "Core/TransferFunction.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using deepshadow::PiecewiseLinear;
using deepshadow::TransferFunction;
using deepshadow::TransferTable;

TEST(PiecewiseLinear, InterpolatesLinearlyBetweenNodesAndClampsOutside)
{
  PiecewiseLinear f({ { 10.0, 0.0 }, { 0.0, 1.0 }, { 20.0, 0.5 } }); // unsorted on purpose
  EXPECT_DOUBLE_EQ(f.Evaluate(0.0), 1.0);
  EXPECT_DOUBLE_EQ(f.Evaluate(5.0), 0.5);
  EXPECT_DOUBLE_EQ(f.Evaluate(15.0), 0.25);
  EXPECT_DOUBLE_EQ(f.Evaluate(-100.0), 1.0);
  EXPECT_DOUBLE_EQ(f.Evaluate(100.0), 0.5);
}

TEST(PiecewiseLinear, WithoutClampingIsZeroOutsideItsNodes)
{
  PiecewiseLinear f({ { 0.0, 0.3 }, { 1.0, 0.7 } }, false);
  EXPECT_DOUBLE_EQ(f.Evaluate(-0.1), 0.0);
  EXPECT_DOUBLE_EQ(f.Evaluate(1.1), 0.0);
  EXPECT_DOUBLE_EQ(f.Evaluate(0.5), 0.5);
}

TEST(PiecewiseLinear, EqualAbscissaeMakeARightContinuousStep)
{
  PiecewiseLinear f({ { 0.0, 0.0 }, { 5.0, 0.0 }, { 5.0, 1.0 }, { 10.0, 1.0 } });
  EXPECT_DOUBLE_EQ(f.Evaluate(4.999), 0.0);
  EXPECT_DOUBLE_EQ(f.Evaluate(5.0), 1.0);
  EXPECT_DOUBLE_EQ(f.MaxOver(0.0, 4.9), 0.0);
  EXPECT_DOUBLE_EQ(f.MaxOver(4.9, 5.0), 1.0);
}

TEST(PiecewiseLinear, NodesFartherApartThanADoubleSpansInterpolateExactly)
{
  // -+1.7e308: their distance overflows to infinity; the data between them was black.
  PiecewiseLinear f({ { -1.7e308, 0.0 }, { 1.7e308, 1.0 } });
  EXPECT_DOUBLE_EQ(f.Evaluate(0.0), 0.5);
  EXPECT_DOUBLE_EQ(f.Evaluate(255.0), 0.5);
  EXPECT_DOUBLE_EQ(f.Evaluate(0.85e308), 0.75);
  EXPECT_DOUBLE_EQ(f.Evaluate(1.7e308), 1.0);
}

TEST(PiecewiseLinear, MaxOverIsTheExactMaximum)
{
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial)
  {
    PiecewiseLinear f;
    for (int n = 0; n < 8; ++n)
    {
      f.AddNode(100.0 * unit(random), unit(random) < 0.3 ? 0.0 : unit(random));
    }
    double lo = 120.0 * unit(random) - 10.0, hi = lo + 50.0 * unit(random);
    double dense = 0.0;
    for (int i = 0; i <= 20000; ++i)
    {
      dense = std::max(dense, f.Evaluate(lo + (hi - lo) * i / 20000.0));
    }
    const double exact = f.MaxOver(lo, hi);
    EXPECT_GE(exact + 1e-12, dense);            // never below any value in the interval
    EXPECT_LE(exact, dense + 1e-3);             // and attained (up to the dense grid)
  }
}

TEST(TransferTable, TexelCentresHoldTheFunctionExactly)
{
  TransferFunction tf = TransferFunction::Grey({ { 0.0, 0.0 }, { 40.0, 0.2 }, { 255.0, 0.9 } });
  const TransferTable table = TransferTable::Sample(tf, 0.0, 255.0, 256, 1.0);
  for (int i = 0; i < 256; ++i)
  {
    const double scalar = i;
    EXPECT_NEAR(table.Lookup(scalar).a, tf.Opacity.Evaluate(scalar), 1e-7) << i;
    EXPECT_NEAR(table.Lookup(scalar).r, tf.Red.Evaluate(scalar), 1e-7) << i;
  }
}

TEST(TransferTable, LookupErrorIsBoundedByOneTexelOfSlope)
{
  // Between texel centres the table interpolates linearly; the exact function bends only at
  // its nodes, so the error is at most the largest slope change times half a texel.
  TransferFunction tf = TransferFunction::Grey({ { 0.0, 0.0 }, { 100.3, 0.0 }, { 101.0, 1.0 } });
  const int size = 4096;
  const TransferTable table = TransferTable::Sample(tf, 0.0, 1000.0, size, 1.0);
  const double texel = 1000.0 / (size - 1);
  const double maxSlope = 1.0 / 0.7;
  double worst = 0.0;
  for (int i = 0; i <= 100000; ++i)
  {
    const double s = 1000.0 * i / 100000.0;
    worst = std::max(worst, std::abs(table.Lookup(s).a - tf.Opacity.Evaluate(s)));
  }
  EXPECT_LE(worst, maxSlope * texel + 1e-6);
}

TEST(TransferTable, StoresOpacityCorrectedForTheStep)
{
  TransferFunction tf = TransferFunction::Grey({ { 0.0, 0.5 }, { 1.0, 0.5 } });
  tf.OpacityUnitDistance = 2.0;
  const TransferTable table = TransferTable::Sample(tf, 0.0, 1.0, 16, 0.5);
  EXPECT_NEAR(table.Lookup(0.5).a, 1.0 - std::pow(0.5, 0.25), 1e-7);
}
