#version 430 core
// A brick's total transmittance per light-space texel (vtkDeepShadowBrickExchange): the
// technique's own lookup (runtime feature Lookup) at the texel's centre, beyond the far end
// of its ray. One invocation per texel of every face of every light: layer
// slot * u_shadowFacesPerLight + face of the output.
layout(local_size_x = 8, local_size_y = 8) in;
//DeepShadow::VolumeSampling::Dec
//DeepShadow::Isosurface::Dec
//DeepShadow::OpacityScale::Dec
//DeepShadow::GradientOpacity::Dec
//DeepShadow::Mask::Dec
//DeepShadow::LabelMap::Dec
//DeepShadow::Transfer2D::Dec
//DeepShadow::EmptySpace::Dec
//DeepShadow::TriangleHierarchy::Dec
//DeepShadow::Bound::Dec
//DeepShadow::Surfaces::Dec
//DeepShadow::Feeler::Dec
//DeepShadow::Hash::Dec
//DeepShadow::Lookup::Dec
layout(rgba32f, binding = 0) uniform writeonly image2DArray u_output;
uniform int u_slots;

// Beyond every stored depth (NoHit, the largest float, marks a texel whose ray found nothing).
const float FarDepth = 3.0e38;

void main()
{
  ivec3 at = ivec3(gl_GlobalInvocationID);
  int size = int(u_shadowSize);
  if (at.x >= size || at.y >= size || at.z >= u_slots * u_shadowFacesPerLight)
  {
    return;
  }
  int slot = at.z / u_shadowFacesPerLight;
  int face = at.z % u_shadowFacesPerLight;
  vec3 total = vec3(1.0);
  if (face < u_shadowFaceCount[slot])
  {
    total = mapVisibility(at.z * u_shadowLayersPerFace, vec2(at.xy), FarDepth, vec2(0.0));
  }
  imageStore(u_output, at, vec4(total, 1.0));
}
