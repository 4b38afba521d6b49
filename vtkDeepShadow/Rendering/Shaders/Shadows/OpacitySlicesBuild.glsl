// Build of "slices", uniform opacity slices (SliceTexel in Core/Shadows/OpacitySlices.cxx is
// the CPU twin): the ray's transmittance, linear across each sample, taken at SLICES depths
// evenly spaced over u_lightDepthRange (slice i at (i + 1) / SLICES of it; at a mesh's step, the
// value before it); slices beyond where the ray stops (below 1/512) or leaves the box keep
// its last value. Four slices per RGBA8 layer.
//@Dec
layout(rgba8, binding = 0) uniform writeonly image2DArray u_output;
uniform float u_lightDepthRange; // world depth of the last slice (LightDepthRange; set by the base class)
float g_slice[SLICES];
int g_next; // the first slice not yet taken
float g_transmittance;

float sliceDepth(int i)
{
  return float(i + 1) * u_lightDepthRange / float(SLICES);
}

// The slices up to depth `end` of the piece from `start` (transmittance `from`) to `end`
// (`to`), linear between; slices in front of `start` take `from`.
bool takeSlices(float start, float end, float from, float to)
{
  while (g_next < SLICES && sliceDepth(g_next) <= end)
  {
    float depth = sliceDepth(g_next);
    g_slice[g_next] = depth <= start ? from : mix(from, to, (depth - start) / (end - start));
    ++g_next;
  }
  return g_transmittance > 1.0 / 512.0;
}

bool visitSample(int j, float t, float scalar)
{
  float before = g_transmittance;
  g_transmittance *= 1.0 - feelerAlpha(scalar);
  return takeSlices(t - 0.5 * u_feelerStep, t + 0.5 * u_feelerStep, before, g_transmittance);
}

bool visitSkipped(int j, float t)
{
  return takeSlices(t - 0.5 * u_feelerStep, t + 0.5 * u_feelerStep, g_transmittance, g_transmittance);
}
//@Surface
bool visitSurface(float t, int surface)
{
  takeSlices(t, t, g_transmittance, g_transmittance);
  g_transmittance *= u_surfaceTransmission[surface].a;
  return g_transmittance > 1.0 / 512.0;
}
//@Texel
void buildTexel(vec3 indexOrigin, vec3 indexDirection, float tEnter, float tExit)
{
  g_next = 0;
  g_transmittance = 1.0;
  marchTexel(indexOrigin, indexDirection, tEnter, tExit);
  for (int i = g_next; i < SLICES; ++i)
  {
    g_slice[i] = g_transmittance;
  }
  // In 255ths plus a quarter, so that a conversion that truncates stores them as one that
  // rounds does.
  for (int l = 0; l < SLICES / 4; ++l)
  {
    vec4 slices = vec4(g_slice[4 * l], g_slice[4 * l + 1], g_slice[4 * l + 2], g_slice[4 * l + 3]);
    imageStore(u_output, ivec3(g_texel, u_layer + l), min((floor(clamp(slices, 0.0, 1.0) * 255.0 + 0.5) + 0.25) / 255.0, vec4(1.0)));
  }
}
