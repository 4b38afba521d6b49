// Feature Jitter: the first sample of each pixel moves by a hash of the pixel and a seed
// (deepshadow::JitterOffset in Core/Jitter.h), so images are reproducible bit for bit.
//@Dec
//DeepShadow::Hash::Dec
uniform int u_jitterSeed;
float jitterOffset(uvec2 pixel, uint seed)
{
  uint hash = pcgHash(pixel.x + pcgHash(pixel.y + pcgHash(seed)));
  return float(hash >> 8u) * (1.0 / 16777216.0);
}
//@Impl
  offset = jitterOffset(uvec2(pixel), uint(u_jitterSeed));
