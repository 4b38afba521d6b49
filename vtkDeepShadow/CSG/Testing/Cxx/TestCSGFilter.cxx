// vtkDeepShadowCSGFilter: exact Boolean CSG of closed bounds through CGAL.
// Volumes are checked against analytic values (axis-aligned boxes) or against each other
// (|A - B| + |A n B| = |A|), the output's topology edge by edge, its orientation by the
// signed volume, and every bad input for its error message.
#include "vtkDeepShadowCSGFilter.h"

#include "vtkAppendPolyData.h"
#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCommand.h"
#include "vtkCubeSource.h"
#include "vtkExecutive.h"
#include "vtkMassProperties.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkStripper.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace
{

// An axis-aligned box from vtkCubeSource: 6 quads with one set of 4 points per face (24 points).
vtkSmartPointer<vtkPolyData> Box(double x0, double x1, double y0, double y1, double z0, double z1)
{
  vtkNew<vtkCubeSource> cube;
  cube->SetBounds(x0, x1, y0, y1, z0, z1);
  cube->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  cube->Update();
  vtkSmartPointer<vtkPolyData> box = cube->GetOutput();
  return box;
}

vtkSmartPointer<vtkPolyData> Sphere(double radius, double cx, double cy, double cz, int resolution)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(radius);
  sphere->SetCenter(cx, cy, cz);
  sphere->SetThetaResolution(resolution);
  sphere->SetPhiResolution(resolution);
  sphere->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  sphere->Update();
  vtkSmartPointer<vtkPolyData> result = sphere->GetOutput();
  return result;
}

// A filter over the given bounds (input i = bound i).
vtkSmartPointer<vtkDeepShadowCSGFilter> Filter(
  const std::vector<vtkSmartPointer<vtkPolyData>>& bounds, const std::string& expression)
{
  auto filter = vtkSmartPointer<vtkDeepShadowCSGFilter>::New();
  for (const auto& bound : bounds)
  {
    filter->AddInputData(bound);
  }
  filter->SetExpression(expression);
  return filter;
}

// Volume by the divergence theorem: positive iff the triangles face outward.
double SignedVolume(vtkPolyData* mesh)
{
  double volume = 0.0;
  auto cell = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (cell->GoToFirstCell(); !cell->IsDoneWithTraversal(); cell->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    cell->GetCurrentCell(n, ids);
    double a[3], b[3], c[3];
    mesh->GetPoint(ids[0], a);
    mesh->GetPoint(ids[1], b);
    mesh->GetPoint(ids[2], c);
    volume += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                a[2] * (b[0] * c[1] - b[1] * c[0])) /
      6.0;
  }
  return volume;
}

double MassVolume(vtkPolyData* mesh)
{
  vtkNew<vtkMassProperties> mass;
  mass->SetInputData(mesh);
  mass->Update();
  return mass->GetVolume();
}

// Only triangles, each directed edge used once and matched by its reverse: closed, manifold
// along edges and consistently oriented.
::testing::AssertionResult IsClosedOrientedTriangleMesh(vtkPolyData* mesh)
{
  if (mesh->GetNumberOfVerts() + mesh->GetNumberOfLines() + mesh->GetNumberOfStrips() != 0)
  {
    return ::testing::AssertionFailure() << "cells other than polygons";
  }
  std::map<std::pair<vtkIdType, vtkIdType>, int> directed;
  auto cell = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (cell->GoToFirstCell(); !cell->IsDoneWithTraversal(); cell->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    cell->GetCurrentCell(n, ids);
    if (n != 3)
    {
      return ::testing::AssertionFailure() << "a cell with " << n << " points";
    }
    for (int k = 0; k < 3; ++k)
    {
      ++directed[{ ids[k], ids[(k + 1) % 3] }];
    }
  }
  for (const auto& edge : directed)
  {
    if (edge.second != 1)
    {
      return ::testing::AssertionFailure() << "directed edge used " << edge.second << " times";
    }
    if (!directed.count({ edge.first.second, edge.first.first }))
    {
      return ::testing::AssertionFailure() << "edge " << edge.first.first << "-" << edge.first.second
                                           << " has no opposite (border or flipped face)";
    }
  }
  return ::testing::AssertionSuccess();
}

// The filter's vtkWarningMacro / vtkErrorMacro lines, caught by observers (so not printed).
struct Messages
{
  std::vector<std::string> Warnings;
  std::vector<std::string> Errors;
  vtkNew<vtkCallbackCommand> Observer;

