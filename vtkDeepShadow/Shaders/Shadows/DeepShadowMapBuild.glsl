// Build of "dsm" / "dsm-color": the texel's visibility sampled as SampleVisibility does and
// compressed on the fly as VisibilityCompressor and CompressVisibility do (all in
// Core/Shadows/DeepShadowMap.cxx, the CPU twin; here in float). Grey functions carry the
// same value in all three channels. Nodes go to layers u_layer + k as (depth, value); a texel
// that needs more than u_layersPerFace nodes is marched again with a doubled bound. The nodes
// needed at the requested bound are gathered in u_statistics.
//@Dec
#ifdef DSM_COLORED
layout(rgba32f, binding = 0) uniform writeonly image2DArray u_output;
#else
layout(rg32f, binding = 0) uniform writeonly image2DArray u_output;
#endif
layout(std430, binding = 1) buffer DeepShadowStatistics
{
  uint texelsHit;
  uint nodesTotal;
  uint nodesMax;
  uint texelsOverflowed;
  uint epsilonMaxBits; // positive floats order like their bits
} u_statistics;
uniform float u_epsilon;

// The compressor's state.
float g_bound;
int g_nodes;
bool g_hasSegment;
float g_startDepth;
vec3 g_startValue;
float g_lastDepth;
vec3 g_lastPreferred;
vec3 g_slopeLow;
vec3 g_slopeHigh;
vec3 g_lastStored;
// The sampled visibility's state.
bool g_started;
vec3 g_transmittance;

void emitNode(float depth, vec3 value)
{
  if (g_nodes < u_layersPerFace)
  {
    imageStore(u_output, ivec3(g_texel, u_layer + g_nodes), vec4(depth, value));
  }
  g_lastStored = value;
  ++g_nodes;
}

void endSegment()
{
  float dz = g_lastDepth - g_startDepth;
  vec3 value = clamp(g_lastPreferred, g_startValue + g_slopeLow * dz, g_startValue + g_slopeHigh * dz);
  emitNode(g_lastDepth, value);
  g_startDepth = g_lastDepth;
  g_startValue = value;
  g_hasSegment = false;
}

void addBounded(float depth, vec3 low, vec3 high, vec3 preferred)
{
  if (g_nodes == 0)
  {
    g_startValue = clamp(preferred, low, high);
    emitNode(depth, g_startValue);
    g_startDepth = depth;
    g_lastDepth = depth;
    g_hasSegment = false;
    return;
  }
  if (!(depth > g_lastDepth))
  {
    depth = uintBitsToFloat(floatBitsToUint(g_lastDepth) + 1u);
  }
  // At most twice: if no line from the start reaches this sample, a new segment starts at
  // the previous sample, and one constraint alone is always feasible.
  for (int attempt = 0; attempt < 2; ++attempt)
  {
    float dz = depth - g_startDepth;
    vec3 low_ = (low - g_startValue) / dz;
    vec3 high_ = (high - g_startValue) / dz;
    if (g_hasSegment)
    {
      low_ = max(low_, g_slopeLow);
      high_ = min(high_, g_slopeHigh);
    }
    if (!g_hasSegment || all(lessThanEqual(low_, high_)))
    {
      g_slopeLow = low_;
      g_slopeHigh = high_;
      g_lastDepth = depth;
      g_lastPreferred = preferred;
      g_hasSegment = true;
      return;
    }
    endSegment();
  }
}

// A point of V at `depth`; false once every channel is at or below the requested bound
// (then V beyond lies in [0, V], and the point says so).
bool addPoint(float depth)
{
  vec3 v = g_transmittance;
  if (max(max(v.r, v.g), v.b) <= u_epsilon)
  {
    addBounded(depth, v - g_bound, vec3(g_bound), v);
    return false;
  }
  addBounded(depth, v - g_bound, v + g_bound, v);
  return true;
}

void startPoint(float t)
{
  if (!g_started)
  {
    g_started = true;
    addBounded(t - 0.5 * u_feelerStep, g_transmittance - g_bound, g_transmittance + g_bound, g_transmittance);
  }
}

bool visitSample(int j, float t, float scalar)
{
  startPoint(t);
  g_transmittance *= feelerTransmission(feelerSample(scalar));
  return addPoint(t + 0.5 * u_feelerStep);
}

bool visitSkipped(int j, float t)
{
  startPoint(t);
  return addPoint(t + 0.5 * u_feelerStep);
}
//@Texel
void compressTexel(vec3 indexOrigin, vec3 indexDirection, float tEnter, float tExit, float bound)
{
  g_bound = bound;
  g_nodes = 0;
  g_hasSegment = false;
  g_started = false;
  g_transmittance = vec3(1.0);
  g_lastStored = vec3(1.0);
  if (tEnter < tExit)
  {
    marchTexel(indexOrigin, indexDirection, tEnter, tExit);
  }
  // A level last segment needs no end node.
  if (g_hasSegment && !(all(lessThanEqual(g_slopeLow, vec3(0.0))) && all(greaterThanEqual(g_slopeHigh, vec3(0.0)))))
  {
    endSegment();
  }
}

void buildTexel(vec3 indexOrigin, vec3 indexDirection, float tEnter, float tExit)
{
  compressTexel(indexOrigin, indexDirection, tEnter, tExit, u_epsilon);
  int needed = g_nodes;
  float bound = u_epsilon;
  for (int attempt = 0; g_nodes > u_layersPerFace && attempt < 64; ++attempt)
  {
    bound = max(2.0 * bound, 1.0 / 1024.0);
    compressTexel(indexOrigin, indexDirection, tEnter, tExit, bound);
  }
  // Unused nodes repeat the last value far away.
  for (int k = min(g_nodes, u_layersPerFace); k < u_layersPerFace; ++k)
  {
    imageStore(u_output, ivec3(g_texel, u_layer + k), vec4(NoHit, g_lastStored));
  }
  if (needed > 0)
  {
    atomicAdd(u_statistics.texelsHit, 1u);
    atomicAdd(u_statistics.nodesTotal, uint(needed));
    atomicMax(u_statistics.nodesMax, uint(needed));
    atomicAdd(u_statistics.texelsOverflowed, needed > u_layersPerFace ? 1u : 0u);
    atomicMax(u_statistics.epsilonMaxBits, floatBitsToUint(bound));
  }
}
