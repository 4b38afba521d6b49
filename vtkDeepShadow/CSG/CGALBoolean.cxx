// The one translation unit that includes CGAL (see CGALBoolean.h).
#include "CGALBoolean.h"

#include "Core/Geometry/PolygonTriangulation.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <exception>
#include <iterator>
#include <sstream>
#include <unordered_map>

namespace deepshadow
{
namespace csg
{

namespace
{
using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace PMP = CGAL::Polygon_mesh_processing;

using Triangle = std::array<std::size_t, 3>;

// Exact coordinates as a hash key; -0.0 and 0.0 are the same point.
using Coordinates = std::array<double, 3>;
struct CoordinatesHash
{
  std::size_t operator()(const Coordinates& c) const
  {
    std::size_t h = 0;
    for (double x : c)
    {
      h ^= std::hash<double>()(x) + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
    }
    return h;
  }
};

std::string Plural(std::size_t n, const char* singular, const char* plural)
{
  return std::to_string(n) + " " + (n == 1 ? singular : plural);
}

std::size_t CountBorderEdges(const Mesh& mesh)
{
  std::size_t border = 0;
  for (auto h : mesh.halfedges())
  {
    if (mesh.is_border(h))
    {
      ++border;
    }
  }
  return border;
}

// The polygons (Core's triangulation: a fan when convex) and strips of `input` as triangles
// over its points; false with `problem` for a polygon that cannot be triangulated.
bool SurfaceTriangles(vtkPolyData* input, std::vector<std::array<vtkIdType, 3>>& triangles, std::string& problem)
{
  vtkCellArray* polys = input->GetPolys();
  vtkCellArray* strips = input->GetStrips();
  const vtkIdType points = input->GetNumberOfPoints();
  for (vtkCellArray* cells : { polys, strips })
  {
    double range[2] = { 0.0, 0.0 };
    if (cells->GetNumberOfConnectivityIds() > 0)
    {
      cells->GetConnectivityArray()->GetRange(range, 0);
    }
    if (!cells->IsValid() || range[0] < 0.0 || range[1] >= static_cast<double>(points))
    {
      problem = "has cells whose point ids are out of range (" + std::to_string(points) +
        " points) or inconsistent";
      return false;
    }
  }
  if (!deepshadow::TriangulateCells(input, triangles, problem))
  {
    problem = "has " + problem;
    return false;
  }
  return true;
}

// Checks that the mesh is closed; `problem` gives the number of border edges if not.
bool CheckClosed(const Mesh& mesh, std::string& problem)
{
  if (!CGAL::is_closed(mesh))
  {
    problem = "is not closed: " + Plural(CountBorderEdges(mesh), "border edge", "border edges");
    return false;
  }
  return true;
}

const char* OperationName(CSGOperation operation)
{
  switch (operation)
  {
    case CSGOperation::Union:
      return "union";
    case CSGOperation::Intersection:
      return "intersection";
    case CSGOperation::Difference:
      return "difference";
    default:
      return "leaf";
  }
}
}

struct ExactMesh::Impl
{
  Mesh M;
};

ExactMesh::ExactMesh()
  : P(new Impl)
{
}
ExactMesh::~ExactMesh() = default;
ExactMesh::ExactMesh(const ExactMesh& other)
  : P(new Impl(*other.P))
{
}
ExactMesh& ExactMesh::operator=(const ExactMesh& other)
{
  if (this != &other)
  {
    *this->P = *other.P;
  }
  return *this;
}
ExactMesh::ExactMesh(ExactMesh&& other) noexcept
  : P(std::move(other.P))
{
  other.P.reset(new Impl);
}
ExactMesh& ExactMesh::operator=(ExactMesh&& other) noexcept
{
  std::swap(this->P, other.P);
  return *this;
}

bool ExactMesh::IsEmpty() const
{
  return this->P->M.number_of_faces() == 0;
}

vtkIdType ExactMesh::GetNumberOfTriangles() const
{
  return static_cast<vtkIdType>(this->P->M.number_of_faces());
}

vtkIdType ExactMesh::GetNumberOfPoints() const
{
  return static_cast<vtkIdType>(this->P->M.number_of_vertices());
}

void ExactMesh::ToPolyData(vtkPolyData* output) const
{
  const Mesh& mesh = this->P->M;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.number_of_vertices()));
  std::vector<vtkIdType> index(mesh.num_vertices(), -1);
  vtkIdType next = 0;
  for (auto v : mesh.vertices())
  {
    const Point& p = mesh.point(v);
    points->SetPoint(next, CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    index[static_cast<std::size_t>(v)] = next++;
  }
  vtkNew<vtkCellArray> polys;
  polys->AllocateExact(static_cast<vtkIdType>(mesh.number_of_faces()),
    3 * static_cast<vtkIdType>(mesh.number_of_faces()));
  for (auto f : mesh.faces())
  {
    vtkIdType ids[3];
    int n = 0;
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
    {
      if (n < 3)
      {
        ids[n] = index[static_cast<std::size_t>(v)];
      }
      ++n;
    }
    if (n == 3)
    {
      polys->InsertNextCell(3, ids);
    }
  }
  output->Initialize();
  output->SetPoints(points);
  output->SetPolys(polys);
}

namespace
{
// Polygons to combine, with finite points: what reaches CGAL at all (nor vtkTriangleFilter).
bool CheckPolygonsAndPoints(vtkPolyData* input, ConversionReport& report, std::string& problem)
{
  if (!input || input->GetNumberOfPoints() == 0 || input->GetNumberOfCells() == 0)
  {
    problem = "is empty";
    return false;
  }
  report.IgnoredCells = input->GetNumberOfVerts() + input->GetNumberOfLines();
  if (input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0)
  {
    problem = "is empty: it has no polygons, only " +
      Plural(static_cast<std::size_t>(report.IgnoredCells), "vertex or line cell", "vertex or line cells");
    return false;
  }
  const vtkIdType numberOfPoints = input->GetNumberOfPoints();
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    double p[3];
    input->GetPoint(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      std::ostringstream text;
      text << "has a NaN or infinite point (point " << i << ": " << p[0] << " " << p[1] << " " << p[2]
           << ")";
      problem = text.str();
      return false;
    }
  }
  return true;
}

// Triangles over exactly merged points (-0.0 is 0.0); faces with a repeated vertex are
// dropped and counted. False with `problem` when none is left.
bool MergedTriangleSoup(vtkPolyData* input, const std::vector<std::array<vtkIdType, 3>>& cells,
  std::vector<Point>& points, std::vector<Triangle>& soup, ConversionReport& report, std::string& problem)
{
  std::unordered_map<Coordinates, std::size_t, CoordinatesHash> merged;
  std::vector<std::size_t> soupIndex(static_cast<std::size_t>(input->GetNumberOfPoints()), SIZE_MAX);
  soup.reserve(cells.size());
  vtkIdType referenced = 0;
  for (const auto& pts : cells)
  {
    Triangle triangle;
    for (int k = 0; k < 3; ++k)
    {
      std::size_t& index = soupIndex[static_cast<std::size_t>(pts[k])];
      if (index == SIZE_MAX)
      {
        ++referenced;
        double p[3];
        input->GetPoint(pts[k], p);
        const Coordinates key{ p[0] == 0.0 ? 0.0 : p[0], p[1] == 0.0 ? 0.0 : p[1],
          p[2] == 0.0 ? 0.0 : p[2] };
        auto found = merged.emplace(key, points.size());
        if (found.second)
        {
          points.emplace_back(key[0], key[1], key[2]);
        }
        index = found.first->second;
      }
      triangle[k] = index;
    }
    if (triangle[0] == triangle[1] || triangle[1] == triangle[2] || triangle[0] == triangle[2])
    {
      ++report.RemovedDegenerateFaces;
      continue;
    }
    soup.push_back(triangle);
  }
  report.MergedPoints = referenced - static_cast<vtkIdType>(points.size());
  if (soup.empty())
  {
    problem = report.RemovedDegenerateFaces > 0
      ? "is empty: all its " + Plural(static_cast<std::size_t>(report.RemovedDegenerateFaces), "face is", "faces are") +
        " degenerate"
      : "is empty";
    return false;
  }
  return true;
}

// An edge shared by more than two triangles cannot be part of a solid's surface.
bool CheckEdgesManifold(const std::vector<Triangle>& soup, std::string& problem)
{
  std::unordered_map<std::uint64_t, int> edgeUses;
  edgeUses.reserve(soup.size() * 2);
  for (const Triangle& t : soup)
  {
    for (int k = 0; k < 3; ++k)
    {
      const std::uint64_t a = t[k], b = t[(k + 1) % 3];
      ++edgeUses[a < b ? (a << 32 | b) : (b << 32 | a)];
    }
  }
  std::size_t nonManifoldEdges = 0;
  for (const auto& edge : edgeUses)
  {
    nonManifoldEdges += edge.second > 2 ? 1 : 0;
  }
  if (nonManifoldEdges > 0)
  {
    problem = "is not a manifold surface: " +
      Plural(nonManifoldEdges, "edge is", "edges are") + " shared by more than two faces";
    return false;
  }
  return true;
}

// Polygon soup -> closed mesh. orient_polygon_soup duplicates the points where separate sheets
// meet (or where no consistent orientation exists); such a surface bounds no volume.
bool SoupToClosedMesh(std::vector<Point>& points, std::vector<Triangle>& soup, Mesh& mesh, std::string& problem)
{
  const std::size_t pointsBefore = points.size();
  if (!PMP::orient_polygon_soup(points, soup))
  {
    problem = "is not a manifold surface: " +
      Plural(points.size() - pointsBefore, "vertex joins", "vertices join") +
      " separate sheets, or its faces cannot be oriented consistently";
    return false;
  }
  if (!PMP::is_polygon_soup_a_polygon_mesh(soup))
  {
    problem = "is not a manifold surface";
    return false;
  }
  PMP::polygon_soup_to_polygon_mesh(points, soup, mesh);
  return CheckClosed(mesh, problem);
}

// Zero-area faces with three distinct vertices (caps and needles): collapsed or flipped away.
bool RemoveZeroAreaFaces(Mesh& mesh, ConversionReport& report, std::string& problem)
{
  std::vector<Mesh::Face_index> degenerate;
  PMP::degenerate_faces(mesh, std::back_inserter(degenerate));
  if (degenerate.empty())
  {
    return true;
  }
  const bool removed = PMP::remove_degenerate_faces(mesh);
  mesh.collect_garbage();
  report.RemovedDegenerateFaces += static_cast<vtkIdType>(degenerate.size());
  if (!removed)
  {
    problem = "has " + Plural(degenerate.size(), "zero-area face", "zero-area faces") +
      " that could not be removed";
    return false;
  }
  return true;
}
}

