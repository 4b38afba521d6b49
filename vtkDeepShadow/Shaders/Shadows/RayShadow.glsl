// Shadow technique "rays": a feeler per sample and light, translucent or opaque
// (deepshadow::MakeLightShadow with ShadowKind::Rays, not cached, is the CPU twin).
//@Dec
uniform float u_shadowAttenuation[MaxLights]; // vtkLight::ShadowAttenuation; 0: no feeler
uniform int u_shadowOpaque;
//@Impl
    if (u_shadowAttenuation[i] > 0.0)
    {
      float visibility = feelerTowardsLight(position, toLight, lightDistance, u_shadowOpaque != 0);
      attenuation *= 1.0 - u_shadowAttenuation[i] * (1.0 - visibility);
    }
