// Per-pixel ray-start jitter from an integer hash, so that a seed gives bit-identical images
// on every run and the GPU (GLSL uint arithmetic, vtkDeepShadowVolumeFS.glsl:jitterOffset)
// and the CPU produce the same offsets.
#ifndef deepshadow_Jitter_h
#define deepshadow_Jitter_h

#include <cstdint>

namespace deepshadow
{

/** PCG hash (Jarzynski & Olano 2020, "Hash Functions for GPU Rendering"). */
inline uint32_t PcgHash(uint32_t value)
{
  const uint32_t state = value * 747796405u + 2891336453u;
  const uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

/** Offset in [0, 1) of the first sample of pixel (x, y), in units of the sample distance. */
inline double JitterOffset(uint32_t x, uint32_t y, uint32_t seed)
{
  const uint32_t hash = PcgHash(x + PcgHash(y + PcgHash(seed)));
  return static_cast<double>(hash >> 8u) * (1.0 / 16777216.0);
}

/** Offset used without jitter: samples sit at the middle of their segment. */
constexpr double UnjitteredOffset = 0.5;

}
#endif