bool MeshFromPolyData(vtkPolyData* input, ExactMesh& result, ConversionReport& report, std::string& problem)
{
  report = ConversionReport();
  result = ExactMesh();
  std::vector<std::array<vtkIdType, 3>> cells;
  std::vector<Point> points;
  std::vector<Triangle> soup;
  Mesh& mesh = result.Get().M;
  return CheckPolygonsAndPoints(input, report, problem) && SurfaceTriangles(input, cells, problem) &&
    MergedTriangleSoup(input, cells, points, soup, report, problem) && CheckEdgesManifold(soup, problem) &&
    SoupToClosedMesh(points, soup, mesh, problem) && RemoveZeroAreaFaces(mesh, report, problem) &&
    ValidateSolid(result, report.Reoriented, problem);
}

namespace
{
// The solid checks, with the kernel and point map given by `np`.
template <class NamedParameters>
bool ValidateWith(Mesh& mesh, const NamedParameters& np, bool& reoriented, std::string& problem)
{
  if (PMP::does_self_intersect(mesh, np))
  {
    problem = "intersects itself";
    return false;
  }
  // CGAL also accepts an inward-facing surface as bounding a volume (the unbounded one outside
  // it); a bound here is always the inside of its outermost shells.
  if (!PMP::does_bound_a_volume(mesh, np))
  {
    PMP::orient_to_bound_a_volume(mesh, np); // outermost shells outward, nested ones alternating
    reoriented = true;
    if (!PMP::does_bound_a_volume(mesh, np))
    {
      problem = "does not bound a volume";
      return false;
    }
  }
  // The vertex with the largest z is on an outermost shell, and all those face the same way.
  if (!PMP::is_outward_oriented(mesh, np))
  {
    PMP::reverse_face_orientations(mesh);
    reoriented = true;
  }
  return true;
}

// Whether every coordinate is exactly a double (as for the bounds as given, unlike points
// constructed by an operation): the lazy kernel's interval approximation is then a point.
bool CoordinatesAreDoubles(const Mesh& mesh)
{
  for (auto v : mesh.vertices())
  {
    const auto& approx = mesh.point(v).approx();
    for (int k = 0; k < 3; ++k)
    {
      if (approx[k].inf() != approx[k].sup())
      {
        return false;
      }
    }
  }
  return true;
}
}

