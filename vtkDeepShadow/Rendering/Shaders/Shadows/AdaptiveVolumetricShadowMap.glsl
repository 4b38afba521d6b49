// Lookup of "avsm" (EvaluateAdaptiveNodes and AdaptiveVolumetricShadowMap::MapVisibility in
// Core/Shadows/AdaptiveVolumetricShadowMap.cxx are the CPU twins): 1 before the first node,
// linear between nodes, the last node's transmittance from there on (unused nodes sit at
// NoHit with it); a fixed loop over the AVSM_NODES nodes, no search. With casting meshes (a
// layer after the nodes) times their steps'; bilinear across the four nearest texels.
//@Dec
float adaptiveVisibility(int layer, ivec2 texel, vec2 xy, float pointDepth, vec2 slope)
{
  float depth = lightSpaceDepthAt(vec2(texel), xy, pointDepth, slope);
  vec4 pair = lightSpaceTexel(texel, layer);
  vec2 previous = pair.xy;
  float visibility = 1.0;
  if (depth >= previous.x)
  {
    // Unused nodes sit at the largest float with the last value: the segment that reaches
    // them gives that value.
    visibility = previous.y;
    bool found = false;
    for (int i = 1; i < AVSM_NODES; ++i)
    {
      if (i % 2 == 0)
      {
        pair = lightSpaceTexel(texel, layer + i / 2);
      }
      vec2 node = i % 2 == 0 ? pair.xy : pair.zw;
      if (!found)
      {
        found = depth < node.x;
        visibility = found ? mix(previous.y, node.y, (depth - previous.x) / (node.x - previous.x)) : node.y;
        previous = node;
      }
    }
  }
  if (u_shadowLayersPerFace > AVSM_NODES / 2)
  {
    visibility *= surfaceStepsVisibility(lightSpaceTexel(texel, layer + AVSM_NODES / 2), depth);
  }
  return visibility;
}

vec3 mapVisibility(int layer, vec2 xy, float depth, vec2 slope)
{
  ivec2 i0;
  vec4 w = lightSpaceBilinear(xy, i0);
  return vec3(w.x * adaptiveVisibility(layer, i0, xy, depth, slope) +
    w.y * adaptiveVisibility(layer, i0 + ivec2(1, 0), xy, depth, slope) +
    w.z * adaptiveVisibility(layer, i0 + ivec2(0, 1), xy, depth, slope) +
    w.w * adaptiveVisibility(layer, i0 + ivec2(1, 1), xy, depth, slope));
}
