#version 330 core
// A mesh lit by the renderer's lights and, with a shadow source, shadowed by the scene's
// shadow structure of each light (the one every caster went into). The hybrid part of
// deepshadow::ReferenceRenderer (ShadeSurface) is the CPU twin. Output is premultiplied.
layout(location = 0) out vec4 fragColor;
in vec3 v_position;
in vec4 v_color;
uniform vec3 u_cameraPosition;
uniform vec3 u_viewDirection; // parallel projection: the direction the camera looks
uniform int u_parallel;
uniform float u_opacity;      // the actor's

// What the shadow lookup reads: the casting volume and surfaces (features in use only).
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
//DeepShadow::MeshNormal::Dec
//DeepShadow::Lighting::Dec
//DeepShadow::Peel::Dec

void main()
{
  //DeepShadow::MeshNormal::Face
  //DeepShadow::Peel::Init
  vec3 toViewer = u_parallel != 0 ? -u_viewDirection : normalize(u_cameraPosition - v_position);
  vec3 color = lightSample(v_color.rgb, vec3(0.0), v_position, toViewer);
  float alpha = v_color.a * u_opacity;
  fragColor = vec4(color * alpha, alpha);
  //DeepShadow::Peel::Exit
}
