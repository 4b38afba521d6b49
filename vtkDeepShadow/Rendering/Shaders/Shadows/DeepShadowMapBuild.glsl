// Build of "dsm" / "dsm-color": the texel's visibility sampled as SampleVisibility does and
// compressed on the fly as VisibilityCompressor and CompressVisibility do (all in
// Core/Shadows/DeepShadowMap.cxx, the CPU twin; here in float). Grey functions carry one
// channel (Value is float; vec3 with the feature FeelerColored). Nodes go to layers u_layer + k as (depth, value); a texel that
// needs more than u_layersPerFace nodes is deferred to the second dispatch, which marches it
// again with doubled bounds until its nodes fit. The nodes needed at the requested bound are
// gathered in u_statistics. With DSM_CHUNKED, nodes go to chunks of a pool instead, any
// number per texel (NodeChunks.h).
//@Dec
// Values have the feelers' transmittance type: vec3 when coloured, else float.
#define Value FeelerTransmittance
layout(std430, binding = 1) buffer DeepShadowStatistics
{
  uint texelsHit;
  uint nodesTotal;
  uint nodesMax;
  uint texelsOverflowed;
  uint epsilonMaxBits; // positive floats order like their bits
  uint chunksRequested[4]; // chunked: per slot, given or not
} u_statistics;
#ifdef DSM_CHUNKED
// Chunked node memory (NodeChunks in Core/Shadows/NodeChunks.cxx is the twin): a chunk is
// DSM_CHUNK_NODES + 1 entries of the pool, its link (the next chunk, -1: none) and then its
// nodes. Chunks are taken from this slot's region with its counter; one asked for beyond
// u_chunkCapacity is counted, not given. The output holds per texel 2 first chunk + 1 if it
// has a next one (-1: no chunk), so that most lookups search their chunk without its link.
// A texel whose one node is 1 (a ray through empty space) takes no chunk, as in the twin.
layout(r32f, binding = 0) uniform writeonly image2DArray u_output;
layout(std430, binding = 3) buffer DeepShadowNodePool
{
#ifdef FEELER_COLORED
  vec4 entries[];
#else
  vec2 entries[];
#endif
} u_pool;
uniform int u_chunkBase;
uniform int u_chunkCapacity;
uniform int u_poolSlot;
const int ChunkNodes = DSM_CHUNK_NODES;
int g_firstChunk; // the texel's first chunk (-1: none yet)
int g_chunk;      // its last
bool g_poolOut;   // a chunk it asked for was not given: it keeps the whole chunks it has
vec4 g_firstNode; // node 0, placed once a second node shows the texel is not empty

void storeEntry(int chunk, int entry, vec4 value)
{
#ifdef FEELER_COLORED
  u_pool.entries[chunk * (ChunkNodes + 1) + entry] = value;
#else
  u_pool.entries[chunk * (ChunkNodes + 1) + entry] = value.xy;
#endif
}

// A chunk after the texel's last one (linked from it, or its first), or none once the pool
// ran out: the texel then keeps the chunks it has.
void takeChunk()
{
  uint asked = atomicAdd(u_statistics.chunksRequested[u_poolSlot], 1u);
  if (!g_poolOut && asked < uint(u_chunkCapacity))
  {
    int chunk = u_chunkBase + int(asked);
    storeEntry(chunk, 0, vec4(-1.0));
    if (g_chunk < 0)
    {
      g_firstChunk = chunk;
    }
    else
    {
      storeEntry(g_chunk, 0, vec4(float(chunk)));
    }
    g_chunk = chunk;
  }
  else
  {
    g_poolOut = true;
  }
}

// Node k of the texel into its chunks, a new chunk every ChunkNodes nodes. Node 0 waits for
// node 1 (buildTexel stores it last), but its chunk is taken with node 1's, in the order the
// twin takes them.
void placeNode(int k, vec4 value)
{
  int entry = k % ChunkNodes;
#if DSM_CHUNK_NODES == 1
  if (k == 1)
  {
    takeChunk(); // node 0's own
  }
#endif
  if (entry == 0 || k == 1)
  {
    takeChunk();
  }
  if (!g_poolOut)
  {
    storeEntry(g_chunk, 1 + entry, value);
  }
}
#elif defined(FEELER_COLORED)
layout(rgba32f, binding = 0) uniform writeonly image2DArray u_output;
#else
layout(rg32f, binding = 0) uniform writeonly image2DArray u_output;
#endif
#ifdef FEELER_COLORED
bool ordered(vec3 low, vec3 high)
{
  return all(lessThanEqual(low, high));
}
vec4 node(float depth, vec3 value)
{
  return vec4(depth, value);
}
#else
bool ordered(float low, float high)
{
  return low <= high;
}
vec4 node(float depth, float value)
{
  return vec4(depth, value, 0.0, 0.0);
}
#endif
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

