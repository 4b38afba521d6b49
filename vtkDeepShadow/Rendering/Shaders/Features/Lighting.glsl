// Feature Lighting: the renderer's lights, in world space (deepshadow::Light::At and
// deepshadow::ShadeVolumeSample are the CPU twins; VTKShading makes it VTK's). What a light does
// at a sample comes from Gradient (Phong of the gradient normal) or Isotropic (scattering
// without a normal, for unshaded volumes that receive shadows); Shadow scales each light by
// its visibility. Ambient light is never shadowed.
//
// What no light of the frame does is left out at composition (LightingShaderFeature): llvmpipe
// runs a branch's code even where no pixel takes it, so a positional light's attenuation and
// cone cost every directional light as well.
//@Dec
#ifndef POSITIONAL_LIGHTS
#define POSITIONAL_LIGHTS 1 // 0: every light is directional
#endif
#ifndef LIGHT_FROM_EYE
#define LIGHT_FROM_EYE 1    // 0: no light is shaded from the eye (u_lightFromEye is -1)
#endif
const int MaxLights = 8;
uniform int u_lightLoopCount;             // the lights the loop visits (deepshadow::LoopedLights)
uniform int u_lightLoop[MaxLights];
uniform int u_lightPositional[MaxLights];
uniform vec3 u_lightPosition[MaxLights];   // positional lights
uniform vec3 u_lightDirection[MaxLights];  // unit, towards the light (directional) or the
                                           // spot axis from the light (positional)
uniform vec3 u_lightDiffuse[MaxLights];    // colour x intensity
uniform vec3 u_lightSpecular[MaxLights];
uniform vec3 u_lightAttenuation[MaxLights];
uniform float u_lightConeCos[MaxLights];   // cos(cone angle); < -1 means no cone
uniform float u_lightExponent[MaxLights];
uniform int u_lightFromEye;                // the light shaded from the eye (a volume's lone
                                           // headlight, deepshadow::Light::ShadedFromEye); -1: none
uniform vec3 u_lightEye;                   // the eye, for it
uniform vec3 u_ambientLight;
uniform vec4 u_material;                   // ambient, diffuse, specular, specular power
uniform int u_twoSidedLighting;

bool lightPositional(int i)
{
  return POSITIONAL_LIGHTS != 0 && u_lightPositional[i] != 0;
}

// Towards light i from `p` (unit), and how far it is (1e30 for a directional light).
vec3 towardsLight(int i, vec3 p, out float lightDistance)
{
  lightDistance = 1e30;
  if (!lightPositional(i))
  {
    return u_lightDirection[i];
  }
  vec3 fromLight = p - u_lightPosition[i];
  lightDistance = length(fromLight);
  return lightDistance > 0.0 ? -fromLight / lightDistance : vec3(0.0, 0.0, 1.0);
}
//DeepShadow::VTKShading::Dec

// The material of what is lit: the volume's, or the component's being lit.
vec4 lightMaterial()
{
  //DeepShadow::Components::Material
  return u_material;
}
//DeepShadow::Gradient::Dec
//DeepShadow::Isotropic::Dec
//DeepShadow::ShadowGrid::Dec
//DeepShadow::Shadow::Dec
//DeepShadow::OtherVolumeShadows::Dec

vec3 lightSample(vec3 color, vec3 index, vec3 position, vec3 toViewer)
{
  vec4 material = lightMaterial();
  vec3 lit = material.x * color * u_ambientLight;
  //DeepShadow::VTKShading::Ambient
  //DeepShadow::ShadowTerm::Start
  //DeepShadow::Gradient::Normal
  //DeepShadow::MeshNormal::Normal
  vec3 litPosition = position; // where the lights are evaluated (shadows: at position)
  //DeepShadow::VTKShading::Start
  //DeepShadow::Shadow::Start
  //DeepShadow::Isotropic::Start
  for (int loop = 0; loop < u_lightLoopCount; ++loop)
  {
    int i = u_lightLoop[loop];
    float lightDistance;
    vec3 toLight = towardsLight(i, litPosition, lightDistance);
    float attenuation = 1.0;
    if (lightPositional(i))
    {
      attenuation = 1.0 / (u_lightAttenuation[i].x + u_lightAttenuation[i].y * lightDistance +
                            u_lightAttenuation[i].z * lightDistance * lightDistance);
      if (u_lightConeCos[i] >= -1.0)
      {
        float coneDot = dot(-toLight, u_lightDirection[i]);
        attenuation = coneDot >= u_lightConeCos[i] ? attenuation * pow(coneDot, u_lightExponent[i]) : 0.0;
      }
    }
    vec3 shadowToLight = toLight; // shadows keep the light's own direction
    //DeepShadow::VTKShading::ShadowRay
    if (LIGHT_FROM_EYE != 0 && i == u_lightFromEye && position != u_lightEye)
    {
      toLight = normalize(u_lightEye - position);
    }
    if (attenuation <= 0.0)
    {
      continue;
    }
    vec3 contribution = vec3(0.0);
    vec3 specularPart = vec3(0.0); // what of contribution is specular
    bool specularLit = false;      // N.H > 0
    //DeepShadow::Phong::Surface
    //DeepShadow::Isotropic::Surface
    //DeepShadow::Shadow::Impl
    //DeepShadow::VTKShading::Accumulate
    lit += attenuation * contribution;
  }
  //DeepShadow::VTKShading::Finish
  //DeepShadow::ShadowTerm::Return
  return clamp(lit, 0.0, 1.0);
}
//DeepShadow::Components::LightingDec
//@Impl
#ifdef COMPONENTS_LIT_APART
    color = lightComponents(componentColors, g_componentValues, index, rayOrigin + receiverT * rayDirection,
      -rayDirection);
#else
    color = lightSample(color, index, rayOrigin + receiverT * rayDirection, -rayDirection);
#endif
