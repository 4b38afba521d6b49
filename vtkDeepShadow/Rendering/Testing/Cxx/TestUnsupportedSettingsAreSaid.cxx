// What VTK's GPU mapper honours and ours does not draw yet is never silent: each setting is
// one warning naming it and what is drawn instead, said once over several frames, listed in
// GetUnsupportedSettings(); and a plain scene says nothing. The mapper is a
// vtkGPUVolumeRayCastMapper: its settings (masks, sampling, window/level...) compile and are
// said too.
#include "DeepShadowTestUtilities.h"

#include "vtkCellData.h"
#include "vtkDeepShadowDeepShadowMapTechnique.h"
#include "vtkDeepShadowRenderWindow.h"
#include "vtkDeepShadowVolumeMapper.h"

#include "vtkColorTransferFunction.h"
#include "vtkContourValues.h"
#include "vtkPiecewiseFunction.h"
#include "vtkTrivialProducer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <functional>

using deepshadow::testing::MessageCapture;

namespace
{
// Renders the test volume three frames with `change` applied; returns the warnings heard and
// what the mapper lists.
std::pair<std::vector<std::string>, std::vector<std::string>> Render(
  const std::function<void(vtkDeepShadowVolumeMapper*, vtkVolumeProperty*)>& change)
{
  vtkNew<vtkDeepShadowRenderWindow> window;
  window->SetSize(48, 48);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkNew<vtkDeepShadowVolumeMapper> mapper;
  mapper->SetInputData(deepshadow::testing::MakeTestVolume(VTK_UNSIGNED_CHAR));
  vtkNew<MessageCapture> capture;
  capture->Watch(mapper);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(255.0, 0.5);
  vtkNew<vtkVolumeProperty> property;
  property->SetScalarOpacity(opacity);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  renderer->AddVolume(volume);
  change(mapper, property);
  renderer->ResetCamera();
  for (int frame = 0; frame < 3; ++frame)
  {
    window->Render();
  }
  return { capture->Warnings, mapper->GetUnsupportedSettings() };
}

bool Says(const std::vector<std::string>& lines, const std::string& needle)
{
  for (const auto& line : lines)
  {
    if (line.find(needle) != std::string::npos)
    {
      return true;
    }
  }
  return false;
}
}

