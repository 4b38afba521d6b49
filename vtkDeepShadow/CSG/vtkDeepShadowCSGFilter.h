/**
 * @class   vtkDeepShadowCSGFilter
 * @brief   Exact Boolean CSG (union, intersection, difference) of closed polyhedral bounds.
 *
 * Input port 0 is repeatable: connection i is bound i, named A, B, C, ... in the order the
 * connections were added (AddInputConnection / AddInputData). The expression (SetExpression)
 * combines them; its grammar (deepshadow::CSGExpression):
 *
 *   expr := NAME | OP '(' expr (',' expr)+ ')'
 *   OP   := union | intersection | inter | difference | diff     (case-insensitive)
 *   NAME := A | B | ... (a single letter, case-insensitive)
 *
 * for example "union(A,diff(B,C))". n-ary operations fold left: diff(A,B,C) = (A-B)-C. An
 * empty expression (the default) is the union of all inputs; inputs that the expression does
 * not name are ignored (with a warning).
 *
 * Each bound is a closed surface: polygons and triangle strips (vertices and lines are
 * ignored, with a warning). It is triangulated (deepshadow::TriangulatePolygon), points with exactly the
 * same coordinates are merged (so STL-like input without shared points works, and so does
 * vtkCubeSource's output with one set of points per face), and degenerate faces (a repeated
 * vertex after merging, or zero area) are removed; GetRemovedDegenerateFaces() counts them
 * and a warning says how many and from which bound. The result must then be a solid: a
 * manifold, closed surface that does not intersect itself and bounds a volume. A bound that
 * faces inward is reoriented (with a warning). Coordinates are used as given (no transform).
 *
 * The Boolean operations are CGAL's corefinement (Polygon_mesh_processing
 * corefine_and_compute_union / _intersection / _difference) over CGAL::Surface_mesh with the
 * exact-predicates, exact-constructions kernel: intermediate results of a tree keep exact
 * coordinates, which are rounded to double only for the output. Coplanar and touching
 * operands are handled exactly. Each intermediate result is validated again before it is used.
 * A closed part of one operand that coincides exactly with a closed part of the other facing
 * the other way (e.g. B filling a cavity of A exactly), which CGAL 5.5's corefinement
 * misclassifies, is handled by splitting the operation at the shared surface. A union of
 * operands that touch along an edge only has no manifold surface: an error. Operands that touch
 * at isolated points give a solid whose surface touches itself there: as the output it is kept
 * (one point per sheet, with a warning); as an operand of a further operation it is an error.
 *
 * Output: a vtkPolyData of triangles with double points, consistently oriented with outward
 * normals (counter-clockwise seen from outside), closed. Point, cell and field data of the
 * inputs are dropped; no normals are computed. An empty result (e.g. the intersection of
 * disjoint solids, or A minus a B that contains A) is not an error: the output is empty,
 * GetResultIsEmpty() is true, and a warning says "the CSG result is empty".
 *
 * Errors (one vtkErrorMacro line, also kept in GetLastError(); the request fails and the
 * output is empty): a bad expression (with the position of the problem), an expression naming
 * a bound that is not connected, no input, an expression whose triangle work exceeds
 * MaximumTriangleWork, and a bound or intermediate result that cannot be a
 * solid, named with the problem, e.g. "bound B (input 1) is not closed: 12 border edges",
 * "bound A (input 0) intersects itself", "bound C (input 2) is empty", "bound A (input 0) has a
 * NaN or infinite point (...)", "the intermediate result union(A,B) ...", and an operation that
 * CGAL reports as failed ("union of A and B failed: ...").
 *
 * Progress (vtkCommand::ProgressEvent) is reported after each binary operation, as the
 * fraction of operations done; setting AbortExecute stops between operations (an error).
 * GetLastMilliseconds() is the wall time of the last run's CGAL work (conversion, validation,
 * Boolean operations and conversion back), for benchmarks.
 */
#ifndef vtkDeepShadowCSGFilter_h
#define vtkDeepShadowCSGFilter_h

#include "vtkDeepShadowCSGModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

#include <string> // For the expression and errors

class VTKDEEPSHADOWCSG_EXPORT vtkDeepShadowCSGFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkDeepShadowCSGFilter* New();
  vtkTypeMacro(vtkDeepShadowCSGFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The Boolean expression over the inputs (A = input connection 0, B = 1, ...), e.g.
   * "union(A,diff(B,C))". Empty (the default): the union of all inputs.
   */
  void SetExpression(const std::string& expression);
  const std::string& GetExpression() const { return this->Expression; }
  ///@}

  ///@{
  /**
   * The most triangle work an expression may ask of CGAL (deepshadow::CSGNode::TriangleWork:
   * each binary operation's operand triangles, summed over the operations), estimated from
   * the inputs before any of it starts; more is refused with an error naming the estimate.
   * CGAL's exact corefinement took 7 to 130 s per million here (2 cores): the union of two
   * intersecting 20,000-triangle spheres (40,000) 0.28 s, of a sphere with itself (coincident
   * surfaces, the slowest case) 5.1 s. Default 500,000 (at most about a minute); 0: no limit.
   */
  vtkSetClampMacro(MaximumTriangleWork, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MaximumTriangleWork, double);
  ///@}

  /** The triangle work the last run's expression was estimated at. */
  vtkGetMacro(LastTriangleWork, double);

  /** The one-line reason of the last failure; empty after a successful run. */
  const std::string& GetLastError() const { return this->LastError; }

  /** Degenerate faces removed from the bounds in the last run (all bounds together). */
  vtkGetMacro(RemovedDegenerateFaces, vtkIdType);

  /** Whether the last successful run gave the empty solid. */
  vtkGetMacro(ResultIsEmpty, bool);

  /** Wall time of the last run's CGAL work, in milliseconds. */
  vtkGetMacro(LastMilliseconds, double);

  /** Binary Boolean operations done in the last run. */
  vtkGetMacro(LastOperations, int);

protected:
  vtkDeepShadowCSGFilter();
  ~vtkDeepShadowCSGFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  /** Reports `message` as the one-line error. */
  void Fail(const std::string& message);

  std::string Expression;
  std::string LastError;
  vtkIdType RemovedDegenerateFaces = 0;
  bool ResultIsEmpty = false;
  double LastMilliseconds = 0.0;
  int LastOperations = 0;
  double MaximumTriangleWork = 5e5;
  double LastTriangleWork = 0.0;

private:
  vtkDeepShadowCSGFilter(const vtkDeepShadowCSGFilter&) = delete;
  void operator=(const vtkDeepShadowCSGFilter&) = delete;
};

#endif
