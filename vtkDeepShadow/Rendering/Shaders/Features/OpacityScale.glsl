// Feature OpacityScale: what the light's sample at hand multiplies its opacity by
// (deepshadow::CastSample's OpacityScale), composed with GradientOpacity or Mask, which set it:
// the marches reset it per sample, those features multiply it in, feelerSample applies it.
//@Dec
float g_opacityScale = 1.0;
//@FeelerSample
    g_opacityScale = 1.0;
//@TexelSample
    g_opacityScale = 1.0;
//@FeelerLookup
  rgba.a *= g_opacityScale;
