// Lookup of "fom" (FourierOpticalDepth and FourierOpacityMap::MapVisibility in
// Core/Shadows/FourierOpacityMap.cxx are the CPU twins): the optical depth
// tau(x) = Total x + sum_k A_k sin(2 pi k x) + B_k (1 - cos(2 pi k x)) at x = depth / End,
// clamped to [0, Total] (0 up to First, Total from End on; UnpackFourierEnd: First in End's
// 12 lowest bits), visibility exp(-tau); with casting meshes (a
// layer after the series) times their steps'; bilinear across the four nearest texels.
//@Dec
const float FourierLookupPi = 3.14159265358979;

float fourierVisibility(int layer, ivec2 texel, vec2 xy, float pointDepth, vec2 slope)
{
  float depth = lightSpaceDepthAt(vec2(texel), xy, pointDepth, slope);
  vec4 head = lightSpaceTexel(texel, layer); // End with First, Total, A_1, B_1
  float end, first;
  unpackSeriesEnd(head.x, end, first);
  float tau = 0.0;
  if (head.y > 0.0 && depth > first)
  {
    tau = head.y;
    if (depth < end)
    {
      float x = depth / end;
      float angle = 2.0 * FourierLookupPi * x;
      vec2 base = vec2(cos(angle), sin(angle));
      vec2 r = base;
      tau = head.y * x + head.z * r.y + head.w * (1.0 - r.x);
      for (int l = 1; l < FOM_LAYERS; ++l)
      {
        vec4 c = lightSpaceTexel(texel, layer + l); // A_2l, B_2l, A_2l+1, B_2l+1
        r = vec2(r.x * base.x - r.y * base.y, r.y * base.x + r.x * base.y);
        tau += c.x * r.y + c.y * (1.0 - r.x);
        r = vec2(r.x * base.x - r.y * base.y, r.y * base.x + r.x * base.y);
        tau += c.z * r.y + c.w * (1.0 - r.x);
      }
      tau = clamp(tau, 0.0, head.y);
    }
  }
  float visibility = exp(-tau);
  if (u_shadowLayersPerFace > FOM_LAYERS)
  {
    visibility *= surfaceStepsVisibility(lightSpaceTexel(texel, layer + FOM_LAYERS), depth);
  }
  return visibility;
}

vec3 mapVisibility(int layer, vec2 xy, float depth, vec2 slope)
{
  ivec2 i0;
  vec4 w = lightSpaceBilinear(xy, i0);
  return vec3(w.x * fourierVisibility(layer, i0, xy, depth, slope) +
    w.y * fourierVisibility(layer, i0 + ivec2(1, 0), xy, depth, slope) +
    w.z * fourierVisibility(layer, i0 + ivec2(0, 1), xy, depth, slope) +
    w.w * fourierVisibility(layer, i0 + ivec2(1, 1), xy, depth, slope));
}
