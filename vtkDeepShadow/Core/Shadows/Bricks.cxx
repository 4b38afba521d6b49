#include "Core/Shadows/Bricks.h"

#include <glm/common.hpp>

#include <algorithm>

namespace deepshadow
{

BrickBox BrickBox::Union(const BrickBox& other) const
{
  if (!other.IsValid())
  {
    return *this;
  }
  if (!this->IsValid())
  {
    return other;
  }
  return BrickBox{ glm::min(this->Min, other.Min), glm::max(this->Max, other.Max) };
}

namespace
{
// An axis-aligned plane x[axis] = plane between a and b (within `tolerance`); -1 if none.
int SeparatingAxis(const BrickBox& a, const BrickBox& b, double tolerance, double& plane, bool& aLow)
{
  for (int axis = 0; axis < 3; ++axis)
  {
    if (a.Max[axis] <= b.Min[axis] + tolerance)
    {
      plane = 0.5 * (a.Max[axis] + b.Min[axis]);
      aLow = true;
      return axis;
    }
    if (b.Max[axis] <= a.Min[axis] + tolerance)
    {
      plane = 0.5 * (b.Max[axis] + a.Min[axis]);
      aLow = false;
      return axis;
    }
  }
  return -1;
}
}

bool BricksOverlap(const BrickBox& a, const BrickBox& b, double tolerance)
{
  double plane = 0.0;
  bool aLow = false;
  return a.IsValid() && b.IsValid() && SeparatingAxis(a, b, tolerance, plane, aLow) < 0;
}

BrickOrder OrderTowardLight(const BrickBox& a, const BrickBox& b, const Light& light, double tolerance)
{
  double plane = 0.0;
  bool aLow = false;
  const int axis = a.IsValid() && b.IsValid() ? SeparatingAxis(a, b, tolerance, plane, aLow) : -1;
  if (axis < 0)
  {
    return BrickOrder::Unordered;
  }
  // How far the light is below the plane: a directional light's rays come from the side
  // they travel away from; a positional light sits on one side.
  const double lightBelow = light.Positional ? plane - light.Position[axis]
                                             : light.FocalPoint[axis] - light.Position[axis];
  if (lightBelow == 0.0)
  {
    // Rays parallel to the plane (or from a light on it) stay on one side of it: none
    // crosses both bricks.
    return BrickOrder::Unordered;
  }
  return (lightBelow > 0.0) == aLow ? BrickOrder::First : BrickOrder::Last;
}

std::vector<float> UpstreamTransmittance(const std::vector<float>& totals, size_t perBrick, int self,
  const std::vector<BrickBox>& boxes, const Light& light, double tolerance, bool& overlapping)
{
  overlapping = false;
  std::vector<float> upstream(perBrick, 1.0f);
  const int bricks = static_cast<int>(std::min(boxes.size(), perBrick ? totals.size() / perBrick : 0));
  if (self < 0 || self >= bricks)
  {
    return upstream;
  }
  for (int other = 0; other < bricks; ++other)
  {
    if (other == self)
    {
      continue;
    }
    if (BricksOverlap(boxes[other], boxes[self], tolerance))
    {
      overlapping = true; // no order: said by the caller, left out here
      continue;
    }
    if (OrderTowardLight(boxes[other], boxes[self], light, tolerance) != BrickOrder::First)
    {
      continue;
    }
    const float* theirs = totals.data() + static_cast<size_t>(other) * perBrick;
    for (size_t i = 0; i < perBrick; ++i)
    {
      upstream[i] *= theirs[i];
    }
  }
  return upstream;
}

}
