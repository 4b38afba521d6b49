// Cell scalars and the array the mapper selects (SetScalarMode, SelectScalarArray), drawn as
// VTK's mapper draws them, and cast into every shadow technique.
//
// 1. Coarse cell scalars (16^3 cells of 3 units: the test volume's values at the cell
//    centres), shaded and not, drawn by our mapper and by VTK's in one run, within a tolerance
//    calibrated on VTK against itself (TestGradientOpacity's rule). The same values drawn as
//    point scalars of the cell grid's points (half a cell off, a cell larger) must fail it;
//    the GPU picture must match its CPU twin.
// 2. A point array and a cell array chosen by name while other arrays are the active scalars,
//    against VTK's mapper choosing the same; ours left on the active scalars must fail.
// 3. The shadow scene's volume as cell scalars: every technique matches its CPU twin, and the
//    deep shadow map darkens the floor under the ball.
// 4. The resampled grid is built once: a second frame uploads nothing.
#include "DeepShadowTestUtilities.h"

#include "vtkCellData.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkUnsignedCharArray.h"

using deepshadow::testing::Check;
using deepshadow::testing::Grab;
using deepshadow::testing::WithinTolerance;

namespace
{
using Drawn = deepshadow::testing::ComparisonPicture;

// `points`' values as the cell scalars of a grid one point larger per axis, each cell centred
// on the point it takes its value from (so both describe the same field inside).
vtkSmartPointer<vtkImageData> AsCells(vtkImageData* points)
{
  int dims[3];
  points->GetDimensions(dims);
  double spacing[3], origin[3];
  points->GetSpacing(spacing);
  points->GetOrigin(origin);
  auto cells = vtkSmartPointer<vtkImageData>::New();
  cells->SetDimensions(dims[0] + 1, dims[1] + 1, dims[2] + 1);
  cells->SetSpacing(spacing);
  cells->SetOrigin(origin[0] - 0.5 * spacing[0], origin[1] - 0.5 * spacing[1], origin[2] - 0.5 * spacing[2]);
  cells->GetCellData()->SetScalars(points->GetPointData()->GetScalars());
  return cells;
}

// The same values as point scalars of the cell grid's points (the mistake part 1 must catch):
// the field stretched by a cell and shifted by half of one.
vtkSmartPointer<vtkImageData> CellValuesAtPoints(vtkImageData* points)
{
  auto cells = AsCells(points);
  auto wrong = vtkSmartPointer<vtkImageData>::New();
  int dims[3];
  points->GetDimensions(dims);
  wrong->SetDimensions(dims);
  wrong->SetOrigin(cells->GetOrigin());
  double spacing[3];
  points->GetSpacing(spacing);
  wrong->SetSpacing(spacing[0] * dims[0] / (dims[0] - 1), spacing[1] * dims[1] / (dims[1] - 1),
    spacing[2] * dims[2] / (dims[2] - 1));
  wrong->GetPointData()->SetScalars(points->GetPointData()->GetScalars());
  return wrong;
}

// The test volume on a coarse grid: 16^3 values 3 units apart.
vtkSmartPointer<vtkImageData> CoarseVolume()
{
  auto image = deepshadow::testing::MakeTestVolume(VTK_UNSIGNED_CHAR, 16);
  image->SetSpacing(3.0, 3.0, 3.0);
  image->SetOrigin(-22.5, -22.5, -22.5);
  return image;
}

using Select = std::function<void(vtkVolumeMapper*)>;

Drawn Draw(vtkRenderWindow* window, vtkImageData* data, bool vtks, bool shade, const Select& select = nullptr,
  float step = 0.5f, bool jitter = false)
{
  deepshadow::testing::ComparisonMappers mappers;
  vtkGPUVolumeRayCastMapper* mapper = mappers.Pick(vtks, step, jitter);
  if (select)
  {
    select(mapper);
  }
  return deepshadow::testing::DrawForComparison(
    window, mapper, data, deepshadow::testing::MakeComparisonProperty(shade), { 0.1, 0.1, 0.15 }, !vtks);
}

// Ours against VTK's on `data`; `wrong` (drawn by ours as it is) must fail the same test.
bool MatchesVTK(vtkRenderWindow* window, vtkImageData* data, const Select& select, bool shade,
  const std::function<Drawn()>& wrong, const std::string& what)
{
  bool ok = true;
  const Drawn ours = Draw(window, data, false, shade, select);
  const Drawn vtks = Draw(window, data, true, shade, select);
  const deepshadow::testing::VTKTolerance tolerance = deepshadow::testing::CalibrateOnVTK(what, vtks.Picture,
    [&](float scale, bool jitter) { return Draw(window, data, true, shade, select, 0.5f * scale, jitter).Picture; });
  ok = WithinTolerance(what.c_str(), ours.Picture, vtks.Picture, tolerance.MaxRMSE, 8.0 / 255.0, tolerance.MaxFraction) && ok;
  ok = WithinTolerance((what + " vs CPU twin").c_str(), ours.Picture, ours.Twin, 1.5 / 255.0, 8.0 / 255.0, 0.005) && ok;
  ok = !WithinTolerance((what + ", the wrong field (must fail)").c_str(), wrong().Picture, vtks.Picture,
         tolerance.MaxRMSE, 8.0 / 255.0, tolerance.MaxFraction) && ok;
  return ok;
}

// `data` with a second array of zeros made the active scalars, its own values kept as the
// array "density" (of points or cells as `cells` says).
vtkSmartPointer<vtkImageData> WithZerosActive(vtkImageData* data, bool cells)
{
  auto copy = vtkSmartPointer<vtkImageData>::New();
  copy->DeepCopy(data);
  vtkDataSetAttributes* attributes =
    cells ? static_cast<vtkDataSetAttributes*>(copy->GetCellData()) : copy->GetPointData();
  vtkSmartPointer<vtkDataArray> density = attributes->GetScalars();
  density->SetName("density");
  vtkNew<vtkUnsignedCharArray> zeros;
  zeros->SetName("zeros");
  zeros->SetNumberOfTuples(density->GetNumberOfTuples());
  zeros->FillValue(0);
  attributes->SetScalars(zeros); // replaces "density" as the active scalars
  attributes->AddArray(density);
  return copy;
}
}

