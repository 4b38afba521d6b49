// Feature ShadowTerm: the image shows the shadow term alone (deepshadow::RenderOutput::
// ShadowTerm, whose CPU twin is in deepshadow::ReferenceRenderer::MarchRay): each sample's
// colour becomes the product of 1 - attenuation (1 - visibility) over the lights that reach
// it, composited with the volume's opacity as colours are.
//@Start
  vec3 shadowTerm = vec3(1.0);
//@Accumulate
      shadowTerm *= shadowFactor;
//@Return
  return clamp(shadowTerm, 0.0, 1.0);