  explicit Messages(vtkObject* object)
  {
    this->Observer->SetClientData(this);
    this->Observer->SetCallback(
      [](vtkObject*, unsigned long event, void* self, void* text)
      {
        auto* messages = static_cast<Messages*>(self);
        (event == vtkCommand::WarningEvent ? messages->Warnings : messages->Errors)
          .emplace_back(static_cast<const char*>(text));
      });
    object->AddObserver(vtkCommand::WarningEvent, this->Observer);
    object->AddObserver(vtkCommand::ErrorEvent, this->Observer);
  }
  bool Warned(const std::string& part) const
  {
    for (const std::string& warning : this->Warnings)
    {
      if (warning.find(part) != std::string::npos)
      {
        return true;
      }
    }
    return false;
  }
  std::string All() const
  {
    std::string text;
    for (const std::string& line : this->Warnings)
    {
      text += "\n  warning: " + line;
    }
    for (const std::string& line : this->Errors)
    {
      text += "\n  error: " + line;
    }
    return text;
  }
};

// Runs the filter, expects success and a closed outward mesh; returns its volume. With no
// `warnings` to fill, the run must not warn.
double SolidVolume(vtkDeepShadowCSGFilter* filter, std::vector<std::string>* warnings = nullptr)
{
  Messages messages(filter);
  EXPECT_EQ(filter->GetExecutive()->Update(), 1) << filter->GetLastError();
  EXPECT_TRUE(filter->GetLastError().empty()) << filter->GetLastError();
  EXPECT_TRUE(messages.Errors.empty()) << messages.All();
  if (warnings)
  {
    *warnings = messages.Warnings;
  }
  else
  {
    EXPECT_TRUE(messages.Warnings.empty()) << messages.All();
  }
  vtkPolyData* output = filter->GetOutput();
  EXPECT_GT(output->GetNumberOfPolys(), 0);
  EXPECT_TRUE(IsClosedOrientedTriangleMesh(output));
  const double signedVolume = SignedVolume(output);
  EXPECT_GT(signedVolume, 0.0) << "the output must face outward";
  EXPECT_NEAR(MassVolume(output), std::abs(signedVolume), 1e-9 * std::abs(signedVolume));
  return signedVolume;
}

bool Contains(const std::vector<std::string>& lines, const std::string& part)
{
  for (const std::string& line : lines)
  {
    if (line.find(part) != std::string::npos)
    {
      return true;
    }
  }
  return false;
}

// Runs the filter, expects success with the empty solid and the warning that says so.
void ExpectEmptyResult(vtkDeepShadowCSGFilter* filter)
{
  Messages messages(filter);
  EXPECT_EQ(filter->GetExecutive()->Update(), 1) << filter->GetLastError();
  EXPECT_TRUE(filter->GetLastError().empty()) << filter->GetLastError();
  EXPECT_TRUE(messages.Errors.empty()) << messages.All();
  EXPECT_TRUE(messages.Warned("the CSG result is empty")) << messages.All();
  EXPECT_TRUE(filter->GetResultIsEmpty());
  EXPECT_EQ(filter->GetOutput()->GetNumberOfCells(), 0);
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
}

// Runs the filter, expects failure with one error line (also GetLastError()) containing every
// one of `parts`, and an empty output.
void ExpectError(vtkDeepShadowCSGFilter* filter, const std::vector<std::string>& parts)
{
  Messages messages(filter);
  Messages pipeline(filter->GetExecutive()); // the executive's own "returned failure" line
  const int updated = filter->GetExecutive()->Update();
  EXPECT_EQ(updated, 0);
  const std::string& error = filter->GetLastError();
  EXPECT_FALSE(error.empty());
  ASSERT_EQ(messages.Errors.size(), 1u) << messages.All();
  EXPECT_NE(messages.Errors[0].find(error), std::string::npos) << messages.All();
  for (const std::string& part : parts)
  {
    EXPECT_NE(error.find(part), std::string::npos) << "\"" << part << "\" not in: " << error;
  }
  EXPECT_EQ(filter->GetOutput()->GetNumberOfCells(), 0);
  std::cout << "  error: " << error << "\n";
}

