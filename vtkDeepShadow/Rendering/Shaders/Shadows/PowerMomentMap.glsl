// Lookup of "moments" (PowerMomentFractionBefore, PowerMomentOpticalDepth and
// PowerMomentMap::MapVisibility in Core/Shadows/PowerMomentMap.cxx are the CPU twins): the
// moments biased towards the uniform distribution's, the kernel polynomial's roots from
// H c = (1, z, ..., z^N) (Cholesky), the polynomial through MOMENTS_OVERESTIMATION at z and
// the indicator of "in front of z" at the roots (divided differences, the Newton form's
// products in powers), its integral the fraction of b0 in front of z; 0 up to First, b0 from End on; visibility
// exp(-b0 fraction), with casting meshes (a layer after the moments) times their steps';
// bilinear across the four nearest texels.
//@Dec
const int MomentsOrder = POWER_MOMENTS / 2;

// The real roots of c[0] + ... + c[N] x^N (N = 1, 2, 3), clamped to [-4, 4] (Roots).
void momentsRoots(float c[MomentsOrder + 1], out float roots[MomentsOrder])
{
#if POWER_MOMENTS == 2
  roots[0] = -c[0] / c[1];
#elif POWER_MOMENTS == 4
  float discriminant = max(c[1] * c[1] - 4.0 * c[2] * c[0], 0.0);
  float q = -0.5 * (c[1] + (c[1] < 0.0 ? -1.0 : 1.0) * sqrt(discriminant));
  roots[0] = q / c[2];
  roots[1] = c[0] / q;
#else
  float a = c[2] / c[3];
  float b = c[1] / c[3];
  float d = c[0] / c[3];
  float p = min(b - a * a / 3.0, -1e-12);
  float q = 2.0 * a * a * a / 27.0 - a * b / 3.0 + d;
  float m = 2.0 * sqrt(-p / 3.0);
  float theta = acos(clamp(3.0 * q / (p * m), -1.0, 1.0)) / 3.0;
  for (int k = 0; k < 3; ++k)
  {
    roots[k] = m * cos(theta - 2.0943951023931957 * float(k)) - a / 3.0;
  }
#endif
  for (int k = 0; k < MomentsOrder; ++k)
  {
    roots[k] = isnan(roots[k]) ? 4.0 : clamp(roots[k], -4.0, 4.0);
  }
}

