// One polygon as triangles (Core/Geometry/PolygonTriangulation.h): every triangle inside,
// their areas summing to the polygon's, in linear time for a convex cap of 20,000 corners,
// at coordinates near 1e300, and a clear refusal where no triangulation exists.
#include "Core/Geometry/PolygonTriangulation.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <chrono>
#include <cmath>

using deepshadow::TriangulatePolygon;
using Triangles = std::vector<std::array<std::size_t, 3>>;

namespace
{
// Signed area of the triangles in the xy plane (counter-clockwise positive).
double Area(const std::vector<glm::dvec3>& p, const Triangles& triangles)
{
  double area = 0.0;
  for (const auto& t : triangles)
  {
    const glm::dvec3 a = p[t[0]], b = p[t[1]], c = p[t[2]];
    area += 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
  }
  return area;
}

std::vector<glm::dvec3> Circle(std::size_t corners, double radius)
{
  std::vector<glm::dvec3> p;
  for (std::size_t i = 0; i < corners; ++i)
  {
    const double angle = 2.0 * M_PI * static_cast<double>(i) / static_cast<double>(corners);
    p.emplace_back(radius * std::cos(angle), radius * std::sin(angle), 1.0);
  }
  return p;
}
}

TEST(PolygonTriangulation, ACapOfTwentyThousandCornersIsCutWhole)
{
  const auto cap = Circle(20000, 10.0);
  Triangles triangles;
  std::string problem;
  const auto start = std::chrono::steady_clock::now();
  ASSERT_TRUE(TriangulatePolygon(cap, triangles, problem)) << problem;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(triangles.size(), cap.size() - 2);
  double polygon = 0.0; // the shoelace area of the corners
  for (std::size_t i = 0; i < cap.size(); ++i)
  {
    const glm::dvec3 &a = cap[i], &b = cap[(i + 1) % cap.size()];
    polygon += 0.5 * (a.x * b.y - b.x * a.y);
  }
  EXPECT_NEAR(Area(cap, triangles), polygon, 1e-9 * polygon) << "the triangles do not tile the cap";
  // Each edge of the cap belongs to exactly one triangle: no hole ("not closed") anywhere.
  std::vector<int> uses(cap.size(), 0);
  for (const auto& t : triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      const std::size_t a = t[k], b = t[(k + 1) % 3];
      if ((a + 1) % cap.size() == b)
      {
        ++uses[a];
      }
    }
  }
  for (std::size_t i = 0; i < cap.size(); ++i)
  {
    ASSERT_EQ(uses[i], 1) << "edge " << i << " of the cap";
  }
  EXPECT_LT(seconds, 60.0) << "not the linear time a convex polygon needs (informative)";
}

TEST(PolygonTriangulation, ConcavePolygonsAreEarClippedInside)
{
  // An L in the plane z = x + y (not an axis plane), clockwise.
  std::vector<glm::dvec3> l;
  for (const glm::dvec2& q : { glm::dvec2(0, 0), glm::dvec2(0, 2), glm::dvec2(1, 2), glm::dvec2(1, 1),
         glm::dvec2(2, 1), glm::dvec2(2, 0) })
  {
    l.emplace_back(q.x, q.y, q.x + q.y);
  }
  Triangles triangles;
  std::string problem;
  ASSERT_TRUE(TriangulatePolygon(l, triangles, problem)) << problem;
  ASSERT_EQ(triangles.size(), 4u);
  EXPECT_NEAR(Area(l, triangles), -3.0, 1e-12) << "clockwise: the triangles keep the polygon's winding";
  // No triangle covers the L's notch (1.5, 1.5).
  for (const auto& t : triangles)
  {
    const glm::dvec3 a = l[t[0]], b = l[t[1]], c = l[t[2]];
    auto side = [](glm::dvec3 p, glm::dvec3 q, double x, double y) {
      return (q.x - p.x) * (y - p.y) - (q.y - p.y) * (x - p.x);
    };
    const double s1 = side(a, b, 1.5, 1.5), s2 = side(b, c, 1.5, 1.5), s3 = side(c, a, 1.5, 1.5);
    EXPECT_FALSE((s1 < 0 && s2 < 0 && s3 < 0) || (s1 > 0 && s2 > 0 && s3 > 0)) << "a triangle covers the notch";
  }
}

TEST(PolygonTriangulation, CoordinatesNear1e300DoNotOverflow)
{
  const std::vector<glm::dvec3> quad = { { -1e300, -1e300, 1e300 }, { 1e300, -1e300, 1e300 },
    { 1e300, 1e300, 1e300 }, { -1e300, 1e300, 1e300 } };
  Triangles triangles;
  std::string problem;
  ASSERT_TRUE(TriangulatePolygon(quad, triangles, problem)) << problem;
  EXPECT_EQ(triangles.size(), 2u);
  for (const auto& t : triangles)
  {
    EXPECT_TRUE(t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) << "a degenerate triangle";
  }
}

TEST(PolygonTriangulation, SelfCrossingPolygonsEndAndHugeConcaveOnesAreRefused)
{
  // A pentagram (every other corner of a pentagon) crosses itself: whatever its triangles,
  // the clipping ends, with at most n - 2 of them or a reason.
  std::vector<glm::dvec3> star;
  for (int i = 0; i < 5; ++i)
  {
    const double angle = 2.0 * M_PI * (2 * i % 5) / 5.0;
    star.emplace_back(std::cos(angle), std::sin(angle), 0.0);
  }
  Triangles triangles;
  std::string problem;
  if (TriangulatePolygon(star, triangles, problem))
  {
    EXPECT_LE(triangles.size(), 3u);
  }
  else
  {
    EXPECT_NE(problem.find("crosses itself"), std::string::npos) << problem;
  }
  // A star of 10,000 points is concave and beyond the corners ear clipping is given.
  std::vector<glm::dvec3> spiky = Circle(10000, 10.0);
  for (std::size_t i = 0; i < spiky.size(); i += 2)
  {
    spiky[i] *= glm::dvec3(0.5, 0.5, 1.0);
  }
  problem.clear();
  EXPECT_FALSE(TriangulatePolygon(spiky, triangles, problem));
  EXPECT_NE(problem.find("at most 4096"), std::string::npos) << problem;
}
