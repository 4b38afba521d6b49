// Build of "cssm": per photon (one layer each), the depth per channel of the segment that
// stopped it, rho = alpha (1 - colour) against one random threshold per segment
// (TraceStochasticPhoton and StochasticThreshold in Core/Shadows/StochasticShadowMap.cxx are
// the CPU twins: the same hashes give the same thresholds).
//@Dec
layout(rgba32f, binding = 0) uniform writeonly image2DArray u_output;
uniform int u_cssmSeed;
uint g_layer;
vec3 g_stop;
uint g_crossings; // surface crossings so far on this photon's ray

float stochasticThreshold(uint x, uint y, uint layer, uint segment, uint seed)
{
  uint hash = pcgHash(x + pcgHash(y + pcgHash(layer + pcgHash(segment + pcgHash(seed)))));
  return float(hash >> 8u) * (1.0 / 16777216.0);
}

// A photon stops in channel c where rho_c exceeds the segment's random threshold.
bool stochasticSegment(float t, vec3 rho, uint segment)
{
  float r = stochasticThreshold(uint(g_texel.x), uint(g_texel.y), g_layer, segment, uint(u_cssmSeed));
  for (int c = 0; c < 3; ++c)
  {
    if (g_stop[c] == NoHit && rho[c] > r)
    {
      g_stop[c] = t;
    }
  }
  return any(equal(g_stop, vec3(NoHit)));
}

bool visitSample(int j, float t, float scalar)
{
  vec4 rgba = feelerSample(scalar);
  return stochasticSegment(t, rgba.a * (1.0 - rgba.rgb), uint(j));
}

bool visitSkipped(int j, float t)
{
  return true; // no photon stops in empty space
}
//@Surface
// A surface is a segment of its own (deepshadow::SurfaceSegmentBase + the crossing's number).
bool visitSurface(float t, int surface)
{
  return stochasticSegment(t, 1.0 - u_surfaceTransmission[surface].rgb, 0x80000000u + g_crossings++);
}
//@Texel
void buildTexel(vec3 indexOrigin, vec3 indexDirection, float tEnter, float tExit)
{
  for (int photon = 0; photon < u_layersPerFace; ++photon)
  {
    g_layer = uint(u_face * u_layersPerFace + photon);
    g_stop = vec3(NoHit);
    g_crossings = 0u;
    marchTexel(indexOrigin, indexDirection, tEnter, tExit);
    imageStore(u_output, ivec3(g_texel, u_layer + photon), vec4(g_stop, 0.0));
  }
}
