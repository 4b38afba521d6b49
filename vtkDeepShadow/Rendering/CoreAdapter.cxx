// VTK objects -> Core: inputs and their checks, placement, bounds, camera. How a volume looks
// (its property and blend mode) is in CoreAdapterAppearance.cxx, how it is lit in
// CoreAdapterLighting.cxx.
#include "CoreAdapter.h"

#include "Core/Geometry/PolygonTriangulation.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkVolumeMapper.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <sstream>

namespace deepshadow
{
namespace adapter
{
namespace
{
// Every numeric type VTK's mapper accepts. Unsigned char and (unsigned) short are uploaded
// exactly; every other type is kept in single precision (24-bit mantissa: integers beyond
// +-2^24 and doubles round to the nearest float), as a float texture normalized over the range.
bool IsSupportedType(int type)
{
  switch (type)
  {
    case VTK_CHAR:
    case VTK_SIGNED_CHAR:
    case VTK_UNSIGNED_CHAR:
    case VTK_SHORT:
    case VTK_UNSIGNED_SHORT:
    case VTK_INT:
    case VTK_UNSIGNED_INT:
    case VTK_LONG:
    case VTK_UNSIGNED_LONG:
    case VTK_LONG_LONG:
    case VTK_UNSIGNED_LONG_LONG:
    case VTK_ID_TYPE:
    case VTK_FLOAT:
    case VTK_DOUBLE:
      return true;
    default:
      return false;
  }
}
}

glm::dvec3 ToGlm3(const double v[3])
{
  return { v[0], v[1], v[2] };
}

glm::dmat4 ToGlm(const vtkMatrix4x4* matrix)
{
  glm::dmat4 m(1.0);
  if (matrix)
  {
    for (int row = 0; row < 4; ++row)
    {
      for (int column = 0; column < 4; ++column)
      {
        m[column][row] = matrix->GetElement(row, column);
      }
    }
  }
  return m;
}

std::string CheckVolumeInput(vtkImageData* image, vtkDataArray*& scalars)
{
  scalars = nullptr;
  if (!image)
  {
    return "no input volume (call SetInputData or SetInputConnection)";
  }
  // Points per axis from the extent in 64 bits: VTK's int dimensions wrap past 2^31 - 1
  // (an extent of 2^32 points read as 0x1x1).
  const int* extent = image->GetExtent();
  long long points[3];
  for (int axis = 0; axis < 3; ++axis)
  {
    points[axis] = static_cast<long long>(extent[2 * axis + 1]) - extent[2 * axis] + 1;
  }
  if (std::any_of(points, points + 3, [](long long n) { return n > 2147483647LL; }))
  {
    std::ostringstream why;
    why << "the volume's extent spans " << points[0] << "x" << points[1] << "x" << points[2]
        << " points; VTK's image data holds at most 2^31 - 1 along an axis";
    return why.str();
  }
  int dims[3];
  image->GetDimensions(dims);
  if (dims[0] <= 0 || dims[1] <= 0 || dims[2] <= 0 || image->GetNumberOfPoints() == 0)
  {
    return "the input volume is empty (no points)";
  }
  for (int axis = 0; axis < 3; ++axis)
  {
    if (dims[axis] < 2)
    {
      std::ostringstream why;
      why << "the volume has zero extent along " << "xyz"[axis] << " (" << dims[0] << "x"
          << dims[1] << "x" << dims[2] << " points); at least 2 points per axis are needed";
      return why.str();
    }
  }
  const double* spacing = image->GetSpacing();
  const double* origin = image->GetOrigin();
  for (int axis = 0; axis < 3; ++axis)
  {
    if (!std::isfinite(spacing[axis]) || spacing[axis] == 0.0 || !std::isfinite(origin[axis]))
    {
      return "the volume's spacing must be non-zero and finite, and its origin finite";
    }
  }
  vtkDataArray* array = image->GetPointData()->GetScalars();
  if (!array)
  {
    return "the volume has no point scalars";
  }
  if (array->GetNumberOfComponents() != 1)
  {
    return "the volume's scalars have " + std::to_string(array->GetNumberOfComponents()) +
      " components; only single-component scalars are supported";
  }
  if (!IsSupportedType(array->GetDataType()))
  {
    return std::string("scalar type ") + array->GetDataTypeAsString() +
      " is not supported (the integer types, float and double are)";
  }
  scalars = array;
  return std::string();
}

std::string CheckMeshInput(vtkPolyData* mesh)
{
  if (!mesh)
  {
    return "no input mesh";
  }
  const vtkIdType points = mesh->GetNumberOfPoints();
  vtkIdType nonFinite = 0;
  for (vtkIdType i = 0; i < points; ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    nonFinite += std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]) ? 0 : 1;
  }
  if (nonFinite > 0)
  {
    return "the mesh has " + std::to_string(nonFinite) + " of " + std::to_string(points) +
      " points that are not finite (NaN or infinite)";
  }
  double largest = 0.0;
  for (vtkIdType i = 0; i < points; ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    largest = std::max({ largest, std::abs(p[0]), std::abs(p[1]), std::abs(p[2]) });
  }
  if (largest > MaxMeshCoordinate)
  {
    std::ostringstream why;
    why << "the mesh's coordinates reach " << largest << "; at most " << MaxMeshCoordinate
        << " can be drawn (single precision on the GPU)";
    return why.str();
  }
  const std::pair<const char*, vtkCellArray*> kinds[] = { { "vertex", mesh->GetVerts() },
    { "line", mesh->GetLines() }, { "polygon", mesh->GetPolys() }, { "strip", mesh->GetStrips() } };
  for (const auto& kind : kinds)
  {
    vtkCellArray* cells = kind.second;
    if (cells && !cells->IsValid())
    {
      return std::string("the mesh's ") + kind.first + " cells are inconsistent (their offsets do "
                                                       "not index their point ids)";
    }
    if (!cells || cells->GetNumberOfConnectivityIds() == 0)
    {
      continue;
    }
    double range[2];
    cells->GetConnectivityArray()->GetRange(range, 0);
    if (range[0] < 0.0 || range[1] >= static_cast<double>(points))
    {
      std::ostringstream why;
      why << "a " << kind.first << " of the mesh has the point id "
          << static_cast<long long>(range[0] < 0.0 ? range[0] : range[1]) << ", out of range ("
          << points << " points)";
      return why.str();
    }
  }
  return std::string();
}

