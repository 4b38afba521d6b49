// Lookup of "dsm-fixed" (EvaluateFixedNodes and FixedBudgetDeepShadowMap::MapVisibility in
// Core/Shadows/FixedBudgetDeepShadowMap.cxx are the CPU twins): a loop over the FIXED_NODES
// nodes in order, no search, of the same terms either way: on a GPU a fixed loop; with
// FIXED_LOOKUP_STOPS (a CPU rasterizer) it stops at the first node beyond the point, whose
// later terms are 0. Stopping made llvmpipe's frame on the head 1.34 times the unshadowed
// one instead of 1.98, and an H200's 3.1 instead of 2.2 at 512 bits (its fetches serialize);
// V(z) = 1 + sum over i >= 1 of (v_i - v_{i-1}) clamp((z - z_{i-1}) / (z_i - z_{i-1}), 0, 1),
// the sum is 1 before node 0, linear between nodes and the last value after them (unused nodes
// lie at the range's end with it); bilinear across the four nearest texels. Depths are
// unorms over u_lightDepthRange.
//@Dec
uniform float u_lightDepthRange;

float fixedVisibility(int layer, ivec2 texel, vec2 xy, float pointDepth, vec2 slope)
{
  float depth = lightSpaceDepthAt(vec2(texel), xy, pointDepth, slope) / u_lightDepthRange;
  float visibility = 1.0;
  vec2 previous = vec2(0.0, 1.0);
  for (int l = 0; l < FIXED_NODES / 2; ++l)
  {
    vec4 pair = lightSpaceTexel(texel, layer + l);
    if (l > 0)
    {
      visibility += (pair.y - previous.y) * clamp((depth - previous.x) / max(pair.x - previous.x, 1.0e-9), 0.0, 1.0);
    }
#ifdef FIXED_LOOKUP_STOPS
    // Nodes beyond the point add nothing: stop at the first of them.
    if (depth < pair.x)
    {
      break;
    }
#endif
    visibility += (pair.w - pair.y) * clamp((depth - pair.x) / max(pair.z - pair.x, 1.0e-9), 0.0, 1.0);
#ifdef FIXED_LOOKUP_STOPS
    if (depth < pair.z)
    {
      break;
    }
#endif
    previous = pair.zw;
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
