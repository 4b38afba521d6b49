// Polyhedral bounds (Core/Bound): the CSG expression, the triangle hierarchy, the walk along
// a ray, and the CPU marches restricted to the bound, against closed forms and brute force.
#include "Core/Bound/BoundRegion.h"
#include "Core/Bound/CSGExpression.h"
#include "Core/ReferenceRenderer.h"
#include "Core/Shadows.h"
#include "Core/Geometry/TriangleBVH.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <random>

using namespace deepshadow;

namespace
{
// 12 triangles, counter-clockwise seen from outside.
std::vector<Triangle> Box(const glm::dvec3& lo, const glm::dvec3& hi)
{
  auto c = [&](int i) { return glm::dvec3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z); };
  const int faces[6][4] = { { 0, 4, 6, 2 }, { 1, 3, 7, 5 }, { 0, 1, 5, 4 }, { 2, 6, 7, 3 },
    { 0, 2, 3, 1 }, { 4, 5, 7, 6 } };
  std::vector<Triangle> triangles;
  for (const auto& f : faces)
  {
    triangles.push_back({ c(f[0]), c(f[1]), c(f[2]) });
    triangles.push_back({ c(f[0]), c(f[2]), c(f[3]) });
  }
  return triangles;
}

std::vector<Triangle> Sphere(const glm::dvec3& centre, double radius, int segments)
{
  auto p = [&](int i, int j) {
    const double theta = M_PI * i / segments, phi = 2.0 * M_PI * j / segments;
    return centre + radius * glm::dvec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
  };
  std::vector<Triangle> triangles;
  for (int i = 0; i < segments; ++i)
  {
    for (int j = 0; j < segments; ++j)
    {
      // Poles: one triangle; elsewhere two. Exact pole points keep the mesh closed.
      const glm::dvec3 a = i == 0 ? centre + glm::dvec3(0, 0, radius) : p(i, j);
      const glm::dvec3 b = i == 0 ? a : p(i, (j + 1) % segments);
      const glm::dvec3 c = i + 1 == segments ? centre - glm::dvec3(0, 0, radius) : p(i + 1, (j + 1) % segments);
      const glm::dvec3 d = i + 1 == segments ? c : p(i + 1, j);
      if (i != 0)
      {
        triangles.push_back({ a, d, b });
      }
      if (i + 1 != segments)
      {
        triangles.push_back({ b, d, c });
      }
    }
  }
  return triangles;
}

BoundRegion Region(std::vector<std::vector<Triangle>> leaves, const std::string& expression)
{
  CSGExpression parsed;
  std::string error;
  EXPECT_TRUE(CSGExpression::Parse(expression, static_cast<int>(leaves.size()), parsed, error)) << error;
  return BoundRegion(std::move(leaves), parsed);
}
}

TEST(CSGExpression, ParsesNestedOperationsAndAliases)
{
  CSGExpression e;
  std::string error;
  ASSERT_TRUE(CSGExpression::Parse(" Union( a , DIFF(B,c) ) ", 3, e, error)) << error;
  EXPECT_EQ(e.ToString(), "union(A,difference(B,C))");
  ASSERT_TRUE(CSGExpression::Parse("inter(A,B)", 2, e, error));
  EXPECT_EQ(e.ToString(), "intersection(A,B)");
  // n-ary difference folds left: A - B - C.
  ASSERT_TRUE(CSGExpression::Parse("diff(A,B,C)", 3, e, error));
  EXPECT_TRUE(e.Evaluate(0b001));
  EXPECT_FALSE(e.Evaluate(0b011));
  EXPECT_FALSE(e.Evaluate(0b101));
  // Empty text: the union of every bound.
  ASSERT_TRUE(CSGExpression::Parse("", 3, e, error));
  EXPECT_EQ(e.ToString(), "union(A,B,C)");
  ASSERT_TRUE(CSGExpression::Parse("", 1, e, error));
  EXPECT_EQ(e.ToString(), "A");
}

