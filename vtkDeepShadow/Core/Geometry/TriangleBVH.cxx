#include "Core/Geometry/TriangleBVH.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace deepshadow
{

bool IntersectTriangle(const glm::dvec3& origin, const glm::dvec3& direction,
  const Triangle& triangle, double& t, bool& entering)
{
  const glm::dvec3 e1 = triangle.V1 - triangle.V0;
  const glm::dvec3 e2 = triangle.V2 - triangle.V0;
  const glm::dvec3 p = glm::cross(direction, e2);
  const double det = glm::dot(e1, p);
  if (det == 0.0 || !std::isfinite(det))
  {
    return false;
  }
  const double inverse = 1.0 / det;
  const glm::dvec3 s = origin - triangle.V0;
  const double u = glm::dot(s, p) * inverse;
  if (u < 0.0 || u > 1.0)
  {
    return false;
  }
  const glm::dvec3 q = glm::cross(s, e1);
  const double v = glm::dot(direction, q) * inverse;
  if (v < 0.0 || u + v > 1.0)
  {
    return false;
  }
  t = glm::dot(e2, q) * inverse;
  // det = -direction . (e1 x e2): positive when the ray meets the outward normal head-on.
  entering = det > 0.0;
  return true;
}

TriangleBVH::TriangleBVH(std::vector<Triangle> triangles)
  : Triangles(std::move(triangles))
{
  if (this->Triangles.empty())
  {
    return;
  }
  this->Nodes.reserve(2 * this->Triangles.size() / LeafSize + 2);
  this->Nodes.emplace_back();
  this->Build(0, 0, static_cast<int>(this->Triangles.size()), 1);
}

int TriangleBVH::Build(int node, int first, int count, int depth)
{
  this->Depth = std::max(this->Depth, depth);
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  glm::dvec3 centreLo = lo, centreHi = hi;
  for (int i = first; i < first + count; ++i)
  {
    const Triangle& tri = this->Triangles[static_cast<size_t>(i)];
    lo = glm::min(lo, glm::min(tri.V0, glm::min(tri.V1, tri.V2)));
    hi = glm::max(hi, glm::max(tri.V0, glm::max(tri.V1, tri.V2)));
    const glm::dvec3 centre = (tri.V0 + tri.V1 + tri.V2) / 3.0;
    centreLo = glm::min(centreLo, centre);
    centreHi = glm::max(centreHi, centre);
  }
  this->Nodes[static_cast<size_t>(node)].Min = lo;
  this->Nodes[static_cast<size_t>(node)].Max = hi;
  const glm::dvec3 extent = centreHi - centreLo;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
  if (count <= LeafSize || extent[axis] <= 0.0)
  {
    this->Nodes[static_cast<size_t>(node)].First = first;
    this->Nodes[static_cast<size_t>(node)].Count = count;
    return node;
  }
  const int half = count / 2;
  auto begin = this->Triangles.begin() + first;
  std::nth_element(begin, begin + half, begin + count, [axis](const Triangle& a, const Triangle& b) {
    return a.V0[axis] + a.V1[axis] + a.V2[axis] < b.V0[axis] + b.V1[axis] + b.V2[axis];
  });
  const int left = static_cast<int>(this->Nodes.size());
  this->Nodes.emplace_back();
  this->Nodes.emplace_back();
  this->Nodes[static_cast<size_t>(node)].First = left;
  this->Nodes[static_cast<size_t>(node)].Count = 0;
  this->Build(left, first, half, depth + 1);
  this->Build(left + 1, first + half, count - half, depth + 1);
  return node;
}

namespace
{
// The parametric interval of the ray inside a node's box, or an empty one.
bool BoxRange(const glm::dvec3& origin, const glm::dvec3& inverse, const TriangleBVH::Node& node,
  double& tNear, double& tFar)
{
  tNear = -std::numeric_limits<double>::infinity();
  tFar = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a)
  {
    if (std::isinf(inverse[a]))
    {
      if (origin[a] < node.Min[a] || origin[a] > node.Max[a])
      {
        return false;
      }
      continue;
    }
    double t0 = (node.Min[a] - origin[a]) * inverse[a];
    double t1 = (node.Max[a] - origin[a]) * inverse[a];
    if (t0 > t1)
    {
      std::swap(t0, t1);
    }
    tNear = std::max(tNear, t0);
    tFar = std::min(tFar, t1);
  }
  return tNear <= tFar;
}
}

MeshHit TriangleBVH::NextHit(const glm::dvec3& origin, const glm::dvec3& direction, double tAfter) const
{
  MeshHit best;
  best.T = std::numeric_limits<double>::infinity();
  if (this->Nodes.empty())
  {
    return best;
  }
  const glm::dvec3 inverse = 1.0 / direction;
  int stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0)
  {
    const Node& node = this->Nodes[static_cast<size_t>(stack[--top])];
    double tNear = 0.0, tFar = 0.0;
    if (!BoxRange(origin, inverse, node, tNear, tFar) || tFar <= tAfter || tNear >= best.T)
    {
      continue;
    }
    if (node.Count > 0)
    {
      for (int i = node.First; i < node.First + node.Count; ++i)
      {
        double t = 0.0;
        bool entering = false;
        if (IntersectTriangle(origin, direction, this->Triangles[static_cast<size_t>(i)], t, entering) &&
          t > tAfter && t < best.T)
        {
          best.T = t;
          best.Entering = entering;
          best.Found = true;
          best.Triangle = i;
        }
      }
      continue;
    }
    stack[top++] = node.First + 1;
    stack[top++] = node.First;
  }
  return best;
}

int TriangleBVH::AppendForGPU(std::vector<glm::vec4>& nodes, std::vector<glm::vec4>& triangles) const
{
  if (this->Empty())
  {
    return -1;
  }
  // Boxes rounded outward, so that float never culls a crossing double finds.
  auto down = [](double v) {
    const float f = static_cast<float>(v);
    return static_cast<double>(f) > v ? std::nextafter(f, -INFINITY) : f;
  };
  auto up = [](double v) {
    const float f = static_cast<float>(v);
    return static_cast<double>(f) < v ? std::nextafter(f, INFINITY) : f;
  };
  const int nodeBase = static_cast<int>(nodes.size() / 2);
  const int triangleBase = static_cast<int>(triangles.size() / 3);
  for (const Node& node : this->Nodes)
  {
    const bool isLeaf = node.Count > 0;
    const int first = node.First + (isLeaf ? triangleBase : nodeBase);
    nodes.emplace_back(down(node.Min.x), down(node.Min.y), down(node.Min.z), static_cast<float>(first));
    nodes.emplace_back(up(node.Max.x), up(node.Max.y), up(node.Max.z), static_cast<float>(node.Count));
  }
  for (const Triangle& t : this->Triangles)
  {
    triangles.emplace_back(glm::vec3(t.V0), static_cast<float>(t.Tag));
    triangles.emplace_back(glm::vec3(t.V1), 0.0f);
    triangles.emplace_back(glm::vec3(t.V2), 0.0f);
  }
  return nodeBase;
}

}
