// Internal: which lights get a shadow structure, and when a structure is stale.
#ifndef vtkDeepShadowShadowSlots_h
#define vtkDeepShadowShadowSlots_h

#include "Core/Light.h"

#include <glm/mat4x4.hpp>

#include <vector>

namespace deepshadow
{
struct ShadowContext;

/**
 * Slots of the shadow-casting lights (ShadowAttenuation > 0), at most `maxSlots`, in the
 * ray caster's light order, and per slot the inputs its structure was built from.
 */
class ShadowSlots
{
public:
  /** Assigns slots; returns how many shadow-casting lights did not get one. */
  int Assign(const std::vector<Light>& lights, int maxSlots);
  int Count() const { return static_cast<int>(this->LightOfSlot.size()); }
  int Light(int slot) const { return this->LightOfSlot[slot]; }
  /** Per ray-caster light: its slot, or -1. */
  std::vector<int> SlotOfEachLight(int lightCount) const;

  /**
   * True if slot `slot` must be rebuilt: its light (position, focal point, kind; not its
   * intensity or shadow attenuation, which apply at lookup), the shared inputs (data,
   * transform, sampling, sample distance) or `parameters` (the technique's, with the casting
   * transfer function's content) differ from its last build. Remembers them. On interactive
   * frames (context.LightLagDegrees > 0) a structure whose light turned less than that about
   * the volume's centre since its build is kept.
   */
  bool Stale(int slot, const ShadowContext& context, const std::vector<double>& parameters);
  /** Whether Stale() would say so now, remembering nothing. */
  bool WouldRebuild(int slot, const ShadowContext& context, const std::vector<double>& parameters) const;
  /** Forget all builds (the storage was reallocated). */
  void Invalidate() { this->Built.clear(); }

private:
  struct BuildKey
  {
    std::vector<double> Shared; // everything but the light's placement; empty: never built
    glm::dvec3 Position{ 0.0 };
    glm::dvec3 FocalPoint{ 0.0 };
  };
  /** What slot `slot`'s structure depends on now; `keeps`: whether its last build still serves. */
  BuildKey Current(int slot, const ShadowContext& context, const std::vector<double>& parameters, bool& keeps) const;
  std::vector<int> LightOfSlot;
  std::vector<BuildKey> Built;
};

}
#endif
