// csg-bench: time of vtkDeepShadowCSGFilter (CGAL corefinement on exact meshes) against mesh size.
//
//   csg-bench [--max-triangles N] [--runs R]
//
// For spheres of increasing size (about 1e3 to 1.3e5 triangles per operand) it computes
// difference(A,B) of two overlapping spheres (in general position) and prints one JSON object
// per line:
//
//   {"triangles_per_operand": N, "operation": "difference", "cgal_ms": T, "output_triangles": M,
//    "one_operand_validation_ms": V, "runs": R}
//
// cgal_ms is the filter's GetLastMilliseconds() (conversion, validation, the Boolean operation and
// the conversion back), the median of R runs (R = 3 by default, 1 for the largest size).
// one_operand_validation_ms is the same filter on A alone: the conversion and validation of one
// operand (and its conversion back), with no Boolean operation.
#include "vtkDeepShadowCSGFilter.h"

#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

namespace
{
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

int Usage(const char* program)
{
  std::cerr << "usage: " << program << " [--max-triangles N] [--runs R]\n"
            << "  Times difference(A,B) of two overlapping spheres of increasing size with\n"
            << "  vtkDeepShadowCSGFilter and prints one JSON object per size.\n";
  return 2;
}
}

int main(int argc, char* argv[])
{
  long long maxTriangles = -1;
  int runs = 3;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if ((arg == "--max-triangles" || arg == "--runs") && i + 1 < argc)
    {
      char* end = nullptr;
      const long long value = std::strtoll(argv[++i], &end, 10);
      if (!end || *end != '\0' || value < 1)
      {
        std::cerr << "csg-bench: " << arg << " needs a positive integer, not '" << argv[i] << "'\n";
        return 2;
      }
      (arg == "--runs" ? (void)(runs = static_cast<int>(value)) : (void)(maxTriangles = value));
    }
    else if (arg == "--help" || arg == "-h")
    {
      Usage(argv[0]);
      return 0;
    }
    else
    {
      std::cerr << "csg-bench: unknown argument '" << arg << "'\n";
      return Usage(argv[0]);
    }
  }

  // vtkSphereSource with resolution n x n gives 2 n (n - 2) triangles.
  const int resolutions[] = { 24, 46, 91, 181, 256 };
  const int largest = resolutions[sizeof(resolutions) / sizeof(resolutions[0]) - 1];
  for (int resolution : resolutions)
  {
    auto a = Sphere(1.0, 0.0, 0.0, 0.0, resolution);
    auto b = Sphere(0.8, 0.55, 0.31, 0.17, resolution);
    const vtkIdType triangles = a->GetNumberOfPolys();
    if (maxTriangles > 0 && triangles > maxTriangles)
    {
      break;
    }
    const int count = resolution == largest ? 1 : runs;
    std::vector<double> times;
    vtkIdType outputTriangles = 0;
    for (int run = 0; run < count; ++run)
    {
      vtkNew<vtkDeepShadowCSGFilter> filter;
      filter->AddInputData(a);
      filter->AddInputData(b);
      filter->SetExpression("difference(A,B)");
      filter->Update();
      if (!filter->GetLastError().empty())
      {
        std::cerr << "csg-bench: " << filter->GetLastError() << "\n";
        return 1;
      }
      times.push_back(filter->GetLastMilliseconds());
      outputTriangles = filter->GetOutput()->GetNumberOfPolys();
    }
    std::sort(times.begin(), times.end());
    // The share of conversion and validation: the same work for A alone (no operation).
    std::vector<double> alone;
    for (int run = 0; run < count; ++run)
    {
      vtkNew<vtkDeepShadowCSGFilter> filter;
      filter->AddInputData(a);
      filter->Update();
      alone.push_back(filter->GetLastMilliseconds());
    }
    std::sort(alone.begin(), alone.end());
    std::cout << "{\"triangles_per_operand\": " << triangles << ", \"operation\": \"difference\", \"cgal_ms\": "
              << times[times.size() / 2] << ", \"output_triangles\": " << outputTriangles
              << ", \"one_operand_validation_ms\": " << alone[alone.size() / 2]
              << ", \"runs\": " << count << "}" << std::endl;
  }
  return 0;
}
