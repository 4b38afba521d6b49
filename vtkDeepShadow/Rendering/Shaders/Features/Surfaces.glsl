// Feature Surfaces: meshes that cast shadows (deepshadow::SurfaceSet in Core/Geometry is the
// CPU twin). Their triangles sit in the volume's index space, so a ray's parameter is the
// same world distance as the volume's marches use. A crossing multiplies a light ray by the
// surface's transmission (SurfaceTransmission): feelers multiply every crossing up to the
// light, binary feelers stop at one above the threshold; light-space builds visit crossings in
// depth order between their samples (MarchTexelRay), through the technique's visitSurface().
//@Dec
const int MaxSurfaces = 64;                     // deepshadow::SurfaceSet::MaxSurfaces
uniform sampler2D u_surfaceNodes;               // TriangleBVH::AppendForGPU, w of a triangle's
uniform sampler2D u_surfaceTriangles;           // first texel: its surface
uniform int u_surfaceRoot;
uniform vec4 u_surfaceTransmission[MaxSurfaces]; // rgb coloured, a grey (SurfaceTransmission)
uniform float u_surfaceThreshold;               // opacity above which a surface is an occluder

// The nearest crossing after tAfter (HierarchyNever: none) and the surface crossed there.
float surfaceNextHit(vec3 origin, vec3 direction, float tAfter, out int surface)
{
  bool entering;
  int triangle;
  float t = hierarchyNextHit(u_surfaceNodes, u_surfaceTriangles, u_surfaceRoot, origin, direction,
    tAfter, entering, triangle);
  surface = triangle >= 0 ? int(hierarchyFetch(u_surfaceTriangles, 3 * triangle).w) : 0;
  return t;
}

// A mesh above the per-sample threshold (binary techniques; occluderCounts in Feeler.glsl
// applies the threshold mode).
bool surfaceAboveThreshold(int surface)
{
  return 1.0 - u_surfaceTransmission[surface].a > u_surfaceThreshold;
}
//@Feeler
  // deepshadow::FeelerVisibility: the surfaces between the point and the light.
  {
    int surface;
    for (float tSurface = surfaceNextHit(start, indexDirection, 0.0, surface); tSurface < lightDistance;
         tSurface = surfaceNextHit(start, indexDirection, tSurface, surface))
    {
      if (opaque)
      {
        float grey = feelerLargest(surfaces);
        if (occluderCounts(u_surfaceTransmission[surface].a, surfaceAboveThreshold(surface), grey))
        {
          return vec3(0.0);
        }
        surfaces = FeelerTransmittance(grey);
        continue;
      }
#ifdef FEELER_COLORED
      surfaces *= u_surfaceTransmission[surface].rgb;
#else
      surfaces *= u_surfaceTransmission[surface].a;
#endif
      if (feelerLargest(surfaces) <= 0.0)
      {
        return vec3(0.0);
      }
    }
  }
//@TexelInit
  int surfaceCrossed;
#ifdef LIGHT_SPACE_CLIP
  // A clustered face whose cluster the surfaces are not in meets none of them.
  float surfaceNext = u_clipSurfaces == 0 ? HierarchyNever : surfaceNextHit(indexOrigin, indexDirection, 0.0, surfaceCrossed);
#else
  float surfaceNext = surfaceNextHit(indexOrigin, indexDirection, 0.0, surfaceCrossed);
#endif
//@TexelUpTo
  // The crossings up to `upTo` come first (deepshadow::MarchTexelRay).
  for (; surfaceNext < HierarchyNever && surfaceNext <= upTo;
       surfaceNext = surfaceNextHit(indexOrigin, indexDirection, surfaceNext, surfaceCrossed))
  {
    if (!visitSurface(surfaceNext, surfaceCrossed))
    {
      return;
    }
  }
//@Visit
//DeepShadow::Build::Surface