TEST(CSGExpression, TruthTableMatchesEvaluation)
{
  CSGExpression e;
  std::string error;
  ASSERT_TRUE(CSGExpression::Parse("union(A,diff(B,C),inter(D,E,F),G,H)", 8, e, error)) << error;
  const std::vector<uint32_t> table = e.TruthTable();
  ASSERT_EQ(table.size(), 8u);
  for (uint32_t s = 0; s < 256; ++s)
  {
    EXPECT_EQ(((table[s / 32] >> (s % 32)) & 1u) != 0, e.Evaluate(s)) << s;
  }
}

TEST(CSGExpression, BadTextIsAClearError)
{
  CSGExpression e;
  std::string error;
  EXPECT_FALSE(CSGExpression::Parse("union(A,C)", 2, e, error));
  EXPECT_NE(error.find("bound C is not given (2 bounds)"), std::string::npos) << error;
  EXPECT_NE(error.find("at character 9"), std::string::npos) << error;
  EXPECT_FALSE(CSGExpression::Parse("xor(A,B)", 2, e, error));
  EXPECT_NE(error.find("unknown operation 'xor'"), std::string::npos) << error;
  EXPECT_FALSE(CSGExpression::Parse("union(A,B", 2, e, error));
  EXPECT_NE(error.find("expected ')'"), std::string::npos) << error;
  EXPECT_FALSE(CSGExpression::Parse("union(A)", 2, e, error));
  EXPECT_NE(error.find("at least two operands"), std::string::npos) << error;
  EXPECT_FALSE(CSGExpression::Parse("A B", 2, e, error));
  EXPECT_NE(error.find("unexpected 'B'"), std::string::npos) << error;
  EXPECT_FALSE(CSGExpression::Parse("union(A,)", 2, e, error));
  EXPECT_FALSE(CSGExpression::Parse("A", 0, e, error));
}

TEST(CSGExpression, TriangleWorkCountsEveryOperationsOperands)
{
  CSGExpression e;
  std::string error;
  ASSERT_TRUE(CSGExpression::Parse("union(A,diff(B,C))", 3, e, error)) << error;
  // diff(B,C): 20 + 30; then union(A, that): 10 + 50.
  EXPECT_DOUBLE_EQ(e.Root().TriangleWork({ 10, 20, 30 }), 110.0);
  // n-ary folds left: union(A,A,A) is (A u A) u A: 2 + 3 triangles of A.
  ASSERT_TRUE(CSGExpression::Parse("union(A,A,A)", 1, e, error)) << error;
  EXPECT_DOUBLE_EQ(e.Root().TriangleWork({ 1000 }), 5000.0);
  // One leaf: nothing to combine.
  ASSERT_TRUE(CSGExpression::Parse("A", 1, e, error)) << error;
  EXPECT_DOUBLE_EQ(e.Root().TriangleWork({ 1000 }), 0.0);
}

TEST(CSGExpression, DeepNestingIsRefusedNotAStackOverflow)
{
  auto nested = [](int depth) {
    std::string text;
    for (int i = 0; i < depth; ++i)
    {
      text += "union(A,";
    }
    return text + "B" + std::string(static_cast<size_t>(depth), ')');
  };
  CSGExpression e;
  std::string error;
  EXPECT_TRUE(CSGExpression::Parse(nested(CSGExpression::MaxDepth), 2, e, error)) << error;
  EXPECT_FALSE(CSGExpression::Parse(nested(CSGExpression::MaxDepth + 1), 2, e, error));
  EXPECT_NE(error.find("nested deeper than 64"), std::string::npos) << error;
  // A million levels: refused at level 65, and the message quotes a short prefix only.
  EXPECT_FALSE(CSGExpression::Parse(nested(1000000), 2, e, error));
  EXPECT_LT(error.size(), 200u) << error.size();
}

