// A volume's polyhedral bound: closed meshes (the leaves) combined by a CSG expression, in the
// volume's continuous voxel-index space. The volume exists only inside it: every march (view
// rays, shadow feelers, light-space builds) skips the samples outside, on the CPU and the GPU.
//
// Along a ray the region is walked, not sampled (paper 000, sec. 3: the CSG tree evaluated
// from each leaf's sorted boundary crossings): for each leaf, its next crossing after the
// current sample; whether a point is inside a leaf follows from that crossing's side (the
// ray leaves the solid there: inside; it enters: outside), so no crossing parity is counted
// and a ray through an edge (two crossings at one t) cannot flip the state. The region's
// state is the expression of the leaves' states; it can change only at the next crossing of
// any leaf, so samples up to there are skipped in one jump when outside. One leaf with the
// expression "A" is the CGAL filter's result used as the bound.
#ifndef deepshadow_BoundRegion_h
#define deepshadow_BoundRegion_h

#include "Core/Bound/CSGExpression.h"
#include "Core/Geometry/TriangleBVH.h"
#include "vtkDeepShadowCoreModule.h"

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <limits>
#include <string>
#include <vector>

namespace deepshadow
{

/**
 * Checks that `triangles` bound a solid the walk can use: not empty, finite, closed (every
 * edge shared by exactly two triangles once coincident points are merged). Returns "" or the
 * problem, e.g. "is not closed: 12 border edges".
 */
VTKDEEPSHADOWCORE_EXPORT std::string CheckClosedMesh(const std::vector<Triangle>& triangles);

/** Six times the signed volume enclosed (positive: counter-clockwise seen from outside). */
VTKDEEPSHADOWCORE_EXPORT double SignedVolume6(const std::vector<Triangle>& triangles);

/** Reverses every triangle if the mesh is oriented inward, so that its normals point out. */
VTKDEEPSHADOWCORE_EXPORT void OrientOutward(std::vector<Triangle>& triangles);

class VTKDEEPSHADOWCORE_EXPORT BoundRegion
{
public:
  /** Leaves (closed, outward-oriented meshes) in voxel-index space, and how they combine. */
  BoundRegion(std::vector<std::vector<Triangle>> leaves, CSGExpression expression);

  int GetLeafCount() const { return static_cast<int>(this->Leaves.size()); }
  const TriangleBVH& GetLeaf(int i) const { return this->Leaves[static_cast<size_t>(i)]; }
  const CSGExpression& GetExpression() const { return this->Expression; }
  size_t GetTriangleCount() const;

  /** Walks one ray origin + t * direction through the region, t non-decreasing. */
  class VTKDEEPSHADOWCORE_EXPORT Walker
  {
  public:
    Walker(const BoundRegion& region, const glm::dvec3& origin, const glm::dvec3& direction);
    /** Whether the point at t is inside the region. */
    bool Inside(double t);
    /** Where the state found by the last Inside() may next change (infinity: never). */
    double Until() const;
    /**
     * For a march with samples dt apart: 0 if the sample at t is inside; else how many steps
     * lead to the first sample at or past Until() (>= 1; LONG_MAX / 2 if the ray never
     * re-enters). The GPU twin is boundSkipSteps() in Features/Bound.glsl.
     */
    long SkipSteps(double t, double dt);

  private:
    const BoundRegion& Region;
    glm::dvec3 Origin, Direction;
    std::vector<double> Next; // each leaf's next crossing after the last query
    uint32_t States = 0;      // bit i: inside leaf i
    // The region's state and where it may next change: a query before there costs one
    // comparison (as boundSkipSteps() does on the GPU).
    bool InsideState = false;
    double UntilT = -std::numeric_limits<double>::infinity();
  };

  /** Whether p is inside (one walk along +x). */
  bool Inside(const glm::dvec3& p) const;
  /** The parts of [t0, t1] of a ray inside the region, in order. */
  std::vector<glm::dvec2> Intervals(const glm::dvec3& origin, const glm::dvec3& direction,
    double t0, double t1) const;

  /** What the GPU walks (Features/Bound.glsl): every leaf's nodes and triangles in float. */
  struct GPUData
  {
    /** Two texels per node: (min, first), (max, count); boxes rounded outward. */
    std::vector<glm::vec4> Nodes;
    /** Three texels per triangle: its vertices (w: the tag, unused here). */
    std::vector<glm::vec4> Triangles;
    std::vector<int> LeafRoots;    // each leaf's root node
    std::vector<int> TruthTable;   // CSGExpression::TruthTable() as GLSL ints
    int MaxDepth = 0;              // deepest leaf (the traversal stack's need)
  };
  GPUData PackForGPU() const;

private:
  std::vector<TriangleBVH> Leaves;
  CSGExpression Expression;
  std::vector<uint32_t> Truth;
};

}
#endif