std::string CheckMeshPlacement(vtkPolyData* mesh, const glm::dmat4& modelToWorld)
{
  double b[6];
  mesh->GetBounds(b);
  if (mesh->GetNumberOfPoints() == 0 || !(b[0] <= b[1]))
  {
    return std::string();
  }
  double largest = 0.0;
  for (int corner = 0; corner < 8; ++corner)
  {
    const glm::dvec4 p = modelToWorld * glm::dvec4(b[corner & 1], b[2 + ((corner >> 1) & 1)], b[4 + (corner >> 2)], 1.0);
    for (int c = 0; c < 3; ++c)
    {
      largest = std::isfinite(p[c]) ? std::max(largest, std::abs(p[c])) : HUGE_VAL;
      if (!(largest <= MaxMeshCoordinate))
      {
        std::ostringstream why;
        why << "its actor's matrix puts the mesh at coordinates of " << largest << "; at most "
            << MaxMeshCoordinate << " can be drawn (single precision on the GPU)";
        return why.str();
      }
    }
  }
  return std::string();
}

std::string CheckVolumePlacement(const glm::dmat4& indexToWorld, const glm::ivec3& dims)
{
  for (int c = 0; c < 4; ++c)
  {
    for (int r = 0; r < 4; ++r)
    {
      if (!std::isfinite(indexToWorld[c][r]))
      {
        return "the volume's placement (spacing, origin, direction matrix or the prop's "
               "matrix) is not finite";
      }
    }
  }
  const glm::dmat3 axes(indexToWorld);
  if (glm::determinant(axes) == 0.0)
  {
    return "the volume's direction matrix (or the prop's matrix) is singular: its voxels have no volume";
  }
  std::ostringstream why;
  for (int axis = 0; axis < 3; ++axis)
  {
    const double edge = glm::length(axes[axis]);
    if (!(edge >= MinVoxelEdge && edge <= MaxVoxelEdge))
    {
      why << "the volume's voxel edge along " << "xyz"[axis] << " is " << edge
          << " world units; single-precision GPU rendering needs " << MinVoxelEdge << " to "
          << MaxVoxelEdge << " (rescale the spacing)";
      return why.str();
    }
  }
  const glm::dvec3 size = axes * glm::dvec3(glm::max(dims - 1, glm::ivec3(1)));
  const glm::dvec3 centre = glm::dvec3(indexToWorld * glm::dvec4(0.5 * glm::dvec3(dims - 1), 1.0));
  const double extent = glm::length(size);
  const double offset = glm::length(centre);
  if (offset > MaxOffsetRatio * extent)
  {
    why << "the volume lies " << offset << " world units from the origin, "
        << offset / extent << " times its size; single-precision GPU rendering resolves its "
        << "voxels up to " << MaxOffsetRatio << " times (move its origin nearer)";
    return why.str();
  }
  return std::string();
}

