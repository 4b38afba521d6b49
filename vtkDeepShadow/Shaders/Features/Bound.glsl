// Feature Bound: the volume exists only inside a polyhedral bound (closed meshes, the leaves,
// combined by a CSG expression; deepshadow::BoundRegion in Core/Bound is the CPU twin). Each
// march walks the bound along its ray: per leaf, the nearest crossing after the current
// sample, found in the leaf's bounding-volume hierarchy; the side the ray crosses gives the
// leaf's state, the truth table of the expression the region's. Samples outside are skipped
// in one jump to the next crossing, in whole steps, so that the samples taken are those of an
// unbounded march (as EmptySpace does).
//@Dec
// BOUND_LEAVES, the number of leaves, is defined by the composer (BoundShaderFeature): loops
// over the leaves have a constant count, so the walker's arrays can stay in registers.
const int BoundTextureWidth = 4096;
const float BoundNever = 3.0e38;
uniform sampler2D u_boundNodes;     // 2 texels per node: (min, first), (max, count)
uniform sampler2D u_boundTriangles; // 3 texels per triangle: its vertices
uniform int u_boundLeafRoot[BOUND_LEAVES]; // -1: an empty leaf
uniform int u_boundTruth[8];        // bit s: the region holds the points whose leaf states are s

vec4 boundFetch(sampler2D data, int i)
{
  return texelFetch(data, ivec2(i % BoundTextureWidth, i / BoundTextureWidth), 0);
}

// deepshadow::IntersectTriangle (Möller-Trumbore).
bool boundTriangle(vec3 origin, vec3 direction, int triangle, out float t, out bool entering)
{
  vec3 v0 = boundFetch(u_boundTriangles, 3 * triangle).xyz;
  vec3 e1 = boundFetch(u_boundTriangles, 3 * triangle + 1).xyz - v0;
  vec3 e2 = boundFetch(u_boundTriangles, 3 * triangle + 2).xyz - v0;
  vec3 p = cross(direction, e2);
  float det = dot(e1, p);
  t = 0.0;
  entering = det > 0.0;
  if (det == 0.0)
  {
    return false;
  }
  float inverse = 1.0 / det;
  vec3 s = origin - v0;
  float u = dot(s, p) * inverse;
  if (u < 0.0 || u > 1.0)
  {
    return false;
  }
  vec3 q = cross(s, e1);
  float v = dot(direction, q) * inverse;
  if (v < 0.0 || u + v > 1.0)
  {
    return false;
  }
  t = dot(e2, q) * inverse;
  return true;
}

// deepshadow::TriangleBVH::NextHit: the nearest crossing of leaf `leaf` after tAfter
// (BoundNever when none), and whether the ray enters the solid there.
float boundNextHit(int leaf, vec3 origin, vec3 direction, float tAfter, out bool entering)
{
  float best = BoundNever;
  entering = false;
  int root = u_boundLeafRoot[leaf];
  if (root < 0)
  {
    return best;
  }
  vec3 inverse = 1.0 / direction;
  bvec3 parallel = equal(direction, vec3(0.0));
  int stack[32];
  int top = 0;
  stack[top++] = root;
  while (top > 0)
  {
    int node = stack[--top];
    vec4 lo = boundFetch(u_boundNodes, 2 * node);
    vec4 hi = boundFetch(u_boundNodes, 2 * node + 1);
    vec3 tA = (lo.xyz - origin) * inverse;
    vec3 tB = (hi.xyz - origin) * inverse;
    // An axis the ray runs parallel to: no limit inside the slab, no box outside it (mix()
    // selects, so the NaN of 0 * inf does not leak).
    bvec3 inSlab = bvec3(vec3(greaterThanEqual(origin, lo.xyz)) * vec3(lessThanEqual(origin, hi.xyz)));
    vec3 tLow = mix(min(tA, tB), mix(vec3(BoundNever), vec3(-BoundNever), inSlab), parallel);
    vec3 tHigh = mix(max(tA, tB), mix(vec3(-BoundNever), vec3(BoundNever), inSlab), parallel);
    float tNear = max(max(tLow.x, tLow.y), tLow.z);
    float tFar = min(min(tHigh.x, tHigh.y), tHigh.z);
    if (!(tNear <= tFar) || tFar <= tAfter || tNear >= best)
    {
      continue;
    }
    int first = int(lo.w);
    int count = int(hi.w);
    if (count > 0)
    {
      for (int i = first; i < first + count; ++i)
      {
        float t;
        bool enters;
        if (boundTriangle(origin, direction, i, t, enters) && t > tAfter && t < best)
        {
          best = t;
          entering = enters;
        }
      }
      continue;
    }
    stack[top++] = first + 1;
    stack[top++] = first;
  }
  return best;
}

// deepshadow::BoundRegion::Walker. The region's state and where it may next change are kept,
// so that a sample before that point costs one comparison (no loop over the leaves).
struct BoundWalker
{
  float next[BOUND_LEAVES]; // each leaf's next crossing
  int states;                   // bit i: inside leaf i
  bool inside;                  // the region's state ...
  float until;                  // ... up to here
};

BoundWalker boundWalkerStart()
{
  BoundWalker walker;
  for (int i = 0; i < BOUND_LEAVES; ++i)
  {
    walker.next[i] = -BoundNever;
  }
  walker.states = 0;
  walker.inside = false;
  walker.until = -BoundNever;
  return walker;
}

// Brings the walker to t: the leaves whose crossing was passed find their next one.
void boundAdvance(inout BoundWalker walker, vec3 origin, vec3 direction, float t)
{
  walker.until = BoundNever;
  for (int i = 0; i < BOUND_LEAVES; ++i)
  {
    if (walker.next[i] <= t)
    {
      bool entering;
      walker.next[i] = boundNextHit(i, origin, direction, t, entering);
      bool inside = walker.next[i] < BoundNever && !entering;
      walker.states = inside ? (walker.states | (1 << i)) : (walker.states & ~(1 << i));
    }
    walker.until = min(walker.until, walker.next[i]);
  }
  walker.inside = ((u_boundTruth[walker.states >> 5] >> (walker.states & 31)) & 1) != 0;
}

// deepshadow::BoundRegion::Walker::SkipSteps: 0 if the sample at t is inside; else the steps
// of dt to the first sample at or past the next crossing (1 << 30: none).
int boundSkipSteps(inout BoundWalker walker, vec3 origin, vec3 direction, float t, float dt)
{
  if (t >= walker.until)
  {
    boundAdvance(walker, origin, direction, t);
  }
  if (walker.inside)
  {
    return 0;
  }
  if (walker.until >= BoundNever)
  {
    return 1 << 30;
  }
  return max(1, int(min(ceil((walker.until - t) / dt), 1073741824.0)));
}
//@Init
  BoundWalker boundView = boundWalkerStart();
//@Impl
    {
      int skip = boundSkipSteps(boundView, indexOrigin, indexDirection, t, u_step);
      if (skip > 0)
      {
        k += skip - 1;
        continue;
      }
    }
//@FeelerInit
  BoundWalker boundFeeler = boundWalkerStart();
//@FeelerSkip
    {
      int skip = boundSkipSteps(boundFeeler, start, indexDirection, t, u_feelerStep);
      if (skip > 0)
      {
        j += skip - 1;
        continue;
      }
    }
//@TexelInit
  BoundWalker boundTexel = boundWalkerStart();
//@TexelSkip
    skip = boundSkipSteps(boundTexel, indexOrigin, indexDirection, t, u_feelerStep);