// A triangle mesh from explicit points and triangles.
vtkSmartPointer<vtkPolyData> Mesh(const std::vector<std::array<double, 3>>& points,
  const std::vector<std::array<vtkIdType, 3>>& triangles)
{
  vtkNew<vtkPoints> p;
  p->SetDataTypeToDouble();
  for (const auto& point : points)
  {
    p->InsertNextPoint(point.data());
  }
  vtkNew<vtkCellArray> polys;
  for (const auto& t : triangles)
  {
    polys->InsertNextCell(3, t.data());
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(p);
  mesh->SetPolys(polys);
  return mesh;
}

const std::vector<std::array<double, 3>> UnitCubePoints = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 },
  { 0, 1, 0 }, { 0, 0, 1 }, { 1, 0, 1 }, { 1, 1, 1 }, { 0, 1, 1 } };
const std::vector<std::array<vtkIdType, 3>> UnitCubeTriangles = { { 0, 2, 1 }, { 0, 3, 2 },
  { 4, 5, 6 }, { 4, 6, 7 }, { 0, 1, 5 }, { 0, 5, 4 }, { 1, 2, 6 }, { 1, 6, 5 }, { 2, 3, 7 },
  { 2, 7, 6 }, { 3, 0, 4 }, { 3, 4, 7 } };

}

// Two overlapping boxes in general position (no coplanar faces).
TEST(CSGFilter, BoxesUnionIntersectionDifference)
{
  auto a = Box(0, 1, 0, 1, 0, 1);
  auto b = Box(0.5, 1.5, 0.25, 1.25, 0.375, 1.375);
  const double both = 0.5 * 0.75 * 0.625;
  const struct
  {
    const char* expression;
    double volume;
  } cases[] = { { "union(A,B)", 2.0 - both }, { "intersection(A,B)", both }, { "difference(A,B)", 1.0 - both },
    { "diff(B,A)", 1.0 - both }, { "inter(A,B)", both } };
  for (const auto& c : cases)
  {
    SCOPED_TRACE(c.expression);
    auto filter = Filter({ a, b }, c.expression);
    EXPECT_NEAR(SolidVolume(filter), c.volume, 1e-9 * c.volume);
    EXPECT_FALSE(filter->GetResultIsEmpty());
    EXPECT_EQ(filter->GetLastOperations(), 1);
    EXPECT_EQ(filter->GetRemovedDegenerateFaces(), 0);
  }
}

// vtkCubeSource gives 24 unshared points: without exact merging there is no closed surface.
TEST(CSGFilter, SingleUnsharedBoxBecomesClosedTriangleMesh)
{
  auto a = Box(-1, 2, 0, 1, 0, 0.5);
  ASSERT_EQ(a->GetNumberOfPoints(), 24);
  auto filter = Filter({ a }, "");
  EXPECT_NEAR(SolidVolume(filter), 1.5, 1e-12);
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 8);
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPolys(), 12);
  EXPECT_EQ(filter->GetOutput()->GetPoints()->GetDataType(), VTK_DOUBLE);
}

TEST(CSGFilter, NestedTreeAndDefaultUnion)
{
  auto a = Box(0, 1, 0, 1, 0, 1);
  auto b = Box(2, 4, 0, 1, 0, 1);        // disjoint from A, volume 2
  auto c = Box(2.5, 3, 0.25, 2, 0.25, 0.75); // pokes through B: B n C = 0.5 * 0.75 * 0.5
  const double bc = 0.5 * 0.75 * 0.5;
  {
    auto filter = Filter({ a, b, c }, "union(A,diff(B,C))");
    EXPECT_NEAR(SolidVolume(filter), 1.0 + 2.0 - bc, 1e-9);
    EXPECT_EQ(filter->GetLastOperations(), 2);
  }
  {
    // No expression: the union of all inputs. C sticks out of B by 0.5 x 1 x 0.5.
    auto filter = Filter({ a, b, c }, "");
    EXPECT_NEAR(SolidVolume(filter), 1.0 + 2.0 + 0.5 * 1.0 * 0.5, 1e-9);
    EXPECT_EQ(filter->GetLastOperations(), 2);
  }
  {
    // n-ary difference folds left; intersection of a union.
    auto filter = Filter({ a, b, c }, "inter(union(A,B),diff(B,C,A))");
    EXPECT_NEAR(SolidVolume(filter), 2.0 - bc, 1e-9);
    EXPECT_EQ(filter->GetLastOperations(), 4);
  }
  {
    // An input the expression does not name is ignored, with a warning.
    auto filter = Filter({ a, b, c }, "diff(B,C)");
    std::vector<std::string> warnings;
    EXPECT_NEAR(SolidVolume(filter, &warnings), 2.0 - bc, 1e-9);
    EXPECT_TRUE(Contains(warnings, "not used by the expression: bound A (input 0)"));
  }
}

