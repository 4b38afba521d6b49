// Lookup of "dsm" / "dsm-color": per texel, linear in depth between the two nodes that
// bracket the point (found by binary search), bilinear across the four nearest texels
// (EvaluateVisibility and DeepShadowMap::Visibility in Core/Shadows/DeepShadowMap.cxx are
// the CPU twins). DsmColored is defined by the technique.
//@Dec

vec3 dsmValue(vec4 node)
{
  return DsmColored ? node.gba : vec3(node.g);
}

vec3 dsmTexel(int layer, ivec2 texel, float depth)
{
  texel = lightSpaceClamp(texel);
  // first = how many nodes lie at or before depth. The search reads the two nodes that
  // bracket depth on its way: the last node found at or before it is node first - 1, and the
  // last found beyond it is node first (each such probe moves the search's right end to
  // itself, and the search ends where its ends meet), so neither is fetched again.
  int first = 0;
  int remaining = u_shadowLayersPerFace;
  vec4 a = vec4(0.0);
  vec4 b = vec4(0.0);
  while (remaining > 0)
  {
    int halfCount = remaining / 2;
    vec4 node = texelFetch(u_shadowMap, ivec3(texel, layer + first + halfCount), 0);
    if (node.r <= depth)
    {
      a = node;
      first += halfCount + 1;
      remaining -= halfCount + 1;
    }
    else
    {
      b = node;
      remaining = halfCount;
    }
  }
  if (first == 0)
  {
    return vec3(1.0);
  }
  if (first == u_shadowLayersPerFace)
  {
    return dsmValue(a);
  }
  return mix(dsmValue(a), dsmValue(b), (depth - a.r) / (b.r - a.r));
}

vec3 dsmAt(int layer, ivec2 texel, vec2 xy, float depth, vec2 slope)
{
  return dsmTexel(layer, texel, lightSpaceDepthAt(vec2(texel), xy, depth, slope));
}

vec3 mapVisibility(int layer, vec2 xy, float depth, vec2 slope)
{
  ivec2 i0;
  vec4 w = lightSpaceBilinear(xy, i0);
  return w.x * dsmAt(layer, i0, xy, depth, slope) + w.y * dsmAt(layer, i0 + ivec2(1, 0), xy, depth, slope) +
    w.z * dsmAt(layer, i0 + ivec2(0, 1), xy, depth, slope) + w.w * dsmAt(layer, i0 + ivec2(1, 1), xy, depth, slope);
}
