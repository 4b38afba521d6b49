#include "Core/VolumeGrid.h"

#include <glm/common.hpp>
#include <glm/mat4x4.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace deepshadow
{

NonFiniteCount CountNonFinite(const float* values, size_t count)
{
  NonFiniteCount result;
  for (size_t i = 0; i < count; ++i)
  {
    const float v = values[i];
    if (std::isnan(v))
    {
      ++result.NaN;
    }
    else if (std::isinf(v))
    {
      ++(v > 0 ? result.PositiveInfinity : result.NegativeInfinity);
    }
  }
  return result;
}

void ReplaceNonFinite(float* values, size_t count)
{
  float lo = std::numeric_limits<float>::max();
  float hi = std::numeric_limits<float>::lowest();
  for (size_t i = 0; i < count; ++i)
  {
    if (std::isfinite(values[i]))
    {
      lo = std::min(lo, values[i]);
      hi = std::max(hi, values[i]);
    }
  }
  if (lo > hi)
  {
    lo = hi = 0.0f;
  }
  for (size_t i = 0; i < count; ++i)
  {
    float& v = values[i];
    if (std::isnan(v))
    {
      v = lo;
    }
    else if (std::isinf(v))
    {
      v = v > 0 ? hi : lo;
    }
  }
}

double DefaultSampleDistance(const glm::dmat4& indexToWorld)
{
  double shortest = std::numeric_limits<double>::max();
  for (int axis = 0; axis < 3; ++axis)
  {
    shortest = std::min(shortest, glm::length(glm::dvec3(indexToWorld[axis])));
  }
  return 0.5 * shortest;
}

double LongestPath(const glm::dmat4& indexToWorld, const glm::ivec3& dims)
{
  const glm::dvec3 extent = glm::dvec3(glm::max(dims - 1, glm::ivec3(0)));
  double longest = 0.0;
  for (int c = 0; c < 4; ++c)
  {
    // The four diagonals of the (possibly sheared) box.
    const glm::dvec3 from((c & 1) * extent.x, ((c >> 1) & 1) * extent.y, 0.0);
    const glm::dvec3 to(extent.x - from.x, extent.y - from.y, extent.z);
    longest = std::max(longest, glm::length(glm::dvec3(indexToWorld * glm::dvec4(to - from, 0.0))));
  }
  return longest;
}

double LongestPathAlong(const glm::dmat4& indexToWorld, const glm::ivec3& dims, const glm::dvec3& direction)
{
  // In index space the box is axis-aligned: a chord spans at most its extent along each axis,
  // and one through a corner does.
  const glm::dvec3 perUnit = glm::abs(glm::dvec3(glm::inverse(indexToWorld) * glm::dvec4(direction, 0.0)));
  double longest = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < 3; ++axis)
  {
    if (perUnit[axis] > 0.0)
    {
      longest = std::min(longest, std::max(dims[axis] - 1, 0) / perUnit[axis]);
    }
  }
  return std::isfinite(longest) ? longest : 0.0;
}

std::string CheckRaySamples(double longest, double step, const std::string& what, double iterationsPerSample)
{
  const double budget = std::floor(MaxRayIterations / std::max(iterationsPerSample, 1.0));
  const double samples = std::ceil(longest / step);
  if (step > 0.0 && samples <= budget)
  {
    return std::string();
  }
  std::ostringstream message;
  message << what << " " << step << " takes up to " << samples << " samples across the volume ("
          << longest << " long), more than the " << budget << " a ray may take";
  if (iterationsPerSample > 1.0)
  {
    message << " with " << iterationsPerSample << " loop iterations a sample (" << MaxRayIterations
            << " in all)";
  }
  message << "; use at least " << longest / budget;
  return message.str();
}

VolumeGrid::VolumeGrid(
  const glm::ivec3& dims, std::vector<float> scalars, const glm::dmat4& indexToWorld)
  : Dims(dims)
  , Scalars(std::move(scalars))
  , IndexToWorld(indexToWorld)
  , WorldToIndex(glm::inverse(indexToWorld))
{
  double lo = std::numeric_limits<double>::max();
  double hi = std::numeric_limits<double>::lowest();
  for (float v : this->Scalars)
  {
    if (std::isfinite(v))
    {
      lo = std::min(lo, static_cast<double>(v));
      hi = std::max(hi, static_cast<double>(v));
    }
  }
  this->Range = lo <= hi ? glm::dvec2(lo, hi) : glm::dvec2(0.0, 0.0);
}

double VolumeGrid::Sample(const glm::dvec3& index, Interpolation interpolation) const
{
  const glm::dvec3 maxIndex = glm::dvec3(this->Dims - 1);
  const glm::dvec3 p = glm::clamp(index, glm::dvec3(0.0), maxIndex);
  if (interpolation == Interpolation::Nearest)
  {
    // GL_NEAREST picks floor(texcoord * dims) = floor(index + 0.5).
    const glm::ivec3 n = glm::min(glm::ivec3(glm::floor(p + 0.5)), this->Dims - 1);
    return this->At(n.x, n.y, n.z);
  }
  const glm::ivec3 i0 = glm::min(glm::ivec3(glm::floor(p)), glm::max(this->Dims - 2, 0));
  const glm::ivec3 i1 = glm::min(i0 + 1, this->Dims - 1);
  const glm::dvec3 t = p - glm::dvec3(i0);
  const double c000 = this->At(i0.x, i0.y, i0.z), c100 = this->At(i1.x, i0.y, i0.z);
  const double c010 = this->At(i0.x, i1.y, i0.z), c110 = this->At(i1.x, i1.y, i0.z);
  const double c001 = this->At(i0.x, i0.y, i1.z), c101 = this->At(i1.x, i0.y, i1.z);
  const double c011 = this->At(i0.x, i1.y, i1.z), c111 = this->At(i1.x, i1.y, i1.z);
  const double c00 = c000 + t.x * (c100 - c000), c10 = c010 + t.x * (c110 - c010);
  const double c01 = c001 + t.x * (c101 - c001), c11 = c011 + t.x * (c111 - c011);
  const double c0 = c00 + t.y * (c10 - c00), c1 = c01 + t.y * (c11 - c01);
  return c0 + t.z * (c1 - c0);
}

glm::dvec3 VolumeGrid::IndexGradient(const glm::dvec3& index, Interpolation interpolation) const
{
  glm::dvec3 gradient;
  for (int axis = 0; axis < 3; ++axis)
  {
    glm::dvec3 offset(0.0);
    offset[axis] = this->GradientReach;
    gradient[axis] =
      0.5 * (this->Sample(index + offset, interpolation) - this->Sample(index - offset, interpolation));
  }
  return gradient;
}

glm::dvec3 VolumeGrid::WorldGradient(const glm::dvec3& index, Interpolation interpolation) const
{
  return glm::transpose(glm::dmat3(this->WorldToIndex)) * this->IndexGradient(index, interpolation);
}

bool VolumeGrid::ContainsIndex(const glm::dvec3& index) const
{
  const glm::dvec3 maxIndex = glm::dvec3(this->Dims - 1);
  return index.x >= 0.0 && index.y >= 0.0 && index.z >= 0.0 && index.x <= maxIndex.x &&
    index.y <= maxIndex.y && index.z <= maxIndex.z;
}

}
