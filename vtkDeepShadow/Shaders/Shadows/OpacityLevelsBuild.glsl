// Build of "dsm3": the depths where the accumulated opacity crosses u_levels and the maximum
// opacity, one RGBA texel (BuildOpacityLevels in Core/Shadows/OpacityLevels.cxx is the CPU
// twin): a crossing between two points is placed by the paper's smoothstep; rays stop below
// 1/512 transmittance, like feelers.
//@Dec
layout(rgba32f, binding = 0) uniform writeonly image2DArray u_output;
uniform vec3 u_levels;
bool g_started;
float g_transmittance;
vec3 g_levelDepth;
float g_maxOpacity;
float g_maxDepth;
float g_previousDepth;
float g_previousOpacity;

void levelsPoint(float depth)
{
  float opacity = 1.0 - g_transmittance;
  if (opacity > g_maxOpacity)
  {
    g_maxOpacity = opacity;
    g_maxDepth = depth;
  }
  for (int k = 0; k < 3; ++k)
  {
    if (g_levelDepth[k] == NoHit && g_previousOpacity < u_levels[k] && opacity >= u_levels[k])
    {
      g_levelDepth[k] = mix(g_previousDepth, depth, smoothstep(g_previousOpacity, opacity, u_levels[k]));
    }
  }
  g_previousDepth = depth;
  g_previousOpacity = opacity;
}

// A sample's interval starts with a point (the first of the ray, or the first after a
// surface's step), as deepshadow::SampleVisibility does.
bool g_afterSurface;
void levelsStart(float t)
{
  if (!g_started)
  {
    g_started = true;
    g_previousDepth = t - 0.5 * u_feelerStep;
    g_maxDepth = g_previousDepth;
  }
  else if (g_afterSurface)
  {
    levelsPoint(t - 0.5 * u_feelerStep);
  }
  g_afterSurface = false;
}

bool visitSample(int j, float t, float scalar)
{
  levelsStart(t);
  g_transmittance *= 1.0 - feelerAlpha(scalar);
  levelsPoint(t + 0.5 * u_feelerStep);
  return g_transmittance > 1.0 / 512.0;
}

bool visitSkipped(int j, float t)
{
  levelsStart(t);
  levelsPoint(t + 0.5 * u_feelerStep);
  return true;
}
//@Surface
// A step: points before and after at one depth.
bool visitSurface(float t, int surface)
{
  if (!g_started)
  {
    g_started = true;
    g_previousDepth = t;
    g_maxDepth = t;
  }
  else
  {
    levelsPoint(t);
  }
  g_transmittance *= u_surfaceTransmission[surface].a;
  levelsPoint(t);
  g_afterSurface = true;
  return g_transmittance > 1.0 / 512.0;
}
//@Texel
void buildTexel(vec3 indexOrigin, vec3 indexDirection, float tEnter, float tExit)
{
  g_started = false;
  g_afterSurface = false;
  g_transmittance = 1.0;
  g_levelDepth = vec3(NoHit);
  g_maxOpacity = 0.0;
  g_previousOpacity = 0.0;
  marchTexel(indexOrigin, indexDirection, tEnter, tExit);
  if (g_maxOpacity > 0.0)
  {
    g_levelDepth = mix(g_levelDepth, vec3(g_maxDepth), equal(g_levelDepth, vec3(NoHit)));
  }
  imageStore(u_output, ivec3(g_texel, u_layer), vec4(g_levelDepth, g_maxOpacity));
}
