// Build of "shadowmap": the depth of the first sample above the threshold (ShadowMapShadow
// in Core/Shadows/ShadowMap.cxx is the CPU twin); rays that find none store NoHit.
//@Dec
layout(r32f, binding = 0) uniform writeonly image2DArray u_output;
float g_depth;

bool visitSample(int j, float t, float scalar)
{
  if (feelerAbove(scalar))
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
  if (surfaceOccludes(surface))
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
  marchTexel(indexOrigin, indexDirection, tEnter, tExit);
  imageStore(u_output, ivec3(g_texel, u_layer), vec4(g_depth));
}