TEST(TriangleBVH, NextHitAgreesWithEveryTriangleTested)
{
  const std::vector<Triangle> sphere = Sphere(glm::dvec3(1.0, 2.0, 3.0), 5.0, 40);
  const TriangleBVH bvh(sphere);
  EXPECT_GT(bvh.GetDepth(), 5);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(-8.0, 8.0);
  for (int r = 0; r < 500; ++r)
  {
    const glm::dvec3 origin(u(random), u(random), u(random));
    const glm::dvec3 direction = glm::normalize(glm::dvec3(u(random), u(random), u(random)));
    const double after = u(random);
    MeshHit brute;
    brute.T = INFINITY;
    for (const Triangle& t : sphere)
    {
      double hit = 0.0;
      bool entering = false;
      if (IntersectTriangle(origin, direction, t, hit, entering) && hit > after && hit < brute.T)
      {
        brute = { hit, entering, true };
      }
    }
    const MeshHit fast = bvh.NextHit(origin, direction, after);
    ASSERT_EQ(fast.Found, brute.Found);
    if (brute.Found)
    {
      EXPECT_EQ(fast.T, brute.T);
      EXPECT_EQ(fast.Entering, brute.Entering);
    }
  }
}

TEST(TriangleBVH, TellsEnteringFromLeaving)
{
  const TriangleBVH box(Box(glm::dvec3(0.0), glm::dvec3(1.0)));
  const MeshHit in = box.NextHit({ -1.0, 0.3, 0.4 }, { 1.0, 0.0, 0.0 }, -INFINITY);
  ASSERT_TRUE(in.Found);
  EXPECT_DOUBLE_EQ(in.T, 1.0);
  EXPECT_TRUE(in.Entering);
  const MeshHit out = box.NextHit({ -1.0, 0.3, 0.4 }, { 1.0, 0.0, 0.0 }, in.T);
  ASSERT_TRUE(out.Found);
  EXPECT_DOUBLE_EQ(out.T, 2.0);
  EXPECT_FALSE(out.Entering);
  EXPECT_FALSE(box.NextHit({ -1.0, 0.3, 0.4 }, { 1.0, 0.0, 0.0 }, out.T).Found);
}

TEST(BoundMesh, OpenInconsistentAndNonFiniteMeshesAreNamed)
{
  std::vector<Triangle> box = Box(glm::dvec3(0.0), glm::dvec3(1.0));
  EXPECT_EQ(CheckClosedMesh(box), "");
  std::vector<Triangle> open(box.begin(), box.end() - 2);
  EXPECT_EQ(CheckClosedMesh(open), "is not closed: 4 border edges");
  std::vector<Triangle> flipped = box;
  std::swap(flipped[0].V1, flipped[0].V2);
  EXPECT_NE(CheckClosedMesh(flipped).find("not consistently oriented"), std::string::npos);
  std::vector<Triangle> bad = box;
  bad[3].V1.x = NAN;
  EXPECT_EQ(CheckClosedMesh(bad), "has a NaN or infinite point");
  EXPECT_EQ(CheckClosedMesh({}), "is empty (no triangles)");
  // Inward normals are turned outward: the signed volume becomes positive.
  std::vector<Triangle> inward = box;
  for (Triangle& t : inward)
  {
    std::swap(t.V1, t.V2);
  }
  EXPECT_NEAR(SignedVolume6(inward), -6.0, 1e-12);
  OrientOutward(inward);
  EXPECT_NEAR(SignedVolume6(inward), 6.0, 1e-12);
}

