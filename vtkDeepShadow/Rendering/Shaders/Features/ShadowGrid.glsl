// Feature ShadowGrid: a trilinear fetch from a grid of light visibilities, lights stacked as
// slabs along z (deepshadow::ShadowGrid::Visibility is the CPU twin). Read by cached
// techniques (Shadows/CachedShadow.glsl) and by OtherVolumeShadows.
//@Dec
vec4 gridVisibility(sampler3D grid, mat4 worldToNode, vec3 dims, float slabs, int slab, vec3 position)
{
  vec3 node = clamp((worldToNode * vec4(position, 1.0)).xyz, vec3(0.0), dims - 1.0);
  vec3 coordinate = vec3((node.xy + 0.5) / dims.xy, (node.z + float(slab) * dims.z + 0.5) / (dims.z * slabs));
  return texture(grid, coordinate);
}