// Operands sharing face planes, and operands touching along a whole face.
TEST(CSGFilter, CoplanarAndTouchingOperands)
{
  auto a = Box(0, 1, 0, 1, 0, 1);
  auto overlapping = Box(0.5, 1.5, 0, 1, 0, 1); // four faces coplanar with A's
  EXPECT_NEAR(SolidVolume(Filter({ a, overlapping }, "union(A,B)")), 1.5, 1e-12);
  EXPECT_NEAR(SolidVolume(Filter({ a, overlapping }, "inter(A,B)")), 0.5, 1e-12);
  EXPECT_NEAR(SolidVolume(Filter({ a, overlapping }, "diff(A,B)")), 0.5, 1e-12);

  auto neighbour = Box(1, 2, 0, 1, 0, 1); // shares the face x = 1
  auto united = Filter({ a, neighbour }, "union(A,B)");
  EXPECT_NEAR(SolidVolume(united), 2.0, 1e-12);
  EXPECT_NEAR(SolidVolume(Filter({ a, neighbour }, "diff(A,B)")), 1.0, 1e-12);

  // Touching along a face only: the intersection has no volume.
  ExpectEmptyResult(Filter({ a, neighbour }, "inter(A,B)"));

  // Identical operands.
  EXPECT_NEAR(SolidVolume(Filter({ a, a }, "union(A,B)")), 1.0, 1e-12);
  EXPECT_NEAR(SolidVolume(Filter({ a }, "inter(A,A)")), 1.0, 1e-12);
}

// Touching along an edge only: the union is not a manifold surface. CGAL says so (its
// corefinement returns false), and so does the filter, rather than output a broken surface.
TEST(CSGFilter, EdgeAndCornerContact)
{
  auto a = Box(0, 1, 0, 1, 0, 1);
  auto b = Box(1, 2, 1, 2, 0, 1);
  ExpectError(Filter({ a, b }, "union(A,B)"), { "union of A and B failed", "not be a manifold surface" });
  // The same contact is fine where the result is manifold.
  EXPECT_NEAR(SolidVolume(Filter({ a, b }, "diff(A,B)")), 1.0, 1e-12);
  ExpectEmptyResult(Filter({ a, b }, "inter(A,B)"));
  // Touching at a corner only: a valid solid whose surface touches itself at that point, kept
  // once per sheet (16 points), with a warning; as an operand again it is an error.
  auto corner = Box(1, 2, 1, 2, 1, 2);
  auto cornerUnion = Filter({ a, corner }, "union(A,B)");
  std::vector<std::string> warnings;
  EXPECT_NEAR(SolidVolume(cornerUnion, &warnings), 2.0, 1e-12);
  EXPECT_EQ(cornerUnion->GetOutput()->GetNumberOfPoints(), 16);
  EXPECT_TRUE(Contains(warnings, "touches itself at 1 point")) << warnings.size();
  ExpectError(Filter({ a, corner, Box(5, 6, 0, 1, 0, 1) }, "union(A,B,C)"),
    { "the intermediate result union(A,B)", "touches itself at 1 point", "cannot be an operand" });
}

TEST(CSGFilter, ContainedDifferenceAndDisjointIntersectionAreEmpty)
{
  auto inner = Box(0.25, 0.75, 0.25, 0.75, 0.25, 0.75);
  auto outer = Box(0, 1, 0, 1, 0, 1);
  auto far = Box(5, 6, 5, 6, 5, 6);
  for (auto expression : { "diff(A,B)", "inter(A,C)", "union(inter(A,C),diff(A,B))" })
  {
    SCOPED_TRACE(expression);
    ExpectEmptyResult(Filter({ inner, outer, far }, expression));
  }
  // The empty intermediate result is a valid operand: B - (A n C) = B.
  auto filter = Filter({ inner, outer, far }, "diff(B,inter(A,C))");
  EXPECT_NEAR(SolidVolume(filter), 1.0, 1e-12);
  EXPECT_FALSE(filter->GetResultIsEmpty());
  EXPECT_EQ(filter->GetLastOperations(), 2);
  // A cavity: B - A has two shells, the inner one facing into the cavity.
  auto hollow = Filter({ inner, outer }, "diff(B,A)");
  EXPECT_NEAR(SolidVolume(hollow), 1.0 - 0.125, 1e-12);
  // ... and it is a valid operand again: (B - A) u A = B.
  auto refilled = Filter({ inner, outer }, "union(diff(B,A),A)");
  EXPECT_NEAR(SolidVolume(refilled), 1.0, 1e-12);
  EXPECT_EQ(refilled->GetOutput()->GetNumberOfPolys(), 12);
}

