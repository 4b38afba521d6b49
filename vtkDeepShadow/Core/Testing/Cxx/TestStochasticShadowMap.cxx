// Coloured stochastic shadow maps, CPU side: the estimator is unbiased against the exact
// coloured transmittance within its sampling error, reproducible by seed, and uses the
// paper's offsets.
#include "Core/Shadows/LightSpace.h"
#include "Core/Shadows.h"
#include "Core/Shadows/StochasticShadowMap.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

using namespace deepshadow;

namespace
{
// A 33^3 volume filled with a smooth coloured medium between z = 8 and z = 24.
struct Medium
{
  std::shared_ptr<VolumeGrid> Grid;
  TransferFunction Transfer;
  ShadowCaster Caster;
  Medium()
  {
    std::vector<float> values(33 * 33 * 33, 0.0f);
    for (int k = 0; k < 33; ++k)
      for (int j = 0; j < 33; ++j)
        for (int i = 0; i < 33; ++i)
          values[i + 33 * (j + 33 * k)] = (k >= 8 && k <= 24) ? 0.5f + 0.5f * std::sin(0.3 * k) : 0.0f;
    this->Grid = std::make_shared<VolumeGrid>(glm::ivec3(33), values, glm::dmat4(1.0));
    this->Transfer = TransferFunction::Grey({ { 0.0, 0.0 }, { 1.0, 0.15 } });
    this->Transfer.Red = PiecewiseLinear({ { 0.0, 0.9 }, { 1.0, 0.8 } });
    this->Transfer.Green = PiecewiseLinear({ { 0.0, 0.5 }, { 1.0, 0.3 } });
    this->Transfer.Blue = PiecewiseLinear({ { 0.0, 0.1 }, { 1.0, 0.0 } });
    this->Caster.Grid = this->Grid.get();
    this->Caster.Transfer = &this->Transfer;
  }
};

Light FromAbove()
{
  Light light;
  light.Position = { 0.0, 0.0, 1.0 };
  return light;
}

// The exact coloured transmittance of the photon's own segments up to `depth` along a ray.
glm::dvec3 ExactTransmittance(const ShadowCaster& caster, const glm::dvec3& origin,
  const glm::dvec3& direction, double step, double depth)
{
  glm::dvec3 t(1.0);
  MarchTexelRay(caster, origin, direction, step, nullptr, [&](long, double s, const CastSample& scalar, bool) {
    if (s > depth)
    {
      return false;
    }
    const glm::dvec4 sample = caster.Sample(scalar, step);
    t *= 1.0 - sample.a * (1.0 - glm::dvec3(sample));
    return true;
  });
  return t;
}
}

TEST(StochasticShadowMap, PhotonsAreUnbiasedWithinTheirSamplingError)
{
  const Medium medium;
  const double step = 0.5;
  const auto faces = ShadowMapFaces(FromAbove(), glm::dvec3(16.0), std::sqrt(3.0) * 16.0);
  const int size = 64;
  for (double depth : { 10.0, 20.0, 30.0, 50.0 })
  {
    glm::dvec3 mean(0.0), exact(0.0);
    long count = 0;
    for (int y = 0; y < size; ++y)
    {
      for (int x = 0; x < size; ++x)
      {
        glm::dvec3 origin, direction;
        faces[0].TexelRay(2.0 * (x + 0.5) / size - 1.0, 2.0 * (y + 0.5) / size - 1.0, origin, direction);
        for (uint32_t layer = 0; layer < 4; ++layer)
        {
          const auto stop = TraceStochasticPhoton(medium.Caster, origin, direction, step, x, y, layer, 11);
          for (int c = 0; c < 3; ++c)
          {
            mean[c] += stop[c] > depth ? 1.0 : 0.0;
          }
          exact += ExactTransmittance(medium.Caster, origin, direction, step, depth);
          ++count;
        }
      }
    }
    mean /= static_cast<double>(count);
    exact /= static_cast<double>(count);
    for (int c = 0; c < 3; ++c)
    {
      const double sigma = std::sqrt(exact[c] * (1.0 - exact[c]) / count);
      EXPECT_NEAR(mean[c], exact[c], 4.0 * sigma + 1e-12) << "depth " << depth << " channel " << c;
    }
  }
}