int TestCellScalars(int, char*[])
{
  bool ok = true;
  vtkNew<vtkDeepShadowRenderWindow> window;
  window->SetSize(200, 200);
  const auto coarse = CoarseVolume();
  const auto cells = AsCells(coarse);
  for (const bool shade : { false, true })
  {
    ok = MatchesVTK(window, cells, nullptr, shade,
           [&] { return Draw(window, CellValuesAtPoints(coarse), false, shade); },
           shade ? "cell scalars, shaded" : "cell scalars") && ok;
  }

  const auto points = deepshadow::testing::MakeTestVolume(VTK_UNSIGNED_CHAR, 32);
  const auto namedPoints = WithZerosActive(points, false);
  const Select byName = [](vtkVolumeMapper* mapper) {
    mapper->SetScalarModeToUsePointFieldData();
    mapper->SelectScalarArray("density");
  };
  ok = MatchesVTK(window, namedPoints, byName, true, [&] { return Draw(window, namedPoints, false, true); },
         "the point array 'density'") && ok;
  const auto namedCells = WithZerosActive(cells, true);
  const Select byCellName = [](vtkVolumeMapper* mapper) {
    mapper->SetScalarModeToUseCellFieldData();
    mapper->SelectScalarArray("density");
  };
  ok = MatchesVTK(window, namedCells, byCellName, true, [&] { return Draw(window, namedCells, false, true); },
         "the cell array 'density'") && ok;

  // Shadows cast by cell scalars.
  deepshadow::testing::ShadowScene scene;
  scene.Data = AsCells(scene.Data);
  scene.Mapper->SetInputData(scene.Data);
  ok = scene.AllMatchTwins("cell scalars") && ok;
  ok = scene.DeepShadowDarkensFloor("cell scalars") && ok;

  // Built once: another frame resamples and uploads nothing.
  const int uploads = scene.Mapper->GetVolumeUploads();
  scene.Window->Render();
  ok = Check("a second frame uploads nothing", scene.Mapper->GetVolumeUploads() == uploads) && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
