// The casting meshes of a light-space build as at most two steps in one RGBA texel, for
// the techniques whose volume representation would smear a mesh's sharp crossing (opacity
// levels, Fourier opacity maps): deepshadow::SurfaceStepsBuilder in
// Core/Shadows/SurfaceSteps.cxx is the CPU twin. Depth and own transmission of up to three;
// a third folds the more transparent of the last two into the one before it. A technique
// prepends this to its build source, calls resetSurfaceSteps() per texel, addSurfaceStep()
// per crossing and stores surfaceStepsTexel() in its last layer.
//@Dec
vec3 g_stepDepth;
vec3 g_stepOwn;
int g_steps;

void resetSurfaceSteps()
{
  g_steps = 0;
}

void addSurfaceStep(float depth, float transmission)
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

// Everything the steps let through so far.
float surfaceStepsTransmittance()
{
  float t = 1.0;
  for (int k = 0; k < g_steps; ++k)
  {
    t *= g_stepOwn[k];
  }
  return t;
}

// Depth and transmittance from there, twice (NoHit depths: no step).
vec4 surfaceStepsTexel()
{
  vec4 steps = vec4(NoHit, 1.0, NoHit, 1.0);
  float t = 1.0;
  for (int k = 0; k < g_steps; ++k)
  {
    t *= g_stepOwn[k];
    steps[2 * k] = g_stepDepth[k];
    steps[2 * k + 1] = t;
  }
  return steps;
}