glm::dmat4 IndexToWorld(vtkImageData* image, const vtkMatrix4x4* propMatrix)
{
  vtkNew<vtkMatrix4x4> indexToPhysical;
  image->ComputeIndexToPhysicalMatrix(image->GetOrigin(), image->GetSpacing(),
    image->GetDirectionMatrix()->GetData(), indexToPhysical->GetData());
  // VTK's index space starts at the extent's minimum, ours at the first point.
  const int* extent = image->GetExtent();
  const glm::dmat4 shift = glm::dmat4(1.0, 0, 0, 0, 0, 1.0, 0, 0, 0, 0, 1.0, 0,
    extent[0], extent[2], extent[4], 1.0);
  return ToGlm(propMatrix) * ToGlm(indexToPhysical) * shift;
}

std::shared_ptr<VolumeGrid> MakeVolumeGrid(vtkImageData* image, const vtkMatrix4x4* propMatrix,
  bool replaceNonFinite, std::string& error, size_t* replaced)
{
  vtkDataArray* scalars = nullptr;
  error = CheckVolumeInput(image, scalars);
  if (!error.empty())
  {
    return nullptr;
  }
  // The grid keeps single precision: a finite scalar beyond float's range (a double) would
  // turn infinite, so it is refused here, where each value is converted (not at every check).
  const vtkIdType count = scalars->GetNumberOfTuples();
  std::vector<float> values(static_cast<size_t>(count));
  for (vtkIdType i = 0; i < count; ++i)
  {
    const double value = scalars->GetComponent(i, 0);
    if (std::isfinite(value) && std::abs(value) > static_cast<double>(FLT_MAX))
    {
      std::ostringstream why;
      why << "the volume's " << scalars->GetDataTypeAsString() << " scalars reach " << value
          << ", beyond single precision's range (+-3.4e38) in which they are kept";
      error = why.str();
      return nullptr;
    }
    values[static_cast<size_t>(i)] = static_cast<float>(value);
  }
  const NonFiniteCount bad = CountNonFinite(values.data(), values.size());
  if (replaced)
  {
    *replaced = replaceNonFinite ? bad.Total() : 0;
  }
  if (bad.Total() > 0)
  {
    if (!replaceNonFinite)
    {
      std::ostringstream why;
      why << "the volume has " << bad.NaN << " NaN, " << bad.PositiveInfinity << " +Inf and "
          << bad.NegativeInfinity
          << " -Inf samples (SetReplaceNonFiniteScalars, or the tool's --replace-nonfinite, renders them)";
      error = why.str();
      return nullptr;
    }
    ReplaceNonFinite(values.data(), values.size());
  }
  int dims[3];
  image->GetDimensions(dims);
  return std::make_shared<VolumeGrid>(
    glm::ivec3(dims[0], dims[1], dims[2]), std::move(values), IndexToWorld(image, propMatrix));
}

vtkImageData* UsableMask(vtkGPUVolumeRayCastMapper* mapper, vtkImageData* volume)
{
  // VTK's mapper skips what a binary mask clears in every blend mode; a label map colours
  // composite samples only.
  vtkImageData* mask = mapper->GetMaskInput();
  const bool projection = MakeProjection(mapper, glm::dvec2(0.0, 1.0)).Mode != BlendMode::Composite;
  const bool binary = mapper->GetMaskType() == vtkGPUVolumeRayCastMapper::BinaryMaskType;
  if (!mask || !volume || !(mapper->GetBlendMode() == vtkVolumeMapper::COMPOSITE_BLEND || (projection && binary)))
  {
    return nullptr;
  }
  int maskDims[3], dims[3];
  mask->GetDimensions(maskDims);
  volume->GetDimensions(dims);
  return std::equal(dims, dims + 3, maskDims) && mask->GetPointData()->GetScalars() ? mask : nullptr;
}

