// The CPU twin of shadows while interacting from a coarser grid (Core/ShadowSubsampling.h):
// the coarse grid's size, the texel's ratio, and the upsampling's weights.
#include "Core/ShadowSubsampling.h"

#include <gtest/gtest.h>

#include <stdexcept>

using namespace deepshadow;

namespace
{
// A 2 x 2 grid of 4 pixels a ray, every texel seeing the same unshadowed colour.
ShadowRatioImage Grid(const glm::dvec3& r00, const glm::dvec3& r10, const glm::dvec3& r01, const glm::dvec3& r11)
{
  ShadowRatioImage image;
  image.Size = { 2, 2 };
  image.Scale = 4;
  for (const glm::dvec3& r : { r00, r10, r01, r11 })
  {
    ShadowRatioTexel texel;
    texel.Ratio = r;
    texel.Alpha = 1.0;
    texel.Unshadowed = glm::dvec3(0.5);
    image.Texels.push_back(texel);
  }
  return image;
}
}

TEST(ShadowSubsampling, CoarseGridCoversTheView)
{
  EXPECT_EQ(ShadowRatioSize(500, 500, 4), glm::ivec2(125, 125));
  EXPECT_EQ(ShadowRatioSize(501, 3, 4), glm::ivec2(126, 1));
  EXPECT_EQ(ShadowRatioRayPosition(0, 2, 4), glm::dvec2(2.0, 10.0));
}

TEST(ShadowSubsampling, TexelIsShadowedOverUnshadowedPerChannel)
{
  const ShadowRatioTexel t = MakeShadowRatioTexel({ 0.2, 0.3, 0.0, 0.8 }, { 0.4, 0.3, 0.0 });
  EXPECT_DOUBLE_EQ(t.Ratio.r, 0.5);
  EXPECT_DOUBLE_EQ(t.Ratio.g, 1.0);
  EXPECT_DOUBLE_EQ(t.Ratio.b, 1.0); // nothing unshadowed to scale: 1
  EXPECT_DOUBLE_EQ(t.Alpha, 0.8);
  EXPECT_EQ(t.Unshadowed, glm::dvec3(0.4, 0.3, 0.0));
}

TEST(ShadowSubsampling, UpsamplingIsBilinearBetweenRayCentres)
{
  const ShadowRatioImage image = Grid(glm::dvec3(0.0), glm::dvec3(1.0), glm::dvec3(0.0), glm::dvec3(1.0));
  // Ray centres at pixels 2 and 6: pixel x's centre x + 0.5 lies (x + 0.5 - 2) / 4 of the way.
  EXPECT_NEAR(UpsampleShadowRatio(image, 1, 0, glm::dvec3(0.5)).r, 0.0, 1e-15); // clamped before the first
  EXPECT_NEAR(UpsampleShadowRatio(image, 2, 0, glm::dvec3(0.5)).r, 0.125, 1e-15);
  EXPECT_NEAR(UpsampleShadowRatio(image, 4, 3, glm::dvec3(0.5)).r, 0.625, 1e-15);
  EXPECT_NEAR(UpsampleShadowRatio(image, 7, 7, glm::dvec3(0.5)).r, 1.0, 1e-15); // and after the last
  // A constant ratio stays constant everywhere.
  const ShadowRatioImage flat = Grid(glm::dvec3(0.3), glm::dvec3(0.3), glm::dvec3(0.3), glm::dvec3(0.3));
  for (int x = 0; x < 8; ++x)
  {
    EXPECT_NEAR(UpsampleShadowRatio(flat, x, 5, glm::dvec3(0.5)).g, 0.3, 1e-15);
  }
}

TEST(ShadowSubsampling, RaysThatSawNothingOrSomethingElseCountLess)
{
  ShadowRatioImage image = Grid(glm::dvec3(0.2), glm::dvec3(1.0), glm::dvec3(0.2), glm::dvec3(1.0));
  // Pixel 3 lies 3/8 of the way from the left column's rays to the right's: weights 5/8 and
  // 3/8; then only the left column once the right saw nothing.
  EXPECT_NEAR(UpsampleShadowRatio(image, 3, 4, glm::dvec3(0.5)).r, 0.625 * 0.2 + 0.375 * 1.0, 1e-12);
  image.Texels[1].Alpha = image.Texels[3].Alpha = 0.0;
  EXPECT_NEAR(UpsampleShadowRatio(image, 3, 4, glm::dvec3(0.5)).r, 0.2, 1e-12);
  // Rays whose unshadowed composite differs by the guide's scale count half.
  image.Texels[1].Alpha = image.Texels[3].Alpha = 1.0;
  image.Texels[1].Unshadowed = image.Texels[3].Unshadowed = glm::dvec3(0.5 + ShadowRatioGuideScale, 0.5, 0.5);
  EXPECT_NEAR(UpsampleShadowRatio(image, 3, 4, glm::dvec3(0.5)).r,
    (0.625 * 0.2 + 0.5 * 0.375 * 1.0) / (0.625 + 0.5 * 0.375), 1e-12);
  // No ray saw anything: unshadowed.
  for (ShadowRatioTexel& texel : image.Texels)
  {
    texel.Alpha = 0.0;
  }
  EXPECT_EQ(UpsampleShadowRatio(image, 3, 4, glm::dvec3(0.5)), glm::dvec3(1.0));
}

TEST(ShadowSubsampling, TwinRefusesWhatItDoesNotDraw)
{
  Scene scene;
  EXPECT_THROW(RenderShadowSubsampled(scene, MarchSettings(), 4), std::invalid_argument); // no volume
}
