// Lookup of "dsm3": the volume's opacity is 0 before the first level's depth, smoothstep in
// depth from level to level, the maximum opacity after the last, never above it; with
// casting meshes (a second layer) times their steps' visibility; bilinear across the four
// nearest texels (EvaluateOpacityLevels, EvaluateSurfaceSteps and
// OpacityLevelsShadow::MapVisibility in Core/Shadows/OpacityLevels.cxx are the CPU twins).
//@Dec
uniform vec3 u_levels;

float levelsVisibility(int layer, ivec2 texel, vec2 xy, float pointDepth, vec2 slope)
{
  float depth = lightSpaceDepthAt(vec2(texel), xy, pointDepth, slope);
  vec4 t = lightSpaceTexel(texel, layer);
  float opacity;
  if (depth < t.x)
  {
    opacity = 0.0;
  }
  else if (depth < t.y)
  {
    opacity = u_levels.x + smoothstep(t.x, t.y, depth) * (u_levels.y - u_levels.x);
  }
  else if (depth < t.z)
  {
    opacity = u_levels.y + smoothstep(t.y, t.z, depth) * (u_levels.z - u_levels.y);
  }
  else
  {
    opacity = t.w;
  }
  float visibility = 1.0 - min(opacity, t.w);
  if (u_shadowLayersPerFace > 1)
  {
    visibility *= surfaceStepsVisibility(lightSpaceTexel(texel, layer + 1), depth);
  }
  return visibility;
}

vec3 mapVisibility(int layer, vec2 xy, float depth, vec2 slope)
{
  ivec2 i0;
  vec4 w = lightSpaceBilinear(xy, i0);
  return vec3(w.x * levelsVisibility(layer, i0, xy, depth, slope) +
    w.y * levelsVisibility(layer, i0 + ivec2(1, 0), xy, depth, slope) +
    w.z * levelsVisibility(layer, i0 + ivec2(0, 1), xy, depth, slope) +
    w.w * levelsVisibility(layer, i0 + ivec2(1, 1), xy, depth, slope));
}