std::shared_ptr<const BoundRegion> MakeBoundRegion(const std::vector<vtkPolyData*>& bounds,
  const std::string& expression, const glm::dmat4& dataToIndex, std::string& error)
{
  const int count = static_cast<int>(bounds.size());
  if (count > CSGExpression::MaxLeaves)
  {
    error = std::to_string(count) + " bounds given; a volume takes at most " +
      std::to_string(CSGExpression::MaxLeaves) + " (combine more with vtkDeepShadowCSGFilter)";
    return nullptr;
  }
  CSGExpression parsed;
  if (!CSGExpression::Parse(expression, count, parsed, error))
  {
    return nullptr;
  }
  std::vector<std::vector<Triangle>> leaves;
  for (int b = 0; b < count; ++b)
  {
    const std::string name = "bound " + CSGExpression::LeafName(b);
    vtkPolyData* mesh = bounds[static_cast<size_t>(b)];
    if (!mesh)
    {
      error = name + " is null";
      return nullptr;
    }
    const std::string problem = CheckMeshInput(mesh);
    if (!problem.empty())
    {
      error = name + ": " + problem;
      return nullptr;
    }
    auto point = [&](vtkIdType id) {
      double p[3];
      mesh->GetPoint(id, p);
      return glm::dvec3(dataToIndex * glm::dvec4(p[0], p[1], p[2], 1.0));
    };
    // Polygons and strips as triangles; vertices and lines bound nothing.
    std::vector<std::array<vtkIdType, 3>> cells;
    std::string why;
    if (!TriangulateCells(mesh, cells, why))
    {
      error = name + ": the mesh has " + why;
      return nullptr;
    }
    std::vector<Triangle> triangles;
    triangles.reserve(cells.size());
    for (const auto& cell : cells)
    {
      triangles.push_back({ point(cell[0]), point(cell[1]), point(cell[2]) });
    }
    if (!triangles.empty())
    {
      const std::string problem = CheckClosedMesh(triangles);
      if (!problem.empty())
      {
        error = name + " " + problem;
        return nullptr;
      }
      OrientOutward(triangles);
    }
    leaves.push_back(std::move(triangles));
  }
  error.clear();
  return std::make_shared<const BoundRegion>(std::move(leaves), parsed);
}

double DatasetLengthScale(const vtkMatrix4x4* propMatrix, bool* anisotropic)
{
  const glm::dmat3 linear = propMatrix ? glm::dmat3(ToGlm(propMatrix)) : glm::dmat3(1.0);
  const double scale = std::cbrt(std::abs(glm::determinant(linear)));
  if (anisotropic)
  {
    const double x = glm::length(linear[0]), y = glm::length(linear[1]), z = glm::length(linear[2]);
    *anisotropic = std::max({ x, y, z }) - std::min({ x, y, z }) > 1e-6 * std::max({ x, y, z });
  }
  return std::isfinite(scale) && scale > 0.0 ? scale : 1.0;
}

SurfaceMaterial MakeSurfaceMaterial(vtkProperty* property)
{
  SurfaceMaterial material;
  double color[3];
  property->GetColor(color);
  material.Color = glm::dvec3(color[0], color[1], color[2]);
  material.Opacity = std::clamp(property->GetOpacity(), 0.0, 1.0);
  material.Shading.Ambient = property->GetAmbient();
  material.Shading.Diffuse = property->GetDiffuse();
  material.Shading.Specular = property->GetSpecular();
  material.Shading.SpecularPower = property->GetSpecularPower();
  double specular[3];
  property->GetSpecularColor(specular);
  material.SpecularColor = glm::dvec3(specular[0], specular[1], specular[2]);
  return material;
}

Camera MakeCamera(vtkRenderer* renderer)
{
  int width = 0, height = 0, x = 0, y = 0;
  renderer->GetTiledSizeAndOrigin(&width, &height, &x, &y);
  const double aspect = renderer->GetTiledAspectRatio();
  vtkMatrix4x4* worldToClip =
    renderer->GetActiveCamera()->GetCompositeProjectionTransformMatrix(aspect, -1, 1);
  return Camera(ToGlm(worldToClip), std::max(width, 1), std::max(height, 1));
}

}
}
