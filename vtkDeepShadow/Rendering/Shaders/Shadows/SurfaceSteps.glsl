// Lookup of the casting meshes' steps that SurfaceStepsBuild.glsl stores (EvaluateSurfaceSteps
// in Core/Shadows/SurfaceSteps.cxx is the CPU twin): 1 before the first step's depth, each
// step's transmittance from its depth on.
//@Dec
float surfaceStepsVisibility(vec4 steps, float depth)
{
  return depth < steps.x ? 1.0 : depth < steps.z ? steps.y : steps.w;
}
