// Feature Isotropic: light scattered equally in all directions, for volumes that are not
// shaded but receive shadows (deepshadow::IsotropicLightScale: fully lit keeps the colour,
// the material's ambient is the shadows' floor; ReferenceRay.cxx's `shade` is the twin).
//@Dec
uniform float u_isotropicLightScale;
uniform vec3 u_isotropicUnlooped; // summed diffuse of the lights the loop leaves out (LoopedLights)
//@Start
  vec3 isotropicShare = max(vec3(1.0) - material.x * u_ambientLight, 0.0) * u_isotropicLightScale * color;
  lit += isotropicShare * u_isotropicUnlooped;
//@Surface
    contribution = isotropicShare * u_lightDiffuse[i];
