// Build of "dsm" / "dsm-color": the texel's visibility sampled as SampleVisibility does and
// compressed on the fly as VisibilityCompressor and CompressVisibility do (all in
// Core/Shadows/DeepShadowMap.cxx, the CPU twin; here in float). Grey functions carry one
// channel (Value is float; vec3 with the feature FeelerColored). Nodes go to layers u_layer + k as (depth, value); a texel that
// needs more than u_layersPerFace nodes is deferred to the second dispatch, which marches it
// again with doubled bounds until its nodes fit. The nodes needed at the requested bound are
// gathered in u_statistics.
//@Dec
// Values have the feelers' transmittance type: vec3 when coloured, else float.
#define Value FeelerTransmittance
#ifdef FEELER_COLORED
layout(rgba32f, binding = 0) uniform writeonly image2DArray u_output;
bool ordered(vec3 low, vec3 high)
{
  return all(lessThanEqual(low, high));
}
vec4 node(float depth, vec3 value)
{
  return vec4(depth, value);
}
#else
layout(rg32f, binding = 0) uniform writeonly image2DArray u_output;
bool ordered(float low, float high)
{
  return low <= high;
}
vec4 node(float depth, float value)
{
  return vec4(depth, value, 0.0, 0.0);
}
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
Value g_startValue;
float g_lastDepth;
Value g_lastPreferred;
Value g_slopeLow;
Value g_slopeHigh;
Value g_lastStored;
// The sampled visibility's state.
bool g_started;
Value g_transmittance;

void emitNode(float depth, Value value)
{
  if (g_nodes < u_layersPerFace)
  {
    imageStore(u_output, ivec3(g_texel, u_layer + g_nodes), node(depth, value));
  }
  g_lastStored = value;
  ++g_nodes;
}

// Emits the node (depth, value) and starts a segment there; with no sample after its start
// yet, any line (slope) is feasible.
void startSegment(float depth, Value value)
{
  emitNode(depth, value);
  g_startDepth = depth;
  g_startValue = value;
  g_lastDepth = depth;
  g_slopeLow = Value(-3.0e38);
  g_slopeHigh = Value(3.0e38);
  g_hasSegment = false;
}

void endSegment()
{
  float dz = g_lastDepth - g_startDepth;
  startSegment(g_lastDepth,
    clamp(g_lastPreferred, g_startValue + g_slopeLow * dz, g_startValue + g_slopeHigh * dz));
}

void addBounded(float depth, Value low, Value high, Value preferred)
{
  // Nodes stay in [0, 1], as in deepshadow::VisibilityCompressor::AddBounded.
  low = max(low, Value(0.0));
  high = min(high, Value(1.0));
  if (g_nodes == 0)
  {
    startSegment(depth, clamp(preferred, low, high));
    return;
  }
  if (!(depth > g_lastDepth))
  {
    depth = uintBitsToFloat(floatBitsToUint(g_lastDepth) + 1u);
  }
  float inverseDz = 1.0 / (depth - g_startDepth);
  Value slopeLow = max((low - g_startValue) * inverseDz, g_slopeLow);
  Value slopeHigh = min((high - g_startValue) * inverseDz, g_slopeHigh);
  if (!ordered(slopeLow, slopeHigh))
  {
    // No line from the start reaches this sample too: a new segment starts at the previous
    // sample, and one constraint alone is always feasible.
    endSegment();
    inverseDz = 1.0 / (depth - g_startDepth);
    slopeLow = (low - g_startValue) * inverseDz;
    slopeHigh = (high - g_startValue) * inverseDz;
  }
  g_slopeLow = slopeLow;
  g_slopeHigh = slopeHigh;
  g_lastDepth = depth;
  g_lastPreferred = preferred;
  g_hasSegment = true;
}

// A point of V at `depth`; false once every channel is at or below the requested bound
// (then V beyond lies in [0, V], and the point says so).
bool addPoint(float depth)
{
  Value v = g_transmittance;
  if (feelerLargest(v) <= u_epsilon)
  {
    addBounded(depth, v - g_bound, Value(g_bound), v);
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
//@Surface
// A step: the value before and after at one depth; the next sample starts its interval anew.
bool visitSurface(float t, int surface)
{
  if (!g_started)
  {
    g_started = true;
    addBounded(t, g_transmittance - g_bound, g_transmittance + g_bound, g_transmittance);
  }
  else
  {
    addPoint(t);
  }
#ifdef FEELER_COLORED
  g_transmittance *= u_surfaceTransmission[surface].rgb;
#else
  g_transmittance *= u_surfaceTransmission[surface].a;
#endif
  g_started = false;
  return addPoint(t);
}
//@Texel
void compressTexel(vec3 indexOrigin, vec3 indexDirection, float tEnter, float tExit, float bound)
{
  g_bound = bound;
  g_nodes = 0;
  g_hasSegment = false;
  g_started = false;
  g_transmittance = Value(1.0);
  g_lastStored = Value(1.0);
  marchTexel(indexOrigin, indexDirection, tEnter, tExit);
  // A level last segment needs no end node.
  if (g_hasSegment && !(ordered(g_slopeLow, Value(0.0)) && ordered(Value(0.0), g_slopeHigh)))
  {
    endSegment();
  }
}

void buildTexel(vec3 indexOrigin, vec3 indexDirection, float tEnter, float tExit)
{
  float bound = u_epsilon;
  if (u_deferredPass == 0)
  {
    compressTexel(indexOrigin, indexDirection, tEnter, tExit, bound);
    int needed = g_nodes;
    if (needed > 0)
    {
      atomicAdd(u_statistics.texelsHit, 1u);
      atomicAdd(u_statistics.nodesTotal, uint(needed));
      atomicMax(u_statistics.nodesMax, uint(needed));
    }
    if (needed > u_layersPerFace)
    {
      atomicAdd(u_statistics.texelsOverflowed, 1u);
      deferTexel();
      return;
    }
  }
  else
  {
    // Overflowed in the first dispatch: double the bound until the nodes fit.
    for (int attempt = 0; attempt < 64; ++attempt)
    {
      bound = max(2.0 * bound, 1.0 / 1024.0);
      compressTexel(indexOrigin, indexDirection, tEnter, tExit, bound);
      if (g_nodes <= u_layersPerFace)
      {
        break;
      }
    }
  }
  // Unused nodes repeat the last value far away.
  for (int k = g_nodes; k < u_layersPerFace; ++k)
  {
    imageStore(u_output, ivec3(g_texel, u_layer + k), node(NoHit, g_lastStored));
  }
  if (g_nodes > 0)
  {
    atomicMax(u_statistics.epsilonMaxBits, floatBitsToUint(bound));
  }
}
