// Feature Shadow, common part: every technique's lookup defines
//   vec3 lightVisibility(int slot, vec3 position, vec3 toLight, float lightDistance,
//     vec3 receiverNormal)
// (the light's visibility per colour channel), and this scales the light's contribution by
// 1 - attenuation (1 - visibility), as deepshadow::ReferenceRenderer::MarchRay does. What
// other volumes cast (OtherVolumeShadows) multiplies the visibility first: light crosses
// every caster on its way.
//@Dec
uniform int u_shadowSlot[MaxLights];          // the light's shadow structure, -1: none
uniform float u_shadowAttenuation[MaxLights]; // vtkLight::ShadowAttenuation
//@Impl
    {
      vec3 shadowPosition = position;
      float shadowDistance = lightDistance;
      vec3 shadowNormal = vec3(0.0); // a volume sample
      //DeepShadow::MeshNormal::ShadowOffset
      //DeepShadow::Isosurface::ShadowOffset
      bool shadowed = u_shadowSlot[i] >= 0;
      vec3 visibility = vec3(1.0);
      if (shadowed)
      {
        visibility = lightVisibility(u_shadowSlot[i], shadowPosition, shadowToLight, shadowDistance, shadowNormal);
      }
      //DeepShadow::OtherVolumeShadows::Impl
      if (shadowed)
      {
        vec3 shadowFactor = 1.0 - u_shadowAttenuation[i] * (1.0 - visibility);
        contribution *= shadowFactor;
        specularPart *= shadowFactor;
        //DeepShadow::ShadowTerm::Accumulate
      }
    }