// A closed component of one operand that coincides with one of the other facing the other way
// (B - A has a cavity that A fills exactly). CGAL 5.5's corefinement alone gets every such
// case wrong; the filter splits the operation at the shared surface.
TEST(CSGFilter, CoincidentShellsWithOppositeOrientation)
{
  auto inner = Box(0.25, 0.75, 0.25, 0.75, 0.25, 0.75);
  auto outer = Box(0, 1, 0, 1, 0, 1);
  // The same cube as `inner`, triangulated along the other diagonals.
  std::vector<std::array<double, 3>> points;
  for (const auto& p : UnitCubePoints)
  {
    points.push_back({ 0.25 + 0.5 * p[0], 0.25 + 0.5 * p[1], 0.25 + 0.5 * p[2] });
  }
  auto other = Mesh(points,
    { { 0, 3, 1 }, { 3, 2, 1 }, { 4, 5, 7 }, { 5, 6, 7 }, { 0, 1, 4 }, { 1, 5, 4 }, { 1, 2, 5 },
      { 2, 6, 5 }, { 2, 3, 6 }, { 3, 7, 6 }, { 3, 0, 7 }, { 0, 4, 7 } });
  auto island = Box(0.4, 0.6, 0.4, 0.6, 0.4, 0.6);
  const double vi = 0.125, vo = 1.0, vd = 0.2 * 0.2 * 0.2;
  const std::vector<vtkSmartPointer<vtkPolyData>> bounds = { inner, outer, other, island };
  const struct
  {
    const char* expression;
    double volume; // 0: empty
  } cases[] = {
    { "union(diff(B,A),A)", vo },
    { "union(A,diff(B,A))", vo },
    { "inter(diff(B,A),A)", 0 },
    { "inter(A,diff(B,A))", 0 },
    { "diff(diff(B,A),A)", vo - vi },
    { "diff(A,diff(B,A))", vi },
    { "union(diff(B,A),C)", vo },
    { "inter(C,diff(B,A))", 0 },
    { "diff(diff(B,C),A)", vo - vi },
    { "diff(A,diff(B,C))", vi },
    // With an island D inside the cavity.
    { "union(union(diff(B,A),D),A)", vo },
    { "inter(union(diff(B,A),D),A)", vd },
    { "diff(union(diff(B,A),D),A)", vo - vi },
    { "diff(A,union(diff(B,A),D))", vi - vd },
    { "diff(C,union(D,diff(B,A)))", vi - vd },
  };
  for (const auto& c : cases)
  {
    SCOPED_TRACE(c.expression);
    auto filter = Filter(bounds, c.expression);
    if (c.volume == 0)
    {
      ExpectEmptyResult(filter);
    }
    else
    {
      std::vector<std::string> warnings; // D or C may be unused
      EXPECT_NEAR(SolidVolume(filter, &warnings), c.volume, 1e-12);
    }
  }
}

TEST(CSGFilter, OpenOperandIsRejected)
{
  auto a = Box(0, 1, 0, 1, 0, 1);
  vtkNew<vtkCubeSource> cube;
  cube->SetBounds(0.5, 1.5, 0.5, 1.5, 0.5, 1.5);
  cube->Update();
  auto open = vtkSmartPointer<vtkPolyData>::New();
  open->DeepCopy(cube->GetOutput());
  open->BuildCells();
  open->DeleteCell(5); // one quad gone: a square hole with 4 border edges
  open->RemoveDeletedCells();
  ASSERT_EQ(open->GetNumberOfPolys(), 5);
  ExpectError(Filter({ a, open }, "union(A,B)"), { "bound B (input 1)", "not closed", "4 border edges" });
}

