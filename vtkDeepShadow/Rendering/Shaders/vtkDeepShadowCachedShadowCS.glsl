#version 430 core
// Any technique's lookup (the runtime feature Lookup) evaluated at each node of a grid, for
// one light, into that light's slab of a 3D texture (deepshadow::ShadowGrid is the CPU twin).
// Two grids are built so: a cached technique's own ("-cached", over its volume's box), and
// the shadows other volumes cast onto a receiver (OTHER_VOLUMES: over the receiver's box;
// each caster multiplies its answer into what the casters before it stored). A cache skips
// nodes that no view sample can interpolate from (all blocks within a node spacing empty):
// the pictures are the same, the pass is cheaper on sparse data.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
const int MaxLights = 8;
//DeepShadow::VolumeSampling::Dec
//DeepShadow::Isosurface::Dec
//DeepShadow::OpacityScale::Dec
//DeepShadow::GradientOpacity::Dec
//DeepShadow::Mask::Dec
//DeepShadow::LabelMap::Dec
//DeepShadow::Transfer2D::Dec
//DeepShadow::EmptySpace::Dec
//DeepShadow::TriangleHierarchy::Dec
//DeepShadow::Bound::Dec
//DeepShadow::Surfaces::Dec
//DeepShadow::Feeler::Dec
//DeepShadow::Hash::Dec
//DeepShadow::Lookup::Dec
#if defined(OTHER_VOLUMES)
layout(rgba16f, binding = 0) uniform image3D u_output;
uniform int u_firstCaster; // 1: store; 0: multiply into what is stored
#elif defined(CACHE_COLORED)
layout(rgba16f, binding = 0) uniform writeonly image3D u_output;
#else
layout(r16f, binding = 0) uniform writeonly image3D u_output;
#endif
uniform ivec3 u_shadowDims;
uniform int u_slot;          // the light's structure in the technique
uniform int u_slab;          // the light's slab in the grid
uniform mat4 u_nodeToWorld;  // deepshadow::GridFrame
uniform int u_lightPositional;
uniform vec3 u_lightPosition;
uniform vec3 u_lightToward; // directional lights: unit direction towards the light
uniform int u_cacheSkipEmpty;
uniform vec3 u_cacheReach;  // one node spacing, in voxels

void main()
{
  ivec3 node = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(node, u_shadowDims)))
  {
    return;
  }
  vec3 world = (u_nodeToWorld * vec4(vec3(node), 1.0)).xyz;
  ivec3 texel = ivec3(node.xy, node.z + u_slab * u_shadowDims.z);
  //DeepShadow::EmptySpace::CacheSkip
  vec3 toLight = u_lightToward;
  float lightDistance = 1e30;
  if (u_lightPositional != 0)
  {
    vec3 d = u_lightPosition - world;
    lightDistance = length(d);
    toLight = lightDistance > 0.0 ? d / lightDistance : vec3(0.0, 0.0, 1.0);
  }
  vec3 visibility = lightVisibility(u_slot, world, toLight, lightDistance, vec3(0.0));
#ifdef OTHER_VOLUMES
  if (u_firstCaster == 0)
  {
    visibility *= imageLoad(u_output, texel).rgb;
  }
#endif
  imageStore(u_output, texel, vec4(visibility, 1.0));
}
