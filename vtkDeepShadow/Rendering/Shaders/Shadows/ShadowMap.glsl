// Lookup of "shadowmap": the depth of the first sample above the threshold per texel,
// percentage-closer filtered (FilterShadowMap in Core/Shadows/ShadowMap.cxx is the CPU twin).
// SHADOW_FILTER and the Poisson disc are defined by the technique from Core's tables. The
// filter is the resolution-matched map's too (SHADOW_MAP_PAGES: `layer` is then a page's slot,
// Shadows/ResolutionMatched.glsl, which defines shadowMapDepth and mapVisibility).
//@Dec
uniform float u_shadowBias; // world units

#ifdef SHADOW_MAP_PAGES
float shadowMapDepth(int layer, ivec2 texel);
#else
float shadowMapDepth(int layer, ivec2 texel)
{
  return lightSpaceTexel(texel, layer).r;
}
#endif

float shadowLit(int layer, ivec2 texel, vec2 xy, float pointDepth, vec2 slope)
{
  float depth = lightSpaceDepthAt(vec2(texel), xy, pointDepth, slope);
  return depth <= shadowMapDepth(layer, texel) ? 1.0 : 0.0;
}

float filteredShadow(int layer, vec2 xy, float depth, vec2 slope)
{
  ivec2 nearest = ivec2(floor(xy + 0.5));
#if SHADOW_FILTER == 0
  return shadowLit(layer, nearest, xy, depth, slope);
#elif SHADOW_FILTER == 1
  ivec2 i0;
  vec4 w = lightSpaceBilinear(xy, i0);
  return w.x * shadowLit(layer, i0, xy, depth, slope) + w.y * shadowLit(layer, i0 + ivec2(1, 0), xy, depth, slope) +
    w.z * shadowLit(layer, i0 + ivec2(0, 1), xy, depth, slope) + w.w * shadowLit(layer, i0 + ivec2(1, 1), xy, depth, slope);
#elif SHADOW_FILTER == 2
  float sum = 0.0;
  for (int dj = -1; dj <= 1; ++dj)
  {
    for (int di = -1; di <= 1; ++di)
    {
      sum += shadowLit(layer, nearest + ivec2(di, dj), xy, depth, slope);
    }
  }
  return sum / 9.0;
#else
  float sum = 0.0;
  for (int k = 0; k < POISSON_TAPS; ++k)
  {
    sum += shadowLit(layer, ivec2(floor(xy + POISSON_DISC[k] + 0.5)), xy, depth, slope);
  }
  return sum / float(POISSON_TAPS);
#endif
}

#ifndef SHADOW_MAP_PAGES
vec3 mapVisibility(int layer, vec2 xy, float depth, vec2 slope)
{
  return vec3(filteredShadow(layer, xy, depth - u_shadowBias, slope));
}
#endif
