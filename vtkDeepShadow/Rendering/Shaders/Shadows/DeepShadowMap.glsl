// Lookup of "dsm" / "dsm-color": per texel, linear in depth between the two nodes that
// bracket the point (found by binary search), bilinear across the four nearest texels
// (EvaluateVisibility and DeepShadowMap::Visibility in Core/Shadows/DeepShadowMap.cxx are
// the CPU twins). DsmColored is defined by the technique, and DSM_CHUNKED for chunked node
// memory (NodeChunks.h).
//@Dec

vec3 dsmValue(vec4 node)
{
  return DsmColored ? node.gba : vec3(node.g);
}

#ifdef DSM_CHUNKED
// Chunked node memory (NodeChunks::Evaluate is the twin): u_shadowMap holds per texel its
// first chunk (see DeepShadowMapBuild.glsl), the pool's entries a chunk's link and then its
// DSM_CHUNK_NODES nodes.
uniform samplerBuffer u_shadowNodes;
const int DsmChunkNodes = DSM_CHUNK_NODES;

vec4 dsmNode(ivec3 at, int k)
{
  return texelFetch(u_shadowNodes, at.x + 1 + k);
}
#else
vec4 dsmNode(ivec3 at, int k)
{
  return texelFetch(u_shadowMap, ivec3(at.xy, at.z + k), 0);
}
#endif

// V' at depth from the `count` nodes at `at`; `before` says whether `a`, a node before them,
// lies at or before depth.
vec3 dsmBetween(ivec3 at, int count, float depth, vec4 a, bool before)
{
  // first = how many nodes lie at or before depth. The search reads the two nodes that
  // bracket depth on its way: the last node found at or before it is node first - 1, and the
  // last found beyond it is node first (each such probe moves the search's right end to
  // itself, and the search ends where its ends meet), so neither is fetched again.
  int first = 0;
  int remaining = count;
  vec4 b = vec4(0.0);
  while (remaining > 0)
  {
    int halfCount = remaining / 2;
    vec4 node = dsmNode(at, first + halfCount);
    if (node.r <= depth)
    {
      a = node;
      first += halfCount + 1;
      remaining -= halfCount + 1;
    }
    else
    {
      b = node;
      remaining = halfCount;
    }
  }
  if (first == 0 && !before)
  {
    return vec3(1.0);
  }
  if (first == count)
  {
    return dsmValue(a);
  }
  return mix(dsmValue(a), dsmValue(b), (depth - a.r) / (b.r - a.r));
}

vec3 dsmTexel(int layer, ivec2 texel, float depth)
{
  texel = lightSpaceClamp(texel);
#ifdef DSM_CHUNKED
  // 2 first chunk + 1 if it has a next one; -1: no chunk (V' = 1).
  float start = texelFetch(u_shadowMap, ivec3(texel, layer), 0).r;
  if (start < 0.0)
  {
    return vec3(1.0);
  }
  int chunk = int(start) / 2;
  // Chunks whose last node lies at or before depth are walked past (most texels have one
  // chunk and skip this); links point to higher chunks only, so the walk ends whatever the
  // pool holds.
  vec4 a = vec4(0.0);
  bool before = false;
  bool more = (int(start) & 1) != 0;
  while (more)
  {
    int base = chunk * (DsmChunkNodes + 1);
    vec4 last = texelFetch(u_shadowNodes, base + DsmChunkNodes);
    int next = last.r <= depth ? int(texelFetch(u_shadowNodes, base).r) : -1;
    more = next > chunk;
    if (more)
    {
      a = last;
      before = true;
      chunk = next;
    }
  }
  return dsmBetween(ivec3(chunk * (DsmChunkNodes + 1), 0, 0), DsmChunkNodes, depth, a, before);
#else
  return dsmBetween(ivec3(texel, layer), u_shadowLayersPerFace, depth, vec4(0.0), false);
#endif
}

vec3 dsmAt(int layer, ivec2 texel, vec2 xy, float depth, vec2 slope)
{
  return dsmTexel(layer, texel, lightSpaceDepthAt(vec2(texel), xy, depth, slope));
}

vec3 mapVisibility(int layer, vec2 xy, float depth, vec2 slope)
{
  ivec2 i0;
  vec4 w = lightSpaceBilinear(xy, i0);
  return w.x * dsmAt(layer, i0, xy, depth, slope) + w.y * dsmAt(layer, i0 + ivec2(1, 0), xy, depth, slope) +
    w.z * dsmAt(layer, i0 + ivec2(0, 1), xy, depth, slope) + w.w * dsmAt(layer, i0 + ivec2(1, 1), xy, depth, slope);
}