bool ValidateSolid(ExactMesh& exact, bool& reoriented, std::string& problem)
{
  reoriented = false;
  Mesh& mesh = exact.Get().M;
  if (mesh.number_of_faces() == 0)
  {
    problem = "is empty";
    return false;
  }
  if (!CheckClosed(mesh, problem))
  {
    return false;
  }
  if (!CoordinatesAreDoubles(mesh))
  {
    return ValidateWith(mesh, PMP::parameters::default_values(), reoriented, problem);
  }
  // Only predicates are needed, and on double coordinates those of the exact-predicates,
  // inexact-constructions kernel are exact too, and much faster than the lazy exact kernel's
  // (which would construct a lazy triangle for each candidate pair of the self-intersection test).
  using Fast = CGAL::Exact_predicates_inexact_constructions_kernel;
  auto points = mesh.add_property_map<Mesh::Vertex_index, Fast::Point_3>("v:csg_double_point").first;
  for (auto v : mesh.vertices())
  {
    const auto& approx = mesh.point(v).approx();
    points[v] = Fast::Point_3(approx[0].inf(), approx[1].inf(), approx[2].inf());
  }
  const bool valid =
    ValidateWith(mesh, PMP::parameters::vertex_point_map(points).geom_traits(Fast()), reoriented, problem);
  mesh.remove_property_map(points);
  return valid;
}

