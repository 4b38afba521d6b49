#include "Core/GradientOpacity.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace deepshadow
{

GradientOpacity GradientOpacity::For(
  const PiecewiseLinear& function, const glm::dvec2& range, const glm::dvec3& spacing)
{
  GradientOpacity gradient;
  gradient.Function = function;
  gradient.MaxMagnitude = range.y > range.x ? 0.25 * (range.y - range.x) : 1.0;
  const glm::dvec3 magnitude = glm::abs(spacing);
  const double mean = (magnitude.x + magnitude.y + magnitude.z) / 3.0;
  for (int axis = 0; axis < 3; ++axis)
  {
    gradient.IndexScale[axis] = magnitude[axis] > 0.0 ? mean / magnitude[axis] : 1.0;
  }
  return gradient;
}

double GradientOpacity::Magnitude(const VolumeGrid& grid, const glm::dvec3& index, Interpolation sampling) const
{
  const double magnitude = glm::length(grid.IndexGradient(index, sampling) * this->IndexScale);
  return std::clamp(magnitude, 0.0, this->MaxMagnitude);
}

}
