// Build of "dsm-fixed", deep shadow maps at a fixed budget (FitFixedBudget in
// Core/Shadows/FixedBudgetDeepShadowMap.cxx is the CPU twin, with VisibilityCompressor on a
// NodeGrid; here in float, depths in steps of the 16-bit grid): the texel's visibility from
// the first absorbing depth on, compressed as the deep shadow map compresses it, at the
// finest bound that fits FIXED_NODES nodes (2^FIXED_BOUND_LOG2_MIN, else a bisection of
// log2 epsilon in FIXED_BISECTION_STEPS steps; each attempt marches the ray again and stops
// once it needs more nodes). Two nodes per RGBA16 layer: depth / u_lightDepthRange, visibility.
// With an error instead of a budget (FIXED_COUNT_BINS: FixedNodesWithin's twin), each texel
// first counts the nodes it needs within u_countBound, into FixedNodeCounts: the technique
// sizes the map from their percentile and builds it again when that changed.
//@Dec
layout(rgba16, binding = 0) uniform writeonly image2DArray u_output;
#ifdef FIXED_COUNT_BINS
layout(std430, binding = 1) buffer FixedNodeCounts
{
  uint u_nodeCounts[]; // per slot FIXED_COUNT_BINS: texels by the nodes they need (last: more)
};
uniform float u_countBound;
uniform int u_countSlot;
#endif
uniform float u_lightDepthRange; // world depth of unorm 1 (LightDepthRange; set by the base class)
const float UnormMax = 65535.0;

// This attempt's nodes (depth in grid steps) and the last ones that fitted.
float g_depth[FIXED_NODES];
float g_value[FIXED_NODES];
float g_bestDepth[FIXED_NODES];
float g_bestValue[FIXED_NODES];
int g_count; // nodes emitted, beyond g_limit too (then the attempt failed)
int g_limit; // nodes this attempt may emit
// The compressor's state (VisibilityCompressor's), for one channel.
float g_bound;
bool g_hasSegment;
float g_startDepth;
float g_startValue;
float g_lastDepth;
float g_lastPreferred;
float g_slopeLow;
float g_slopeHigh;
// The sampled visibility's.
bool g_hit;       // the first absorbing depth was met (node 0 placed)
bool g_needStart; // after a mesh's step, the next sample's start is a point of its own
float g_transmittance;

// The grid value nearest `preferred` inside [low, high] (GridInside).
float gridValue(float low, float high, float preferred)
{
  float stored = floor(clamp(preferred, low, high) * UnormMax + 0.5) / UnormMax;
  if (stored < low && stored + 1.0 / UnormMax <= high)
  {
    stored += 1.0 / UnormMax;
  }
  else if (stored > high && stored - 1.0 / UnormMax >= low)
  {
    stored -= 1.0 / UnormMax;
  }
  return stored;
}

void startSegment(float depth, float value)
{
  if (g_count < FIXED_NODES)
  {
    g_depth[g_count] = depth;
    g_value[g_count] = value;
  }
  ++g_count;
  g_startDepth = depth;
  g_startValue = value;
  g_lastDepth = depth;
  g_hasSegment = false;
}

void endSegment()
{
  float dz = g_lastDepth - g_startDepth;
  startSegment(g_lastDepth,
    gridValue(g_startValue + g_slopeLow * dz, g_startValue + g_slopeHigh * dz, g_lastPreferred));
}

// A constraint at grid depth `depth` (VisibilityCompressor::AddBounded).
void addBounded(float depth, float low, float high, float preferred)
{
  low = max(low, 0.0);
  high = min(high, 1.0);
  depth = depth > g_lastDepth ? depth : g_lastDepth + 1.0;
  float inverseDz = 1.0 / (depth - g_startDepth);
  float slopeLow = (low - g_startValue) * inverseDz;
  float slopeHigh = (high - g_startValue) * inverseDz;
  if (g_hasSegment)
  {
    float joinedLow = max(slopeLow, g_slopeLow);
    float joinedHigh = min(slopeHigh, g_slopeHigh);
    if (joinedLow <= joinedHigh)
    {
      slopeLow = joinedLow;
      slopeHigh = joinedHigh;
    }
    else
    {
      // No line from the start reaches this sample too: a segment starts at the previous one.
      endSegment();
      inverseDz = 1.0 / (depth - g_startDepth);
      slopeLow = (low - g_startValue) * inverseDz;
      slopeHigh = (high - g_startValue) * inverseDz;
    }
  }
  g_slopeLow = slopeLow;
  g_slopeHigh = slopeHigh;
  g_lastDepth = depth;
  g_lastPreferred = preferred;
  g_hasSegment = true;
}

// Node 0: visibility 1 where the ray first meets something absorbing (rounded down).
void firstHit(float t)
{
  g_hit = true;
  startSegment(floor(t / u_lightDepthRange * UnormMax), 1.0);
}

