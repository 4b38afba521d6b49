// Bad input gets one clear error (once, not every frame), no crash, and no garbage: the
// volume is not drawn and the picture shows only the background.
//   no input, an empty image, zero extent (N x N x 1), cell scalars only, three components,
//   unsupported scalar types (int, double), NaN and Inf samples (an error, or with
//   ReplaceNonFiniteScalars a warning and a defined picture), a volume beyond the GL's 3D
//   texture limit.
#include "DeepShadowTestUtilities.h"
#include "vtkDeepShadowRenderWindow.h"
#include "vtkDeepShadowVolumeMapper.h"

#include "vtkCellData.h"
#include "vtkColorTransferFunction.h"
#include "vtkFloatArray.h"
#include "vtkPiecewiseFunction.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <functional>
#include <limits>

using deepshadow::testing::MessageCapture;

namespace
{
struct Outcome
{
  std::vector<std::string> Errors;
  std::vector<std::string> Warnings;
  double Covered = 0.0;
};

// Renders `data` (null: no input) three times; returns what the mapper said and drew.
Outcome RenderBad(vtkImageData* data, bool replaceNonFinite = false)
{
  vtkNew<vtkDeepShadowRenderWindow> window;
  window->SetSize(64, 64);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.2, 0.3, 0.4);
  window->AddRenderer(renderer);
  vtkNew<vtkDeepShadowVolumeMapper> mapper;
  mapper->SetReplaceNonFiniteScalars(replaceNonFinite);
  vtkNew<MessageCapture> capture;
  capture->Watch(mapper);
  if (data)
  {
    mapper->SetInputData(data);
  }
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(-10.0, 1.0);
  opacity->AddPoint(10.0, 1.0);
  vtkNew<vtkVolumeProperty> property;
  property->SetScalarOpacity(opacity);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  renderer->AddVolume(volume);
  renderer->GetActiveCamera()->SetPosition(0.0, 0.0, 10.0);
  renderer->GetActiveCamera()->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->ResetCameraClippingRange();
  for (int frame = 0; frame < 3; ++frame)
  {
    window->Render();
  }
  Outcome outcome;
  outcome.Errors = capture->Errors;
  outcome.Warnings = capture->Warnings;
  outcome.Covered =
    deepshadow::testing::CoveredFraction(deepshadow::testing::Grab(window), { 0.2, 0.3, 0.4 });
  return outcome;
}

vtkSmartPointer<vtkImageData> Image(int nx, int ny, int nz, int type, int components = 1)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(nx, ny, nz);
  image->SetOrigin(-0.5 * (nx - 1), -0.5 * (ny - 1), -0.5 * (nz - 1));
  if (type != VTK_VOID)
  {
    image->AllocateScalars(type, components);
    vtkDataArray* scalars = image->GetPointData()->GetScalars();
    for (vtkIdType i = 0; i < scalars->GetNumberOfTuples(); ++i)
    {
      for (int c = 0; c < components; ++c)
      {
        scalars->SetComponent(i, c, 1.0);
      }
    }
  }
  return image;
}

bool Expect(const char* what, const Outcome& outcome, const std::string& needle, bool drawn)
{
  bool ok = true;
  const bool mentioned = std::any_of(outcome.Errors.begin(), outcome.Errors.end(),
    [&](const std::string& e) { return e.find(needle) != std::string::npos; });
  if (!needle.empty() && (!mentioned || outcome.Errors.size() != 1))
  {
    std::printf("%s: expected exactly one error mentioning '%s', got %zu\n", what,
      needle.c_str(), outcome.Errors.size());
    ok = false;
  }
  if (needle.empty() && !outcome.Errors.empty())
  {
    std::printf("%s: unexpected error: %s\n", what, outcome.Errors.front().c_str());
    ok = false;
  }
  if (drawn != (outcome.Covered > 0.05))
  {
    std::printf("%s: volume %s drawn (%.1f%% covered)\n", what, drawn ? "not" : "wrongly",
      100.0 * outcome.Covered);
    ok = false;
  }
  // Print the message without VTK's "ERROR: In file, line" header (ctest fails on it).
  std::string message;
  if (!outcome.Errors.empty())
  {
    message = outcome.Errors.front();
    const size_t at = message.find("): ");
    message = ": " + (at == std::string::npos ? message : message.substr(at + 3));
  }
  std::printf("%-28s %s%s\n", what, ok ? "ok" : "FAILED", message.c_str());
  return ok;
}
}

int TestBadInput(int, char*[])
{
  bool ok = true;
  ok = Expect("no input", RenderBad(nullptr), "no input volume", false) && ok;
  ok = Expect("empty image", RenderBad(Image(0, 0, 0, VTK_VOID)), "empty", false) && ok;
  ok = Expect("zero extent (N x N x 1)", RenderBad(Image(8, 8, 1, VTK_UNSIGNED_CHAR)),
         "zero extent along z", false) && ok;
  {
    auto cells = Image(8, 8, 8, VTK_VOID);
    vtkNew<vtkFloatArray> values;
    values->SetNumberOfTuples(cells->GetNumberOfCells());
    values->FillValue(1.0f);
    cells->GetCellData()->SetScalars(values);
    ok = Expect("cell scalars only", RenderBad(cells), "vtkCellDataToPointData", false) && ok;
  }
  ok = Expect("three components", RenderBad(Image(8, 8, 8, VTK_UNSIGNED_CHAR, 3)),
         "3 components", false) && ok;
  ok = Expect("int scalars", RenderBad(Image(8, 8, 8, VTK_INT)), "scalar type int", false) && ok;
  ok = Expect("double scalars", RenderBad(Image(8, 8, 8, VTK_DOUBLE)), "scalar type double",
         false) && ok;
  ok = Expect("beyond 3D texture limit", RenderBad(Image(20000, 2, 2, VTK_UNSIGNED_CHAR)),
         "3D texture limit", false) && ok;

  auto nonFinite = Image(8, 8, 8, VTK_FLOAT);
  auto* values = static_cast<float*>(nonFinite->GetScalarPointer());
  values[0] = std::numeric_limits<float>::quiet_NaN();
  values[1] = std::numeric_limits<float>::infinity();
  values[2] = -std::numeric_limits<float>::infinity();
  ok = Expect("NaN and Inf samples", RenderBad(nonFinite), "1 NaN, 1 +Inf and 1 -Inf", false) && ok;
  const Outcome replaced = RenderBad(nonFinite, true);
  ok = Expect("NaN and Inf, replaced", replaced, "", true) && ok;
  if (replaced.Warnings.size() != 1 || replaced.Warnings[0].find("3 non-finite") == std::string::npos)
  {
    std::printf("NaN and Inf, replaced: expected one warning about 3 non-finite samples\n");
    ok = false;
  }
  // A good volume after all that still renders (the control).
  ok = Expect("valid volume (control)", RenderBad(Image(8, 8, 8, VTK_UNSIGNED_CHAR)), "", true) && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
