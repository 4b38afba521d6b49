#include "vtkDeepShadowBoundedScene.h"

#include "vtkCellArray.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkDeepShadowBoundedScene);

namespace
{
struct BoundedSpec
{
  const char* Name;
  const char* Volume;
  const char* Expression;
  const char* Description;
};

const BoundedSpec Specs[] = {
  { "head-cut", "head", "diff(A,B)", "the head minus a sphere biting into its upper front-left" },
  { "box-torus", "box", "A", "the box scene inside a torus about z" },
  { "spheres-half", "spheres", "A", "the spheres scene below its mid-plane: a bound on five of its faces" },
};

const BoundedSpec* Find(const std::string& name)
{
  for (const BoundedSpec& spec : Specs)
  {
    if (name == spec.Name)
    {
      return &spec;
    }
  }
  return nullptr;
}

vtkSmartPointer<vtkPolyData> Mesh(vtkPoints* points, vtkCellArray* triangles)
{
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(triangles);
  return mesh;
}

void AddTriangle(vtkCellArray* cells, vtkIdType a, vtkIdType b, vtkIdType c)
{
  const vtkIdType ids[3] = { a, b, c };
  cells->InsertNextCell(3, ids);
}
}

std::vector<std::string> vtkDeepShadowBoundedScene::GetSceneNames()
{
  std::vector<std::string> names;
  for (const BoundedSpec& spec : Specs)
  {
    names.emplace_back(spec.Name);
  }
  return names;
}

bool vtkDeepShadowBoundedScene::IsSceneName(const std::string& name)
{
  return Find(name) != nullptr;
}

std::string vtkDeepShadowBoundedScene::GetSceneDescription(const std::string& name)
{
  const BoundedSpec* spec = Find(name);
  return spec ? spec->Description : "";
}

std::string vtkDeepShadowBoundedScene::GetVolumeSceneName(const std::string& name)
{
  const BoundedSpec* spec = Find(name);
  return spec ? spec->Volume : "";
}

std::string vtkDeepShadowBoundedScene::GetBoundExpression(const std::string& name)
{
  const BoundedSpec* spec = Find(name);
  return spec ? spec->Expression : "";
}

std::vector<vtkSmartPointer<vtkPolyData>> vtkDeepShadowBoundedScene::MakeBounds(
  const std::string& name, const double b[6])
{
  const double centre[3] = { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]) };
  const double size = std::max({ b[1] - b[0], b[3] - b[2], b[5] - b[4] });
  if (name == "head-cut")
  {
    const double margin = 0.01 * size;
    const double around[6] = { b[0] - margin, b[1] + margin, b[2] - margin, b[3] + margin,
      b[4] - margin, b[5] + margin };
    // The face looks towards -y and +x is the patient's left (vtkDeepShadowStandardScene).
    const double bite[3] = { centre[0] + 0.22 * (b[1] - b[0]), centre[1] - 0.3 * (b[3] - b[2]),
      centre[2] + 0.25 * (b[5] - b[4]) };
    return { MakeBox(around), MakeSphere(bite, 0.33 * size, 64) };
  }
  if (name == "box-torus")
  {
    return { MakeTorus(centre, 0.3 * size, 0.16 * size, 96) };
  }
  if (name == "spheres-half")
  {
    const double lower[6] = { b[0], b[1], b[2], b[3], b[4], centre[2] };
    return { MakeBox(lower) };
  }
  return {};
}

vtkSmartPointer<vtkPolyData> vtkDeepShadowBoundedScene::MakeBox(const double b[6])
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (int i = 0; i < 8; ++i)
  {
    points->InsertNextPoint(b[i & 1 ? 1 : 0], b[i & 2 ? 3 : 2], b[i & 4 ? 5 : 4]);
  }
  vtkNew<vtkCellArray> triangles;
  const int faces[6][4] = { { 0, 4, 6, 2 }, { 1, 3, 7, 5 }, { 0, 1, 5, 4 }, { 2, 6, 7, 3 },
    { 0, 2, 3, 1 }, { 4, 5, 7, 6 } };
  for (const auto& f : faces)
  {
    AddTriangle(triangles, f[0], f[1], f[2]);
    AddTriangle(triangles, f[0], f[2], f[3]);
  }
  return Mesh(points, triangles);
}

vtkSmartPointer<vtkPolyData> vtkDeepShadowBoundedScene::MakeSphere(const double c[3], double radius, int resolution)
{
  const int rings = std::max(resolution / 2, 2), segments = std::max(resolution, 3);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->InsertNextPoint(c[0], c[1], c[2] + radius); // north pole: 0
  for (int i = 1; i < rings; ++i)
  {
    const double theta = M_PI * i / rings;
    for (int j = 0; j < segments; ++j)
    {
      const double phi = 2.0 * M_PI * j / segments;
      points->InsertNextPoint(c[0] + radius * std::sin(theta) * std::cos(phi),
        c[1] + radius * std::sin(theta) * std::sin(phi), c[2] + radius * std::cos(theta));
    }
  }
  const vtkIdType south = points->InsertNextPoint(c[0], c[1], c[2] - radius);
  auto ring = [segments](int i, int j) { return 1 + (i - 1) * segments + (j % segments); };
  vtkNew<vtkCellArray> triangles;
  for (int j = 0; j < segments; ++j)
  {
    AddTriangle(triangles, 0, ring(1, j), ring(1, j + 1));
    for (int i = 1; i + 1 < rings; ++i)
    {
      AddTriangle(triangles, ring(i, j), ring(i + 1, j), ring(i + 1, j + 1));
      AddTriangle(triangles, ring(i, j), ring(i + 1, j + 1), ring(i, j + 1));
    }
    AddTriangle(triangles, ring(rings - 1, j), south, ring(rings - 1, j + 1));
  }
  return Mesh(points, triangles);
}

vtkSmartPointer<vtkPolyData> vtkDeepShadowBoundedScene::MakeTorus(
  const double c[3], double major, double minor, int resolution)
{
  const int around = std::max(resolution, 3), tube = std::max(resolution / 2, 3);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (int i = 0; i < around; ++i)
  {
    const double u = 2.0 * M_PI * i / around;
    for (int j = 0; j < tube; ++j)
    {
      const double v = 2.0 * M_PI * j / tube;
      const double r = major + minor * std::cos(v);
      points->InsertNextPoint(c[0] + r * std::cos(u), c[1] + r * std::sin(u), c[2] + minor * std::sin(v));
    }
  }
  auto id = [around, tube](int i, int j) { return (i % around) * tube + (j % tube); };
  vtkNew<vtkCellArray> triangles;
  for (int i = 0; i < around; ++i)
  {
    for (int j = 0; j < tube; ++j)
    {
      AddTriangle(triangles, id(i, j), id(i + 1, j), id(i + 1, j + 1));
      AddTriangle(triangles, id(i, j), id(i + 1, j + 1), id(i, j + 1));
    }
  }
  return Mesh(points, triangles);
}

void vtkDeepShadowBoundedScene::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  for (const BoundedSpec& spec : Specs)
  {
    os << indent << spec.Name << ": " << spec.Description << " (" << spec.Expression << ")\n";
  }
}
