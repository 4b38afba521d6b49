// Feature Shadow, common part: every technique's lookup defines
//   vec3 lightVisibility(int slot, vec3 position, vec3 toLight, float lightDistance,
//     vec3 receiverNormal)
// (the light's visibility per colour channel), and this scales the light's contribution by
// 1 - attenuation (1 - visibility), as deepshadow::ReferenceRenderer::MarchRay does. What
// other volumes cast (OtherVolumeShadows) multiplies the visibility first: light crosses
// every caster on its way.
//
// Each structure is looked up before the lights' loop, once per slot (Start): llvmpipe runs
// the code of a branch not taken as well (masked), so a lookup inside the loop cost every
// light, shadowed or not (ParaView's light kit: five lookups a sample for its key light's one).
// The volumes' composer defines SHADOW_SLOTS (the technique's slots this frame) and
// SHADOW_SLOT_ARRAY (at least 1), so that the loop is unrolled and the array holds no more than
// the slots; llvmpipe keeps a dynamically indexed array in memory (the meshes' shader takes
// the count from the uniform).
//@Dec
#ifndef SHADOW_SLOTS
#define SHADOW_SLOTS u_shadowSlotCount
#define SHADOW_SLOT_ARRAY MaxLights
#endif
uniform int u_shadowSlot[MaxLights];          // the light's shadow structure, -1: none
uniform float u_shadowAttenuation[MaxLights]; // vtkLight::ShadowAttenuation
uniform int u_shadowSlotCount;                // structures
uniform int u_shadowSlotLight[MaxLights];     // the light of each
//@Start
  vec3 slotVisibility[SHADOW_SLOT_ARRAY];
  for (int s = 0; s < SHADOW_SLOTS; ++s)
  {
    int i = u_shadowSlotLight[s];
    float lightDistance;
    vec3 shadowToLight = towardsLight(i, position, lightDistance); // the shadow ray leaves from the sample
    vec3 shadowPosition = position;
    float shadowDistance = lightDistance;
    vec3 shadowNormal = vec3(0.0); // a volume sample
    //DeepShadow::MeshNormal::ShadowOffset
    //DeepShadow::Isosurface::ShadowOffset
    slotVisibility[s] = lightVisibility(s, shadowPosition, shadowToLight, shadowDistance, shadowNormal);
  }
//@Impl
    {
      vec3 shadowPosition = position;
      float shadowDistance = lightDistance;
      vec3 shadowNormal = vec3(0.0); // a volume sample
      //DeepShadow::MeshNormal::ShadowOffset
      //DeepShadow::Isosurface::ShadowOffset
      bool shadowed = u_shadowSlot[i] >= 0;
#ifdef SHADOW_RATIO_PASS
      shadowed = shadowed && !g_shadowsOff; // the coarse pass's unshadowed colour (ShadowRatio)
#endif
      vec3 visibility = shadowed ? slotVisibility[SHADOW_SLOT_ARRAY == 1 ? 0 : u_shadowSlot[i]] : vec3(1.0);
      //DeepShadow::OtherVolumeShadows::Impl
      if (shadowed)
      {
        vec3 shadowFactor = 1.0 - u_shadowAttenuation[i] * (1.0 - visibility);
        contribution *= shadowFactor;
        specularPart *= shadowFactor;
        //DeepShadow::ShadowTerm::Accumulate
      }
    }