namespace
{
bool CombineMeshes(CSGOperation operation, Mesh& a, Mesh& b, std::string& problem);

// Connected components of a mesh with their (conservative, approximate) bounding boxes.
std::vector<CGAL::Bbox_3> ComponentBoxes(Mesh& mesh)
{
  auto component = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:csg_component", 0).first;
  const std::size_t count = PMP::connected_components(mesh, component);
  std::vector<CGAL::Bbox_3> boxes(count);
  std::vector<bool> started(count, false);
  for (auto f : mesh.faces())
  {
    const std::size_t c = component[f];
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
    {
      boxes[c] = started[c] ? boxes[c] + mesh.point(v).bbox() : mesh.point(v).bbox();
      started[c] = true;
    }
  }
  mesh.remove_property_map(component);
  return boxes;
}

bool NearlySameBox(const CGAL::Bbox_3& a, const CGAL::Bbox_3& b)
{
  double extent = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    extent = std::max(extent, std::max(a.max(k) - a.min(k), b.max(k) - b.min(k)));
  }
  const double tolerance = 1e-9 * extent + 1e-300;
  for (int k = 0; k < 3; ++k)
  {
    if (std::abs(a.min(k) - b.min(k)) > tolerance || std::abs(a.max(k) - b.max(k)) > tolerance)
    {
      return false;
    }
  }
  return true;
}