TEST(CSGFilter, SelfIntersectingOperandIsRejected)
{
  vtkNew<vtkAppendPolyData> append;
  append->AddInputData(Box(0, 1, 0, 1, 0, 1));
  append->AddInputData(Box(0.5, 1.5, 0.5, 1.5, 0.5, 1.5));
  append->Update();
  auto twoBoxes = vtkSmartPointer<vtkPolyData>::New();
  twoBoxes->ShallowCopy(append->GetOutput());
  ExpectError(Filter({ Box(3, 4, 0, 1, 0, 1), twoBoxes }, "union(A,B)"),
    { "bound B (input 1)", "intersects itself" });
  // As bound A, with no other input.
  ExpectError(Filter({ twoBoxes }, ""), { "bound A (input 0)", "intersects itself" });
}

TEST(CSGFilter, NonFinitePointsAreRejected)
{
  for (double bad : { std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity() })
  {
    auto b = Box(0.5, 1.5, 0.5, 1.5, 0.5, 1.5);
    auto broken = vtkSmartPointer<vtkPolyData>::New();
    broken->DeepCopy(b);
    double p[3];
    broken->GetPoint(7, p);
    p[1] = bad;
    broken->GetPoints()->SetPoint(7, p);
    ExpectError(Filter({ Box(0, 1, 0, 1, 0, 1), broken }, "diff(A,B)"),
      { "bound B (input 1)", "NaN or infinite point" });
  }
}

TEST(CSGFilter, EmptyOperandsAndMissingInputsAreRejected)
{
  auto a = Box(0, 1, 0, 1, 0, 1);
  auto empty = vtkSmartPointer<vtkPolyData>::New();
  ExpectError(Filter({ a, a, empty }, "union(A,diff(B,C))"), { "bound C (input 2)", "is empty" });

  // Only lines: nothing bounds a volume.
  auto lines = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  vtkNew<vtkCellArray> cells;
  vtkIdType line[2] = { 0, 1 };
  cells->InsertNextCell(2, line);
  lines->SetPoints(points);
  lines->SetLines(cells);
  ExpectError(Filter({ lines, a }, ""), { "bound A (input 0)", "is empty" });

  // No input at all.
  ExpectError(Filter({}, ""), { "no input" });
}

TEST(CSGFilter, BadExpressionsAreRejected)
{
  auto a = Box(0, 1, 0, 1, 0, 1);
  auto b = Box(0.5, 1.5, 0, 1, 0, 1);
  ExpectError(Filter({ a, b }, "union(A,,B)"), { "at character 9" });
  ExpectError(Filter({ a, b }, "union(A,B"), { "expected ')'" });
  ExpectError(Filter({ a, b }, "xor(A,B)"), { "unknown operation 'xor'", "at character 1" });
  ExpectError(Filter({ a, b }, "union(A,C)"), { "bound C is not given", "at character 9" });
  ExpectError(Filter({ a, b }, "union(A)"), { "at least two operands" });

  // The same filter recovers once the expression is fixed: no stale error.
  auto filter = Filter({ a, b }, "diff(A,C)");
  ExpectError(filter, { "bound C" });
  filter->SetExpression("diff(A,B)");
  EXPECT_NEAR(SolidVolume(filter), 0.5, 1e-12);
}

