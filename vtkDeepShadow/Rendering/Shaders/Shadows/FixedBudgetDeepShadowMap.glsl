// Lookup of "dsm-fixed" (EvaluateFixedNodes and FixedBudgetDeepShadowMap::MapVisibility in
// Core/Shadows/FixedBudgetDeepShadowMap.cxx are the CPU twins): a fixed loop over the
// FIXED_NODES nodes, no search,
// V(z) = 1 + sum over i >= 1 of (v_i - v_{i-1}) clamp((z - z_{i-1}) / (z_i - z_{i-1}), 0, 1),
// which is 1 before node 0, linear between nodes and the last value after them (unused nodes
// lie at the range's end with it); bilinear across the four nearest texels. Depths are
// unorms over u_fixedDepthRange.
//@Dec
uniform float u_fixedDepthRange;

float fixedVisibility(int layer, ivec2 texel, vec2 xy, float pointDepth, vec2 slope)
{
  float depth = lightSpaceDepthAt(vec2(texel), xy, pointDepth, slope) / u_fixedDepthRange;
  vec4 pair = lightSpaceTexel(texel, layer);
  vec2 previous = pair.xy;
  float visibility = 1.0;
  for (int i = 1; i < FIXED_NODES; ++i)
  {
    if (i % 2 == 0)
    {
      pair = lightSpaceTexel(texel, layer + i / 2);
    }
    vec2 node = i % 2 == 0 ? pair.xy : pair.zw;
    visibility += (node.y - previous.y) * clamp((depth - previous.x) / max(node.x - previous.x, 1.0e-9), 0.0, 1.0);
    previous = node;
  }
  return visibility;
}

vec3 mapVisibility(int layer, vec2 xy, float depth, vec2 slope)
{
  ivec2 i0;
  vec4 w = lightSpaceBilinear(xy, i0);
  return vec3(w.x * fixedVisibility(layer, i0, xy, depth, slope) +
    w.y * fixedVisibility(layer, i0 + ivec2(1, 0), xy, depth, slope) +
    w.z * fixedVisibility(layer, i0 + ivec2(0, 1), xy, depth, slope) +
    w.w * fixedVisibility(layer, i0 + ivec2(1, 1), xy, depth, slope));
}
