// Lookup of "cssm": per channel, the fraction of the tests (the offsets around the nearest
// texel, times the photons: a face's layers) whose photon got beyond the point (on a
// receiving surface, beyond its plane at that texel) (StochasticShadowMap::MapVisibility in Core/Shadows/StochasticShadowMap.cxx is the CPU
// twin). CSSM_OFFSETS and CSSM_OFFSET are defined by the technique from Core's table.
//@Dec
vec3 mapVisibility(int layer, vec2 xy, float depth, vec2 slope)
{
  ivec2 nearest = ivec2(floor(xy + 0.5));
  vec3 lit = vec3(0.0);
  for (int k = 0; k < CSSM_OFFSETS; ++k)
  {
    ivec2 offsetTexel = nearest + CSSM_OFFSET[k];
    vec3 texelDepth = vec3(lightSpaceDepthAt(vec2(offsetTexel), xy, depth, slope));
    for (int photon = 0; photon < u_shadowLayersPerFace; ++photon)
    {
      vec3 stop = lightSpaceTexel(offsetTexel, layer + photon).rgb;
      lit += vec3(greaterThan(stop, texelDepth));
    }
  }
  return lit / float(CSSM_OFFSETS * u_shadowLayersPerFace);
}
