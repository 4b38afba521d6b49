// Build of "moments", power-moment maps (PowerMomentBuilder and PowerMomentMap in
// Core/Shadows/PowerMomentMap.cxx are the CPU twins): per texel the sums of each sample's
// optical depth times the k-th moment of its box (z = 2 t / End - 1, End the box's exit plus
// one step, rounded up to free 12 bits for First, where the first absorbing sample starts),
// divided by the total at the end; MOMENTS_LAYERS RGBA layers (End with First, b0, b_1, ...),
// with casting meshes one more of their steps (SurfaceStepsBuild.glsl). Rays stop below 1/512
// of what the volume and the meshes let through together, like feelers.
//@Dec
layout(rgba32f, binding = 0) uniform writeonly image2DArray u_output;
float g_transmittance; // the volume's
float g_end;
float g_first;
float g_total;
float g_sums[POWER_MOMENTS];

// Optical depth `tau` at the sample centred at depth t: times the k-th moment of the uniform
// distribution on [z - h, z + h], sum over even j of C(k, j) z^(k - j) h^j / (j + 1) (BoxMoment;
// powers by products: pow() is undefined for a negative base).
void momentsAdd(float t, float tau)
{
  if (g_total == 0.0)
  {
    g_first = t - 0.5 * u_feelerStep;
  }
  g_total += tau;
  float z = 2.0 * t / g_end - 1.0;
  float h = u_feelerStep / g_end;
  float zPower[POWER_MOMENTS + 1];
  float hPower[POWER_MOMENTS + 1];
  zPower[0] = 1.0;
  hPower[0] = 1.0;
  for (int k = 1; k <= POWER_MOMENTS; ++k)
  {
    zPower[k] = zPower[k - 1] * z;
    hPower[k] = hPower[k - 1] * h;
  }
  for (int k = 1; k <= POWER_MOMENTS; ++k)
  {
    float moment = 0.0;
    float binomial = 1.0;
    for (int j = 0; j <= k; ++j)
    {
      if (j % 2 == 0)
      {
        moment += binomial * zPower[k - j] * hPower[j] / float(j + 1);
      }
      binomial = binomial * float(k - j) / float(j + 1);
    }
    g_sums[k - 1] += tau * moment;
  }
}

bool momentsMore()
{
  return g_transmittance * surfaceStepsTransmittance() > 1.0 / 512.0;
}

bool visitSample(int j, float t, float scalar)
{
  float opacity = feelerAlpha(scalar);
  g_transmittance *= 1.0 - opacity;
  // An opaque sample counts as 1/1024 let through: the moments stay finite.
  momentsAdd(t, -log(max(1.0 - opacity, 1.0 / 1024.0)));
  return momentsMore();
}

bool visitSkipped(int j, float t)
{
  return true;
}
//@Surface
bool visitSurface(float t, int surface)
{
  addSurfaceStep(t, u_surfaceTransmission[surface].a);
  return momentsMore();
}
//@Texel
void buildTexel(vec3 indexOrigin, vec3 indexDirection, float tEnter, float tExit)
{
  g_transmittance = 1.0;
  g_total = 0.0;
  g_first = 0.0;
  g_end = seriesEnd(tEnter, tExit, u_feelerStep);
  for (int k = 0; k < POWER_MOMENTS; ++k)
  {
    g_sums[k] = 0.0;
  }
  resetSurfaceSteps();
  marchTexel(indexOrigin, indexDirection, tEnter, tExit);
  float packedEnd = packSeriesEnd(g_end, g_first);
  float values[4 * MOMENTS_LAYERS];
  for (int i = 0; i < 4 * MOMENTS_LAYERS; ++i)
  {
    values[i] = 0.0;
  }
  values[0] = packedEnd;
  values[1] = g_total;
  for (int k = 1; k <= POWER_MOMENTS && g_total > 0.0; ++k)
  {
    values[1 + k] = g_sums[k - 1] / g_total;
  }
  for (int l = 0; l < MOMENTS_LAYERS; ++l)
  {
    imageStore(u_output, ivec3(g_texel, u_layer + l),
      vec4(values[4 * l], values[4 * l + 1], values[4 * l + 2], values[4 * l + 3]));
  }
  if (u_layersPerFace > MOMENTS_LAYERS)
  {
    imageStore(u_output, ivec3(g_texel, u_layer + MOMENTS_LAYERS), surfaceStepsTexel());
  }
}