// Every vertex and every face centroid of `part` lies on the closed surface `surface`.
bool LiesOn(const Mesh& part, const Mesh& surface)
{
  CGAL::Side_of_triangle_mesh<Mesh, Kernel> side(surface);
  for (auto v : part.vertices())
  {
    if (side(part.point(v)) != CGAL::ON_BOUNDARY)
    {
      return false;
    }
  }
  for (auto f : part.faces())
  {
    const auto h = part.halfedge(f);
    const Point centroid = CGAL::centroid(part.point(part.source(h)), part.point(part.target(h)),
      part.point(part.target(part.next(h))));
    if (side(centroid) != CGAL::ON_BOUNDARY)
    {
      return false;
    }
  }
  return true;
}

Mesh Flipped(Mesh mesh)
{
  PMP::reverse_face_orientations(mesh);
  return mesh;
}

// CGAL 5.5's corefinement misclassifies a closed component of one operand that coincides with
// a closed component of the other with the opposite orientation (e.g. B filling exactly a
// cavity of A): it treats the pair as if both faced the same way. Such a shared surface S
// separates everything else, so the operation is done here in three parts: inside S, outside
// S, and S itself, with the states of A and B just inside S known from the orientations.
// Returns false if there is no such pair (nothing done); otherwise the result is in `a`.
bool CombineAtCoincidentShell(CSGOperation operation, Mesh& a, Mesh& b, bool& valid, std::string& problem)
{
  const std::vector<CGAL::Bbox_3> boxesA = ComponentBoxes(a);
  const std::vector<CGAL::Bbox_3> boxesB = ComponentBoxes(b);
  bool candidate = false;
  for (const auto& boxA : boxesA)
  {
    for (const auto& boxB : boxesB)
    {
      candidate = candidate || NearlySameBox(boxA, boxB);
    }
  }
  if (!candidate)
  {
    return false;
  }
  std::vector<Mesh> partsA, partsB;
  PMP::split_connected_components(a, partsA);
  PMP::split_connected_components(b, partsB);
  for (std::size_t i = 0; i < partsA.size(); ++i)
  {
    const CGAL::Bbox_3 boxA = PMP::bbox(partsA[i]);
    for (std::size_t j = 0; j < partsB.size(); ++j)
    {
      if (!NearlySameBox(boxA, PMP::bbox(partsB[j])) || !LiesOn(partsA[i], partsB[j]) ||
        !LiesOn(partsB[j], partsA[i]))
      {
        continue;
      }
      // A is just inside S iff its copy of S faces outward; the same for B.
      const bool alpha = PMP::is_outward_oriented(partsA[i]);
      const bool beta = PMP::is_outward_oriented(partsB[j]);
      if (alpha == beta)
      {
        continue; // same orientation: CGAL classifies it right
      }
      // Everything else lies strictly inside or strictly outside S.
      CGAL::Side_of_triangle_mesh<Mesh, Kernel> side(partsA[i]);
      Mesh insideA, outsideA, insideB, outsideB;
      for (std::size_t k = 0; k < partsA.size(); ++k)
      {
        if (k != i)
        {
          (side(partsA[k].point(*partsA[k].vertices().begin())) == CGAL::ON_BOUNDED_SIDE ? insideA : outsideA)
            .join(partsA[k]);
        }
      }
      for (std::size_t k = 0; k < partsB.size(); ++k)
      {
        if (k != j)
        {
          (side(partsB[k].point(*partsB[k].vertices().begin())) == CGAL::ON_BOUNDED_SIDE ? insideB : outsideB)
            .join(partsB[k]);
        }
      }
      // Inside S, an operand whose state just inside S is "in" is the complement of its nested
      // parts flipped (P, Q below are then valid solids). With alpha != beta:
      //   union:        in = not(P - Q)  (alpha)   or not(Q - P)  (beta)
      //   intersection: in = Q - P       (alpha)   or P - Q       (beta)
      //   difference:   in = not(P u Q)  (alpha)   or P n Q       (beta)
      Mesh p = alpha ? Flipped(insideA) : insideA;
      Mesh q = beta ? Flipped(insideB) : insideB;
      Mesh inside;
      bool complement = false;
      switch (operation)
      {
        case CSGOperation::Union:
          valid = alpha ? CombineMeshes(CSGOperation::Difference, p, q, problem)
                        : CombineMeshes(CSGOperation::Difference, q, p, problem);
          inside = alpha ? std::move(p) : std::move(q);
          complement = true;
          break;
        case CSGOperation::Intersection:
          valid = alpha ? CombineMeshes(CSGOperation::Difference, q, p, problem)
                        : CombineMeshes(CSGOperation::Difference, p, q, problem);
          inside = alpha ? std::move(q) : std::move(p);
          break;
        case CSGOperation::Difference:
        default:
          valid = CombineMeshes(alpha ? CSGOperation::Union : CSGOperation::Intersection, p, q, problem);
          inside = std::move(p);
          complement = alpha;
          break;
      }
      if (!valid)
      {
        return true;
      }
      if (complement)
      {
        PMP::reverse_face_orientations(inside);
      }
      // Outside S: the ordinary operation. S itself stays only in a difference (A - B keeps A's
      // side of it, with A's orientation); a union fuses across it, an intersection is empty there.
      valid = CombineMeshes(operation, outsideA, outsideB, problem);
      if (!valid)
      {
        return true;
      }
      Mesh result = std::move(outsideA);
      if (operation == CSGOperation::Difference)
      {
        result.join(partsA[i]);
      }
      result.join(inside);
      a = std::move(result);
      return true;
    }
  }
  return false;
}

