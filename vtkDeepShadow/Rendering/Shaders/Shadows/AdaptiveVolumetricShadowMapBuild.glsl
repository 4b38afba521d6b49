// Build of "avsm", adaptive volumetric shadow maps (AdaptiveNodesBuilder and
// AdaptiveVolumetricShadowMap in Core/Shadows/AdaptiveVolumetricShadowMap.cxx are the CPU
// twins): front to back, an absorbing sample appends a node at its end (and one at its
// start after samples that absorbed nothing); past AVSM_NODES nodes the interior node whose
// triangle with its neighbours has the smallest area goes. AVSM_NODES / 2 RGBA layers of
// (depth, transmittance) pairs, unused nodes at NoHit with the last transmittance; with
// casting meshes one more layer of their steps (SurfaceStepsBuild.glsl). Rays stop below
// 1/512 of what the volume and the meshes let through together, like feelers.
//@Dec
layout(rgba32f, binding = 0) uniform writeonly image2DArray u_output;
float g_transmittance; // the volume's
bool g_absorbing;
int g_nodes;
float g_nodeDepth[AVSM_NODES + 1];
float g_nodeValue[AVSM_NODES + 1];

void adaptiveAppend(float depth, float value)
{
  g_nodeDepth[g_nodes] = depth;
  g_nodeValue[g_nodes] = value;
  if (++g_nodes <= AVSM_NODES)
  {
    return;
  }
  int drop = 1;
  float smallest = 0.0;
  for (int i = 1; i + 1 < g_nodes; ++i)
  {
    float area = abs((g_nodeDepth[i] - g_nodeDepth[i - 1]) * (g_nodeValue[i + 1] - g_nodeValue[i - 1]) -
      (g_nodeDepth[i + 1] - g_nodeDepth[i - 1]) * (g_nodeValue[i] - g_nodeValue[i - 1]));
    if (i == 1 || area < smallest)
    {
      smallest = area;
      drop = i;
    }
  }
  for (int i = drop; i < AVSM_NODES; ++i)
  {
    g_nodeDepth[i] = g_nodeDepth[i + 1];
    g_nodeValue[i] = g_nodeValue[i + 1];
  }
  g_nodes = AVSM_NODES;
}

bool adaptiveMore()
{
  return g_transmittance * surfaceStepsTransmittance() > 1.0 / 512.0;
}

bool visitSample(int j, float t, float scalar)
{
  float transmission = 1.0 - feelerAlpha(scalar);
  if (transmission >= 1.0)
  {
    g_absorbing = false;
    return true;
  }
  if (!g_absorbing)
  {
    adaptiveAppend(t - 0.5 * u_feelerStep, g_transmittance);
  }
  g_absorbing = true;
  g_transmittance *= transmission;
  adaptiveAppend(t + 0.5 * u_feelerStep, g_transmittance);
  return adaptiveMore();
}

bool visitSkipped(int j, float t)
{
  g_absorbing = false;
  return true;
}
//@Surface
bool visitSurface(float t, int surface)
{
  addSurfaceStep(t, u_surfaceTransmission[surface].a);
  return adaptiveMore();
}
//@Texel
void buildTexel(vec3 indexOrigin, vec3 indexDirection, float tEnter, float tExit)
{
  g_transmittance = 1.0;
  g_absorbing = false;
  g_nodes = 0;
  resetSurfaceSteps();
  marchTexel(indexOrigin, indexDirection, tEnter, tExit);
  float last = g_nodes > 0 ? g_nodeValue[g_nodes - 1] : 1.0;
  for (int l = 0; l < AVSM_NODES / 2; ++l)
  {
    int i = 2 * l;
    imageStore(u_output, ivec3(g_texel, u_layer + l),
      vec4(i < g_nodes ? g_nodeDepth[i] : NoHit, i < g_nodes ? g_nodeValue[i] : last,
        i + 1 < g_nodes ? g_nodeDepth[i + 1] : NoHit, i + 1 < g_nodes ? g_nodeValue[i + 1] : last));
  }
  if (u_layersPerFace > AVSM_NODES / 2)
  {
    imageStore(u_output, ivec3(g_texel, u_layer + AVSM_NODES / 2), surfaceStepsTexel());
  }
}
