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
const float BoundNever = HierarchyNever;
uniform sampler2D u_boundNodes;     // TriangleBVH::AppendForGPU's nodes of every leaf
uniform sampler2D u_boundTriangles; // ... and their triangles
uniform int u_boundLeafRoot[BOUND_LEAVES]; // -1: an empty leaf
uniform int u_boundTruth[8];        // bit s: the region holds the points whose leaf states are s

// The nearest crossing of leaf `leaf` after tAfter (BoundNever when none), and whether the ray
// enters the solid there.
float boundNextHit(int leaf, vec3 origin, vec3 direction, float tAfter, out bool entering)
{
  int triangle;
  return hierarchyNextHit(u_boundNodes, u_boundTriangles, u_boundLeafRoot[leaf], origin, direction,
    tAfter, entering, triangle);
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
