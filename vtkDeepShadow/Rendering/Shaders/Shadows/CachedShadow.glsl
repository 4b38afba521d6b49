// Lookup of any cached technique ("-cached"): its answer stored per node of a grid over the
// volume's box (one slab of the 3D texture per shadowed light), fetched trilinearly (the
// ShadowGrid of Core/Shadows/ShadowGrid.h is the CPU twin). Needs the ShadowGrid feature.
//@Dec
uniform sampler3D u_shadowVolume; // lights stacked along z, u_shadowDims.z nodes each: R or RGBA
uniform vec3 u_shadowDims;
uniform float u_shadowSlabs;      // shadowed lights the texture has room for
uniform mat4 u_shadowWorldToNode; // deepshadow::GridFrame

vec3 lightVisibility(int slot, vec3 position, vec3 toLight, float lightDistance, vec3 receiverNormal)
{
  vec4 stored = gridVisibility(u_shadowVolume, u_shadowWorldToNode, u_shadowDims, u_shadowSlabs, slot, position);
  return ShadowCacheColored ? stored.rgb : vec3(stored.r); // set by the technique
}
