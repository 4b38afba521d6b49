#include "Core/Geometry/PolygonTriangulation.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>
#include <list>

namespace deepshadow
{
namespace
{
double Cross(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c)
{
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// The corners in the plane of the polygon, scaled by a power of two so that the largest
// coordinate is below 1 (exact), turned so that the polygon winds counter-clockwise.
std::vector<glm::dvec2> PlaneCorners(const std::vector<glm::dvec3>& corners, bool& flipped)
{
  double largest = 0.0;
  for (const glm::dvec3& p : corners)
  {
    largest = std::max({ largest, std::abs(p.x), std::abs(p.y), std::abs(p.z) });
  }
  int exponent = 0;
  std::frexp(largest, &exponent);
  std::vector<glm::dvec3> scaled;
  scaled.reserve(corners.size());
  for (const glm::dvec3& p : corners)
  {
    scaled.emplace_back(std::ldexp(p.x, -exponent), std::ldexp(p.y, -exponent), std::ldexp(p.z, -exponent));
  }
  // Newell's normal: the polygon's area vector, robust to collinear and concave corners.
  glm::dvec3 normal(0.0);
  for (std::size_t i = 0; i < scaled.size(); ++i)
  {
    const glm::dvec3& a = scaled[i];
    const glm::dvec3& b = scaled[(i + 1) % scaled.size()];
    normal += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
  }
  // Drop the axis the normal is largest along; the winding follows that component's sign.
  const glm::dvec3 size = glm::abs(normal);
  const int drop = size.x >= size.y && size.x >= size.z ? 0 : size.y >= size.z ? 1 : 2;
  const int u = (drop + 1) % 3, v = (drop + 2) % 3;
  flipped = normal[drop] < 0.0;
  std::vector<glm::dvec2> plane;
  plane.reserve(scaled.size());
  for (const glm::dvec3& p : scaled)
  {
    plane.emplace_back(p[u], flipped ? -p[v] : p[v]);
  }
  return plane;
}

bool IsConvex(const std::vector<glm::dvec2>& plane)
{
  const std::size_t n = plane.size();
  for (std::size_t i = 0; i < n; ++i)
  {
    if (Cross(plane[i], plane[(i + 1) % n], plane[(i + 2) % n]) < 0.0)
    {
      return false;
    }
  }
  return true;
}

bool Inside(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c)
{
  return Cross(a, b, p) >= 0.0 && Cross(b, c, p) >= 0.0 && Cross(c, a, p) >= 0.0;
}
}

bool TriangulatePolygon(const std::vector<glm::dvec3>& corners,
  std::vector<std::array<std::size_t, 3>>& triangles, std::string& problem)
{
  const std::size_t n = corners.size();
  if (n < 3)
  {
    return true;
  }
  bool flipped = false;
  const std::vector<glm::dvec2> plane = PlaneCorners(corners, flipped);
  if (n == 3 || IsConvex(plane))
  {
    // Every other corner cut off, round after round: triangles of neighbouring corners first,
    // so that a cap of 20,000 corners is not 20,000 needles from one corner (whose boxes
    // all overlap: CGAL's self-intersection test then compares every pair).
    std::vector<std::size_t> ring(n);
    for (std::size_t i = 0; i < n; ++i)
    {
      ring[i] = i;
    }
    while (ring.size() > 3)
    {
      const std::size_t m = ring.size();
      std::vector<std::size_t> kept;
      for (std::size_t k = 0; k < m; k += 2)
      {
        kept.push_back(ring[k]);
        if (k + 1 < m)
        {
          triangles.push_back({ ring[k], ring[k + 1], ring[(k + 2) % m] });
        }
      }
      ring.swap(kept);
    }
    if (ring.size() == 3) // else a round of 4 corners left 2: all of it is cut
    {
      triangles.push_back({ ring[0], ring[1], ring[2] });
    }
    return true;
  }
  if (n > MaxConcavePolygonCorners)
  {
    problem = "a concave polygon of " + std::to_string(n) + " corners (at most " +
      std::to_string(MaxConcavePolygonCorners) + " are triangulated; split it)";
    return false;
  }
  // Ear clipping: a corner whose triangle turns left and holds no other remaining corner.
  std::list<std::size_t> remaining;
  for (std::size_t i = 0; i < n; ++i)
  {
    remaining.push_back(i);
  }
  auto next = [&](std::list<std::size_t>::iterator it) {
    return ++it == remaining.end() ? remaining.begin() : it;
  };
  std::size_t sinceLastEar = 0;
  for (auto it = remaining.begin(); remaining.size() > 3;)
  {
    const auto before = it == remaining.begin() ? std::prev(remaining.end()) : std::prev(it);
    const auto after = next(it);
    const glm::dvec2 &a = plane[*before], &b = plane[*it], &c = plane[*after];
    bool ear = Cross(a, b, c) > 0.0;
    for (auto other = next(after); ear && other != before; other = next(other))
    {
      const glm::dvec2& p = plane[*other];
      ear = p == a || p == b || p == c || !Inside(p, a, b, c);
    }
    if (!ear && Cross(a, b, c) == 0.0 && sinceLastEar >= remaining.size())
    {
      ear = true; // only collinear corners are left where an ear would be: a zero-area cut
    }
    if (ear)
    {
      triangles.push_back({ *before, *it, *after });
      it = remaining.erase(it);
      it = it == remaining.end() ? remaining.begin() : it;
      sinceLastEar = 0;
      continue;
    }
    if (++sinceLastEar > 2 * remaining.size())
    {
      problem = "a polygon of " + std::to_string(n) + " corners that crosses itself";
      return false;
    }
    it = after;
  }
  triangles.push_back({ remaining.front(), *std::next(remaining.begin()), remaining.back() });
  return true;
}

}
