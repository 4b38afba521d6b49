#include "Core/Image.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

using namespace deepshadow;

TEST(Image, CompareReportsRMSEMaximumAndShareAboveThreshold)
{
  Image a(2, 1), b(2, 1);
  b.Set(1, 0, { 0.1, 0.0, 0.0 });
  const ImageDifference d = Compare(a, b, 0.05);
  EXPECT_NEAR(d.MaxAbs, 0.1, 1e-15);
  EXPECT_NEAR(d.RMSE, std::sqrt(0.01 / 6.0), 1e-15);
  EXPECT_NEAR(d.FractionAbove, 0.5, 1e-15);
  EXPECT_THROW(Compare(a, Image(3, 1)), std::invalid_argument);
}

TEST(Image, BytesRoundTripRoundsAndClamps)
{
  Image a(1, 1);
  a.Set(0, 0, { -0.2, 0.5, 1.7 });
  const std::vector<uint8_t> bytes = a.ToBytes();
  EXPECT_EQ(bytes, (std::vector<uint8_t>{ 0, 128, 255 }));
  const Image back = Image::FromBytes(bytes.data(), 1, 1, 3);
  EXPECT_NEAR(back.At(0, 0).y, 128.0 / 255.0, 1e-15);
}