TEST(StochasticShadowMap, LookupsAverageTheOffsetsAndApproachTheGroundTruth)
{
  const Medium medium;
  ShadowParameters p;
  p.Kind = ShadowKind::Stochastic;
  p.MapSize = 64;
  p.Photons = 4;
  const auto map = MakeLightShadow(p, medium.Caster, FromAbove(), 0.5, 2);
  const auto truth = MakeLightShadow(ShadowParameters::GroundTruth(true, 1.0), medium.Caster, FromAbove(), 0.5);
  // 13 offsets x 4 photons = 52 tests per lookup: each a multiple of 1/52.
  glm::dvec3 error(0.0);
  int points = 0;
  for (int i = 4; i < 29; i += 3)
  {
    for (int j = 4; j < 29; j += 3)
    {
      const glm::dvec3 p0(i, j, 3.0);
      const glm::dvec3 v = map->Visibility(p0);
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_NEAR(std::round(v[c] * 52.0), v[c] * 52.0, 1e-9);
      }
      error += glm::abs(v - truth->Visibility(p0));
      ++points;
    }
  }
  error /= static_cast<double>(points);
  EXPECT_LT(std::max({ error.r, error.g, error.b }), 0.06);
  EXPECT_EQ(map->Visibility({ 16, 16, 30 }), glm::dvec3(1.0)); // above the medium
  EXPECT_EQ(map->Bytes(), 64u * 64 * 4 * 16);
}

TEST(StochasticShadowMap, SeedsMakeMapsReproducible)
{
  const Medium medium;
  ShadowParameters p;
  p.Kind = ShadowKind::Stochastic;
  p.MapSize = 16;
  const auto a = MakeLightShadow(p, medium.Caster, FromAbove(), 0.5, 2);
  const auto b = MakeLightShadow(p, medium.Caster, FromAbove(), 0.5, 1);
  p.Seed = 1;
  const auto c = MakeLightShadow(p, medium.Caster, FromAbove(), 0.5, 2);
  bool differs = false;
  for (int i = 0; i < 33; ++i)
  {
    const glm::dvec3 point(i, 16.5, 6.0);
    EXPECT_EQ(a->Visibility(point), b->Visibility(point));
    differs = differs || a->Visibility(point) != c->Visibility(point);
  }
  EXPECT_TRUE(differs);
  EXPECT_EQ(StochasticThreshold(1, 2, 3, 4, 5), StochasticThreshold(1, 2, 3, 4, 5));
  EXPECT_NE(StochasticThreshold(1, 2, 3, 4, 5), StochasticThreshold(1, 2, 3, 5, 5));
}

TEST(StochasticShadowMap, OffsetSetsAreThePapers)
{
  EXPECT_EQ(StochasticOffsets(7).size(), 7u);
  EXPECT_EQ(StochasticOffsets(13).size(), 13u);
  EXPECT_EQ(StochasticOffsets(21).size(), 21u);
  EXPECT_THROW(StochasticOffsets(8), std::invalid_argument);
  // The 13 of the paper, and the 7 its smallest (by length).
  const std::set<std::pair<int, int>> paper{ { 0, 0 }, { 3, 3 }, { -3, 3 }, { 3, -3 }, { -3, -3 },
    { 4, 0 }, { -4, 0 }, { 0, 4 }, { 0, -4 }, { 7, 0 }, { -7, 0 }, { 0, 7 }, { 0, -7 } };
  std::set<std::pair<int, int>> thirteen;
  for (const glm::ivec2& o : StochasticOffsets(13))
  {
    thirteen.emplace(o.x, o.y);
  }
  EXPECT_EQ(thirteen, paper);
  double longestOfSeven = 0.0;
  for (const glm::ivec2& o : StochasticOffsets(7))
  {
    EXPECT_TRUE(paper.count({ o.x, o.y }));
    longestOfSeven = std::max(longestOfSeven, std::hypot(o.x, o.y));
  }
  EXPECT_LT(longestOfSeven, 5.0);
}
