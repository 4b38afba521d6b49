// Gradient opacity (vtkVolumeProperty::SetGradientOpacity), drawn as VTK's mapper draws it and
// cast into every shadow technique.
//
// 1. The comparison volume (unsigned char, and a float copy spanning 40..160) with a gradient
//    opacity that clears flat regions, shaded, drawn by our mapper and by VTK's in one run,
//    within a tolerance calibrated on VTK against itself (0.8x and 1.25x its sample distance,
//    jittered): 1.5 times that, at least RMSE 0.007 and 1% of pixels beyond 8/255. Ours
//    without the gradient opacity must fail it; the GPU picture must match its CPU twin.
// 2. The shadow scene (a dense ball over a plate, a ground mesh below) with a gradient
//    opacity that clears the flat insides and leaves a faint trace of the rims: the ground's
//    darkest point (in the plate's shadow) gets more light than without it; every technique's
//    picture matches its CPU twin with the insides cleared and the rims kept.
#include "DeepShadowTestUtilities.h"
#include "vtkDeepShadowPass.h"
#include "vtkDeepShadowPolyDataMapper.h"

#include "vtkActor.h"
#include "vtkGPUVolumeRayCastMapper.h"

#include <algorithm>

using deepshadow::testing::Check;
using deepshadow::testing::Grab;
using deepshadow::testing::WithinTolerance;

namespace
{
// 0 where the scalar is flat, 1 from `full` (data units per mean spacing) up.
vtkSmartPointer<vtkPiecewiseFunction> ClearFlat(double full)
{
  auto gradient = vtkSmartPointer<vtkPiecewiseFunction>::New();
  gradient->AddPoint(0.0, 0.0);
  gradient->AddPoint(0.1 * full, 0.0);
  gradient->AddPoint(full, 1.0);
  return gradient;
}

using Drawn = deepshadow::testing::ComparisonPicture;

Drawn Draw(vtkRenderWindow* window, vtkImageData* data, bool vtks, bool gradientOpacity, float step = 0.5f,
  bool jitter = false)
{
  deepshadow::testing::ComparisonMappers mappers;
  vtkGPUVolumeRayCastMapper* mapper = mappers.Pick(vtks, step, jitter);
  double range[2];
  data->GetScalarRange(range);
  const double span = (range[1] - range[0]) / 255.0;
  vtkSmartPointer<vtkVolumeProperty> property = deepshadow::testing::MakeComparisonProperty(true);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(range[0], 0.0, 0.0, 0.0);
  color->AddRGBPoint(range[0] + 60 * span, 1.0, 0.5, 0.2);
  color->AddRGBPoint(range[1], 0.9, 0.9, 1.0);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(range[0], 0.0);
  opacity->AddPoint(range[0] + 20 * span, 0.0);
  opacity->AddPoint(range[1], 0.6);
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  if (gradientOpacity)
  {
    // Magnitudes are in data units: the same look per normalized scalar on either range.
    property->SetGradientOpacity(ClearFlat(60.0 * span));
  }
  return deepshadow::testing::DrawForComparison(window, mapper, data, property, { 0.1, 0.1, 0.15 }, !vtks);
}

bool MatchesVTK(vtkRenderWindow* window, vtkImageData* data, const std::string& what)
{
  bool ok = true;
  const Drawn ours = Draw(window, data, false, true);
  const Drawn vtks = Draw(window, data, true, true);
  const deepshadow::testing::VTKTolerance tolerance = deepshadow::testing::CalibrateOnVTK(
    what, vtks.Picture, [&](float scale, bool jitter) { return Draw(window, data, true, true, 0.5f * scale, jitter).Picture; });
  const double maxRMSE = tolerance.MaxRMSE;
  const double maxFraction = tolerance.MaxFraction;
  ok = WithinTolerance(what.c_str(), ours.Picture, vtks.Picture, maxRMSE, 8.0 / 255.0, maxFraction) && ok;
  ok = WithinTolerance((what + " vs CPU twin").c_str(), ours.Picture, ours.Twin, 1.5 / 255.0, 8.0 / 255.0, 0.005) && ok;
  const Drawn without = Draw(window, data, false, false);
  ok = !WithinTolerance((what + ", ours without it (must fail)").c_str(), without.Picture, vtks.Picture,
         maxRMSE, 8.0 / 255.0, maxFraction) && ok;
  return ok;
}
}

