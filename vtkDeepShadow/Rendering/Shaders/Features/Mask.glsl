// Feature Mask: a binary mask (vtkGPUVolumeRayCastMapper::SetMaskInput), read as VTK's mapper
// reads it: a sample is clear where the mask's nearest voxel is 0 or less (the texture filters
// nearest); deepshadow::MaskFactor in Core/Mask.h is the CPU twin. The view ray (composite
// and projections), the feelers and the light-space builds all apply it: what the mask clears
// casts nothing.
//@Dec
uniform sampler3D u_mask;
uniform vec2 u_maskToData; // texel -> the mask's data value

float maskFactor(vec3 index)
{
  return texture(u_mask, (index + 0.5) / u_dims).r * u_maskToData.x + u_maskToData.y > 0.0 ? 1.0 : 0.0;
}
//@Impl
    // Skipped in every blend mode, as VTK's mapper skips it (composite: as if clear).
    if (maskFactor(index) <= 0.0)
    {
      continue;
    }
//@FeelerSample
    g_opacityScale *= maskFactor(sampleIndex);
//@TexelSample
    g_opacityScale *= maskFactor(sampleIndex);
