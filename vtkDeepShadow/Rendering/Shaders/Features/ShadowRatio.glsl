// Feature ShadowRatio: the coarse pass of shadows while interacting
// (vtkDeepShadowVolumeMapper::InteractiveShadowSubsampling; deepshadow::MakeShadowRatioTexel
// and RenderShadowSubsampled in Core/ShadowSubsampling.h are the CPU twin). One ray per
// u_ratioScale x u_ratioScale block of the view's pixels, through the block's centre, marched
// shadowed as usual; it writes, per channel, its shadowed composite over the composite of
// what the full pass draws without the technique (an unshaded sample's colour before lighting;
// a shaded one lit with its shadows off: SHADOW_RATIO_SHADED, lightSample again with
// g_shadowsOff), its opacity, and that unshadowed composite itself. Drawn into targets of the
// coarse grid's size, not blended; ShadowRatioApply reads them.
//@Dec
#define SHADOW_RATIO_PASS
bool g_shadowsOff = false; // Shadow.glsl: every light unshadowed
uniform float u_ratioScale;
layout(location = 1) out vec4 ratioGuide;
//@Pixel
  pixel = gl_FragCoord.xy * u_ratioScale; // the block's centre, in the view's pixels
//@Init
  vec3 unshadowedAccumulated = vec3(0.0);
//@Unshadowed
#ifdef SHADOW_RATIO_SHADED
    g_shadowsOff = true;
    vec3 unshadowedColor = lightSample(color, index, rayOrigin + receiverT * rayDirection, -rayDirection);
    g_shadowsOff = false;
#else
    vec3 unshadowedColor = color;
#endif
//@Impl
    unshadowedAccumulated += (1.0 - accumulated.a) * transfer.a * unshadowedColor;
//@Output
  fragColor = vec4(mix(vec3(1.0), accumulated.rgb / max(unshadowedAccumulated, vec3(1e-30)),
                     greaterThan(unshadowedAccumulated, vec3(1e-6))),
    accumulated.a);
  ratioGuide = vec4(unshadowedAccumulated, 0.0);