bool CombineMeshes(CSGOperation operation, Mesh& a, Mesh& b, std::string& problem)
{
  // The empty solid needs no corefinement.
  if (a.number_of_faces() == 0 || b.number_of_faces() == 0)
  {
    switch (operation)
    {
      case CSGOperation::Union:
        if (a.number_of_faces() == 0)
        {
          a = std::move(b);
        }
        break;
      case CSGOperation::Intersection:
        a = Mesh();
        break;
      case CSGOperation::Difference:
      default:
        break; // empty - b = empty; a - empty = a
    }
    b = Mesh();
    return true;
  }
  bool valid = false;
  if (CombineAtCoincidentShell(operation, a, b, valid, problem))
  {
    b = Mesh();
    return valid;
  }
  switch (operation)
  {
    case CSGOperation::Union:
      valid = PMP::corefine_and_compute_union(a, b, a);
      break;
    case CSGOperation::Intersection:
      valid = PMP::corefine_and_compute_intersection(a, b, a);
      break;
    case CSGOperation::Difference:
      valid = PMP::corefine_and_compute_difference(a, b, a);
      break;
    default:
      problem = "not a Boolean operation";
      return false;
  }
  b = Mesh();
  if (!valid)
  {
    problem = "CGAL reports that the result would not be a manifold surface (the operands may "
              "touch along an edge or at a vertex only)";
    a = Mesh();
    return false;
  }
  a.collect_garbage();
  return true;
}
}

bool Combine(CSGOperation operation, ExactMesh& a, ExactMesh& b, std::string& problem)
{
  const bool valid = CombineMeshes(operation, a.Get().M, b.Get().M, problem);
  b = ExactMesh();
  return valid;
}

vtkIdType CountPinchedPoints(const ExactMesh& exact)
{
  const Mesh& mesh = exact.Get().M;
  std::vector<Point> points;
  points.reserve(mesh.number_of_vertices());
  for (auto v : mesh.vertices())
  {
    points.push_back(mesh.point(v));
  }
  std::sort(points.begin(), points.end(),
    [](const Point& a, const Point& b) { return CGAL::compare_xyz(a, b) == CGAL::SMALLER; });
  vtkIdType pinched = 0;
  for (std::size_t i = 1; i < points.size(); ++i)
  {
    if (points[i] == points[i - 1] && (i < 2 || !(points[i - 1] == points[i - 2])))
    {
      ++pinched;
    }
  }
  return pinched;
}

