// Feature Transfer2D: a 2D transfer function (vtkVolumeProperty TF_2D) as VTK 9.1's mapper reads
// it: colour and opacity from an RGBA image at (the scalar over the data's range, the gradient
// magnitude VTK measures over a quarter of that range), the opacity as given for a view step;
// deepshadow::Transfer2D in Core/Transfer2D.h is the CPU twin. The view ray, the feelers and
// the light-space builds all read it: what is drawn casts.
//@Dec
uniform sampler2D u_transfer2D;          // the image, linearly filtered
uniform vec2 u_transfer2DSize;           // its width and height in texels
uniform vec4 u_transfer2DImageMap;       // normalized (scalar, magnitude) -> image position (x: xy, y: zw)
uniform vec2 u_transfer2DNormalize;      // the shaders' scalar -> [0, 1] over the data's range
uniform vec3 u_transfer2DGradientScale;  // per index axis: to data units per mean spacing
uniform float u_transfer2DGradientMax;   // a quarter of the data's range
uniform float u_transfer2DViewStep;      // the step its opacities hold for (the view's, still)
float g_transfer2DMagnitude = 0.0;       // the light's sample at hand's

float transfer2DMagnitude(vec3 index)
{
  return clamp(length(indexGradient(index) * u_transfer2DGradientScale), 0.0, u_transfer2DGradientMax);
}

// Colour and opacity at the shaders' scalar `scalar` of magnitude `magnitude`, its opacity a
// seen by a step of `stepRatio` view steps as 1 - (1 - a)^stepRatio.
vec4 transfer2D(float scalar, float magnitude, float stepRatio)
{
  vec2 normalized = clamp(vec2(scalar * u_transfer2DNormalize.x + u_transfer2DNormalize.y,
                            magnitude / u_transfer2DGradientMax), 0.0, 1.0);
  vec2 position = clamp(normalized * u_transfer2DImageMap.xz + u_transfer2DImageMap.yw, vec2(0.0),
    u_transfer2DSize - 1.0);
  vec4 rgba = texture(u_transfer2D, (position + 0.5) / u_transfer2DSize);
  rgba.a = 1.0 - pow(max(1.0 - rgba.a, 0.0), stepRatio);
  return rgba;
}
//@Impl
    transfer = transfer2D(scalar, transfer2DMagnitude(index), 1.0);
//@FeelerSample
    g_transfer2DMagnitude = transfer2DMagnitude(sampleIndex);
//@TexelSample
    g_transfer2DMagnitude = transfer2DMagnitude(sampleIndex);
//@FeelerLookup
  rgba = transfer2D(scalar, g_transfer2DMagnitude, u_feelerStep / u_transfer2DViewStep);