// Degenerate faces: a repeated vertex (after exact merging) and a zero-area "cap" triangle.
TEST(CSGFilter, DegenerateFacesAreRemovedAndCounted)
{
  // 1. The unit cube plus a triangle whose first two points coincide (STL-like: its own points).
  {
    auto points = UnitCubePoints;
    auto triangles = UnitCubeTriangles;
    points.push_back({ 1, 1, 1 });
    points.push_back({ 1, 1, 1 });
    points.push_back({ 0, 0, 0 });
    triangles.push_back({ 8, 9, 10 });
    auto filter = Filter({ Mesh(points, triangles), Box(0.5, 1.5, 0, 1, 0, 1) }, "union(A,B)");
    std::vector<std::string> warnings;
    EXPECT_NEAR(SolidVolume(filter, &warnings), 1.5, 1e-12);
    EXPECT_EQ(filter->GetRemovedDegenerateFaces(), 1);
    EXPECT_TRUE(Contains(warnings, "removed 1 degenerate face (zero area or a repeated vertex) from bound A (input 0)"));
    EXPECT_EQ(warnings.size(), 1u);
  }
  // 2. The unit cube whose edge (0,0,0)-(1,0,0) has a point M at its middle: the bottom face
  //    uses M as a regular vertex, the front face has the zero-area triangle (1,0,0) M (0,0,0).
  {
    auto points = UnitCubePoints;
    points.push_back({ 0.5, 0, 0 }); // 8 = M
    const std::vector<std::array<vtkIdType, 3>> triangles = {
      // bottom (z = 0, facing -z): pentagon 0 3 2 1 M
      { 0, 3, 8 }, { 8, 3, 2 }, { 8, 2, 1 },
      // front (y = 0, facing -y): pentagon 0 M 1 5 4, with the cap (M, 1, 0)... as 1 0 M
      { 1, 0, 8 }, { 0, 1, 5 }, { 0, 5, 4 },
      // the rest of the cube
      { 4, 5, 6 }, { 4, 6, 7 }, { 1, 2, 6 }, { 1, 6, 5 }, { 2, 3, 7 }, { 2, 7, 6 }, { 3, 0, 4 },
      { 3, 4, 7 } };
    auto mesh = Mesh(points, triangles);
    auto filter = Filter({ mesh, Box(0.5, 1.5, 0.25, 1.25, 0.375, 1.375) }, "union(A,B)");
    std::vector<std::string> warnings;
    const double volume = SolidVolume(filter, &warnings);
    const double both = 0.5 * 0.75 * 0.625;
    EXPECT_NEAR(volume, 2.0 - both, 1e-12);
    EXPECT_EQ(filter->GetRemovedDegenerateFaces(), 1);
    EXPECT_TRUE(Contains(warnings, "removed 1 degenerate face")) << warnings.size();
  }
  // 3. A clean input counts none.
  auto clean = Filter({ Mesh(UnitCubePoints, UnitCubeTriangles) }, "");
  EXPECT_NEAR(SolidVolume(clean), 1.0, 1e-12);
  EXPECT_EQ(clean->GetRemovedDegenerateFaces(), 0);
}

// An inward-facing bound is reoriented; the output still faces outward.
TEST(CSGFilter, InwardBoundIsReoriented)
{
  auto triangles = UnitCubeTriangles;
  for (auto& t : triangles)
  {
    std::swap(t[1], t[2]);
  }
  auto inward = Mesh(UnitCubePoints, triangles);
  ASSERT_LT(SignedVolume(inward), 0.0);
  auto filter = Filter({ inward, Box(0.5, 1.5, 0, 1, 0, 1) }, "diff(A,B)");
  std::vector<std::string> warnings;
  EXPECT_NEAR(SolidVolume(filter, &warnings), 0.5, 1e-12);
  EXPECT_TRUE(Contains(warnings, "bound A (input 0) did not face outward")) << warnings.size();
}

// Spheres: triangles from vtkSphereSource, cut in general position.
TEST(CSGFilter, SpheresDifferencePlusIntersectionIsTheFirstSphere)
{
  auto a = Sphere(1.0, 0, 0, 0, 24);
  auto b = Sphere(0.7, 0.6, 0.2, 0.1, 20);
  const double va = SolidVolume(Filter({ a }, ""));
  const double difference = SolidVolume(Filter({ a, b }, "diff(A,B)"));
  const double intersection = SolidVolume(Filter({ a, b }, "inter(A,B)"));
  const double both = SolidVolume(Filter({ a, b }, "union(A,B)"));
  const double vb = SolidVolume(Filter({ b }, ""));
  EXPECT_NEAR(difference + intersection, va, 1e-9 * va);
  EXPECT_NEAR(both + intersection, va + vb, 1e-9 * va);
  EXPECT_GT(intersection, 0.05);
  EXPECT_GT(difference, 0.05);
}

// Single-precision points (VTK's sources' default) and triangle strips are used as given.
TEST(CSGFilter, FloatPointsAndTriangleStrips)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(30);
  sphere->SetPhiResolution(30);
  sphere->Update();
  ASSERT_EQ(sphere->GetOutput()->GetPoints()->GetDataType(), VTK_FLOAT);
  auto a = vtkSmartPointer<vtkPolyData>::New();
  a->ShallowCopy(sphere->GetOutput());
  vtkNew<vtkCubeSource> cube; // float too
  cube->SetBounds(0.1, 0.7, -0.3, 0.3, -0.2, 0.4);
  cube->Update();
  auto b = vtkSmartPointer<vtkPolyData>::New();
  b->ShallowCopy(cube->GetOutput());
  const double difference = SolidVolume(Filter({ a, b }, "diff(A,B)"));
  const double intersection = SolidVolume(Filter({ a, b }, "inter(A,B)"));
  EXPECT_NEAR(difference + intersection, SignedVolume(a), 1e-9);
  EXPECT_GT(intersection, 0.1);

  // The same sphere as strips only: the same solid.
  vtkNew<vtkStripper> stripper;
  stripper->SetInputData(a);
  stripper->Update();
  auto strips = vtkSmartPointer<vtkPolyData>::New();
  strips->ShallowCopy(stripper->GetOutput());
  ASSERT_GT(strips->GetNumberOfStrips(), 0);
  ASSERT_EQ(strips->GetNumberOfPolys(), 0);
  EXPECT_NEAR(SolidVolume(Filter({ strips, b }, "diff(A,B)")), difference, 1e-12);
}

