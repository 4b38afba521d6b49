// Clustered light-space maps (Core/Shadows/Clusters.h): the objects found in the empty-space
// map, paper 000's greedy clustering, and clustered deep shadow maps against closed forms:
// two balls in different clusters along the light (their shadows multiply), and a cube in the
// hole of a ring whose cluster's box contains it (its samples must count once).
#include "ClosedFormScenes.h"

#include "Core/EmptySpace.h"
#include "Core/Shadows/Clusters.h"
#include "Core/Shadows/LightSpace.h"

#include <gtest/gtest.h>

#include <set>

using namespace deepshadow;
using namespace deepshadow::closedform;

namespace
{
// A volume of unit spacing (world = index + origin) whose field is 1 inside `inside`.
std::unique_ptr<Body> Shapes(const glm::ivec3& dims, const glm::dvec3& origin,
  const std::function<bool(const glm::dvec3&)>& inside, double opacity)
{
  return std::make_unique<Body>(dims, origin, opacity, glm::dvec3(0.0),
    [inside](const glm::dvec3& p) { return inside(p) ? 1.0f : 0.0f; });
}

// Two balls of one opacity in a grid of unit spacing (Path: through both), the caster
// skipping the grid's empty blocks.
struct TwoBalls
{
  std::unique_ptr<Body> Volume;
  std::unique_ptr<EmptySpaceMap> Empty;
};

TwoBalls MakeTwoBalls(const glm::dvec3& a, const glm::dvec3& b, double radius, double opacity,
  const glm::ivec3& dims, const glm::dvec3& origin)
{
  TwoBalls balls;
  balls.Volume = std::make_unique<Body>(dims, origin, opacity, glm::dvec3(0.0),
    [=](const glm::dvec3& p) { return std::max(BallField(p, a, radius), BallField(p, b, radius)); });
  balls.Volume->Path = [=](const glm::dvec3& p, const glm::dvec3& d, double maxS, double grow) {
    return SphereChord(a, radius + grow, p, d, maxS) + SphereChord(b, radius + grow, p, d, maxS);
  };
  balls.Empty = std::make_unique<EmptySpaceMap>(*balls.Volume->Grid, balls.Volume->Transfer.Opacity);
  balls.Volume->Caster.Empty = balls.Empty.get();
  return balls;
}

// Deep shadow maps of 128^2, at most `clusters` per light (0: one map).
ShadowParameters ClusteredMaps(int clusters, double distance)
{
  ShadowParameters parameters = Technique("dsm");
  parameters.Clusters = clusters;
  parameters.ClusterDistance = distance;
  parameters.MapSize = 128;
  return parameters;
}

int ClusterCount(const std::vector<int>& cluster)
{
  return static_cast<int>(std::set<int>(cluster.begin(), cluster.end()).size());
}
}

TEST(Clusters, ObjectsAreConnectedGroupsOfOccupiedBlocks)
{
  // Two cubes 24 voxels apart, and two cubes touching diagonally by one block corner.
  const auto body = Shapes(glm::ivec3(96, 96, 33), glm::dvec3(0.0),
    [](const glm::dvec3& p) {
      const auto in = [&](double x0, double x1, double y0, double y1) {
        return p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1 && p.z >= 10 && p.z <= 20;
      };
      return in(2, 12, 2, 12) || in(40, 50, 2, 12) || in(66, 70, 66, 70) || in(73, 78, 73, 78);
    },
    0.5);
  const EmptySpaceMap empty(*body->Grid, body->Transfer.Opacity);
  const VolumeObjects objects = OccupiedObjects(empty, body->Grid->GetDims());
  ASSERT_EQ(objects.Boxes.size(), 3u);
  // The first cube's blocks (0 and 1 with their aprons), one voxel of apron, within the grid.
  EXPECT_EQ(objects.Boxes[0].Lo, glm::dvec3(0.0, 0.0, 7.0));
  EXPECT_EQ(objects.Boxes[0].Hi, glm::dvec3(17.0, 17.0, 25.0));
  // Every block with an opacity belongs to an object, every other to none.
  for (size_t b = 0; b < empty.Occupied.size(); ++b)
  {
    EXPECT_EQ(objects.BlockObject[b] >= 0, empty.Occupied[b] != 0) << "block " << b;
  }
}