void MakeCoordinatesExact(ExactMesh& exact)
{
  Mesh& mesh = exact.Get().M;
  for (auto v : mesh.vertices())
  {
    CGAL::exact(mesh.point(v)); // computes the exact value and prunes the lazy graph
  }
}

int CountOperations(const CSGNode& node)
{
  if (node.Operation == CSGOperation::Leaf)
  {
    return 0;
  }
  int count = static_cast<int>(node.Operands.size()) - 1;
  for (const CSGNode& operand : node.Operands)
  {
    count += CountOperations(operand);
  }
  return count;
}

std::string BoundName(int leaf)
{
  return "bound " + CSGExpression::LeafName(leaf) + " (input " + std::to_string(leaf) + ")";
}

namespace
{
class Evaluator
{
public:
  Evaluator(const std::vector<vtkPolyData*>& bounds, EvaluationResult& result, const ProgressFunction& progress,
    int total)
    : Bounds(bounds)
    , Leaves(bounds.size())
    , Result(result)
    , Progress(progress)
    , Total(total)
  {
  }

  bool Evaluate(const CSGNode& node, ExactMesh& out)
  {
    if (node.Operation == CSGOperation::Leaf)
    {
      return this->Leaf(node.Leaf, out);
    }
    ExactMesh accumulated;
    if (!this->Evaluate(node.Operands.front(), accumulated))
    {
      return false;
    }
    // The fold so far, for messages: op(first, ..., i-th).
    CSGNode partial;
    partial.Operation = node.Operation;
    partial.Operands.push_back(node.Operands.front());
    bool accumulatedIsIntermediate = node.Operands.front().Operation != CSGOperation::Leaf;
    for (size_t i = 1; i < node.Operands.size(); ++i)
    {
      const CSGNode& operand = node.Operands[i];
      ExactMesh next;
      if (!this->Evaluate(operand, next))
      {
        return false;
      }
      const std::string leftName =
        partial.Operands.size() == 1 ? partial.Operands.front().ToString() : partial.ToString();
      if ((accumulatedIsIntermediate && !this->CheckIntermediate(accumulated, leftName)) ||
        (operand.Operation != CSGOperation::Leaf && !this->CheckIntermediate(next, operand.ToString())))
      {
        return false;
      }
      std::string problem;
      if (!Combine(node.Operation, accumulated, next, problem))
      {
        this->Result.Error = std::string(OperationName(node.Operation)) + " of " + leftName + " and " +
          operand.ToString() + " failed: " + problem;
        return false;
      }
      partial.Operands.push_back(operand);
      accumulatedIsIntermediate = true;
      ++this->Result.Operations;
      // Operands touching at isolated points give a solid whose surface touches itself there
      // (CGAL keeps one vertex per sheet). Fine as the output; not as an operand again.
      const vtkIdType pinched = CountPinchedPoints(accumulated);
      if (pinched > 0)
      {
        const std::string what = partial.ToString() + " has a surface that touches itself at " +
          Plural(static_cast<std::size_t>(pinched), "point", "points") + " (operands touching at isolated points)";
        if (this->Result.Operations < this->Total)
        {
          this->Result.Error = "the intermediate result " + what + ", so it cannot be an operand again";
          return false;
        }
        this->Result.Warnings.push_back("the result " + what + "; each such point is output once per sheet");
      }
      if (this->Result.Operations < this->Total)
      {
        MakeCoordinatesExact(accumulated); // it is an operand again
      }
      if (this->Progress && !this->Progress(static_cast<double>(this->Result.Operations) / this->Total))
      {
        this->Result.Error = "aborted after " + std::to_string(this->Result.Operations) + " of " +
          Plural(static_cast<std::size_t>(this->Total), "operation", "operations");
        return false;
      }
    }
    out = std::move(accumulated);
    return true;
  }

private:
  bool Leaf(int leaf, ExactMesh& out)
  {
    if (leaf < 0 || static_cast<size_t>(leaf) >= this->Bounds.size())
    {
      this->Result.Error = "bound " + CSGExpression::LeafName(leaf) + " is not given (" +
        std::to_string(this->Bounds.size()) + " bounds)";
      return false;
    }
    std::unique_ptr<ExactMesh>& cached = this->Leaves[static_cast<size_t>(leaf)];
    if (!cached)
    {
      auto mesh = std::unique_ptr<ExactMesh>(new ExactMesh);
      ConversionReport report;
      std::string problem;
      const bool valid = MeshFromPolyData(this->Bounds[static_cast<size_t>(leaf)], *mesh, report, problem);
      this->Result.RemovedDegenerateFaces += report.RemovedDegenerateFaces;
      const std::string name = BoundName(leaf);
      if (report.RemovedDegenerateFaces > 0)
      {
        this->Result.Warnings.push_back(
          "removed " + Plural(static_cast<std::size_t>(report.RemovedDegenerateFaces), "degenerate face", "degenerate faces") +
          " (zero area or a repeated vertex) from " + name);
      }
      if (report.IgnoredCells > 0)
      {
        this->Result.Warnings.push_back("ignored " +
          Plural(static_cast<std::size_t>(report.IgnoredCells), "vertex or line cell", "vertex or line cells") +
          " of " + name);
      }
      if (!valid)
      {
        this->Result.Error = name + " " + problem;
        return false;
      }
      if (report.Reoriented)
      {
        this->Result.Warnings.push_back(
          name + " did not face outward (or its nested parts were not oriented alternately); reoriented it");
      }
      cached = std::move(mesh);
    }
    out = *cached; // a copy: corefinement modifies its operands
    return true;
  }

