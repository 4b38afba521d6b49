// Feature Isotropic: light scattered equally in all directions, for volumes that are not
// shaded but receive shadows (deepshadow::IsotropicLightScale: fully lit keeps the colour,
// the material's ambient is the shadows' floor; ReferenceRay.cxx's `shade` is the twin).
//@Dec
uniform float u_isotropicLightScale;
//@Surface
    contribution = max(vec3(1.0) - material.x * u_ambientLight, 0.0) * u_isotropicLightScale *
      u_lightDiffuse[i] * color;
