// Empty-space skipping: the volume is cut into blocks; a block whose scalar range maps to
// zero opacity can be skipped whole. Skipping is exact, not an approximation: each block's
// range includes a one-voxel apron on every side, which covers every voxel that a linear or
// nearest lookup anywhere in the block reads.
#ifndef deepshadow_EmptySpace_h
#define deepshadow_EmptySpace_h

#include "Core/TransferFunction.h"
#include "Core/VolumeGrid.h"
#include "vtkDeepShadowCoreModule.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace deepshadow
{

/** Scalar range of every block (apron included). Depends on the data only. */
struct VTKDEEPSHADOWCORE_EXPORT BlockRanges
{
  int BlockSize = 8;
  glm::ivec3 BlockCount{ 0 };
  std::vector<float> Min;
  std::vector<float> Max;

  static BlockRanges Compute(const VolumeGrid& grid, int blockSize = 8);

  /** 1 where some scalar in the block has opacity > 0. Depends on data and opacity only. */
  std::vector<uint8_t> Occupancy(const PiecewiseLinear& opacity) const;
};

/** Which blocks a ray may skip: the block ranges and their occupancy for one opacity. */
struct VTKDEEPSHADOWCORE_EXPORT EmptySpaceMap
{
  BlockRanges Blocks;
  std::vector<uint8_t> Occupied;

  EmptySpaceMap() = default;
  EmptySpaceMap(const VolumeGrid& grid, const PiecewiseLinear& opacity, int blockSize = 8);

  /**
   * If the sample at `index` lies in an empty block, the number of steps of `indexStep`
   * that leave it (>= 1); 0 if the sample must be taken.
   */
  int SkipSteps(const glm::dvec3& index, const glm::dvec3& indexStep) const;
};

/**
 * Number of whole steps after which the sample position index + s * indexStep has left the
 * block `block` (of `blockSize` voxels), at least 1. Twin of the GPU's skip.
 */
VTKDEEPSHADOWCORE_EXPORT int StepsToLeaveBlock(const glm::dvec3& index,
  const glm::dvec3& indexStep, const glm::ivec3& block, int blockSize);

}
#endif
