#version 430 core
// Build pass of every cached technique: the technique's own lookup (the runtime feature
// Lookup) evaluated at each node of the shadow grid, for one light, written into that
// light's slab of the shadow texture (the CachedShadow constructor in Core/Shadows.cxx is
// the CPU twin). Nodes that no view sample can interpolate from (all blocks within a node
// spacing empty) are skipped: the pictures are the same, the pass is cheaper on sparse data.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
const int MaxLights = 8;
//DeepShadow::VolumeSampling::Dec
//DeepShadow::EmptySpace::Dec
//DeepShadow::TriangleHierarchy::Dec
//DeepShadow::Bound::Dec
//DeepShadow::Surfaces::Dec
//DeepShadow::Feeler::Dec
//DeepShadow::Hash::Dec
//DeepShadow::Lookup::Dec
#ifdef CACHE_COLORED
layout(rgba16f, binding = 0) uniform writeonly image3D u_output;
#else
layout(r16f, binding = 0) uniform writeonly image3D u_output;
#endif
uniform ivec3 u_shadowDims;
uniform int u_slot;
uniform mat4 u_indexToWorld;
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
  vec3 index = vec3(node) * (u_dims - 1.0) / vec3(u_shadowDims - 1);
  //DeepShadow::EmptySpace::CacheSkip
  vec3 world = (u_indexToWorld * vec4(index, 1.0)).xyz;
  vec3 toLight = u_lightToward;
  float lightDistance = 1e30;
  if (u_lightPositional != 0)
  {
    vec3 d = u_lightPosition - world;
    lightDistance = length(d);
    toLight = lightDistance > 0.0 ? d / lightDistance : vec3(0.0, 0.0, 1.0);
  }
  vec3 visibility = lightVisibility(u_slot, world, toLight, lightDistance);
  imageStore(u_output, ivec3(node.xy, node.z + u_slot * u_shadowDims.z), vec4(visibility, 1.0));
}
