#include "Core/Bound/BoundRegion.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <climits>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>

namespace deepshadow
{

std::string CheckClosedMesh(const std::vector<Triangle>& triangles)
{
  if (triangles.empty())
  {
    return "is empty (no triangles)";
  }
  // Merge coincident points exactly, so that meshes with unshared points (STL) count right.
  std::map<std::tuple<double, double, double>, int> ids;
  auto id = [&ids](const glm::dvec3& p) {
    return ids.emplace(std::make_tuple(p.x, p.y, p.z), static_cast<int>(ids.size())).first->second;
  };
  std::map<std::pair<int, int>, int> edges; // directed edge -> uses
  for (const Triangle& t : triangles)
  {
    for (const glm::dvec3& p : { t.V0, t.V1, t.V2 })
    {
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      {
        return "has a NaN or infinite point";
      }
    }
    const int v[3] = { id(t.V0), id(t.V1), id(t.V2) };
    for (int e = 0; e < 3; ++e)
    {
      ++edges[{ v[e], v[(e + 1) % 3] }];
    }
  }
  // Closed: every edge has two sides. Consistently oriented: each directed edge is matched by
  // as many uses in the opposite direction.
  long border = 0, inconsistent = 0;
  for (const auto& [edge, uses] : edges)
  {
    if (edge.first == edge.second)
    {
      continue; // a degenerate triangle's edge: harmless to the walk
    }
    const auto twin = edges.find({ edge.second, edge.first });
    const int reverse = twin == edges.end() ? 0 : twin->second;
    if (uses + reverse == 1)
    {
      ++border; // counted once: its twin does not exist
    }
    else if (uses != reverse)
    {
      ++inconsistent;
    }
  }
  if (border > 0)
  {
    return "is not closed: " + std::to_string(border) + " border edge" + (border == 1 ? "" : "s");
  }
  if (inconsistent > 0)
  {
    return "is not consistently oriented (" + std::to_string(inconsistent) + " edges)";
  }
  return "";
}

double SignedVolume6(const std::vector<Triangle>& triangles)
{
  double sum = 0.0;
  for (const Triangle& t : triangles)
  {
    sum += glm::dot(t.V0, glm::cross(t.V1, t.V2));
  }
  return sum;
}

void OrientOutward(std::vector<Triangle>& triangles)
{
  if (SignedVolume6(triangles) < 0.0)
  {
    for (Triangle& t : triangles)
    {
      std::swap(t.V1, t.V2);
    }
  }
}

BoundRegion::BoundRegion(std::vector<std::vector<Triangle>> leaves, CSGExpression expression)
  : Expression(std::move(expression))
{
  for (std::vector<Triangle>& leaf : leaves)
  {
    this->Leaves.emplace_back(std::move(leaf));
  }
  this->Truth = this->Expression.TruthTable();
}

size_t BoundRegion::GetTriangleCount() const
{
  size_t count = 0;
  for (const TriangleBVH& leaf : this->Leaves)
  {
    count += leaf.GetTriangles().size();
  }
  return count;
}

BoundRegion::Walker::Walker(const BoundRegion& region, const glm::dvec3& origin, const glm::dvec3& direction)
  : Region(region)
  , Origin(origin)
  , Direction(direction)
  , Next(region.Leaves.size(), -std::numeric_limits<double>::infinity())
{
}

bool BoundRegion::Walker::Inside(double t)
{
  if (t < this->UntilT)
  {
    return this->InsideState; // nothing crossed since the last query
  }
  this->UntilT = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < this->Next.size(); ++i)
  {
    if (this->Next[i] <= t)
    {
      const MeshHit hit = this->Region.Leaves[i].NextHit(this->Origin, this->Direction, t);
      this->Next[i] = hit.Found ? hit.T : std::numeric_limits<double>::infinity();
      const uint32_t bit = 1u << i;
      this->States = hit.Found && !hit.Entering ? (this->States | bit) : (this->States & ~bit);
    }
    this->UntilT = std::min(this->UntilT, this->Next[i]);
  }
  this->InsideState = ((this->Region.Truth[this->States / 32] >> (this->States % 32)) & 1u) != 0;
  return this->InsideState;
}

double BoundRegion::Walker::Until() const
{
  return this->UntilT;
}

long BoundRegion::Walker::SkipSteps(double t, double dt)
{
  if (this->Inside(t))
  {
    return 0;
  }
  const double steps = std::ceil((this->Until() - t) / dt);
  return steps < 1.0 ? 1 : steps >= static_cast<double>(LONG_MAX / 2) ? LONG_MAX / 2 : static_cast<long>(steps);
}

bool BoundRegion::Inside(const glm::dvec3& p) const
{
  Walker walker(*this, p, glm::dvec3(1.0, 0.0, 0.0));
  return walker.Inside(0.0);
}

std::vector<glm::dvec2> BoundRegion::Intervals(
  const glm::dvec3& origin, const glm::dvec3& direction, double t0, double t1) const
{
  std::vector<glm::dvec2> intervals;
  Walker walker(*this, origin, direction);
  double t = t0;
  while (t < t1)
  {
    const bool inside = walker.Inside(t);
    const double until = std::min(walker.Until(), t1);
    if (inside)
    {
      if (!intervals.empty() && intervals.back().y == t)
      {
        intervals.back().y = until; // a leaf's crossing that does not change the region
      }
      else
      {
        intervals.emplace_back(t, until);
      }
    }
    t = until;
  }
  return intervals;
}

BoundRegion::GPUData BoundRegion::PackForGPU() const
{
  GPUData data;
  for (const TriangleBVH& leaf : this->Leaves)
  {
    data.LeafRoots.push_back(leaf.AppendForGPU(data.Nodes, data.Triangles));
    data.MaxDepth = std::max(data.MaxDepth, leaf.GetDepth());
  }
  for (uint32_t word : this->Truth)
  {
    data.TruthTable.push_back(static_cast<int>(word));
  }
  return data;
}

}
