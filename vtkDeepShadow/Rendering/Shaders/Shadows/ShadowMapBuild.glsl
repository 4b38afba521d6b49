// Build of "shadowmap": the depth of the first occluder along the texel's ray (where the
// accumulated opacity exceeds the threshold, or the first sample or mesh above it:
// feelerOccludes, occluderCounts; ShadowMapShadow in Core/Shadows/ShadowMap.cxx is the CPU
// twin); rays that find none store NoHit.
//@Dec
layout(r32f, binding = 0) uniform writeonly image2DArray u_output;
float g_depth;
float g_transmittance; // what the ray let through so far (accumulated threshold)

bool visitSample(int j, float t, float scalar)
{
  if (feelerOccludes(scalar, g_transmittance))
  {
    g_depth = t;
    return false;
  }
  return true;
}

bool visitSkipped(int j, float t)
{
  return true;
}
//@Surface
bool visitSurface(float t, int surface)
{
  if (occluderCounts(u_surfaceTransmission[surface].a, surfaceAboveThreshold(surface), g_transmittance))
  {
    g_depth = t;
    return false;
  }
  return true;
}
//@Texel
void buildTexel(vec3 indexOrigin, vec3 indexDirection, float tEnter, float tExit)
{
  g_depth = NoHit;
  g_transmittance = 1.0;
  marchTexel(indexOrigin, indexDirection, tEnter, tExit);
  imageStore(u_output, lightSpaceOutputTexel(), vec4(g_depth));
}
