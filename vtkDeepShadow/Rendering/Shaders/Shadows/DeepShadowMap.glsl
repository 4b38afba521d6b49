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
// The chunk of the texel whose start entry is `start` that holds depth (`at`: its nodes), and
// whether a node of an earlier chunk (`a`) lies at or before depth. Chunks whose last node
// lies at or before depth are walked past (most texels have one chunk and skip this); links
// point to higher chunks only, so the walk ends whatever the pool holds.
void dsmChunkOf(float start, float depth, out ivec3 at, inout vec4 a, out bool before)
{
  // 2 first chunk + 1 if it has a next one; -1: no chunk (V' = 1, see mapVisibility).
  int chunk = int(max(start, 0.0)) / 2;
  before = false;
  bool more = start > 0.0 && (int(start) & 1) != 0;
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
  at = ivec3(chunk * (DsmChunkNodes + 1), 0, 0);
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
  ivec3 at0, at1, at2, at3;
  bvec4 before;
  dsmChunkOf(start.x, d.x, at0, a0, before.x);
  dsmChunkOf(start.y, d.y, at1, a1, before.y);
  dsmChunkOf(start.z, d.z, at2, a2, before.z);
  dsmChunkOf(start.w, d.w, at3, a3, before.w);
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