TEST(BoundRegion, IntervalsOfBooleanCombinationsAreExact)
{
  const auto a = Box(glm::dvec3(0.0), glm::dvec3(10.0));
  const auto b = Box(glm::dvec3(3.0, -1.0, -1.0), glm::dvec3(5.0, 11.0, 11.0)); // a wall through A
  const auto c = Box(glm::dvec3(8.0, 2.0, 2.0), glm::dvec3(14.0, 8.0, 8.0));
  const glm::dvec3 origin(-5.0, 4.5, 4.5), direction(1.0, 0.0, 0.0);
  auto intervals = [&](const BoundRegion& region) { return region.Intervals(origin, direction, 0.0, 30.0); };
  using I = std::vector<glm::dvec2>;
  EXPECT_EQ(intervals(Region({ a }, "A")), (I{ { 5.0, 15.0 } }));
  EXPECT_EQ(intervals(Region({ a, b }, "diff(A,B)")), (I{ { 5.0, 8.0 }, { 10.0, 15.0 } }));
  EXPECT_EQ(intervals(Region({ a, b }, "inter(A,B)")), (I{ { 8.0, 10.0 } }));
  EXPECT_EQ(intervals(Region({ a, c }, "union(A,B)")), (I{ { 5.0, 19.0 } }));
  EXPECT_EQ(intervals(Region({ a, b, c }, "union(diff(A,B),C)")), (I{ { 5.0, 8.0 }, { 10.0, 19.0 } }));
  EXPECT_EQ(intervals(Region({ b, c }, "inter(A,B)")), (I{}));
  // A bound with two components: both intervals, not just the first entry and last exit.
  std::vector<Triangle> twoParts = Box(glm::dvec3(0.0), glm::dvec3(2.0, 10.0, 10.0));
  const auto second = Box(glm::dvec3(6.0, 0.0, 0.0), glm::dvec3(7.0, 10.0, 10.0));
  twoParts.insert(twoParts.end(), second.begin(), second.end());
  EXPECT_EQ(intervals(Region({ twoParts }, "")), (I{ { 5.0, 7.0 }, { 11.0, 12.0 } }));
  // An empty leaf is an empty solid.
  EXPECT_EQ(intervals(Region({ a, {} }, "union(A,B)")), (I{ { 5.0, 15.0 } }));
  EXPECT_EQ(intervals(Region({ {} }, "")), (I{}));
}

