#include "Core/Shadows/ShadowGrid.h"

#include "Core/Parallel.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace deepshadow
{

GridFrame GridFrame::OverVolume(const glm::ivec3& dataDims, const glm::dmat4& indexToWorld, int size)
{
  GridFrame frame;
  frame.Dims = ShadowVolumeDims(dataDims, size);
  // A flat axis has no extent: one voxel per node spacing there (node 0 stays on the slab).
  const glm::dvec3 nodeToIndex =
    glm::max(glm::dvec3(dataDims - 1), glm::dvec3(1.0)) / glm::dvec3(frame.Dims - 1);
  frame.NodeToWorld = indexToWorld * glm::scale(glm::dmat4(1.0), nodeToIndex);
  frame.WorldToNode = glm::inverse(frame.NodeToWorld);
  return frame;
}

GridFrame GridFrame::OverBox(const glm::dvec3& lo, const glm::dvec3& hi, int size)
{
  GridFrame frame;
  if (!std::isfinite(glm::dot(lo, hi)) || glm::any(glm::greaterThan(lo, hi)))
  {
    return OverBox(glm::dvec3(0.0), glm::dvec3(0.0), size); // no points: a tiny box at the origin
  }
  glm::dvec3 extent = hi - lo;
  const double longest = std::max({ extent.x, extent.y, extent.z });
  const double least = std::max(1e-3 * longest, 1e-9);
  glm::dvec3 origin = lo;
  for (int axis = 0; axis < 3; ++axis)
  {
    if (extent[axis] < least)
    {
      origin[axis] -= 0.5 * (least - extent[axis]);
      extent[axis] = least;
    }
    frame.Dims[axis] = std::max(2,
      static_cast<int>(std::lround(std::max(size, 2) * extent[axis] / std::max(longest, least))));
  }
  frame.NodeToWorld = glm::scale(glm::translate(glm::dmat4(1.0), origin),
    extent / glm::dvec3(frame.Dims - 1));
  frame.WorldToNode = glm::inverse(frame.NodeToWorld);
  return frame;
}

ShadowGrid::ShadowGrid(const Function& visibility, const GridFrame& frame, bool colored, int threads)
  : Frame(frame)
  , Colored(colored)
  , Values(3 * static_cast<size_t>(frame.Dims.x) * frame.Dims.y * frame.Dims.z)
{
  ParallelFor(
    this->Frame.Dims.z,
    [&](int k) {
      for (int j = 0; j < this->Frame.Dims.y; ++j)
      {
        for (int i = 0; i < this->Frame.Dims.x; ++i)
        {
          const glm::dvec3 world = glm::dvec3(this->Frame.NodeToWorld * glm::dvec4(i, j, k, 1.0));
          const glm::dvec3 v = visibility(world);
          const size_t n = 3 * this->Node(i, j, k);
          this->Values[n] = static_cast<float>(v.r);
          this->Values[n + 1] = static_cast<float>(v.g);
          this->Values[n + 2] = static_cast<float>(v.b);
        }
      }
    },
    threads);
}

size_t ShadowGrid::Node(int i, int j, int k) const
{
  return i + static_cast<size_t>(this->Frame.Dims.x) * (j + static_cast<size_t>(this->Frame.Dims.y) * k);
}

glm::dvec3 ShadowGrid::Visibility(const glm::dvec3& p) const
{
  const glm::ivec3 dims = this->Frame.Dims;
  const glm::dvec3 raw = glm::dvec3(this->Frame.WorldToNode * glm::dvec4(p, 1.0));
  if (!(raw == raw)) // a NaN position: nothing is known to shadow it
  {
    return glm::dvec3(1.0);
  }
  const glm::dvec3 node = glm::clamp(raw, glm::dvec3(0.0), glm::dvec3(dims - 1));
  const glm::ivec3 n0 = glm::min(glm::ivec3(glm::floor(node)), dims - 2);
  const glm::dvec3 t = node - glm::dvec3(n0);
  glm::dvec3 result(0.0);
  for (int c = 0; c < 8; ++c)
  {
    const glm::ivec3 o((c & 1), (c >> 1) & 1, (c >> 2) & 1);
    const double w = (o.x ? t.x : 1.0 - t.x) * (o.y ? t.y : 1.0 - t.y) * (o.z ? t.z : 1.0 - t.z);
    const size_t n = 3 * this->Node(n0.x + o.x, n0.y + o.y, n0.z + o.z);
    result += w * glm::dvec3(this->Values[n], this->Values[n + 1], this->Values[n + 2]);
  }
  return result;
}

size_t ShadowGrid::Bytes() const
{
  return this->Values.size() / 3 * (this->Colored ? 8 : 2);
}

glm::dvec3 ProductShadow::Visibility(const glm::dvec3& p) const
{
  glm::dvec3 product(1.0);
  for (const LightShadow* factor : this->Factors)
  {
    product *= factor->Visibility(p);
  }
  return product;
}

}
