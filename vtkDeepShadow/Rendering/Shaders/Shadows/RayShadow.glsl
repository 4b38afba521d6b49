// Lookup of "rays": a feeler from the sample to the light, translucent (grey or coloured) or
// opaque (deepshadow::FeelerVisibility in Core/Shadows.cxx is the CPU twin).
//@Dec
uniform int u_shadowOpaque;

vec3 lightVisibility(int slot, vec3 position, vec3 toLight, float lightDistance, vec3 receiverNormal)
{
  return feelerTowardsLight(position, toLight, lightDistance, u_shadowOpaque != 0);
}
