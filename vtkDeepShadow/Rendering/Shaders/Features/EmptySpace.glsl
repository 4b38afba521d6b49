// Feature EmptySpace: blocks of u_blockSize^3 voxels whose scalar range has zero opacity are
// skipped whole, in whole steps so that the samples taken are exactly those of an
// unskipping ray (deepshadow::StepsToLeaveBlock in Core/EmptySpace.cxx is the CPU twin).
//@Dec
uniform sampler3D u_occupancy; // 1 where a block can be visible (R8, nearest)
uniform float u_blockSize;
int stepsToLeaveBlock(vec3 index, vec3 indexStep, vec3 block)
{
  vec3 lo = block * u_blockSize;
  vec3 hi = lo + u_blockSize;
  vec3 exitPlane = mix(lo, hi, greaterThan(indexStep, vec3(0.0)));
  vec3 steps = (exitPlane - index) / indexStep;
  steps = mix(steps, vec3(1e30), equal(indexStep, vec3(0.0)));
  return max(1, int(ceil(min(min(steps.x, steps.y), steps.z))));
}
// Whether every block within `reach` voxels of `index` (per axis) is empty, so that no
// sample of a view ray comes that near. Checks the blocks of the 8 corners of that box,
// which are all the blocks it touches when reach <= u_blockSize.
bool emptyAround(vec3 index, vec3 reach)
{
  for (int c = 0; c < 8; ++c)
  {
    vec3 corner = index + reach * vec3((c & 1) != 0 ? 1.0 : -1.0, (c & 2) != 0 ? 1.0 : -1.0,
      (c & 4) != 0 ? 1.0 : -1.0);
    corner = clamp(corner, vec3(0.0), u_dims - 1.0);
    if (texelFetch(u_occupancy, ivec3(floor(corner / u_blockSize)), 0).r != 0.0)
    {
      return false;
    }
  }
  return true;
}
//@Init
  vec3 indexStep = indexDirection * u_step;
//@Impl
    {
      vec3 block = floor(index / u_blockSize);
      if (texelFetch(u_occupancy, ivec3(block), 0).r == 0.0)
      {
        k += stepsToLeaveBlock(index, indexStep, block) - 1;
        continue;
      }
    }
//@FeelerSkip
      if (u_feelerSkipEmpty != 0)
      {
        vec3 block = floor(sampleIndex / u_blockSize);
        if (texelFetch(u_occupancy, ivec3(block), 0).r == 0.0)
        {
          j += stepsToLeaveBlock(sampleIndex, indexStep, block) - 1;
          continue;
        }
      }
//@TexelSkip
    if (skip == 0 && u_feelerSkipEmpty != 0)
    {
      vec3 block = floor(sampleIndex / u_blockSize);
#ifdef LIGHT_SPACE_CLIP
      if (!lightSpaceOwnBlock(ivec3(block))) // a clustered face's: another cluster's block too
#else
      if (texelFetch(u_occupancy, ivec3(block), 0).r == 0.0)
#endif
      {
        skip = stepsToLeaveBlock(sampleIndex, indexStep, block);
      }
    }
//@CacheSkip
  // Nodes no view sample interpolates from need no answer (they hold "lit").
  if (u_cacheSkipEmpty != 0 && emptyAround((u_worldToIndex * vec4(world, 1.0)).xyz, u_cacheReach))
  {
    imageStore(u_output, texel, vec4(1.0));
    return;
  }
