// Feature ShadowRatioApply: the full pass of shadows while interacting, drawn without the
// technique: its colour times the coarse pass's ratio (Features/ShadowRatio.glsl) at the
// pixel, from the four nearest coarse texels, each weighted by its bilinear weight, its
// opacity and 1 / (1 + (d / u_ratioGuideScale)^2), d the distance of its unshadowed composite
// from the pixel's own (accumulated, before the ratio); deepshadow::UpsampleShadowRatio is the CPU
// twin.
//@Dec
uniform sampler2D u_shadowRatio; // the coarse pass's ratio and opacity (RGBA16F)
uniform sampler2D u_ratioGuide;  // and its unshadowed composite (RGBA16F)
uniform float u_ratioScale;      // view pixels per coarse texel, along each axis
uniform float u_ratioGuideScale; // deepshadow::ShadowRatioGuideScale
vec3 shadowRatioAt(vec2 pixel, vec3 unshadowed) // `pixel`: a pixel's centre in the view
{
  ivec2 size = textureSize(u_shadowRatio, 0);
  vec2 u = pixel / u_ratioScale - 0.5;
  vec2 base = floor(u);
  vec2 f = u - base;
  vec3 sum = vec3(0.0);
  float weight = 0.0;
  for (int corner = 0; corner < 4; ++corner)
  {
    ivec2 offset = ivec2(corner & 1, corner >> 1);
    ivec2 texel = clamp(ivec2(base) + offset, ivec2(0), size - 1);
    vec4 r = texelFetch(u_shadowRatio, texel, 0);
    float apart = distance(texelFetch(u_ratioGuide, texel, 0).rgb, unshadowed) / u_ratioGuideScale;
    float w = (offset.x == 1 ? f.x : 1.0 - f.x) * (offset.y == 1 ? f.y : 1.0 - f.y) * r.a / (1.0 + apart * apart);
    sum += w * r.rgb;
    weight += w;
  }
  return weight > 1e-6 ? sum / weight : vec3(1.0);
}
//@Exit
  accumulated.rgb *= shadowRatioAt(pixel, accumulated.rgb);
