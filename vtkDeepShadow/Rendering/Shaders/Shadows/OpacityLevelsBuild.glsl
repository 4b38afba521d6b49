// Build of "dsm3": the depths where the volume's accumulated opacity crosses u_levels and its
// maximum opacity, one RGBA texel; with casting meshes (two layers a face) their crossings
// as at most two steps in a second texel (BuildOpacityLevels, SurfaceStepsBuilder and
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

// The meshes' steps (deepshadow::SurfaceStepsBuilder): depth and own transmission of up to
// three; a third folds the more transparent of the last two into the one before it.
vec3 g_stepDepth;
vec3 g_stepOwn;
int g_steps;

void addStep(float depth, float transmission)
{
  g_stepDepth[g_steps] = depth;
  g_stepOwn[g_steps] = transmission;
  if (++g_steps < 3)
  {
    return;
  }
  int folded = g_stepOwn[1] > g_stepOwn[2] ? 1 : 2;
  g_stepOwn[folded - 1] *= g_stepOwn[folded];
  if (folded == 1)
  {
    g_stepDepth[1] = g_stepDepth[2];
    g_stepOwn[1] = g_stepOwn[2];
  }
  g_steps = 2;
}

float stepsTransmittance()
{
  float t = 1.0;
  for (int k = 0; k < g_steps; ++k)
  {
    t *= g_stepOwn[k];
  }
  return t;
}

bool levelsMore()
{
  return g_transmittance * stepsTransmittance() > 1.0 / 512.0;
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
  addStep(t, u_surfaceTransmission[surface].a);
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
  g_steps = 0;
  marchTexel(indexOrigin, indexDirection, tEnter, tExit);
  if (g_maxOpacity > 0.0)
  {
    g_levelDepth = mix(g_levelDepth, vec3(g_maxDepth), equal(g_levelDepth, vec3(NoHit)));
  }
  imageStore(u_output, ivec3(g_texel, u_layer), vec4(g_levelDepth, g_maxOpacity));
  if (u_layersPerFace > 1)
  {
    vec4 steps = vec4(NoHit, 1.0, NoHit, 1.0); // depth, transmittance from there; twice
    float t = 1.0;
    for (int k = 0; k < g_steps; ++k)
    {
      t *= g_stepOwn[k];
      steps[2 * k] = g_stepDepth[k];
      steps[2 * k + 1] = t;
    }
    imageStore(u_output, ivec3(g_texel, u_layer + 1), steps);
  }
}