TEST(BoundRegion, ARayThroughAnEdgeOrAlongAFaceKeepsTheRightState)
{
  const BoundRegion box = Region({ Box(glm::dvec3(0.0), glm::dvec3(10.0)) }, "");
  // Along the diagonal of a face's two triangles (their shared edge), and along a face.
  const auto diagonal = box.Intervals({ -5.0, 5.0, 5.0 }, glm::dvec3(1.0, 0.0, 0.0), 0.0, 30.0);
  EXPECT_EQ(diagonal, (std::vector<glm::dvec2>{ { 5.0, 15.0 } }));
  const auto corner = box.Intervals({ -1.0, -1.0, -1.0 }, glm::normalize(glm::dvec3(1.0)), 0.0, 30.0);
  ASSERT_EQ(corner.size(), 1u);
  EXPECT_NEAR(corner[0].x, std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(corner[0].y, 11.0 * std::sqrt(3.0), 1e-12);
  EXPECT_TRUE(box.Inside({ 5.0, 5.0, 5.0 }));
  EXPECT_FALSE(box.Inside({ 15.0, 5.0, 5.0 }));
  EXPECT_FALSE(box.Inside({ -1.0, 5.0, 5.0 }));
}

TEST(BoundRegion, SkippingTakesExactlyTheSamplesInside)
{
  const auto sphere = Sphere(glm::dvec3(10.0), 7.0, 24);
  const auto hole = Sphere(glm::dvec3(12.0, 10.0, 10.0), 3.0, 16);
  const BoundRegion region = Region({ sphere, hole }, "diff(A,B)");
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(-5.0, 25.0);
  for (int r = 0; r < 200; ++r)
  {
    const glm::dvec3 origin(u(random), u(random), -10.0);
    const glm::dvec3 direction = glm::normalize(glm::dvec3(u(random) * 0.02, u(random) * 0.02, 1.0));
    const double dt = 0.37;
    std::vector<long> skipped, brute;
    BoundRegion::Walker walker(region, origin, direction);
    for (long k = 0; k < 120; ++k)
    {
      if (const long skip = walker.SkipSteps((k + 0.5) * dt, dt))
      {
        k += skip - 1;
        continue;
      }
      skipped.push_back(k);
    }
    for (long k = 0; k < 120; ++k)
    {
      if (region.Inside(origin + (k + 0.5) * dt * direction))
      {
        brute.push_back(k);
      }
    }
    EXPECT_EQ(skipped, brute) << "ray " << r;
  }
}

TEST(BoundRegion, TheMarchesSeeTheVolumeOnlyInsideTheBound)
{
  // A constant volume on [0, 20]^3, bounded to x in [4, 9] u [13, 15] (union of two slabs).
  auto grid = std::make_shared<VolumeGrid>(glm::ivec3(21), std::vector<float>(21 * 21 * 21, 1.0f), glm::dmat4(1.0));
  const TransferFunction transfer = TransferFunction::Grey({ { 0.0, 0.0 }, { 1.0, 0.2 } });
  auto bound = std::make_shared<const BoundRegion>(Region(
    { Box({ 4.0, -1.0, -1.0 }, { 9.0, 21.0, 21.0 }), Box({ 13.0, -1.0, -1.0 }, { 15.0, 21.0, 21.0 }) }, ""));
  ShadowCaster caster;
  caster.Grid = grid.get();
  caster.Transfer = &transfer;
  caster.Bound = bound.get();
  // A feeler along +x from x = 0.25 (samples at 0.25 + 0.5 (j + 0.5)): Beer-Lambert over the
  // 7 metres of bound, 14 samples of opacity 0.2 corrected to the half step.
  const ShadowParameters truth = ShadowParameters::GroundTruth(false, 1.0);
  const double v = FeelerVisibility(caster, { 0.25, 10.0, 10.0 }, { 1.0, 0.0, 0.0 }, 1e300, 0.5, truth).r;
  EXPECT_NEAR(v, std::pow(1.0 - CorrectOpacity(0.2, 0.5, 1.0), 14.0), 1e-12);
  // Outside the bound, nothing casts: from x = 16 towards +x the feeler sees no volume.
  EXPECT_DOUBLE_EQ(FeelerVisibility(caster, { 16.0, 10.0, 10.0 }, { 1.0, 0.0, 0.0 }, 1e300, 0.5, truth).r, 1.0);

  // The view march: the same count of samples composited.
  Scene scene;
  const glm::dmat4 view = glm::lookAt(glm::dvec3(-10.0, 10.0, 10.0), glm::dvec3(10.0), glm::dvec3(0, 0, 1));
  scene.View = Camera(glm::ortho(-1.0, 1.0, -1.0, 1.0, 1.0, 100.0) * view, 1, 1);
  VolumeInstance volume;
  volume.Grid = grid;
  volume.Transfer = transfer;
  volume.Transfer.Red = volume.Transfer.Green = volume.Transfer.Blue = PiecewiseLinear({ { 0.0, 1.0 } });
  volume.Bound = bound;
  scene.Volumes.push_back(volume);
  MarchSettings settings;
  settings.SampleDistance = 0.5;
  const Image image = ReferenceRenderer::Render(scene, settings, 1);
  EXPECT_NEAR(image.At(0, 0).r, 1.0 - std::pow(1.0 - CorrectOpacity(0.2, 0.5, 1.0), 14.0), 1e-12);

  // A deep shadow map built through the bound agrees with the feelers within its epsilon.
  ShadowParameters dsm;
  dsm.Kind = ShadowKind::DeepShadowMap;
  dsm.Epsilon = 0.01;
  dsm.MapSize = 64;
  Light light;
  light.Position = glm::dvec3(1.0, 0.0, 0.0); // directional, from +x
  light.FocalPoint = glm::dvec3(0.0);
  const auto shadow = MakeLightShadow(dsm, caster, light, 0.5, 1);
  const auto rays = MakeLightShadow(ShadowParameters::GroundTruth(false, 1.0), caster, light, 0.5, 1);
  for (double x : { 2.0, 6.0, 11.0, 14.0, 18.0, 19.5 })
  {
    const glm::dvec3 p(x, 10.0, 10.0);
    EXPECT_NEAR(shadow->Visibility(p).r, rays->Visibility(p).r, 0.03) << x;
  }
  EXPECT_NEAR(rays->Visibility({ 18.0, 10.0, 10.0 }).r, 1.0, 1e-12); // nothing between it and the light
}