  bool CheckIntermediate(ExactMesh& mesh, const std::string& name)
  {
    if (mesh.IsEmpty())
    {
      return true; // the empty solid is a valid operand
    }
    bool reoriented = false;
    std::string problem;
    if (!ValidateSolid(mesh, reoriented, problem))
    {
      this->Result.Error = "the intermediate result " + name + " " + problem;
      return false;
    }
    if (reoriented)
    {
      this->Result.Warnings.push_back("the intermediate result " + name + " had to be reoriented");
    }
    return true;
  }

  const std::vector<vtkPolyData*>& Bounds;
  std::vector<std::unique_ptr<ExactMesh>> Leaves;
  EvaluationResult& Result;
  const ProgressFunction& Progress;
  int Total;
};

void UsedLeaves(const CSGNode& node, std::vector<bool>& used)
{
  if (node.Operation == CSGOperation::Leaf)
  {
    if (node.Leaf >= 0 && static_cast<size_t>(node.Leaf) < used.size())
    {
      used[static_cast<size_t>(node.Leaf)] = true;
    }
    return;
  }
  for (const CSGNode& operand : node.Operands)
  {
    UsedLeaves(operand, used);
  }
}
}

bool Evaluate(const CSGNode& root, const std::vector<vtkPolyData*>& bounds, vtkPolyData* output,
  EvaluationResult& result, const ProgressFunction& progress)
{
  result = EvaluationResult();
  if (output)
  {
    output->Initialize();
  }
  std::vector<bool> used(bounds.size(), false);
  UsedLeaves(root, used);
  std::string unused;
  for (size_t i = 0; i < used.size(); ++i)
  {
    if (!used[i])
    {
      unused += (unused.empty() ? "" : ", ") + BoundName(static_cast<int>(i));
    }
  }
  if (!unused.empty())
  {
    result.Warnings.push_back("not used by the expression: " + unused);
  }
  try
  {
    Evaluator evaluator(bounds, result, progress, CountOperations(root));
    ExactMesh mesh;
    if (!evaluator.Evaluate(root, mesh))
    {
      return false;
    }
    result.Empty = mesh.IsEmpty();
    if (output)
    {
      mesh.ToPolyData(output);
    }
    return true;
  }
  catch (const std::exception& e)
  {
    result.Error = std::string("CGAL failed: ") + e.what();
  }
  catch (...)
  {
    result.Error = "CGAL failed with an unknown exception";
  }
  if (output)
  {
    output->Initialize();
  }
  return false;
}

}
}
