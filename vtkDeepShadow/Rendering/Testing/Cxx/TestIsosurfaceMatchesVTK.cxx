// Isosurface blending as VTK's mapper draws it, and as the CPU twin computes it.
//
// Two contour values on the comparison volume (unsigned char 0..255, and a float copy spanning
// 40..160): an outer, translucent surface (opacity 0.35 at its value) around an opaque inner
// one, shaded, drawn by our mapper and by VTK's in one run. The tolerance is calibrated on VTK
// against itself (CalibrateOnVTK: its pictures at 0.8x and 1.25x its sample distance and
// jittered): 1.5 times the largest difference, at least RMSE 0.007 and 1% of pixels off by
// more than 8/255. The control, the same volume
// composited, must fall outside it; no picture may be black; the GPU picture must match its
// CPU twin.
#include "DeepShadowTestUtilities.h"

#include "vtkContourValues.h"
#include "vtkGPUVolumeRayCastMapper.h"

#include <algorithm>

using deepshadow::testing::Grab;
using deepshadow::testing::WithinTolerance;

namespace
{
using Drawn = deepshadow::testing::ComparisonPicture;

Drawn Draw(vtkRenderWindow* window, vtkImageData* data, bool vtks, int blend, float step = 0.5f,
  bool jitter = false)
{
  deepshadow::testing::ComparisonMappers mappers;
  vtkGPUVolumeRayCastMapper* mapper = mappers.Pick(vtks, step, jitter);
  mapper->SetBlendMode(blend);
  // The look over this data's range: the same colours and opacities per normalized scalar.
  double range[2];
  data->GetScalarRange(range);
  const double span = (range[1] - range[0]) / 255.0;
  vtkSmartPointer<vtkVolumeProperty> property = deepshadow::testing::MakeComparisonProperty(true);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(range[0], 0.2, 0.4, 1.0);
  color->AddRGBPoint(range[0] + 60 * span, 1.0, 0.5, 0.2);
  color->AddRGBPoint(range[1], 0.9, 0.9, 1.0);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(range[0], 0.0);
  opacity->AddPoint(range[0] + 50 * span, 0.35);
  opacity->AddPoint(range[0] + 140 * span, 1.0);
  opacity->AddPoint(range[1], 1.0);
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  // Given unsorted: both mappers sort them.
  property->GetIsoSurfaceValues()->SetValue(0, range[0] + 150 * span);
  property->GetIsoSurfaceValues()->SetValue(1, range[0] + 50 * span);
  return deepshadow::testing::DrawForComparison(window, mapper, data, property, { 0.1, 0.1, 0.15 }, !vtks);
}
}

int TestIsosurfaceMatchesVTK(int, char*[])
{
  vtkSmartPointer<vtkImageData> bytes = deepshadow::testing::MakeTestVolume(VTK_UNSIGNED_CHAR);
  vtkSmartPointer<vtkImageData> floats = deepshadow::testing::MakeTestVolume(VTK_FLOAT, 48, 120.0, 40.0);
  vtkNew<vtkDeepShadowRenderWindow> window;
  window->SetSize(200, 200);
  bool ok = true;
  const int iso = vtkVolumeMapper::ISOSURFACE_BLEND;
  for (vtkImageData* data : { bytes.Get(), floats.Get() })
  {
    const std::string what = std::string("isosurface, ") + (data == bytes ? "unsigned char" : "float 40..160");
    const Drawn ours = Draw(window, data, false, iso);
    const Drawn vtks = Draw(window, data, true, iso);
    const deepshadow::testing::VTKTolerance tolerance = deepshadow::testing::CalibrateOnVTK(
      what, vtks.Picture, [&](float scale, bool jitter) { return Draw(window, data, true, iso, 0.5f * scale, jitter).Picture; });
    const double maxRMSE = tolerance.MaxRMSE;
    const double maxFraction = tolerance.MaxFraction;
    ok = WithinTolerance(what.c_str(), ours.Picture, vtks.Picture, maxRMSE, 8.0 / 255.0, maxFraction) && ok;
    ok = WithinTolerance((what + " vs CPU twin").c_str(), ours.Picture, ours.Twin, 1.5 / 255.0, 8.0 / 255.0,
           0.005) && ok;
    const Drawn composite = Draw(window, data, false, vtkVolumeMapper::COMPOSITE_BLEND);
    ok = !WithinTolerance((what + ", ours compositing (must fail)").c_str(), composite.Picture,
           vtks.Picture, maxRMSE, 8.0 / 255.0, maxFraction) && ok;
    ok = deepshadow::testing::Check(what + ": not black",
           deepshadow::testing::CoveredFraction(ours.Picture, { 0.1, 0.1, 0.15 }) > 0.05) && ok;
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
