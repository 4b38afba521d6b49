// Lookup of "slices" (EvaluateSlices and OpacitySlicesShadow::MapVisibility in
// Core/Shadows/OpacitySlices.cxx are the CPU twins): linear between the two slices around
// the point moved one slice towards the light (1 at depth 0, the last slice beyond
// u_lightDepthRange), bilinear across the four nearest texels; one or two texel fetches each.
//@Dec
uniform float u_lightDepthRange;

float sliceValue(int layer, ivec2 texel, int i)
{
  return i < 0 ? 1.0 : lightSpaceTexel(texel, layer + i / 4)[i % 4];
}

float slicesVisibility(int layer, ivec2 texel, vec2 xy, float pointDepth, vec2 slope)
{
  // One slice towards the light: a surface does not shadow itself.
  float f = lightSpaceDepthAt(vec2(texel), xy, pointDepth, slope) / u_lightDepthRange * float(SLICES) - 1.0;
  if (!(f > 0.0))
  {
    return 1.0;
  }
  if (f >= float(SLICES))
  {
    return sliceValue(layer, texel, SLICES - 1);
  }
  int j = int(floor(f));
  return mix(sliceValue(layer, texel, j - 1), sliceValue(layer, texel, j), f - float(j));
}

vec3 mapVisibility(int layer, vec2 xy, float depth, vec2 slope)
{
  ivec2 i0;
  vec4 w = lightSpaceBilinear(xy, i0);
  return vec3(w.x * slicesVisibility(layer, i0, xy, depth, slope) +
    w.y * slicesVisibility(layer, i0 + ivec2(1, 0), xy, depth, slope) +
    w.z * slicesVisibility(layer, i0 + ivec2(0, 1), xy, depth, slope) +
    w.w * slicesVisibility(layer, i0 + ivec2(1, 1), xy, depth, slope));
}