TEST(Clusters, GreedyClusteringFollowsDistanceAndLimit)
{
  // Four objects along u: two pairs 10 apart.
  const std::vector<glm::dvec4> extents{ { 0.0, 0.0, 1.0, 1.0 }, { 1.1, 0.0, 2.1, 1.0 }, { 10.0, 0.0, 11.0, 1.0 },
    { 11.1, 0.0, 12.1, 1.0 } };
  EXPECT_DOUBLE_EQ(ExtentDistance(extents[0], extents[1]), 1.1);
  const auto distance = [&](size_t a, size_t b) { return ExtentDistance(extents[a], extents[b]); };
  const std::vector<int> pairs = ClusterObjects(4, distance, 4, 1.5);
  EXPECT_EQ(ClusterCount(pairs), 2);
  EXPECT_EQ(pairs[0], pairs[1]);
  EXPECT_EQ(pairs[2], pairs[3]);
  EXPECT_NE(pairs[0], pairs[2]);
  // d0 = 0: every object apart while the limit allows; the limit then groups the nearest.
  EXPECT_EQ(ClusterCount(ClusterObjects(4, distance, 4, 0.0)), 4);
  const std::vector<int> three = ClusterObjects(4, distance, 3, 0.0);
  EXPECT_EQ(ClusterCount(three), 3);
  EXPECT_EQ(ClusterCount(ClusterObjects(4, distance, 1, 0.0)), 1);
  // A heavy object (large on screen) gets a cluster of its own where its neighbour joined
  // it before.
  EXPECT_EQ(ClusterCount(ClusterObjects(4, distance, 3, 1.5)), 2);
  const std::vector<double> weights{ 1.0, 1.0, 1.0, 8.0 };
  const std::vector<int> weighted = ClusterObjects(4, distance, 3, 1.5, &weights);
  EXPECT_EQ(ClusterCount(weighted), 3);
  for (int o = 0; o < 3; ++o)
  {
    EXPECT_NE(weighted[o], weighted[3]) << "object " << o;
  }
}

TEST(Clusters, ShadowsOfTwoClustersMultiplyAlongTheLight)
{
  // Two balls of radius 8, one above the other (shifted by 4 in x, so that d0 = 0 parts
  // them), lit from above: below both, Beer-Lambert through both chords.
  const glm::dvec3 a(0.0, 0.0, 20.0), b(4.0, 0.0, -20.0);
  const double radius = 8.0, opacity = 0.08;
  const TwoBalls balls = MakeTwoBalls(a, b, radius, opacity, glm::ivec3(41, 41, 65), glm::dvec3(-20.0, -20.0, -32.0));
  Body* body = balls.Volume.get();
  const Light light = Directional({ 0.0, 0.0, 1.0 });

  ShadowParameters parameters = ClusteredMaps(2, 0.0);
  const auto clustered = MakeLightShadow(parameters, body->Caster, light, ViewStep);
  const auto* faces = dynamic_cast<const LightSpaceShadow*>(clustered.get());
  ASSERT_NE(faces, nullptr);
  EXPECT_TRUE(faces->IsClustered());
  ASSERT_EQ(faces->GetFaces().size(), 2u);
  parameters.Clusters = 0;
  const auto whole = MakeLightShadow(parameters, body->Caster, light, ViewStep);
  // Each face is fitted to its ball's blocks, not to the whole box.
  const double wholeExtent = dynamic_cast<const LightSpaceShadow&>(*whole).GetFaces().front().Extent;
  for (const ShadowMapFace& face : faces->GetFaces())
  {
    EXPECT_LT(face.Extent, 0.85 * wholeExtent);
  }

  int checked = 0;
  double worst = 0.0, worstWhole = 0.0, worstOneCluster = 1.0;
  for (double x = -6.0; x <= 8.0; x += 1.0)
    for (double y = -6.0; y <= 6.0; y += 1.0)
    {
      const glm::dvec3 p(x, y, -30.0);
      const double exact = body->Exact(p, light, false).r;
      const double got = clustered->Visibility(p).r;
      worst = std::max(worst, std::abs(got - exact));
      worstWhole = std::max(worstWhole, std::abs(whole->Visibility(p).r - exact));
      // Where both balls shadow, one cluster's shadow alone is far from the answer.
      const double lower = Transmittance(opacity, 1.0, SphereChord(b, radius, p, light.At(p).ToLight));
      if (SphereChord(a, radius, p, light.At(p).ToLight) > 4.0)
      {
        worstOneCluster = std::min(worstOneCluster, std::abs(lower - exact));
      }
      ++checked;
    }
  std::printf("two clusters: %d points, max error %.4f against Beer-Lambert (one map: %.4f; one cluster "
              "alone: %.4f or more)\n", checked, worst, worstWhole, worstOneCluster);
  EXPECT_LT(worst, 0.05);
  EXPECT_GT(worstOneCluster, 0.1); // the check above would catch a missing cluster
}

