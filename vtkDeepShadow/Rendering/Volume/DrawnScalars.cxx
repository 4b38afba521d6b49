#include "Volume/DrawnScalars.h"

#include "vtkAbstractMapper.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkVolumeMapper.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <new>
#include <sstream>
#include <vector>

namespace deepshadow
{
namespace
{

// What the mapper's selection names, for messages: "point array 'density'", ...
std::string SelectionName(vtkVolumeMapper* mapper)
{
  const int mode = mapper->GetScalarMode();
  if (mode != VTK_SCALAR_MODE_USE_POINT_FIELD_DATA && mode != VTK_SCALAR_MODE_USE_CELL_FIELD_DATA)
  {
    return mode == VTK_SCALAR_MODE_USE_CELL_DATA ? "cell scalars"
      : mode == VTK_SCALAR_MODE_USE_POINT_DATA   ? "point scalars"
                                                 : "point or cell scalars";
  }
  const std::string where = mode == VTK_SCALAR_MODE_USE_CELL_FIELD_DATA ? "cell" : "point";
  if (mapper->GetArrayAccessMode() == VTK_GET_ARRAY_BY_NAME)
  {
    return where + " array '" + (mapper->GetArrayName() ? mapper->GetArrayName() : "") + "'";
  }
  return where + " array number " + std::to_string(mapper->GetArrayId());
}

// Per axis of a grid resampled from n cells: fine point k reads the cells lo and hi (equal at a
// centre, neighbours halfway between centres, the edge cell over the outer half cells).
void CellPairs(int cells, std::vector<int>& lo, std::vector<int>& hi)
{
  const int points = 2 * cells + 1;
  lo.resize(static_cast<size_t>(points));
  hi.resize(static_cast<size_t>(points));
  for (int k = 0; k < points; ++k)
  {
    const bool centre = k % 2 == 1;
    lo[static_cast<size_t>(k)] = centre ? (k - 1) / 2 : std::max(k / 2 - 1, 0);
    hi[static_cast<size_t>(k)] = centre ? (k - 1) / 2 : std::min(k / 2, cells - 1);
  }
}

// The cells per axis of `input` and the 2n + 1 points per axis they are drawn on; false with
// `error` for an axis without a cell or beyond what a 3D texture holds.
bool CellGrid(vtkImageData* input, int cellsPerAxis[3], int points[3], std::string& error)
{
  int dims[3];
  input->GetDimensions(dims);
  for (int axis = 0; axis < 3; ++axis)
  {
    cellsPerAxis[axis] = dims[axis] - 1;
    points[axis] = 2 * cellsPerAxis[axis] + 1;
    if (cellsPerAxis[axis] < 1)
    {
      std::ostringstream why;
      why << "the volume has zero extent along " << "xyz"[axis] << " (" << dims[0] << "x" << dims[1]
          << "x" << dims[2] << " points); cell scalars need at least one cell per axis";
      error = why.str();
      return false;
    }
    if (points[axis] > DrawnScalars::MaxCellGridPoints)
    {
      std::ostringstream why;
      why << "cell scalars of " << cellsPerAxis[0] << "x" << cellsPerAxis[1] << "x" << cellsPerAxis[2]
          << " cells are drawn on a grid of 2n + 1 points per axis, beyond the " << DrawnScalars::MaxCellGridPoints
          << " a 3D texture holds (at most " << (DrawnScalars::MaxCellGridPoints - 1) / 2 << " cells per axis)";
      error = why.str();
      return false;
    }
  }
  return true;
}

// Each point of the 2n + 1 grid: the mean of the 8 cells around it (Image's float values);
// false with `error` for a mean beyond single precision.
bool ResampleCells(vtkDataArray* values, const int cellsPerAxis[3], const int points[3], float* out, std::string& error)
{
  std::vector<int> lo[3], hi[3];
  for (int axis = 0; axis < 3; ++axis)
  {
    CellPairs(cellsPerAxis[axis], lo[axis], hi[axis]);
  }
  auto cell = [&](int i, int j, int k) {
    return values->GetComponent(
      static_cast<vtkIdType>(i) + cellsPerAxis[0] * (static_cast<vtkIdType>(j) + static_cast<vtkIdType>(cellsPerAxis[1]) * k), 0);
  };
  for (int k = 0; k < points[2]; ++k)
  {
    for (int j = 0; j < points[1]; ++j)
    {
      for (int i = 0; i < points[0]; ++i)
      {
        // Equal weights: each axis reads one cell twice or two neighbours once each.
        double sum = 0.0;
        for (int c = 0; c < 8; ++c)
        {
          sum += cell((c & 1 ? hi : lo)[0][static_cast<size_t>(i)], (c & 2 ? hi : lo)[1][static_cast<size_t>(j)],
            (c & 4 ? hi : lo)[2][static_cast<size_t>(k)]);
        }
        const double value = sum / 8.0;
        if (std::isfinite(value) && std::abs(value) > static_cast<double>(FLT_MAX))
        {
          std::ostringstream why;
          why << "the volume's " << values->GetDataTypeAsString() << " cell scalars reach " << value
              << ", beyond single precision's range (+-3.4e38) in which they are kept";
          error = why.str();
          return false;
        }
        *out++ = static_cast<float>(value);
      }
    }
  }
  return true;
}

}

vtkImageData* DrawnScalars::Update(vtkVolumeMapper* mapper, vtkImageData* input, std::string& error)
{
  error.clear();
  if (!input || input->GetNumberOfPoints() == 0)
  {
    return input; // CheckVolumeInput says what is wrong with an empty one
  }
  int cellFlag = 0;
  vtkAbstractArray* array = vtkAbstractMapper::GetAbstractScalars(input, mapper->GetScalarMode(),
    mapper->GetArrayAccessMode(), mapper->GetArrayId(), mapper->GetArrayName(), cellFlag);
  if (!array)
  {
    const bool hasAny = input->GetPointData()->GetNumberOfArrays() + input->GetCellData()->GetNumberOfArrays() > 0;
    error = "the volume has no " + SelectionName(mapper) + " to draw" +
      (hasAny ? " (choose another with the mapper's SetScalarMode and SelectScalarArray)" : "");
    return nullptr;
  }
  const bool cells = cellFlag == 1;
  if (!cells && array == input->GetPointData()->GetScalars() && array->GetNumberOfComponents() == 1)
  {
    this->Cells = false;
    this->Others.clear();
    return input; // drawn as it is
  }
  const bool same = input == this->Source && input->GetMTime() == this->SourceTime &&
    array == this->Array && array->GetMTime() == this->ArrayTime && cells == this->Cells;
  if (!same)
  {
    // Built (or found wanting) once per change; a failed build is not retried every frame.
    this->Source = input;
    this->SourceTime = input->GetMTime();
    this->Array = array;
    this->ArrayTime = array->GetMTime();
    this->Cells = cells;
    ++this->Builds;
    this->BuildError.clear();
    if (!this->Build(input, array, cells, this->BuildError))
    {
      this->Image->Initialize();
    }
  }
  error = this->BuildError;
  return error.empty() ? this->Image.Get() : nullptr;
}

bool DrawnScalars::Build(vtkImageData* input, vtkAbstractArray* array, bool cells, std::string& error)
{
  auto* values = vtkDataArray::SafeDownCast(array);
  if (!values || values->GetDataType() == VTK_BIT)
  {
    error = std::string("the volume's ") + (cells ? "cell" : "point") + " array '" +
      (array->GetName() ? array->GetName() : "") + "' is of type " + array->GetDataTypeAsString() +
      ", not numbers that can be drawn";
    return false;
  }
  this->Others.clear();
  return cells ? this->BuildFromCells(input, values, error) : this->BuildFromPoints(input, values, error);
}

bool DrawnScalars::BuildFromPoints(vtkImageData* input, vtkDataArray* values, std::string& error)
{
  const int components = values->GetNumberOfComponents();
  if (components == 1)
  {
    this->Image->Initialize();
    this->Image->CopyStructure(input);
    this->Image->GetPointData()->SetScalars(values);
    return true;
  }
  if (components > MaxComponents)
  {
    error = "the volume's scalars have " + std::to_string(components) + " components; at most " +
      std::to_string(MaxComponents) + " are drawn";
    return false;
  }
  // One image per component, in the array's own type: each is a volume of its own to the
  // textures and the twin (Core/Components.h combines them).
  for (int c = 0; c < components; ++c)
  {
    vtkSmartPointer<vtkDataArray> single = vtk::TakeSmartPointer(values->NewInstance());
    single->SetNumberOfComponents(1);
    single->SetNumberOfTuples(values->GetNumberOfTuples());
    single->CopyComponent(0, values, c);
    single->SetName(values->GetName());
    vtkImageData* image = this->Image;
    if (c > 0)
    {
      this->Others.push_back(vtkSmartPointer<vtkImageData>::New());
      image = this->Others.back();
    }
    image->Initialize();
    image->CopyStructure(input);
    image->GetPointData()->SetScalars(single);
  }
  return true;
}

bool DrawnScalars::BuildFromCells(vtkImageData* input, vtkDataArray* values, std::string& error)
{
  if (values->GetNumberOfComponents() != 1)
  {
    error = "the volume's cell scalars have " + std::to_string(values->GetNumberOfComponents()) +
      " components; only single-component scalars are supported";
    return false;
  }
  int cellsPerAxis[3], points[3];
  if (!CellGrid(input, cellsPerAxis, points, error))
  {
    return false;
  }
  const vtkIdType expected = static_cast<vtkIdType>(cellsPerAxis[0]) * cellsPerAxis[1] * cellsPerAxis[2];
  if (values->GetNumberOfTuples() != expected)
  {
    error = "the volume's cell array has " + std::to_string(values->GetNumberOfTuples()) +
      " values for " + std::to_string(expected) + " cells";
    return false;
  }
  vtkNew<vtkFloatArray> resampled;
  resampled->SetName(values->GetName());
  const size_t count = static_cast<size_t>(points[0]) * points[1] * points[2];
  try
  {
    resampled->SetNumberOfTuples(static_cast<vtkIdType>(count));
  }
  catch (const std::bad_alloc&)
  {
    error = "no memory for the " + std::to_string(count) + " points that the cell scalars are drawn on";
    return false;
  }
  if (!ResampleCells(values, cellsPerAxis, points, resampled->GetPointer(0), error))
  {
    return false;
  }
  double spacing[3];
  input->GetSpacing(spacing);
  const int* extent = input->GetExtent();
  this->Image->Initialize();
  this->Image->SetOrigin(input->GetOrigin());
  this->Image->SetSpacing(spacing[0] / 2.0, spacing[1] / 2.0, spacing[2] / 2.0);
  this->Image->SetDirectionMatrix(input->GetDirectionMatrix());
  // Index 2e of the half-spacing grid is index e of the input: the same world box.
  this->Image->SetExtent(2 * extent[0], 2 * extent[0] + points[0] - 1, 2 * extent[2],
    2 * extent[2] + points[1] - 1, 2 * extent[4], 2 * extent[4] + points[2] - 1);
  this->Image->GetPointData()->SetScalars(resampled);
  return true;
}

}
