// Feature GradientOpacity: a sample's opacity times the gradient-opacity function of its
// gradient magnitude, as VTK's mapper measures it: central differences one voxel apart, each
// axis in data units per mean spacing, clamped to a quarter of the data's range
// (deepshadow::GradientOpacity in Core/GradientOpacity.h is the CPU twin). The view ray, the
// feelers and the light-space builds all apply it: what it leaves clear casts nothing.
//@Dec
uniform sampler2D u_gradientOpacity;   // the function's table over [0, u_gradientOpacityMax] (alpha)
uniform vec2 u_gradientOpacityMap;     // table coordinate = magnitude * .x + .y
uniform vec3 u_gradientOpacityScale;   // per index axis: mean spacing / spacing, in data units
uniform float u_gradientOpacityMax;

float gradientOpacity(vec3 index)
{
  float magnitude = clamp(length(indexGradient(index) * u_gradientOpacityScale), 0.0, u_gradientOpacityMax);
  return texture(u_gradientOpacity, vec2(magnitude * u_gradientOpacityMap.x + u_gradientOpacityMap.y, 0.5)).a;
}
//@Impl
    if (transfer.a > 0.0)
    {
      transfer.a *= gradientOpacity(index);
    }
//@FeelerSample
    g_opacityScale *= gradientOpacity(sampleIndex);
//@TexelSample
    g_opacityScale *= gradientOpacity(sampleIndex);
