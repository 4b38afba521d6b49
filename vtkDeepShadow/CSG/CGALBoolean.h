// Internal bridge between VTK and CGAL for the Boolean CSG of closed bounds (not installed).
//
// vtkPolyData -> triangle soup (triangulated, coincident points merged exactly, faces with a
// repeated vertex dropped) -> CGAL::Surface_mesh over the exact-constructions kernel (Epeck),
// validated as a solid (closed, manifold, not self-intersecting, bounding a volume, oriented
// outward) -> Boolean operations by corefinement, chained on exact meshes -> vtkPolyData of
// triangles (points rounded to double once, at the end).
//
// Every CGAL header is included by CGALBoolean.cxx only: this header names no CGAL type, so the
// filter and its users compile without CGAL. The heavy templates are instantiated once.
#ifndef deepshadow_csg_CGALBoolean_h
#define deepshadow_csg_CGALBoolean_h

#include "Core/Bound/CSGExpression.h" // For CSGNode, CSGOperation

#include "vtkType.h" // For vtkIdType

#include <functional> // For ProgressFunction
#include <memory>     // For the mesh's implementation
#include <string>     // For messages
#include <vector>     // For the bounds

class vtkPolyData;

namespace deepshadow
{
namespace csg
{

/**
 * A closed triangle mesh with exact coordinates (CGAL::Surface_mesh of Epeck points), held
 * through an opaque implementation. Copies are deep (operations modify their operands).
 */
class ExactMesh
{
public:
  ExactMesh();
  ~ExactMesh();
  ExactMesh(const ExactMesh& other);
  ExactMesh& operator=(const ExactMesh& other);
  ExactMesh(ExactMesh&& other) noexcept;
  ExactMesh& operator=(ExactMesh&& other) noexcept;

  /** No face: the empty solid. */
  bool IsEmpty() const;
  vtkIdType GetNumberOfTriangles() const;
  vtkIdType GetNumberOfPoints() const;

  /**
   * Writes the mesh into `output` (which is reset): double points and triangles, oriented as
   * the mesh is (outward for a validated solid). No point or cell data.
   */
  void ToPolyData(vtkPolyData* output) const;

  struct Impl;
  Impl& Get() { return *this->P; }
  const Impl& Get() const { return *this->P; }

private:
  std::unique_ptr<Impl> P;
};

/** What the conversion of one operand found and did. */
struct ConversionReport
{
  /** Faces dropped or collapsed: a repeated vertex (after merging) or zero area. */
  vtkIdType RemovedDegenerateFaces = 0;
  /** Vertex and line cells, which bound no volume and were ignored. */
  vtkIdType IgnoredCells = 0;
  /** Points merged because they had exactly the same coordinates as an earlier point. */
  vtkIdType MergedPoints = 0;
  /** Whether the mesh had to be reoriented to bound a volume (e.g. it faced inward). */
  bool Reoriented = false;
};

/**
 * Converts `input` (polygons and triangle strips; vertices and lines are ignored) into a
 * closed exact mesh and validates it as a solid (see ValidateSolid). Returns false with
 * `problem` ("is empty", "is not closed: 12 border edges", ...; the caller prefixes the name
 * of the bound) if it cannot be one. Non-finite points are rejected before CGAL sees them.
 */
bool MeshFromPolyData(vtkPolyData* input, ExactMesh& mesh, ConversionReport& report, std::string& problem);

/**
 * Checks that `mesh` is a solid: not empty, closed (CGAL::is_closed), free of
 * self-intersections (PMP::does_self_intersect) and bounding a volume
 * (PMP::does_bound_a_volume). If only its orientation is wrong, it is reoriented
 * (PMP::orient_to_bound_a_volume) and `reoriented` is set. False with `problem` otherwise.
 */
bool ValidateSolid(ExactMesh& mesh, bool& reoriented, std::string& problem);

/**
 * `a` = `a` op `b` by corefinement (PMP::corefine_and_compute_union / _intersection /
 * _difference). Both operands are consumed (corefinement modifies them). Either may be empty
 * (the empty solid). False with `problem` if CGAL reports failure (a result that would not be a
 * manifold surface, e.g. operands touching along an edge only).
 */
bool Combine(CSGOperation operation, ExactMesh& a, ExactMesh& b, std::string& problem);

/**
 * Points where the surface touches itself: positions held by more than one vertex (CGAL
 * keeps one vertex per sheet where operands touched at an isolated point). Such a mesh is a
 * valid solid but not a valid operand (it counts as self-intersecting).
 */
vtkIdType CountPinchedPoints(const ExactMesh& mesh);

/**
 * Replaces the lazily evaluated coordinates of `mesh` by their exact values, so that chained
 * operations do not grow the lazy-evaluation graphs of the kernel.
 */
void MakeCoordinatesExact(ExactMesh& mesh);

/** Called after each Boolean operation with the fraction of operations done; false aborts. */
using ProgressFunction = std::function<bool(double fraction)>;

/** The outcome of Evaluate. */
struct EvaluationResult
{
  /** Empty when the evaluation succeeded; otherwise one line naming the operand and problem. */
  std::string Error;
  /** Things the user should know about (degenerate faces removed, reoriented bounds...). */
  std::vector<std::string> Warnings;
  /** Degenerate faces removed from all the bounds used. */
  vtkIdType RemovedDegenerateFaces = 0;
  /** Binary Boolean operations done (n-ary operations count n - 1). */
  int Operations = 0;
  /** The result is the empty solid (no error). */
  bool Empty = false;
};

/** Binary operations in a tree: the progress denominator. */
int CountOperations(const CSGNode& node);

/**
 * Evaluates the tree `root` on `bounds` (leaf i is bounds[i]) and writes the result into
 * `output` (reset first; left empty on error). Each bound used is converted and validated once;
 * intermediate results stay exact and are validated before they are used again.
 */
bool Evaluate(const CSGNode& root, const std::vector<vtkPolyData*>& bounds, vtkPolyData* output,
  EvaluationResult& result, const ProgressFunction& progress = nullptr);

/** "bound B (input 1)". */
std::string BoundName(int leaf);

}
}
#endif
