#version 330 core
// Composite ray casting of one volume; the GPU twin of deepshadow::ReferenceRenderer::MarchRay
// (vtkDeepShadow/Core/ReferenceRenderer.cxx). Optional features (Shaders/Features/*.glsl)
// are spliced in at their tags by ShaderComposer; a feature that is off leaves its tags
// empty, so its code is not compiled at all.
//
// Conventions shared with the CPU: positions are continuous voxel indices (voxel i at i,
// texture coordinate (i + 0.5) / Dims); t is world distance along the ray from the near
// plane; samples sit at t0 + (k + offset) * u_step.

//DeepShadow::VolumeSegments::Output
#ifndef VOLUME_SEGMENT_OUTPUT
layout(location = 0) out vec4 fragColor;
#endif

//DeepShadow::VolumeSampling::Dec
//DeepShadow::Isosurface::Dec
//DeepShadow::OpacityScale::Dec
//DeepShadow::GradientOpacity::Dec
//DeepShadow::Mask::Dec
//DeepShadow::LabelMap::Dec
//DeepShadow::Transfer2D::Dec
uniform sampler2D u_transfer;    // RGBA table: colour, opacity corrected for u_step
//DeepShadow::Components::ViewDec
uniform mat4 u_clipToWorld;      // inverse view-projection
uniform vec4 u_viewport;         // x, y, width, height in window pixels
uniform float u_step;            // world distance between samples
uniform float u_terminationOpacity;

vec3 unproject(vec2 ndc, float z)
{
  vec4 p = u_clipToWorld * vec4(ndc, z, 1.0);
  return p.xyz / p.w;
}

// Ray t of the surface drawn at window depth `depth` in this pixel (opaque or peeled).
float windowDepthToRayT(float depth, vec2 ndc, vec3 rayOrigin, vec3 rayDirection)
{
  return dot(unproject(ndc, 2.0 * depth - 1.0) - rayOrigin, rayDirection);
}

// Front-to-back "over" (deepshadow::CompositeFrontToBack).
void compositeFrontToBack(inout vec4 accumulated, vec3 color, float alpha)
{
  float weight = (1.0 - accumulated.a) * alpha;
  accumulated += vec4(weight * color, weight);
}

// Declarations of the features in use (they may call the helpers above).
//DeepShadow::Jitter::Dec
//DeepShadow::OpaqueDepth::Dec
//DeepShadow::EmptySpace::Dec
//DeepShadow::TriangleHierarchy::Dec
//DeepShadow::Bound::Dec
//DeepShadow::Surfaces::Dec
//DeepShadow::Feeler::Dec
//DeepShadow::ShadowRatio::Dec
//DeepShadow::Lighting::Dec
//DeepShadow::TranslucentLayers::Dec
//DeepShadow::VolumeSegments::Dec
//DeepShadow::Projection::Dec
//DeepShadow::UserShader::Dec
//DeepShadow::DatasetOpacity::Dec
//DeepShadow::ShadowRatioApply::Dec

void main()
{
  vec2 pixel = gl_FragCoord.xy - u_viewport.xy;
  //DeepShadow::ShadowRatio::Pixel
  vec2 ndc = 2.0 * pixel / u_viewport.zw - 1.0;
  vec3 rayOrigin = unproject(ndc, -1.0);
  vec3 rayDirection = normalize(unproject(ndc, 1.0) - rayOrigin);

  // Box [0, Dims - 1] in index space; t stays world distance (deepshadow::IntersectBox).
  vec3 indexOrigin = (u_worldToIndex * vec4(rayOrigin, 1.0)).xyz;
  vec3 indexDirection = (u_worldToIndex * vec4(rayDirection, 0.0)).xyz;
  vec2 inside = boxInterval(indexOrigin, indexDirection);
  float t0 = max(inside.x, 0.0);
  float t1 = inside.y;

  //DeepShadow::OpaqueDepth::Impl
  //DeepShadow::TranslucentLayers::Init

  if (!(t0 < t1))
  {
    //DeepShadow::TranslucentLayers::Miss
    discard;
  }

  float offset = 0.5;
  //DeepShadow::Jitter::Impl

  vec4 accumulated = vec4(0.0);
  //DeepShadow::EmptySpace::Init
  //DeepShadow::Bound::Init
  //DeepShadow::VolumeSegments::Init
  //DeepShadow::Projection::Init
  //DeepShadow::Isosurface::Init
  //DeepShadow::DatasetOpacity::Init
  //DeepShadow::UserShader::Init
  //DeepShadow::ShadowRatio::Init
  for (int k = 0;; ++k)
  {
    float t = t0 + (float(k) + offset) * u_step;
    if (!(t < t1) || accumulated.a > u_terminationOpacity)
    {
      break;
    }
    //DeepShadow::TranslucentLayers::Impl
    //DeepShadow::Bound::Impl
    vec3 index = indexOrigin + t * indexDirection;
    //DeepShadow::UserShader::Impl
    //DeepShadow::UserShader::ImplEnd
    //DeepShadow::EmptySpace::Impl

    //DeepShadow::Mask::Impl
    float scalar = sampleScalar(index);
    float receiverT = t; // where the sample receives light (Isosurface: the sample before)
    //DeepShadow::Isosurface::Impl
    //DeepShadow::Projection::Impl
    vec4 transfer = texture(u_transfer, vec2(scalar * u_tableMap.x + u_tableMap.y, 0.5));
    //DeepShadow::Transfer2D::Impl
    //DeepShadow::Components::Impl
    //DeepShadow::LabelMap::Impl
    //DeepShadow::GradientOpacity::Impl
    //DeepShadow::DatasetOpacity::Impl
    if (transfer.a <= 0.0)
    {
      continue;
    }
    vec3 color = transfer.rgb;
    //DeepShadow::ShadowRatio::Unshadowed
    //DeepShadow::Lighting::Impl
    //DeepShadow::LabelMap::Lit
    //DeepShadow::VolumeSegments::Impl
    //DeepShadow::UserShader::Sample
    //DeepShadow::ShadowRatio::Impl
    compositeFrontToBack(accumulated, color, transfer.a);
  }
  //DeepShadow::TranslucentLayers::Exit
  //DeepShadow::VolumeSegments::Exit
  //DeepShadow::Projection::Exit
  //DeepShadow::UserShader::Exit
  //DeepShadow::UserShader::ExitEnd
  //DeepShadow::ShadowRatioApply::Exit
  // Premultiplied; blended with (ONE, ONE_MINUS_SRC_ALPHA), or replacing the pixel when the
  // translucent layers (and the opaque image behind them) are composited here.
  fragColor = accumulated;
  //DeepShadow::ShadowRatio::Output
  //DeepShadow::UserShader::Output
}