int TestGradientOpacity(int, char*[])
{
  bool ok = true;
  {
    vtkNew<vtkDeepShadowRenderWindow> window;
    window->SetSize(200, 200);
    ok = MatchesVTK(window, deepshadow::testing::MakeTestVolume(VTK_UNSIGNED_CHAR), "gradient opacity, unsigned char") && ok;
    ok = MatchesVTK(window, deepshadow::testing::MakeTestVolume(VTK_FLOAT, 48, 120.0, 40.0),
           "gradient opacity, float 40..160") && ok;
  }

  // Shadows: flat insides cleared, rims (magnitudes 45-50, a quarter of the range at most)
  // kept at 5 %; a ground mesh under the ball shows its shadow term.
  deepshadow::testing::ShadowScene scene;
  vtkNew<vtkDeepShadowPass> pass;
  scene.Renderer->SetPass(pass);
  vtkNew<vtkDeepShadowPolyDataMapper> groundMapper;
  groundMapper->SetOutputModeToShadowTerm();
  vtkNew<vtkActor> ground;
  scene.AddGround(groundMapper, ground);
  scene.Renderer->ResetCameraClippingRange();
  vtkSmartPointer<vtkDeepShadowTechnique> dsm = vtkDeepShadowTechniqueFactory::New("dsm");
  scene.Mapper->SetShadowTechnique(dsm);
  scene.Window->Render();
  const deepshadow::Image plain = Grab(scene.Window);
  const int builds = dsm->GetBuildCount();
  vtkNew<vtkPiecewiseFunction> faint;
  faint->AddPoint(0.0, 0.0);
  faint->AddPoint(40.0, 0.0);
  faint->AddPoint(50.0, 0.05);
  scene.Property->SetGradientOpacity(faint);
  scene.Window->Render();
  const deepshadow::Image cleared = Grab(scene.Window);
  ok = Check("a gradient opacity set: the deep shadow map rebuilt", dsm->GetBuildCount() == builds + 1) && ok;
  ok = Check("composed with GradientOpacity", deepshadow::testing::HasFeature(scene.Mapper, "GradientOpacity")) && ok;
  // Left out where it is not used: no gradient-opacity or opacity-factor code without it.
  const std::string withSource = scene.Mapper->GetFragmentShaderSource();
  scene.Property->SetDisableGradientOpacity(1);
  scene.Window->Render();
  const std::string withoutSource = scene.Mapper->GetFragmentShaderSource();
  scene.Property->SetDisableGradientOpacity(0);
  ok = Check("its code composed only while it is used",
         withSource.find("g_opacityScale") != std::string::npos &&
           withoutSource.find("g_opacityScale") == std::string::npos &&
           withoutSource.find("gradientOpacity(") == std::string::npos) && ok;
  // The ground's darkest pixel without it (under the plate) gets more light with it.
  int darkest = -1;
  double darkestTerm = 2.0;
  for (int y = 0; y < plain.Height; ++y)
    for (int x = 0; x < plain.Width; ++x)
    {
      const glm::dvec3 c = plain.At(x, y);
      // Ground pixels are grey (the volume's term is composited over its own colours).
      if (std::abs(c.x - c.z) < 1.0 / 255.0 && c.x > 0.0 && c.x < darkestTerm)
      {
        darkestTerm = c.x;
        darkest = x + plain.Width * y;
      }
    }
  const double clearedTerm = darkest >= 0 ? cleared.At(darkest % plain.Width, darkest / plain.Width).x : 0.0;
  std::printf("the ground's darkest term without gradient opacity %.3f, with it %.3f\n", darkestTerm, clearedTerm);
  if (const char* directory = std::getenv("DEEPSHADOW_TEST_IMAGES"))
  {
    deepshadow::WritePNG(plain, std::string(directory) + "/gradient-opacity-term-without.png");
    deepshadow::WritePNG(cleared, std::string(directory) + "/gradient-opacity-term-with.png");
  }
  ok = Check("what the gradient opacity clears casts nothing: more light on the ground",
         darkest >= 0 && clearedTerm > darkestTerm + 0.2) && ok;

  // The twins compared on a picture with something in it: flat insides cleared, rims kept.
  groundMapper->SetOutputModeToColor();
  scene.Property->SetGradientOpacity(ClearFlat(40.0));
  ok = scene.AllMatchTwins("gradient opacity") && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
