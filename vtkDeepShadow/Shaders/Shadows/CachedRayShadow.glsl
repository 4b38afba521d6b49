// Shadow technique "rays-cached": the feeler's answer stored per node of a grid over the
// volume's box (one slab of the 3D texture per shadowed light), looked up trilinearly
// (the CachedShadow of Core/Shadows.cxx is the CPU twin).
//@Dec
uniform sampler3D u_shadowVolume; // lights stacked along z, u_shadowDims.z nodes each
uniform vec3 u_shadowDims;
uniform float u_shadowSlabs;      // shadowed lights in the texture
uniform int u_shadowSlot[MaxLights];          // slab of each light, -1: none
uniform float u_shadowAttenuation[MaxLights];

float cachedVisibility(int slot, vec3 position)
{
  vec3 index = (u_worldToIndex * vec4(position, 1.0)).xyz;
  vec3 node = clamp(index * (u_shadowDims - 1.0) / (u_dims - 1.0), vec3(0.0), u_shadowDims - 1.0);
  vec3 coordinate = vec3((node.xy + 0.5) / u_shadowDims.xy,
    (node.z + float(slot) * u_shadowDims.z + 0.5) / (u_shadowDims.z * u_shadowSlabs));
  return texture(u_shadowVolume, coordinate).r;
}
//@Impl
    if (u_shadowSlot[i] >= 0)
    {
      float visibility = cachedVisibility(u_shadowSlot[i], position);
      attenuation *= 1.0 - u_shadowAttenuation[i] * (1.0 - visibility);
    }
