// Lookup of any cached technique ("-cached"): its answer stored per node of a grid over the
// volume's box (one slab of the 3D texture per shadowed light), fetched trilinearly (the
// CachedShadow of Core/Shadows.cxx is the CPU twin).
//@Dec
uniform sampler3D u_shadowVolume; // lights stacked along z, u_shadowDims.z nodes each: R or RGBA
uniform vec3 u_shadowDims;
uniform float u_shadowSlabs;      // shadowed lights the texture has room for

vec3 lightVisibility(int slot, vec3 position, vec3 toLight, float lightDistance)
{
  vec3 index = (u_worldToIndex * vec4(position, 1.0)).xyz;
  vec3 node = clamp(index * (u_shadowDims - 1.0) / (u_dims - 1.0), vec3(0.0), u_shadowDims - 1.0);
  vec3 coordinate = vec3((node.xy + 0.5) / u_shadowDims.xy,
    (node.z + float(slot) * u_shadowDims.z + 0.5) / (u_shadowDims.z * u_shadowSlabs));
  vec4 stored = texture(u_shadowVolume, coordinate);
  return ShadowCacheColored ? stored.rgb : vec3(stored.r); // set by the technique

}