// At least 1e5 triangles; the time is printed, never asserted.
TEST(CSGFilter, LargeSphereMinusSmallSphere)
{
  auto large = Sphere(1.0, 0, 0, 0, 230);
  auto small = Sphere(0.25, 0.95, 0.1, 0.05, 40);
  ASSERT_GE(large->GetNumberOfPolys(), 100000);
  auto difference = Filter({ large, small }, "diff(A,B)");
  const double vd = SolidVolume(difference);
  std::cout << "  " << large->GetNumberOfPolys() << " - " << small->GetNumberOfPolys()
            << " triangles: difference in " << difference->GetLastMilliseconds() << " ms, "
            << difference->GetOutput()->GetNumberOfPolys() << " triangles out\n";
  auto intersection = Filter({ large, small }, "inter(A,B)");
  const double vi = SolidVolume(intersection);
  std::cout << "  intersection in " << intersection->GetLastMilliseconds() << " ms\n";
  const double va = SignedVolume(large);
  EXPECT_NEAR(vd + vi, va, 1e-9 * va);
  EXPECT_GT(vi, 0.01);
  EXPECT_GT(difference->GetLastMilliseconds(), 0.0);
}

TEST(CSGFilter, ProgressIsReportedBetweenOperations)
{
  auto a = Box(0, 1, 0, 1, 0, 1);
  auto b = Box(0.5, 1.5, 0.25, 1.25, 0.375, 1.375);
  auto c = Box(-0.5, 0.5, -0.25, 0.75, 0.125, 0.625);
  auto filter = Filter({ a, b, c }, "diff(union(A,B),C)");
  std::vector<double> seen;
  vtkNew<vtkCallbackCommand> observer;
  observer->SetClientData(&seen);
  observer->SetCallback(
    [](vtkObject* caller, unsigned long, void* data, void*)
    {
      static_cast<std::vector<double>*>(data)->push_back(static_cast<vtkAlgorithm*>(caller)->GetProgress());
    });
  filter->AddObserver(vtkCommand::ProgressEvent, observer);
  SolidVolume(filter);
  ASSERT_GT(seen.size(), 0u);
  // The pipeline itself reports 0 and 1; the filter reports 1/2 after the first of two operations.
  bool half = false;
  for (double p : seen)
  {
    half = half || std::abs(p - 0.5) < 1e-12;
  }
  EXPECT_TRUE(half) << seen.size() << " progress events, none at 0.5";

  // An observer may stop the work between operations: the run then fails, saying so.
  auto stopped = Filter({ a, b, c }, "diff(union(A,B),C)");
  vtkNew<vtkCallbackCommand> stopper;
  stopper->SetCallback([](vtkObject* caller, unsigned long, void*, void*)
    {
      auto* algorithm = static_cast<vtkAlgorithm*>(caller);
      if (algorithm->GetProgress() > 0.0 && algorithm->GetProgress() < 1.0)
      {
        algorithm->SetAbortExecute(1);
      }
    });
  stopped->AddObserver(vtkCommand::ProgressEvent, stopper);
  ExpectError(stopped, { "aborted after 1 of 2 operations" });
  EXPECT_EQ(stopped->GetLastOperations(), 1);
}

TEST(CSGFilter, PrintSelfAndExpressionModifies)
{
  auto filter = vtkSmartPointer<vtkDeepShadowCSGFilter>::New();
  const vtkMTimeType before = filter->GetMTime();
  filter->SetExpression("union(A,B)");
  EXPECT_GT(filter->GetMTime(), before);
  const vtkMTimeType after = filter->GetMTime();
  filter->SetExpression("union(A,B)");
  EXPECT_EQ(filter->GetMTime(), after);
  EXPECT_EQ(filter->GetExpression(), "union(A,B)");
  std::ostringstream text;
  filter->Print(text);
  EXPECT_NE(text.str().find("Expression: union(A,B)"), std::string::npos);
}
