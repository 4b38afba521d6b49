#include "ShadowSlots.h"

#include "Sampling/ShadowContext.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <utility>

namespace deepshadow
{

int ShadowSlots::Assign(const std::vector<deepshadow::Light>& lights, int maxSlots)
{
  this->LightOfSlot.clear();
  int dropped = 0;
  for (size_t l = 0; l < lights.size(); ++l)
  {
    if (lights[l].ShadowAttenuation <= 0.0)
    {
      continue;
    }
    if (static_cast<int>(this->LightOfSlot.size()) < maxSlots)
    {
      this->LightOfSlot.push_back(static_cast<int>(l));
    }
    else
    {
      ++dropped;
    }
  }
  return dropped;
}

std::vector<int> ShadowSlots::SlotOfEachLight(int lightCount) const
{
  std::vector<int> slots(static_cast<size_t>(lightCount), -1);
  for (int s = 0; s < this->Count(); ++s)
  {
    slots[static_cast<size_t>(this->LightOfSlot[s])] = s;
  }
  return slots;
}

namespace
{
// Where light `light` shines from, seen from `centre`: its direction, or a positional light's
// offset.
glm::dvec3 LightFrom(bool positional, const glm::dvec3& position, const glm::dvec3& focalPoint,
  const glm::dvec3& centre)
{
  return positional ? position - centre : position - focalPoint;
}

// Whether `now` is within `degrees` of `built` (and, for a positional light, its distance
// within as much: tan(degrees) of the built one).
bool Within(const glm::dvec3& built, const glm::dvec3& now, bool positional, double degrees)
{
  const double a = glm::length(built), b = glm::length(now);
  if (a <= 0.0 || b <= 0.0)
  {
    return false;
  }
  const double radians = degrees * 3.14159265358979323846 / 180.0;
  const bool turned = glm::dot(built, now) / (a * b) < std::cos(radians);
  return !turned && (!positional || std::abs(b - a) <= std::tan(radians) * a);
}
}

ShadowSlots::BuildKey ShadowSlots::Current(
  int slot, const ShadowContext& context, const std::vector<double>& parameters, bool& keeps) const
{
  const deepshadow::Light& light = context.Lights[static_cast<size_t>(this->LightOfSlot[slot])];
  std::vector<double> shared = parameters;
  shared.insert(shared.end(), { static_cast<double>(context.DataVersion),
    static_cast<double>(context.BoundVersion), static_cast<double>(context.SurfacesVersion), context.ShadowStep,
    static_cast<double>(context.Sampling == Interpolation::Nearest), light.Positional ? 1.0 : 0.0 });
  for (int column = 0; column < 4; ++column)
  {
    for (int row = 0; row < 4; ++row)
    {
      shared.push_back(context.IndexToWorld[column][row]);
    }
  }
  const glm::dvec3 centre = glm::dvec3(context.IndexToWorld * glm::dvec4(0.5 * glm::dvec3(context.Dims - 1), 1.0));
  keeps = false;
  if (slot < static_cast<int>(this->Built.size()))
  {
    const BuildKey& built = this->Built[static_cast<size_t>(slot)];
    const bool sameLight = built.Position == light.Position && built.FocalPoint == light.FocalPoint;
    // (The same Shared holds the kind and the transform, so the centre is the build's.) A
    // structure whose light moved lags it, and the next frame without a lag (a still frame)
    // finds its light moved and rebuilds it.
    keeps = !built.Shared.empty() && built.Shared == shared &&
      (sameLight ||
        (context.LightLagDegrees > 0.0 &&
          Within(LightFrom(light.Positional, built.Position, built.FocalPoint, centre),
            LightFrom(light.Positional, light.Position, light.FocalPoint, centre), light.Positional,
            context.LightLagDegrees)));
  }
  return BuildKey{ shared, light.Position, light.FocalPoint };
}

bool ShadowSlots::WouldRebuild(int slot, const ShadowContext& context, const std::vector<double>& parameters) const
{
  bool keeps = false;
  this->Current(slot, context, parameters, keeps);
  return !keeps;
}

bool ShadowSlots::Stale(int slot, const ShadowContext& context, const std::vector<double>& parameters)
{
  bool keeps = false;
  BuildKey now = this->Current(slot, context, parameters, keeps);
  if (keeps)
  {
    return false;
  }
  if (static_cast<int>(this->Built.size()) <= slot)
  {
    this->Built.resize(static_cast<size_t>(slot) + 1);
  }
  this->Built[static_cast<size_t>(slot)] = std::move(now);
  return true;
}

}