int TestUnsupportedSettingsAreSaid(int, char*[])
{
  bool ok = true;
  const auto plain = Render([](vtkDeepShadowVolumeMapper*, vtkVolumeProperty*) {});
  if (!plain.first.empty() || !plain.second.empty())
  {
    std::printf("a plain scene said: %s\n", plain.first.empty() ? plain.second[0].c_str() : plain.first[0].c_str());
    ok = false;
  }

  struct Case
  {
    const char* Name;
    const char* Needle;
    std::function<void(vtkDeepShadowVolumeMapper*, vtkVolumeProperty*)> Change;
  };
  const std::vector<Case> cases = {
    { "MIP with shadows", "shadows do not apply to maximum intensity projection",
      [](vtkDeepShadowVolumeMapper* m, vtkVolumeProperty*) {
        vtkNew<vtkDeepShadowDeepShadowMapTechnique> dsm;
        m->SetShadowTechnique(dsm);
        m->SetBlendModeToMaximumIntensity();
      } },
    { "isosurface without contour values", "isosurface blending without contour values",
      [](vtkDeepShadowVolumeMapper* m, vtkVolumeProperty* p) {
        m->SetBlendModeToIsoSurface();
        p->GetIsoSurfaceValues()->SetNumberOfContours(0); // VTK's default is one, at 0
      } },
    { "isosurface with 17 contour values", "the lowest 16 of 17 are drawn",
      [](vtkDeepShadowVolumeMapper* m, vtkVolumeProperty* p) {
        m->SetBlendModeToIsoSurface();
        p->GetIsoSurfaceValues()->GenerateValues(17, 10.0, 200.0);
      } },
    { "2D transfer function under MIP", "2D transfer functions apply to composite blending",
      [](vtkDeepShadowVolumeMapper* m, vtkVolumeProperty* p) {
        p->SetTransferFunctionMode(vtkVolumeProperty::TF_2D);
        m->SetBlendModeToMaximumIntensity();
      } },
    { "label-map mask without labels", "without label functions",
      [](vtkDeepShadowVolumeMapper* m, vtkVolumeProperty*) {
        m->SetMaskInput(deepshadow::testing::MakeTestVolume(VTK_UNSIGNED_CHAR));
        m->SetMaskTypeToLabelMap();
      } },
    { "label gradient opacity", "label gradient opacity",
      [](vtkDeepShadowVolumeMapper* m, vtkVolumeProperty* p) {
        m->SetMaskInput(deepshadow::testing::MakeTestVolume(VTK_UNSIGNED_CHAR));
        m->SetMaskTypeToLabelMap();
        vtkNew<vtkPiecewiseFunction> opacity;
        opacity->AddPoint(0.0, 1.0);
        p->SetLabelScalarOpacity(1, opacity);
        p->SetLabelGradientOpacity(1, opacity);
      } },
    { "mask of other dimensions", "the mask's dimensions 40x40x40 differ from the volume's 48x48x48",
      [](vtkDeepShadowVolumeMapper* m, vtkVolumeProperty*) {
        m->SetMaskInput(deepshadow::testing::MakeTestVolume(VTK_UNSIGNED_CHAR, 40));
        m->SetMaskTypeToBinary();
      } },
    { "mask over cell scalars", "masks are not drawn over cell scalars",
      [](vtkDeepShadowVolumeMapper* m, vtkVolumeProperty*) {
        auto cells = vtkSmartPointer<vtkImageData>::New();
        cells->SetDimensions(49, 49, 49);
        cells->GetCellData()->SetScalars(deepshadow::testing::MakeTestVolume(VTK_UNSIGNED_CHAR)->GetPointData()->GetScalars());
        m->SetInputData(cells);
        m->SetMaskInput(deepshadow::testing::MakeTestVolume(VTK_UNSIGNED_CHAR));
        m->SetMaskTypeToBinary();
      } },
    { "label map under MIP", "a label map colours composite blending only",
      [](vtkDeepShadowVolumeMapper* m, vtkVolumeProperty* p) {
        m->SetMaskInput(deepshadow::testing::MakeTestVolume(VTK_UNSIGNED_CHAR));
        m->SetMaskTypeToLabelMap();
        vtkNew<vtkPiecewiseFunction> opacity;
        opacity->AddPoint(0.0, 1.0);
        p->SetLabelScalarOpacity(1, opacity);
        m->SetBlendModeToMaximumIntensity();
      } },
    { "mask under isosurface blending", "masks apply to composite blending and projections only",
      [](vtkDeepShadowVolumeMapper* m, vtkVolumeProperty* p) {
        m->SetMaskInput(deepshadow::testing::MakeTestVolume(VTK_UNSIGNED_CHAR));
        m->SetMaskTypeToBinary();
        p->GetIsoSurfaceValues()->SetValue(0, 100.0);
        m->SetBlendModeToIsoSurface();
      } },
    { "image sample distance", "image sample distance 2",
      [](vtkDeepShadowVolumeMapper* m, vtkVolumeProperty*) { m->SetImageSampleDistance(2.0f); } },
    { "final colour level", "final colour window/level",
      [](vtkDeepShadowVolumeMapper* m, vtkVolumeProperty*) { m->SetFinalColorLevel(0.7f); } },
    { "render to image", "RenderToImage",
      [](vtkDeepShadowVolumeMapper* m, vtkVolumeProperty*) { m->RenderToImageOn(); } },
    { "depth pass", "UseDepthPass",
      [](vtkDeepShadowVolumeMapper* m, vtkVolumeProperty*) { m->UseDepthPassOn(); } },
    { "second input volume", "input ports 1 and up",
      [](vtkDeepShadowVolumeMapper* m, vtkVolumeProperty*) {
        vtkNew<vtkTrivialProducer> second;
        second->SetOutput(deepshadow::testing::MakeTestVolume(VTK_UNSIGNED_CHAR));
        m->SetInputConnection(1, second->GetOutputPort());
      } },
  };
  for (const Case& c : cases)
  {
    const auto heard = Render(c.Change);
    const bool once = heard.first.size() == 1 && Says(heard.first, c.Needle);
    const bool listed = heard.second.size() == 1 && Says(heard.second, c.Needle);
    std::printf("%-22s %s: %s\n", c.Name, once && listed ? "said once" : "NOT said as it should",
      heard.first.empty() ? "(nothing)" : heard.first[0].c_str());
    ok = ok && once && listed;
  }
  // A gradient opacity that changes nothing (all ones) is not a setting to warn about.
  const auto ones = Render([](vtkDeepShadowVolumeMapper*, vtkVolumeProperty* p) {
    vtkNew<vtkPiecewiseFunction> gradient;
    gradient->AddPoint(0.0, 1.0);
    gradient->AddPoint(50.0, 1.0);
    p->SetGradientOpacity(gradient);
  });
  ok = ok && ones.first.empty();
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