// The fraction of the distribution in front of z from its stored moments b_1.. b_M.
float momentsFractionBefore(float stored[POWER_MOMENTS], float z)
{
  float b[POWER_MOMENTS + 1];
  b[0] = 1.0;
  for (int k = 1; k <= POWER_MOMENTS; ++k)
  {
    b[k] = (1.0 - MOMENTS_BIAS) * stored[k - 1] + MOMENTS_BIAS * (k % 2 == 0 ? 1.0 / float(k + 1) : 0.0);
  }
  float L[(MomentsOrder + 1) * (MomentsOrder + 1)];
  for (int i = 0; i <= MomentsOrder; ++i)
  {
    for (int j = 0; j <= i; ++j)
    {
      float sum = b[i + j];
      for (int k = 0; k < j; ++k)
      {
        sum -= L[i * (MomentsOrder + 1) + k] * L[j * (MomentsOrder + 1) + k];
      }
      L[i * (MomentsOrder + 1) + j] = i == j ? sqrt(max(sum, 1e-30)) : sum / L[j * (MomentsOrder + 1) + j];
    }
  }
  float c[MomentsOrder + 1];
  float power = 1.0;
  for (int i = 0; i <= MomentsOrder; ++i)
  {
    float sum = power;
    for (int k = 0; k < i; ++k)
    {
      sum -= L[i * (MomentsOrder + 1) + k] * c[k];
    }
    c[i] = sum / L[i * (MomentsOrder + 1) + i];
    power *= z;
  }
  for (int i = MomentsOrder; i >= 0; --i)
  {
    float sum = c[i];
    for (int k = i + 1; k <= MomentsOrder; ++k)
    {
      sum -= L[k * (MomentsOrder + 1) + i] * c[k];
    }
    c[i] = sum / L[i * (MomentsOrder + 1) + i];
  }
  float roots[MomentsOrder];
  momentsRoots(c, roots);
  float x[MomentsOrder + 1];
  float d[MomentsOrder + 1];
  x[0] = z;
  d[0] = MOMENTS_OVERESTIMATION;
  for (int i = 1; i <= MomentsOrder; ++i)
  {
    x[i] = roots[i - 1];
    for (int j = 0; j < i; ++j)
    {
      if (abs(x[i] - x[j]) < 1e-6)
      {
        x[i] = x[j] + (x[i] < x[j] ? -1e-6 : 1e-6);
      }
    }
    d[i] = x[i] < z ? 1.0 : 0.0;
  }
  for (int j = 1; j <= MomentsOrder; ++j)
  {
    for (int i = MomentsOrder; i >= j; --i)
    {
      d[i] = (d[i] - d[i - 1]) / (x[i] - x[i - j]);
    }
  }
  // The Newton form's integral: d[j] times that of prod_(i < j) (x - x_i), expanded in powers
  // of x as it grows (ascending, with the coefficient below carried along).
  float product[MomentsOrder + 1];
  product[0] = 1.0;
  for (int k = 1; k <= MomentsOrder; ++k)
  {
    product[k] = 0.0;
  }
  float fraction = d[0];
  for (int j = 1; j <= MomentsOrder; ++j)
  {
    float below = 0.0;
    float integral = 0.0;
    for (int k = 0; k <= j; ++k)
    {
      float coefficient = product[k];
      product[k] = below - x[j - 1] * coefficient;
      below = coefficient;
      integral += product[k] * b[k];
    }
    fraction += d[j] * integral;
  }
  return isnan(fraction) || isinf(fraction) ? 0.0 : clamp(fraction, 0.0, 1.0);
}

float momentsVisibility(int layer, ivec2 texel, vec2 xy, float pointDepth, vec2 slope)
{
  float depth = lightSpaceDepthAt(vec2(texel), xy, pointDepth, slope);
  float values[4 * MOMENTS_LAYERS];
  for (int l = 0; l < MOMENTS_LAYERS; ++l)
  {
    vec4 v = lightSpaceTexel(texel, layer + l);
    values[4 * l] = v.x;
    values[4 * l + 1] = v.y;
    values[4 * l + 2] = v.z;
    values[4 * l + 3] = v.w;
  }
  float end, first;
  unpackSeriesEnd(values[0], end, first);
  float total = values[1];
  float tau = 0.0;
  if (total > 0.0 && depth > first)
  {
    tau = total;
    if (depth < end)
    {
      float stored[POWER_MOMENTS];
      for (int k = 0; k < POWER_MOMENTS; ++k)
      {
        stored[k] = values[2 + k];
      }
      tau = total * momentsFractionBefore(stored, 2.0 * depth / end - 1.0);
    }
  }
  float visibility = exp(-tau);
  if (u_shadowLayersPerFace > MOMENTS_LAYERS)
  {
    visibility *= surfaceStepsVisibility(lightSpaceTexel(texel, layer + MOMENTS_LAYERS), depth);
  }
  return visibility;
}

vec3 mapVisibility(int layer, vec2 xy, float depth, vec2 slope)
{
  ivec2 i0;
  vec4 w = lightSpaceBilinear(xy, i0);
  return vec3(w.x * momentsVisibility(layer, i0, xy, depth, slope) +
    w.y * momentsVisibility(layer, i0 + ivec2(1, 0), xy, depth, slope) +
    w.z * momentsVisibility(layer, i0 + ivec2(0, 1), xy, depth, slope) +
    w.w * momentsVisibility(layer, i0 + ivec2(1, 1), xy, depth, slope));
}
