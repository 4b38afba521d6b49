#include "ShadowSlots.h"

#include "Sampling/ShadowContext.h"

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

bool ShadowSlots::Stale(
  int slot, const ShadowContext& context, const std::vector<double>& parameters)
{
  const deepshadow::Light& light = context.Lights[static_cast<size_t>(this->LightOfSlot[slot])];
  std::vector<double> key = parameters;
  key.insert(key.end(), { static_cast<double>(context.DataVersion),
    static_cast<double>(context.BoundVersion), static_cast<double>(context.SurfacesVersion), context.ShadowStep,
    static_cast<double>(context.Sampling == Interpolation::Nearest), light.Positional ? 1.0 : 0.0 });
  for (int c = 0; c < 3; ++c)
  {
    key.insert(key.end(), { light.Position[c], light.FocalPoint[c] });
  }
  for (int column = 0; column < 4; ++column)
  {
    for (int row = 0; row < 4; ++row)
    {
      key.push_back(context.IndexToWorld[column][row]);
    }
  }
  if (static_cast<int>(this->Keys.size()) <= slot)
  {
    this->Keys.resize(static_cast<size_t>(slot) + 1);
  }
  if (this->Keys[static_cast<size_t>(slot)] == key)
  {
    return false;
  }
  this->Keys[static_cast<size_t>(slot)] = key;
  return true;
}

}
