// Build of "fom", Fourier opacity maps (FourierSeriesBuilder and FourierOpacityMap in
// Core/Shadows/FourierOpacityMap.cxx are the CPU twins): per texel the sums of each sample's
// optical depth times cos and sin of 2 pi k x (x = depth / End, End the box's exit plus one
// step, rounded up to free 12 bits for First, where the first absorbing sample starts),
// turned into the stored coefficients at the end (a sample is a box one step wide:
// sinc(k step / End) / (pi k)); FOM_LAYERS RGBA layers (End with First, Total, A_1, B_1, A_2,
// ...), with
// casting meshes one more of their steps (SurfaceStepsBuild.glsl). Rays stop below 1/512 of
// what the volume and the meshes let through together, like feelers.
//@Dec
layout(rgba32f, binding = 0) uniform writeonly image2DArray u_output;
const int FourierTerms = 2 * FOM_LAYERS - 1;
const float FourierPi = 3.14159265358979;
float g_transmittance; // the volume's
float g_end;
float g_first;
float g_total;
float g_cosSum[FourierTerms];
float g_sinSum[FourierTerms];

// Optical depth `tau` at the sample centred at depth t; cos and sin of k angle by rotation.
void fourierAdd(float t, float tau)
{
  if (g_total == 0.0)
  {
    g_first = t - 0.5 * u_feelerStep;
  }
  g_total += tau;
  float angle = 2.0 * FourierPi * t / g_end;
  vec2 base = vec2(cos(angle), sin(angle));
  vec2 r = base;
  for (int k = 0; k < FourierTerms; ++k)
  {
    g_cosSum[k] += tau * r.x;
    g_sinSum[k] += tau * r.y;
    r = vec2(r.x * base.x - r.y * base.y, r.y * base.x + r.x * base.y);
  }
}

bool fourierMore()
{
  return g_transmittance * surfaceStepsTransmittance() > 1.0 / 512.0;
}

bool visitSample(int j, float t, float scalar)
{
  float opacity = feelerAlpha(scalar);
  g_transmittance *= 1.0 - opacity;
  // An opaque sample counts as 1/1024 let through: the series stays finite.
  fourierAdd(t, -log(max(1.0 - opacity, 1.0 / 1024.0)));
  return fourierMore();
}

bool visitSkipped(int j, float t)
{
  return true;
}
//@Surface
bool visitSurface(float t, int surface)
{
  addSurfaceStep(t, u_surfaceTransmission[surface].a);
  return fourierMore();
}
//@Texel
// The stored coefficient of pair k (1-based), the sum `sum`: times sinc(k width) / (pi k).
float fourierCoefficient(int k, float width, float sum)
{
  float h = FourierPi * float(k) * width;
  return (h > 0.0 ? sin(h) / h : 1.0) / (FourierPi * float(k)) * sum;
}

void buildTexel(vec3 indexOrigin, vec3 indexDirection, float tEnter, float tExit)
{
  g_transmittance = 1.0;
  g_total = 0.0;
  g_first = 0.0;
  g_end = seriesEnd(tEnter, tExit, u_feelerStep);
  for (int k = 0; k < FourierTerms; ++k)
  {
    g_cosSum[k] = 0.0;
    g_sinSum[k] = 0.0;
  }
  resetSurfaceSteps();
  marchTexel(indexOrigin, indexDirection, tEnter, tExit);
  float width = u_feelerStep / g_end;
  float packedEnd = packSeriesEnd(g_end, g_first);
  imageStore(u_output, ivec3(g_texel, u_layer),
    vec4(packedEnd, g_total, fourierCoefficient(1, width, g_cosSum[0]), fourierCoefficient(1, width, g_sinSum[0])));
  for (int l = 1; l < FOM_LAYERS; ++l)
  {
    int k = 2 * l; // pairs k and k + 1
    imageStore(u_output, ivec3(g_texel, u_layer + l),
      vec4(fourierCoefficient(k, width, g_cosSum[k - 1]), fourierCoefficient(k, width, g_sinSum[k - 1]),
        fourierCoefficient(k + 1, width, g_cosSum[k]), fourierCoefficient(k + 1, width, g_sinSum[k])));
  }
  if (u_layersPerFace > FOM_LAYERS)
  {
    imageStore(u_output, ivec3(g_texel, u_layer + FOM_LAYERS), surfaceStepsTexel());
  }
}
