// A scalar volume on a regular grid, sampled exactly as an OpenGL 3D texture samples it.
//
// Positions are continuous voxel indices: voxel (i, j, k) sits at index (i, j, k), the
// texture coordinate of index p is (p + 0.5) / Dims, and lookups clamp to the edge. So the
// CPU reference and the GPU mapper read the same value at the same place.
#ifndef deepshadow_VolumeGrid_h
#define deepshadow_VolumeGrid_h

#include "vtkDeepShadowCoreModule.h"

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace deepshadow
{

enum class Interpolation
{
  Nearest,
  Linear
};

/** Non-finite samples found in a scalar array. */
struct NonFiniteCount
{
  size_t NaN = 0;
  size_t PositiveInfinity = 0;
  size_t NegativeInfinity = 0;
  size_t Total() const { return NaN + PositiveInfinity + NegativeInfinity; }
};

VTKDEEPSHADOWCORE_EXPORT NonFiniteCount CountNonFinite(const float* values, size_t count);

/**
 * The defined treatment of non-finite samples when a user asks to render them anyway:
 * NaN becomes the smallest finite value (empty space under the usual transfer functions),
 * +Inf the largest, -Inf the smallest. An array with no finite value becomes all zeros.
 */
VTKDEEPSHADOWCORE_EXPORT void ReplaceNonFinite(float* values, size_t count);

/**
 * Sample distance used when none is set: half the shortest world-space voxel edge of the
 * grid (index-to-world includes spacing, direction and the prop's transform).
 */
VTKDEEPSHADOWCORE_EXPORT double DefaultSampleDistance(const glm::dmat4& indexToWorld);

/**
 * The most loop iterations a ray (a view ray, a feeler, a light ray) may take across a volume,
 * with what each sample adds: llvmpipe ends every shader invocation's loops after 65535
 * iterations in all, silently, and a GPU or the CPU reference would take hours beyond it.
 * The same bound holds on every GL and on the CPU, so that pictures do not depend on where
 * they are made.
 */
constexpr double MaxRayIterations = 65535.0;

/** The longest path of any ray through the box [0, dims - 1] mapped by indexToWorld: its longest diagonal. */
VTKDEEPSHADOWCORE_EXPORT double LongestPath(const glm::dmat4& indexToWorld, const glm::ivec3& dims);
/** The longest path through that box of a ray along the unit world direction `direction`. */
VTKDEEPSHADOWCORE_EXPORT double LongestPathAlong(
  const glm::dmat4& indexToWorld, const glm::ivec3& dims, const glm::dvec3& direction);

/**
 * Empty if a ray of `step` (world units) along a path of `longest` takes at most
 * MaxRayIterations / `iterationsPerSample` samples; else one sentence for the user naming
 * `what` (e.g. "the sample distance"), the samples asked for and the smallest step that fits.
 */
VTKDEEPSHADOWCORE_EXPORT std::string CheckRaySamples(
  double longest, double step, const std::string& what, double iterationsPerSample = 1.0);

class VTKDEEPSHADOWCORE_EXPORT VolumeGrid
{
public:
  VolumeGrid() = default;
  /** `scalars` has x fastest; `indexToWorld` maps voxel indices to world coordinates. */
  VolumeGrid(const glm::ivec3& dims, std::vector<float> scalars, const glm::dmat4& indexToWorld);

  const glm::ivec3& GetDims() const { return this->Dims; }
  const std::vector<float>& GetScalars() const { return this->Scalars; }
  const glm::dmat4& GetIndexToWorld() const { return this->IndexToWorld; }
  const glm::dmat4& GetWorldToIndex() const { return this->WorldToIndex; }
  /** Smallest and largest (finite) scalar. */
  const glm::dvec2& GetRange() const { return this->Range; }

  float At(int i, int j, int k) const
  {
    return this->Scalars[static_cast<size_t>(i) +
      static_cast<size_t>(this->Dims.x) *
        (static_cast<size_t>(j) + static_cast<size_t>(this->Dims.y) * static_cast<size_t>(k))];
  }

  /** Value at a continuous index, as GL_NEAREST / GL_LINEAR with clamp-to-edge read it. */
  double Sample(const glm::dvec3& index, Interpolation interpolation) const;

  /**
   * Half the central differences over +-GradientReach voxels (the GPU's formula): per index
   * unit at reach 1; per two index units at reach 2, a grid resampled from cell scalars
   * (whose cells are two voxels wide), so that it is VTK's gradient, one cell apart.
   */
  glm::dvec3 IndexGradient(const glm::dvec3& index, Interpolation interpolation) const;
  int GetGradientReach() const { return this->GradientReach; }
  void SetGradientReach(int voxels) { this->GradientReach = voxels; }
  /** The same gradient in world units: transpose(J) * g with J the world-to-index Jacobian. */
  glm::dvec3 WorldGradient(const glm::dvec3& index, Interpolation interpolation) const;

  /** True if a continuous index lies in the sampled box [0, Dims - 1]. */
  bool ContainsIndex(const glm::dvec3& index) const;

private:
  glm::ivec3 Dims{ 0 };
  std::vector<float> Scalars;
  glm::dmat4 IndexToWorld{ 1.0 };
  glm::dmat4 WorldToIndex{ 1.0 };
  glm::dvec2 Range{ 0.0, 0.0 };
  int GradientReach = 1;
};

}
#endif
