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
// The most nodes a texel of the maps holds: the search covers no more of the layers, whose
// unused ones repeat the last value far away (u_shadowLayersPerFace of them per face).
uniform int u_dsmSearchNodes;

vec4 dsmNode(ivec3 at, int k)
{
  return lightSpaceTexel(at.xy, at.z + k);
}
#endif

// One step of the binary search over the nodes at `at` for depth: `first` counts the nodes
// found at or before depth, `remaining` those left to search after them. The search reads
// the two nodes that bracket depth on its way: the last node found at or before it (`a`) is
// node first - 1, and the last found beyond it (`b`) is node first (each such probe moves
// the search's right end to itself, and the search ends where its ends meet), so neither is
// fetched again.
void dsmSearchStep(ivec3 at, float depth, inout int first, inout int remaining, inout vec4 a, inout vec4 b)
{
  if (remaining > 0)
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
}

// V' at depth once the search of `count` nodes ended; `before` says whether `a` is a node
// before them that lies at or before depth.
vec3 dsmBracketed(int count, int first, bool before, vec4 a, vec4 b, float depth)
{
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

#ifdef DSM_CHUNKED
// One step of the walk to the chunk that holds depth, from the chunk `chunk` (while `more`):
// a chunk whose last node lies at or before depth is walked past, that node becoming `a`, a
// node before the chunk searched (`before`). Most texels have one chunk and never walk;
// links point to higher chunks only, so a walk ends whatever the pool holds.
void dsmWalkStep(float depth, inout int chunk, inout bool more, inout vec4 a, inout bool before)
{
  if (more)
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
}
#endif

// The four texels' searches in step, in one loop: llvmpipe pays a loop's bookkeeping once
// instead of four times.
vec3 mapVisibility(int layer, vec2 xy, float depth, vec2 slope)
{
  ivec2 i0;
  vec4 w = lightSpaceBilinear(xy, i0);
  ivec2 i1 = i0 + ivec2(1, 0), i2 = i0 + ivec2(0, 1), i3 = i0 + ivec2(1, 1);
  vec4 d = vec4(lightSpaceDepthAt(vec2(i0), xy, depth, slope), lightSpaceDepthAt(vec2(i1), xy, depth, slope),
    lightSpaceDepthAt(vec2(i2), xy, depth, slope), lightSpaceDepthAt(vec2(i3), xy, depth, slope));
  vec4 a0 = vec4(0.0), a1 = vec4(0.0), a2 = vec4(0.0), a3 = vec4(0.0);
  vec4 b0 = vec4(0.0), b1 = vec4(0.0), b2 = vec4(0.0), b3 = vec4(0.0);
#ifdef DSM_CHUNKED
  vec4 start = vec4(lightSpaceTexel(i0, layer).r, lightSpaceTexel(i1, layer).r, lightSpaceTexel(i2, layer).r,
    lightSpaceTexel(i3, layer).r);
  // Start entries: 2 first chunk + 1 if it has a next one; -1: no chunk (V' = 1, below).
  ivec4 code = ivec4(max(start, vec4(0.0)));
  ivec4 chunk = code / 2;
  bvec4 more = notEqual(code & 1, ivec4(0));
  bvec4 before = bvec4(false);
  while (any(more))
  {
    dsmWalkStep(d.x, chunk.x, more.x, a0, before.x);
    dsmWalkStep(d.y, chunk.y, more.y, a1, before.y);
    dsmWalkStep(d.z, chunk.z, more.z, a2, before.z);
    dsmWalkStep(d.w, chunk.w, more.w, a3, before.w);
  }
  ivec4 base = chunk * (DsmChunkNodes + 1);
  ivec3 at0 = ivec3(base.x, 0, 0), at1 = ivec3(base.y, 0, 0), at2 = ivec3(base.z, 0, 0), at3 = ivec3(base.w, 0, 0);
  const int count = DsmChunkNodes;
#else
  ivec3 at0 = ivec3(i0, layer), at1 = ivec3(i1, layer), at2 = ivec3(i2, layer), at3 = ivec3(i3, layer);
  bvec4 before = bvec4(false);
  int count = u_dsmSearchNodes;
#endif
  ivec4 first = ivec4(0), remaining = ivec4(count);
  // As many steps as a search of count nodes takes (count, then at most half of it, ...).
  for (int steps = count; steps > 0; steps /= 2)
  {
    dsmSearchStep(at0, d.x, first.x, remaining.x, a0, b0);
    dsmSearchStep(at1, d.y, first.y, remaining.y, a1, b1);
    dsmSearchStep(at2, d.z, first.z, remaining.z, a2, b2);
    dsmSearchStep(at3, d.w, first.w, remaining.w, a3, b3);
  }
  vec3 v0 = dsmBracketed(count, first.x, before.x, a0, b0, d.x);
  vec3 v1 = dsmBracketed(count, first.y, before.y, a1, b1, d.y);
  vec3 v2 = dsmBracketed(count, first.z, before.z, a2, b2, d.z);
  vec3 v3 = dsmBracketed(count, first.w, before.w, a3, b3, d.w);
#ifdef DSM_CHUNKED
  v0 = start.x < 0.0 ? vec3(1.0) : v0;
  v1 = start.y < 0.0 ? vec3(1.0) : v1;
  v2 = start.z < 0.0 ? vec3(1.0) : v2;
  v3 = start.w < 0.0 ? vec3(1.0) : v3;
#endif
  return w.x * v0 + w.y * v1 + w.z * v2 + w.w * v3;
}
