// A bounding-volume hierarchy over triangles, and the one query both of its users need: the
// nearest crossing of a ray after a given parameter, which triangle it is, and whether the ray
// meets its front side. Bounded volumes (Bound/BoundRegion.h) walk closed meshes with it;
// shadow-casting surfaces (SurfaceSet.h) are found along light rays with it. The GPU walks the
// same flattened nodes (AppendForGPU) with the same Möller-Trumbore test in float
// (Shaders/Features/TriangleHierarchy.glsl).
#ifndef deepshadow_TriangleBVH_h
#define deepshadow_TriangleBVH_h

#include "vtkDeepShadowCoreModule.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <vector>

namespace deepshadow
{

struct Triangle
{
  glm::dvec3 V0, V1, V2; // counter-clockwise seen from outside the solid
  /** The user's label (SurfaceSet: the surface it belongs to); kept through the build. */
  int Tag = 0;
};

/** A ray's crossing of a mesh. */
struct MeshHit
{
  double T = 0.0;
  /** Entering the solid: the ray meets the triangle's front (outer) side. */
  bool Entering = false;
  bool Found = false;
  /** Index of the triangle crossed, in TriangleBVH::GetTriangles(). */
  int Triangle = -1;
};

class VTKDEEPSHADOWCORE_EXPORT TriangleBVH
{
public:
  /** Leaves hold at most this many triangles. */
  static constexpr int LeafSize = 4;

  struct Node
  {
    glm::dvec3 Min{ 0.0 }, Max{ 0.0 };
    /** Leaf (Count > 0): first triangle. Inner node: first child (the second follows it). */
    int32_t First = 0;
    int32_t Count = 0;
  };

  TriangleBVH() = default;
  /** Builds the hierarchy (binned by centroid, median split of the longest axis). */
  explicit TriangleBVH(std::vector<Triangle> triangles);

  /**
   * The nearest crossing of origin + t * direction with t > tAfter (any parametrisation:
   * direction need not be unit). Found == false when there is none.
   */
  MeshHit NextHit(const glm::dvec3& origin, const glm::dvec3& direction, double tAfter) const;

  const std::vector<Node>& GetNodes() const { return this->Nodes; }
  /** In the hierarchy's order (leaves index into it). */
  const std::vector<Triangle>& GetTriangles() const { return this->Triangles; }
  bool Empty() const { return this->Triangles.empty(); }
  /** Longest root-to-leaf path (the GPU's traversal stack must hold it). */
  int GetDepth() const { return this->Depth; }

  /**
   * Appends the hierarchy in the GPU's layout and returns its root node (-1 when empty):
   * two texels per node, (min, first) and (max, count), boxes rounded outward to float; three
   * texels per triangle, its vertices, the first with w = Tag.
   */
  int AppendForGPU(std::vector<glm::vec4>& nodes, std::vector<glm::vec4>& triangles) const;

private:
  int Build(int node, int first, int count, int depth);

  std::vector<Triangle> Triangles;
  std::vector<Node> Nodes;
  int Depth = 0;
};

/**
 * Möller-Trumbore: the parameter t of the ray's crossing of the triangle, and the sign of the
 * determinant (> 0: the ray meets the front side). Returns false when it misses (or runs
 * parallel). The GPU twin is boundTriangle() in Features/Bound.glsl.
 */
VTKDEEPSHADOWCORE_EXPORT bool IntersectTriangle(const glm::dvec3& origin, const glm::dvec3& direction,
  const Triangle& triangle, double& t, bool& entering);

}
#endif
