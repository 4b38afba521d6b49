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

// Positive where `light` lies below the plane x[axis] = plane (its rays cross it upwards),
// negative above, 0 where no ray crosses it: a directional light's rays come from the side
// they travel away from; a positional light sits on one side.
double LightBelowPlane(const Light& light, int axis, double plane)
{
  return light.Positional ? plane - light.Position[axis] : light.FocalPoint[axis] - light.Position[axis];
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
  const double lightBelow = LightBelowPlane(light, axis, plane);
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

namespace
{
// Appends `bricks` to `order` as the light's rays cross them: splits them by an axis-aligned
// plane that no brick straddles (a kd partition, as ParaView's ordered compositing cuts a
// volume, always has one) and puts the light's side first, recursively. A ray that crosses
// two bricks crosses the plane that first separates them once, from the light's side. False
// if some set of bricks has no such plane.
bool AppendInLightOrder(const std::vector<BrickBox>& boxes, const std::vector<int>& bricks, const Light& light,
  double tolerance, std::vector<int>& order)
{
  if (bricks.size() <= 1)
  {
    order.insert(order.end(), bricks.begin(), bricks.end());
    return true;
  }
  for (int axis = 0; axis < 3; ++axis)
  {
    for (int candidate : bricks)
    {
      const double plane = boxes[static_cast<size_t>(candidate)].Max[axis];
      std::vector<int> low, high;
      for (int b : bricks)
      {
        const BrickBox& box = boxes[static_cast<size_t>(b)];
        if (box.Max[axis] <= plane + tolerance)
        {
          low.push_back(b);
        }
        else if (box.Min[axis] >= plane - tolerance)
        {
          high.push_back(b);
        }
      }
      if (low.empty() || high.empty() || low.size() + high.size() != bricks.size())
      {
        continue;
      }
      // Rays parallel to the plane, or from a light on it, cross no brick of both sides: a
      // prefix product would still multiply one side's totals into the other's texels that
      // straddle the plane, which the gather leaves out (UpstreamTransmittance): no order.
      const double lightBelow = LightBelowPlane(light, axis, plane);
      if (lightBelow == 0.0)
      {
        return false;
      }
      const bool lowFirst = lightBelow > 0.0;
      return AppendInLightOrder(boxes, lowFirst ? low : high, light, tolerance, order) &&
        AppendInLightOrder(boxes, lowFirst ? high : low, light, tolerance, order);
    }
  }
  return false;
}
}

std::vector<int> LightOrder(const std::vector<BrickBox>& boxes, const Light& light, double tolerance)
{
  std::vector<int> valid, invalid;
  for (int b = 0; b < static_cast<int>(boxes.size()); ++b)
  {
    (boxes[static_cast<size_t>(b)].IsValid() ? valid : invalid).push_back(b);
  }
  std::vector<int> order;
  if (!AppendInLightOrder(boxes, valid, light, tolerance, order))
  {
    return {};
  }
  // Empty bricks last: nothing of theirs lies in front of anything.
  order.insert(order.end(), invalid.begin(), invalid.end());
  return order;
}

int ScanRounds(int bricks)
{
  int rounds = 0;
  while ((1 << rounds) < bricks)
  {
    ++rounds;
  }
  return rounds;
}

bool ExclusiveProductScan(const std::vector<int>& order, int self, const std::vector<float>& local, int tag,
  const ScanMessage& message, std::vector<float>& upstream)
{
  const auto found = std::find(order.begin(), order.end(), self);
  if (found == order.end())
  {
    return false;
  }
  const int position = static_cast<int>(found - order.begin());
  const int bricks = static_cast<int>(order.size());
  std::vector<float> inclusive = local;
  upstream.assign(local.size(), 1.0f);
  std::vector<float> received(local.size());
  for (int round = 0, stride = 1; stride < bricks; ++round, stride *= 2)
  {
    const int to = position + stride < bricks ? order[static_cast<size_t>(position + stride)] : -1;
    const int from = position >= stride ? order[static_cast<size_t>(position - stride)] : -1;
    // Blocks of `stride` positions alternate: one sends first, the next receives first, so
    // every send meets a receive that is already waiting.
    const bool sendFirst = (position / stride) % 2 == 0;
    if (!message(to, inclusive, from, received, sendFirst, tag + round))
    {
      return false;
    }
    if (from >= 0)
    {
      for (size_t i = 0; i < local.size(); ++i)
      {
        upstream[i] *= received[i];
        inclusive[i] *= received[i];
      }
    }
  }
  return true;
}

}