TEST(Clusters, ASampleInsideAnotherClustersBoxCountsOnce)
{
  // A square ring (z 12 to 20) around a cube in its hole: the ring's box contains the cube,
  // yet the ring's face must not cast the cube's shadow a second time.
  const auto inRing = [](const glm::dvec3& p) {
    const double m = std::max(std::abs(p.x - 48.0), std::abs(p.y - 48.0));
    return p.z >= 12.0 && p.z <= 20.0 && m >= 18.0 && m <= 40.0;
  };
  const auto inCube = [](const glm::dvec3& p) {
    return p.z >= 12.0 && p.z <= 20.0 && std::abs(p.x - 48.0) <= 6.0 && std::abs(p.y - 48.0) <= 6.0;
  };
  const double opacity = 0.1;
  auto body = Shapes(glm::ivec3(97, 97, 33), glm::dvec3(0.0), [&](const glm::dvec3& p) { return inRing(p) || inCube(p); }, opacity);
  const EmptySpaceMap empty(*body->Grid, body->Transfer.Opacity);
  ASSERT_EQ(OccupiedObjects(empty, body->Grid->GetDims()).Boxes.size(), 2u);
  body->Caster.Empty = &empty;
  const Light light = Directional({ 0.0, 0.0, 1.0 });
  const auto clustered = MakeLightShadow(ClusteredMaps(2, 0.0), body->Caster, light, ViewStep);
  ASSERT_EQ(dynamic_cast<const LightSpaceShadow&>(*clustered).GetFaces().size(), 2u);
  const auto truth = MakeLightShadow(ShadowParameters::GroundTruth(false, 1.0), body->Caster, light, ViewStep);
  // Under the cube (8.5 units of it), and under the ring.
  for (const glm::dvec3& p : { glm::dvec3(48.0, 48.0, 4.0), glm::dvec3(46.0, 50.0, 4.0), glm::dvec3(20.0, 48.0, 4.0) })
  {
    const double expected = truth->Visibility(p).r;
    EXPECT_NEAR(clustered->Visibility(p).r, expected, 0.02) << p.x << " " << p.y;
    EXPECT_GT(std::abs(expected * expected - expected), 0.05); // counted twice would show
  }
}

TEST(Clusters, APointLightAmongObjectsNeedsFewerThanSixMaps)
{
  // Two balls on either side of a point light between them: one unclustered map would be a
  // cube of six faces; clustered, one perspective face per ball.
  const TwoBalls balls = MakeTwoBalls({ -40.0, 0.0, 0.0 }, { 40.0, 0.0, 0.0 }, 7.0, 0.08, glm::ivec3(113, 33, 33),
    glm::dvec3(-56.0, -16.0, -16.0));
  Body* body = balls.Volume.get();
  const Light light = Positional({ 0.0, 0.0, 0.0 }, { 1.0, 0.0, 0.0 });
  ShadowParameters parameters = ClusteredMaps(4, 0.25);
  const auto clustered = MakeLightShadow(parameters, body->Caster, light, ViewStep);
  const auto& faces = dynamic_cast<const LightSpaceShadow&>(*clustered).GetFaces();
  ASSERT_EQ(faces.size(), 2u);
  for (const ShadowMapFace& face : faces)
  {
    EXPECT_TRUE(face.Perspective);
  }
  parameters.Clusters = 0;
  EXPECT_EQ(dynamic_cast<const LightSpaceShadow&>(*MakeLightShadow(parameters, body->Caster, light, ViewStep)).GetFaces().size(), 6u);
  // Behind each ball, Beer-Lambert through its chord.
  double worst = 0.0;
  for (double y = -5.0; y <= 5.0; y += 1.0)
    for (const double x : { -52.0, 52.0 })
    {
      const glm::dvec3 p(x, y, 2.0);
      worst = std::max(worst, std::abs(clustered->Visibility(p).r - body->Exact(p, light, false).r));
    }
  std::printf("point light between two clusters: max error %.4f against Beer-Lambert\n", worst);
  EXPECT_LT(worst, 0.05);
}

TEST(Clusters, ASpotLightSkipsClustersOutsideItsCone)
{
  // Two balls under a narrow spot on the right one: the left ball needs no map.
  const glm::dvec3 b(20.0, 0.0, 0.0);
  const TwoBalls balls = MakeTwoBalls({ -20.0, 0.0, 0.0 }, b, 7.0, 0.08, glm::ivec3(65, 33, 33), glm::dvec3(-32.0, -16.0, -16.0));
  const VolumeGrid& grid = *balls.Volume->Grid;
  const ClusteredFaces spot = ClusterFaces(Positional({ 20.0, 0.0, 40.0 }, b, 15.0), grid.GetIndexToWorld(),
    grid.GetDims(), *balls.Empty, nullptr, 4, 0.25);
  EXPECT_EQ(spot.Faces.size(), 1u);
  const ClusteredFaces wide = ClusterFaces(Positional({ 20.0, 0.0, 40.0 }, b, 80.0), grid.GetIndexToWorld(),
    grid.GetDims(), *balls.Empty, nullptr, 4, 0.25);
  EXPECT_EQ(wide.Faces.size(), 2u);
}
