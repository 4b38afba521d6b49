#include "Core/EmptySpace.h"

#include <glm/common.hpp>
#include <glm/vector_relational.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace deepshadow
{

BlockRanges BlockRanges::Compute(const VolumeGrid& grid, int blockSize)
{
  BlockRanges ranges;
  ranges.BlockSize = blockSize;
  const glm::ivec3 dims = grid.GetDims();
  ranges.BlockCount = (dims + blockSize - 1) / blockSize;
  const size_t count = static_cast<size_t>(ranges.BlockCount.x) * ranges.BlockCount.y * ranges.BlockCount.z;
  ranges.Min.assign(count, std::numeric_limits<float>::max());
  ranges.Max.assign(count, std::numeric_limits<float>::lowest());

  size_t b = 0;
  for (int bz = 0; bz < ranges.BlockCount.z; ++bz)
  {
    for (int by = 0; by < ranges.BlockCount.y; ++by)
    {
      for (int bx = 0; bx < ranges.BlockCount.x; ++bx, ++b)
      {
        const glm::ivec3 block(bx, by, bz);
        const glm::ivec3 lo = glm::max(block * blockSize - 1, 0);
        const glm::ivec3 hi = glm::min((block + 1) * blockSize + 1, dims - 1);
        float mn = ranges.Min[b], mx = ranges.Max[b];
        for (int k = lo.z; k <= hi.z; ++k)
        {
          for (int j = lo.y; j <= hi.y; ++j)
          {
            for (int i = lo.x; i <= hi.x; ++i)
            {
              const float v = grid.At(i, j, k);
              mn = std::min(mn, v);
              mx = std::max(mx, v);
            }
          }
        }
        ranges.Min[b] = mn;
        ranges.Max[b] = mx;
      }
    }
  }
  return ranges;
}

std::vector<uint8_t> BlockRanges::Occupancy(const PiecewiseLinear& opacity) const
{
  std::vector<uint8_t> occupied(this->Min.size());
  for (size_t b = 0; b < this->Min.size(); ++b)
  {
    occupied[b] = opacity.MaxOver(this->Min[b], this->Max[b]) > 0.0 ? 1 : 0;
  }
  return occupied;
}

EmptySpaceMap::EmptySpaceMap(const VolumeGrid& grid, const PiecewiseLinear& opacity, int blockSize)
  : Blocks(BlockRanges::Compute(grid, blockSize))
  , Occupied(Blocks.Occupancy(opacity))
{
}

int EmptySpaceMap::SkipSteps(const glm::dvec3& index, const glm::dvec3& indexStep) const
{
  const glm::ivec3 block = glm::ivec3(glm::floor(index / static_cast<double>(this->Blocks.BlockSize)));
  if (glm::any(glm::lessThan(block, glm::ivec3(0))) ||
    glm::any(glm::greaterThanEqual(block, this->Blocks.BlockCount)))
  {
    return 0;
  }
  const size_t b = block.x +
    static_cast<size_t>(this->Blocks.BlockCount.x) *
      (block.y + static_cast<size_t>(this->Blocks.BlockCount.y) * block.z);
  return this->Occupied[b] ? 0 : StepsToLeaveBlock(index, indexStep, block, this->Blocks.BlockSize);
}

int StepsToLeaveBlock(
  const glm::dvec3& index, const glm::dvec3& indexStep, const glm::ivec3& block, int blockSize)
{
  const glm::dvec3 lo = glm::dvec3(block * blockSize);
  const glm::dvec3 hi = lo + static_cast<double>(blockSize);
  double steps = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < 3; ++axis)
  {
    if (indexStep[axis] > 0.0)
    {
      steps = std::min(steps, (hi[axis] - index[axis]) / indexStep[axis]);
    }
    else if (indexStep[axis] < 0.0)
    {
      steps = std::min(steps, (lo[axis] - index[axis]) / indexStep[axis]);
    }
  }
  if (!std::isfinite(steps))
  {
    return 1;
  }
  return std::max(1, static_cast<int>(std::ceil(steps)));
}

}
