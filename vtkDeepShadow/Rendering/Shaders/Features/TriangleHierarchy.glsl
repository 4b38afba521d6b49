// Feature TriangleHierarchy: the walk of a bounding-volume hierarchy over triangles, as
// deepshadow::TriangleBVH::AppendForGPU packs it into two float textures (the CPU twins are
// TriangleBVH::NextHit and IntersectTriangle in Core/Geometry). Shared by Bound (closed meshes
// that bound a volume) and Surfaces (meshes that cast shadows); each passes its own textures.
//@Dec
const int HierarchyTextureWidth = 4096;
const float HierarchyNever = 3.0e38;

vec4 hierarchyFetch(sampler2D data, int i)
{
  return texelFetch(data, ivec2(i % HierarchyTextureWidth, i / HierarchyTextureWidth), 0);
}

// deepshadow::IntersectTriangle (Möller-Trumbore).
bool hierarchyTriangle(sampler2D triangles, vec3 origin, vec3 direction, int triangle, out float t,
  out bool entering)
{
  vec3 v0 = hierarchyFetch(triangles, 3 * triangle).xyz;
  vec3 e1 = hierarchyFetch(triangles, 3 * triangle + 1).xyz - v0;
  vec3 e2 = hierarchyFetch(triangles, 3 * triangle + 2).xyz - v0;
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

// deepshadow::TriangleBVH::NextHit from node `root` (-1: empty): the nearest crossing after
// tAfter (HierarchyNever when none), whether the ray meets its front side, and its triangle.
float hierarchyNextHit(sampler2D nodes, sampler2D triangles, int root, vec3 origin, vec3 direction,
  float tAfter, out bool entering, out int triangle)
{
  float best = HierarchyNever;
  entering = false;
  triangle = -1;
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
    vec4 lo = hierarchyFetch(nodes, 2 * node);
    vec4 hi = hierarchyFetch(nodes, 2 * node + 1);
    vec3 tA = (lo.xyz - origin) * inverse;
    vec3 tB = (hi.xyz - origin) * inverse;
    // An axis the ray runs parallel to: no limit inside the slab, no box outside it (mix()
    // selects, so the NaN of 0 * inf does not leak).
    bvec3 inSlab = bvec3(vec3(greaterThanEqual(origin, lo.xyz)) * vec3(lessThanEqual(origin, hi.xyz)));
    vec3 tLow = mix(min(tA, tB), mix(vec3(HierarchyNever), vec3(-HierarchyNever), inSlab), parallel);
    vec3 tHigh = mix(max(tA, tB), mix(vec3(-HierarchyNever), vec3(HierarchyNever), inSlab), parallel);
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
        if (hierarchyTriangle(triangles, origin, direction, i, t, enters) && t > tAfter && t < best)
        {
          best = t;
          entering = enters;
          triangle = i;
        }
      }
      continue;
    }
    stack[top++] = first + 1;
    stack[top++] = first;
  }
  return best;
}
