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
  // first = how many nodes lie at or before depth.
  int first = 0;
  int remaining = u_shadowLayersPerFace;
  while (remaining > 0)
  {
    int halfCount = remaining / 2;
    if (texelFetch(u_shadowMap, ivec3(texel, layer + first + halfCount), 0).r <= depth)
    {
      first += halfCount + 1;
      remaining -= halfCount + 1;
    }
    else
    {
      remaining = halfCount;
    }
  }
  if (first == 0)
  {
    return vec3(1.0);
  }
  vec4 a = texelFetch(u_shadowMap, ivec3(texel, layer + first - 1), 0);
  if (first == u_shadowLayersPerFace)
  {
    return dsmValue(a);
  }
  vec4 b = texelFetch(u_shadowMap, ivec3(texel, layer + first), 0);
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