// Inlined wherever a segment starts: kept short (llvmpipe's time grows with the code).
void emitNode(float depth, Value value)
{
#ifdef DSM_CHUNKED
  // Node 0 waits for node 1 (a texel with one node of 1 takes no chunk). One placeNode here:
  // it is inlined wherever a segment starts, and storing node 0 too cost 0.1 of the build.
  vec4 stored = node(depth, value);
  if (g_nodes > 0)
  {
    placeNode(g_nodes, stored);
  }
  g_firstNode = g_nodes == 0 ? stored : g_firstNode;
#else
  if (g_nodes < u_layersPerFace)
  {
    imageStore(u_output, ivec3(g_texel, u_layer + g_nodes), node(depth, value));
  }
#endif
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
  bool first = g_nodes == 0;
  bool split = false;
  Value slopeLow, slopeHigh;
  if (!first)
  {
    if (!(depth > g_lastDepth))
    {
      depth = uintBitsToFloat(floatBitsToUint(g_lastDepth) + 1u);
    }
    float inverseDz = 1.0 / (depth - g_startDepth);
    slopeLow = max((low - g_startValue) * inverseDz, g_slopeLow);
    slopeHigh = min((high - g_startValue) * inverseDz, g_slopeHigh);
    // No line from the start reaches this sample too: a new segment starts at the previous
    // sample (endSegment), and one constraint alone is always feasible.
    split = !ordered(slopeLow, slopeHigh);
  }
  if (first || split)
  {
    // One startSegment for both cases: each call is inlined, and llvmpipe pays for the code.
    float dz = g_lastDepth - g_startDepth;
    startSegment(first ? depth : g_lastDepth,
      first ? clamp(preferred, low, high)
            : clamp(g_lastPreferred, g_startValue + g_slopeLow * dz, g_startValue + g_slopeHigh * dz));
    if (first)
    {
      return;
    }
    float inverseDz = 1.0 / (depth - g_startDepth);
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
  bool beyond = feelerLargest(v) <= u_epsilon;
  addBounded(depth, v - g_bound, beyond ? Value(g_bound) : v + g_bound, v);
  return !beyond;
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

#ifdef DSM_CHUNKED
// Any number of nodes per texel while the pool lasts; the bound is this slot's (the host
// doubles it for a build again when the pool ran out, ChunkedBuildBound).
void buildTexel(vec3 indexOrigin, vec3 indexDirection, float tEnter, float tExit)
{
  g_firstChunk = -1;
  g_chunk = -1;
  g_poolOut = false;
  compressTexel(indexOrigin, indexDirection, tEnter, tExit, u_epsilon);
  if (g_nodes == 1 && feelerLargest(Value(1.0) - g_lastStored) > 0.0)
  {
    placeNode(0, g_firstNode);
  }
  else if (g_firstChunk >= 0)
  {
    storeEntry(g_firstChunk, 1, g_firstNode); // node 0, which waited for node 1
  }
  if (g_chunk >= 0 && !g_poolOut && g_nodes % ChunkNodes != 0)
  {
    // The last chunk's tail repeats the last value far away.
    for (int entry = g_nodes % ChunkNodes; entry < ChunkNodes; ++entry)
    {
      storeEntry(g_chunk, 1 + entry, node(NoHit, g_lastStored));
    }
  }
  float start = g_firstChunk < 0 ? -1.0 : float(2 * g_firstChunk + (g_chunk != g_firstChunk ? 1 : 0));
  imageStore(u_output, ivec3(g_texel, u_layer), vec4(start));
  if (g_nodes > 0)
  {
    atomicAdd(u_statistics.texelsHit, 1u);
    atomicAdd(u_statistics.nodesTotal, uint(g_nodes));
    atomicMax(u_statistics.nodesMax, uint(g_nodes));
    atomicMax(u_statistics.epsilonMaxBits, floatBitsToUint(u_epsilon));
  }
  if (g_poolOut)
  {
    atomicAdd(u_statistics.texelsOverflowed, 1u);
  }
}
#else
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
#endif