// A point of V at world depth t; false once V is at or below the bound (V beyond lies in
// [0, V]) or the nodes overflowed.
bool addPoint(float t)
{
  float v = g_transmittance;
  bool beyond = v <= g_bound;
  addBounded(floor(t / u_lightDepthRange * UnormMax + 0.5), v - g_bound, beyond ? g_bound : v + g_bound, v);
  return !beyond && g_count <= g_limit;
}

bool visitSample(int j, float t, float scalar)
{
  float alpha = feelerAlpha(scalar);
  if (!g_hit)
  {
    if (alpha <= 0.0)
    {
      return true; // nothing absorbed yet: nothing stored
    }
    firstHit(t - 0.5 * u_feelerStep);
  }
  else if (g_needStart)
  {
    addPoint(t - 0.5 * u_feelerStep);
  }
  g_needStart = false;
  g_transmittance *= 1.0 - alpha;
  return addPoint(t + 0.5 * u_feelerStep);
}

bool visitSkipped(int j, float t)
{
  if (!g_hit)
  {
    return true;
  }
  if (g_needStart)
  {
    addPoint(t - 0.5 * u_feelerStep);
  }
  g_needStart = false;
  return addPoint(t + 0.5 * u_feelerStep);
}
//@Surface
// A step: the value before and after at one depth.
bool visitSurface(float t, int surface)
{
  if (!g_hit)
  {
    firstHit(t);
  }
  else
  {
    addPoint(t);
  }
  g_transmittance *= u_surfaceTransmission[surface].a;
  g_needStart = true;
  return addPoint(t);
}
//@Texel
// One attempt at `bound` within `limit` nodes; true if they fit (or the ray absorbs nothing),
// and then they are kept as the best when `limit` is FIXED_NODES.
bool attemptTexel(vec3 indexOrigin, vec3 indexDirection, float tEnter, float tExit, float bound, int limit)
{
  g_bound = bound;
  g_limit = limit;
  g_count = 0;
  g_hasSegment = false;
  g_hit = false;
  g_needStart = false;
  g_transmittance = 1.0;
  g_lastDepth = -1.0;
  marchTexel(indexOrigin, indexDirection, tEnter, tExit);
  // A level last segment needs no end node.
  if (g_hasSegment && g_count <= g_limit && !(g_slopeLow <= 0.0 && 0.0 <= g_slopeHigh))
  {
    endSegment();
  }
  bool fits = g_count <= g_limit;
  if (limit != FIXED_NODES)
  {
    return fits;
  }
  float last = g_count > 0 ? g_value[max(g_count - 1, 0)] : 1.0;
  for (int i = 0; fits && i < FIXED_NODES; ++i)
  {
    g_bestDepth[i] = i < g_count ? g_depth[i] : UnormMax;
    g_bestValue[i] = i < g_count ? g_value[i] : last;
  }
  return fits;
}

void buildTexel(vec3 indexOrigin, vec3 indexDirection, float tEnter, float tExit)
{
#ifdef FIXED_COUNT_BINS
  attemptTexel(indexOrigin, indexDirection, tEnter, tExit, u_countBound, FIXED_COUNT_BINS - 2);
  if (g_hit)
  {
    atomicAdd(u_nodeCounts[u_countSlot * FIXED_COUNT_BINS + min(g_count, FIXED_COUNT_BINS - 1)], 1u);
  }
#endif
  if (!attemptTexel(indexOrigin, indexDirection, tEnter, tExit, exp2(float(FIXED_BOUND_LOG2_MIN)), FIXED_NODES) && g_hit)
  {
    // lo never fits, hi always does (one node at a bound of 1).
    float lo = float(FIXED_BOUND_LOG2_MIN), hi = 0.0;
    bool found = false;
    for (int i = 0; i < FIXED_BISECTION_STEPS; ++i)
    {
      float middle = 0.5 * (lo + hi);
      if (attemptTexel(indexOrigin, indexDirection, tEnter, tExit, exp2(middle), FIXED_NODES))
      {
        hi = middle;
        found = true;
      }
      else
      {
        lo = middle;
      }
    }
    if (!found)
    {
      attemptTexel(indexOrigin, indexDirection, tEnter, tExit, 1.0, FIXED_NODES);
    }
  }
  // As grid steps plus a quarter, so that a conversion that truncates stores them as one
  // that rounds does.
  for (int l = 0; l < FIXED_NODES / 2; ++l)
  {
    int i = 2 * l;
    vec4 steps = g_hit ? vec4(g_bestDepth[i], g_bestValue[i] * UnormMax, g_bestDepth[i + 1], g_bestValue[i + 1] * UnormMax)
                       : vec4(UnormMax);
    imageStore(u_output, ivec3(g_texel, u_layer + l), min((floor(steps + 0.5) + 0.25) / UnormMax, vec4(1.0)));
  }
}
