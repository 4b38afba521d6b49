// Build of "dsm3": the depths where the volume's accumulated opacity crosses u_levels and its
// maximum opacity, one RGBA texel; with casting meshes (two layers a face) their crossings
// as at most two steps in a second texel (SurfaceStepsBuild.glsl; BuildOpacityLevels and
// OpacityLevelsShadow in Core/Shadows/OpacityLevels.cxx are the CPU twins): a crossing
// between two points is placed by the paper's smoothstep; rays stop below 1/512 of what the
// volume and the meshes let through together, like feelers.
//@Dec
layout(rgba32f, binding = 0) uniform writeonly image2DArray u_output;
uniform vec3 u_levels;
bool g_started;
float g_transmittance; // the volume's
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

bool levelsMore()
{
  return g_transmittance * surfaceStepsTransmittance() > 1.0 / 512.0;
}

// The volume's visibility starts at its first sample's start.
void levelsStart(float t)
{
  if (!g_started)
  {
    g_started = true;
    g_previousDepth = t - 0.5 * u_feelerStep;
    g_maxDepth = g_previousDepth;
  }
}

bool visitSample(int j, float t, float scalar)
{
  levelsStart(t);
  g_transmittance *= 1.0 - feelerAlpha(scalar);
  levelsPoint(t + 0.5 * u_feelerStep);
  return levelsMore();
}

bool visitSkipped(int j, float t)
{
  levelsStart(t);
  levelsPoint(t + 0.5 * u_feelerStep);
  return true;
}
//@Surface
bool visitSurface(float t, int surface)
{
  addSurfaceStep(t, u_surfaceTransmission[surface].a);
  return levelsMore();
}
//@Texel
void buildTexel(vec3 indexOrigin, vec3 indexDirection, float tEnter, float tExit)
{
  g_started = false;
  g_transmittance = 1.0;
  g_levelDepth = vec3(NoHit);
  g_maxOpacity = 0.0;
  g_previousOpacity = 0.0;
  resetSurfaceSteps();
  marchTexel(indexOrigin, indexDirection, tEnter, tExit);
  if (g_maxOpacity > 0.0)
  {
    g_levelDepth = mix(g_levelDepth, vec3(g_maxDepth), equal(g_levelDepth, vec3(NoHit)));
  }
  imageStore(u_output, ivec3(g_texel, u_layer), vec4(g_levelDepth, g_maxOpacity));
  if (u_layersPerFace > 1)
  {
    imageStore(u_output, ivec3(g_texel, u_layer + 1), surfaceStepsTexel());
  }
}
