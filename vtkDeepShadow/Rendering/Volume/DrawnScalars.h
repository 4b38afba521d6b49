// Internal: the image whose point scalars a volume mapper draws, from the array it selects as
// VTK's mappers select it (scalar mode, array name or id: vtkAbstractMapper::GetAbstractScalars).
//
// - A point array is drawn as it is: the input itself when it is the active scalars, else the
//   input's structure with that array as its scalars (no copy of the values).
// - A cell array is drawn as vtkGPUVolumeRayCastMapper draws it: each value at its cell's
//   centre, interpolated linearly between centres, constant over the outer half cells (the
//   texture clamps), over the box of the input's points. That field is piecewise trilinear
//   between centres, so it is resampled exactly onto a point grid of half the spacing, 2n + 1
//   points for n cells per axis, kept in single precision (8 times the cells' count).
// - Point scalars of 2 to 4 components are drawn as that many volumes, one per component
//   (copies in the array's type): the image drawn is component 0, GetOtherComponents() the
//   rest (Core/Components.h says how they combine).
#ifndef vtkDeepShadowDrawnScalars_h
#define vtkDeepShadowDrawnScalars_h

#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <string>
#include <vector>

class vtkAbstractArray;
class vtkDataArray;
class vtkVolumeMapper;

namespace deepshadow
{

class DrawnScalars
{
public:
  /** Most points per axis of a grid drawn from cells (the common GL 3D texture limit). */
  static constexpr int MaxCellGridPoints = 2048;

  /**
   * The image to draw for `mapper`'s input `input`: `input` itself, or an image held here,
   * rebuilt only when the input, its arrays or the mapper's selection changed. Null, with
   * `error` set to one line, when the selection finds no array or cannot be drawn.
   */
  vtkImageData* Update(vtkVolumeMapper* mapper, vtkImageData* input, std::string& error);

  /** Most components per point. */
  static constexpr int MaxComponents = 4;

  /** Components 1.. of the last image when the array has several (else empty). */
  const std::vector<vtkSmartPointer<vtkImageData>>& GetOtherComponents() const { return this->Others; }

  /** Whether the last image was drawn from cell scalars. */
  bool FromCells() const { return this->Cells; }
  /** How many times an image was built here (a cell array resampled or a point array set). */
  int GetBuilds() const { return this->Builds; }

private:
  bool Build(vtkImageData* input, vtkAbstractArray* array, bool cells, std::string& error);
  /** Point scalars: the array itself, or one image per component. */
  bool BuildFromPoints(vtkImageData* input, vtkDataArray* values, std::string& error);
  /** Cell scalars, resampled onto the grid of 2n + 1 points per axis. */
  bool BuildFromCells(vtkImageData* input, vtkDataArray* values, std::string& error);

  vtkNew<vtkImageData> Image;
  std::vector<vtkSmartPointer<vtkImageData>> Others;
  // What Image was built from.
  vtkImageData* Source = nullptr;
  vtkMTimeType SourceTime = 0;
  vtkAbstractArray* Array = nullptr;
  vtkMTimeType ArrayTime = 0;
  bool Cells = false;
  std::string BuildError;
  int Builds = 0;
};

}
#endif
