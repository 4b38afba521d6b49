// Light-space shadows of a volume split into bricks (one per MPI rank under ParaView): every
// brick builds its maps in the same faces (fitted to the union of the bricks), and a brick's
// lookups are multiplied by the total transmittance, texel by texel, of the bricks that lie
// between it and the light. This file is the CPU side of that product: which bricks come
// first, and the product itself. Shaders/Shadows/LightSpace.glsl (LIGHT_SPACE_UPSTREAM)
// multiplies it into every lookup; vtkDeepShadowBrickExchange moves the totals.
//
// Why the order of two bricks is the order of their boxes: bricks do not overlap (they may
// share a face), so some axis-aligned plane separates them. A ray that passes through both
// crosses that plane once, from the side the light is on; a ray that does not pass through
// both never reads the other brick's totals as anything but 1 (its ray misses that brick).
#ifndef deepshadow_Bricks_h
#define deepshadow_Bricks_h

#include "Core/Light.h"
#include "vtkDeepShadowCoreModule.h"

#include <glm/vec3.hpp>

#include <functional>
#include <vector>

namespace deepshadow
{

/** A brick's world box (Min > Max on some axis: no brick, e.g. an empty rank). */
struct VTKDEEPSHADOWCORE_EXPORT BrickBox
{
  glm::dvec3 Min{ 1.0 };
  glm::dvec3 Max{ -1.0 };

  bool IsValid() const { return this->Min.x <= this->Max.x && this->Min.y <= this->Max.y && this->Min.z <= this->Max.z; }
  /** The smallest box holding both (an invalid box holds nothing). */
  BrickBox Union(const BrickBox& other) const;
};

enum class BrickOrder
{
  First,     // a lies between the light and b: rays through both cross a first
  Last,      // b lies between the light and a
  Unordered  // no ray of this light passes through both, or the boxes overlap
};

/** Whether a and b overlap by more than `tolerance` (no plane separates them). */
VTKDEEPSHADOWCORE_EXPORT bool BricksOverlap(const BrickBox& a, const BrickBox& b, double tolerance);

/**
 * The order in which `light`'s rays cross bricks a and b. Boxes that share a face are
 * separated by it; boxes that overlap by more than `tolerance` (world units) have no order.
 */
VTKDEEPSHADOWCORE_EXPORT BrickOrder OrderTowardLight(
  const BrickBox& a, const BrickBox& b, const Light& light, double tolerance);

/**
 * The transmittance of the bricks in front of brick `self` for one light: `totals` holds
 * every brick's total transmittance for that light, `perBrick` values each (texels times
 * channels, the same layout for all), bricks in order. Returns perBrick values, 1 where no
 * brick is in front. `overlapping` is set when some brick overlaps `self` (it is left out).
 */
VTKDEEPSHADOWCORE_EXPORT std::vector<float> UpstreamTransmittance(const std::vector<float>& totals,
  size_t perBrick, int self, const std::vector<BrickBox>& boxes, const Light& light,
  double tolerance, bool& overlapping);

/**
 * The bricks in the order `light`'s rays cross them, nearest the light first: every ray that
 * crosses two bricks crosses the earlier one first. Found as the kd tree the boxes form (an
 * axis plane that no box straddles splits them, recursively; a kd partition always has one,
 * whereas choosing any separating plane per pair, as OrderTowardLight does, can make cycles
 * between bricks no ray crosses together). Empty when no such tree exists (overlapping
 * bricks, a pinwheel) or a plane of it is parallel to the light's rays (a light along an
 * axis): the bricks then gather instead. Invalid boxes (empty ranks) come last.
 */
VTKDEEPSHADOWCORE_EXPORT std::vector<int> LightOrder(
  const std::vector<BrickBox>& boxes, const Light& light, double tolerance);

/**
 * One step of a scan between bricks: send `send` to brick `to` and receive `received.size()`
 * values from brick `from` (-1: none), sending first when `sendFirst` (the scan alternates it
 * so that blocking sends and receives pair up without waiting along a chain); `tag` tells a
 * frame's messages apart. False if a message failed.
 */
using ScanMessage = std::function<bool(
  int to, const std::vector<float>& send, int from, std::vector<float>& received, bool sendFirst, int tag)>;

/** How many rounds a scan of `bricks` takes: ceil(log2 bricks). */
VTKDEEPSHADOWCORE_EXPORT int ScanRounds(int bricks);

/**
 * Collective over the bricks of `order`: the product, value by value, of the `local` values
 * of the bricks before `self` in `order` (1 for the first), Hillis and Steele's scan. In round
 * r the brick at position p sends its running product of the 2^r bricks up to it to position
 * p + 2^r and multiplies in what p - 2^r sent: an inclusive product (what it sends on) and an
 * exclusive one (its answer), so nothing is divided. ScanRounds messages at most, each way.
 * `tag` is the first of the ScanRounds tags it uses.
 */
VTKDEEPSHADOWCORE_EXPORT bool ExclusiveProductScan(const std::vector<int>& order, int self,
  const std::vector<float>& local, int tag, const ScanMessage& message, std::vector<float>& upstream);

}
#endif
