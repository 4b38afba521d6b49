// Our mapper in place of VTK's: code written for vtkGPUVolumeRayCastMapper compiles and runs
// on vtkDeepShadowVolumeMapper unchanged (sampling, jitter, masks, memory, reduction), and
// vtkDeepShadowVolumeMapperFactory::Override makes vtkGPUVolumeRayCastMapper::New() - so
// vtkSmartVolumeMapper - draw with our mapper: with deep shadows (darker where the light is
// blocked), or without shadows as VTK draws; Restore() gives VTK's mapper back.
// AutoAdjustSampleDistances steps coarser while moving and keeps the shadows. With
// "--environment" (ctest sets VTK_DEEPSHADOW_VOLUME_MAPPER=cssm) the override is on from
// the start.
#include "DeepShadowTestUtilities.h"
#include "vtkDeepShadowStochasticShadowMapTechnique.h"
#include "vtkDeepShadowDeepShadowMapTechnique.h"
#include "vtkDeepShadowVolumeMapperFactory.h"

#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkSmartVolumeMapper.h"

#include <cstring>

using deepshadow::testing::Check;

namespace
{
// Written for VTK's mapper: its sampling, jitter, mask, memory and reduction API.
void ConfigureAsForVTK(vtkGPUVolumeRayCastMapper* mapper, vtkImageData* mask)
{
  mapper->SetAutoAdjustSampleDistances(0);
  mapper->SetLockSampleDistanceToInputSpacing(0);
  mapper->SetSampleDistance(0.02f);
  mapper->SetImageSampleDistance(1.0f);
  mapper->SetMinimumImageSampleDistance(1.0f);
  mapper->SetMaximumImageSampleDistance(10.0f);
  mapper->SetUseJittering(0);
  mapper->SetMaxMemoryInBytes(256 * 1024 * 1024);
  mapper->SetMaxMemoryFraction(0.75f);
  mapper->SetMaskTypeToBinary();
  mapper->SetMaskBlendFactor(1.0f);
  mapper->SetMaskInput(mask);
  mapper->SetMaskInput(nullptr);
  double ratio[3];
  mapper->GetReductionRatio(ratio);
}

// Drawn by a vtkSmartVolumeMapper (which makes its GPU mapper with
// vtkGPUVolumeRayCastMapper::New()): the shadow test scene, or (`asCompared`)
// TestVolumeMapperMatchesVTK's shaded volume under the headlight, where our mapper without
// shadows matches VTK's.
deepshadow::Image DrawSmart(bool asCompared, int& renderMode)
{
  deepshadow::testing::ShadowScene scene;
  vtkNew<vtkSmartVolumeMapper> smart;
  smart->SetInputData(scene.Data);
  if (asCompared)
  {
    smart->SetInputData(deepshadow::testing::MakeTestVolume(VTK_UNSIGNED_CHAR));
    scene.Volume->SetProperty(deepshadow::testing::MakeComparisonProperty(true));
    scene.Renderer->RemoveAllLights();
    scene.Renderer->ResetCamera();
  }
  scene.Volume->SetMapper(smart);
  scene.Window->Render();
  renderMode = smart->GetLastUsedRenderMode();
  return deepshadow::testing::Grab(scene.Window);
}

double Mean(const deepshadow::Image& image)
{
  double sum = 0.0;
  for (double v : image.RGB)
  {
    sum += v;
  }
  return image.RGB.empty() ? 0.0 : sum / static_cast<double>(image.RGB.size());
}

bool MadeByNew(const char* className)
{
  vtkSmartPointer<vtkGPUVolumeRayCastMapper> made;
  made.TakeReference(vtkGPUVolumeRayCastMapper::New());
  return made->IsA(className) != 0;
}
}

int TestVolumeMapperDropIn(int argc, char* argv[])
{
  bool ok = true;
  if (argc > 1 && std::strcmp(argv[1], "--environment") == 0)
  {
    vtkSmartPointer<vtkGPUVolumeRayCastMapper> made;
    made.TakeReference(vtkGPUVolumeRayCastMapper::New());
    auto* ours = vtkDeepShadowVolumeMapper::SafeDownCast(made);
    ok = Check("VTK_DEEPSHADOW_VOLUME_MAPPER=cssm: overriding with cssm",
           vtkDeepShadowVolumeMapperFactory::IsOverriding() &&
             std::strcmp(vtkDeepShadowVolumeMapperFactory::GetTechnique(), "cssm") == 0) && ok;
    ok = Check("  and New() makes ours with a CSSM",
           ours && vtkDeepShadowStochasticShadowMapTechnique::SafeDownCast(ours->GetShadowTechnique())) && ok;
    return ok ? EXIT_SUCCESS : EXIT_FAILURE;
  }

  // 1. VTK's API on our mapper: compiles, runs, draws.
  {
    deepshadow::testing::ShadowScene scene;
    ConfigureAsForVTK(scene.Mapper, scene.Data);
    scene.Window->Render();
    const double covered =
      deepshadow::testing::CoveredFraction(deepshadow::testing::Grab(scene.Window), { 0.05, 0.05, 0.08 });
    ok = Check("VTK's mapper API on ours: drawn, " + std::to_string(covered).substr(0, 4) + " covered",
           scene.Mapper->GetLastError().empty() && covered > 0.05 &&
             scene.Mapper->GetUnsupportedSettings().empty()) && ok;
  }

  // 1b. AutoAdjustSampleDistances: coarser view rays while the interactor moves, the deep
  // shadow map kept (not rebuilt), and the still picture back exactly when it stops. Twice
  // the step on this hard-edged scene: RMSE 0.038 against the still frame (banding on the
  // plate; the shadows unchanged); bound at 0.06.
  {
    deepshadow::testing::ShadowScene scene;
    vtkNew<vtkDeepShadowDeepShadowMapTechnique> dsm;
    scene.Mapper->SetShadowTechnique(dsm);
    scene.Mapper->AutoAdjustSampleDistancesOn();
    scene.Window->SetDesiredUpdateRate(0.0001); // still
    scene.Window->Render();
    const deepshadow::Image still = deepshadow::testing::Grab(scene.Window);
    const double stillStep = scene.Mapper->GetEffectiveSampleDistance();
    const int builds = scene.Mapper->GetShadowBuilds();
    scene.Window->SetDesiredUpdateRate(15.0); // what an interactor asks for while moving
    scene.Window->Render();
    const deepshadow::Image moving = deepshadow::testing::Grab(scene.Window);
    const double movingStep = scene.Mapper->GetEffectiveSampleDistance();
    const int movingBuilds = scene.Mapper->GetShadowBuilds();
    scene.Window->SetDesiredUpdateRate(0.0001);
    scene.Window->Render();
    const deepshadow::Image stillAgain = deepshadow::testing::Grab(scene.Window);
    const deepshadow::ImageDifference d = deepshadow::Compare(moving, still);
    if (const char* directory = std::getenv("DEEPSHADOW_TEST_IMAGES"))
    {
      WritePNG(moving, std::string(directory) + "/auto-adjusted-moving.png");
      WritePNG(still, std::string(directory) + "/auto-adjusted-still.png");
    }
    ok = Check("auto-adjusted: step " + std::to_string(stillStep).substr(0, 5) + " still, " +
             std::to_string(movingStep).substr(0, 5) + " moving, shadows built " +
             std::to_string(builds) + " then " + std::to_string(movingBuilds - builds) +
             " more, moving RMSE " + std::to_string(d.RMSE).substr(0, 7),
           movingStep == 2.0 * stillStep && movingBuilds == builds && scene.Mapper->GetShadowBuilds() == builds &&
             d.RMSE > 0.0 && d.RMSE < 0.06 && scene.Mapper->GetUnsupportedSettings().empty() &&
             deepshadow::Compare(stillAgain, still).MaxAbs == 0.0) && ok;
    scene.Mapper->AutoAdjustSampleDistancesOff();
    scene.Window->SetDesiredUpdateRate(15.0);
    scene.Window->Render();
    ok = Check("  off: the step stays while moving", scene.Mapper->GetEffectiveSampleDistance() == stillStep) && ok;
  }

  // 2. Without the override: VTK's mapper.
  ok = Check("before Override(): New() makes VTK's mapper",
         !vtkDeepShadowVolumeMapperFactory::IsOverriding() && !MadeByNew("vtkDeepShadowVolumeMapper")) && ok;
  int mode = -1;
  const deepshadow::Image vtks = DrawSmart(true, mode);
  ok = Check("vtkSmartVolumeMapper chose its GPU mapper", mode == vtkSmartVolumeMapper::GPURenderMode) && ok;

  // 3. Override("none"): ours without shadows draws what VTK's mapper draws (its sample
  // distance locked to the spacing by vtkSmartVolumeMapper, as VTK's).
  ok = Check("Override(\"none\"): New() makes ours",
         vtkDeepShadowVolumeMapperFactory::Override("none") && MadeByNew("vtkDeepShadowVolumeMapper")) && ok;
  const deepshadow::Image plain = DrawSmart(true, mode);
  ok = deepshadow::testing::WithinTolerance(
         "  ours without shadows, as VTK's mapper", plain, vtks, 0.007, 16.0 / 255.0, 0.005) && ok;
  const deepshadow::Image unshadowed = DrawSmart(false, mode);

  // 4. Override("dsm"): ours, with deep shadows: darker where the light is blocked.
  ok = Check("Override(\"dsm\")", vtkDeepShadowVolumeMapperFactory::Override("dsm")) && ok;
  {
    vtkSmartPointer<vtkGPUVolumeRayCastMapper> made;
    made.TakeReference(vtkGPUVolumeRayCastMapper::New());
    auto* ours = vtkDeepShadowVolumeMapper::SafeDownCast(made);
    ok = Check("  New() makes ours with a deep shadow map",
           ours && vtkDeepShadowDeepShadowMapTechnique::SafeDownCast(ours->GetShadowTechnique())) && ok;
  }
  const deepshadow::Image shadowed = DrawSmart(false, mode);
  const double darker = Mean(shadowed) / Mean(unshadowed);
  ok = Check("  vtkSmartVolumeMapper draws ours with shadows (mean " +
           std::to_string(darker).substr(0, 5) + " of the unshadowed)",
         mode == vtkSmartVolumeMapper::GPURenderMode && darker < 0.95 && darker > 0.3) && ok;
  ok = !deepshadow::testing::WithinTolerance("  shadowed as unshadowed (must fail)", shadowed,
         unshadowed, 0.007, 16.0 / 255.0, 0.005) && ok;

  // 5. An unknown technique changes nothing; Restore() gives VTK's mapper back.
  vtkDeepShadowVolumeMapperFactory::Restore();
  ok = Check("Restore(): New() makes VTK's mapper again",
         !vtkDeepShadowVolumeMapperFactory::IsOverriding() &&
           MadeByNew("vtkOpenGLGPUVolumeRayCastMapper")) && ok;
  vtkObject::GlobalWarningDisplayOff();
  const bool refused = !vtkDeepShadowVolumeMapperFactory::Override("no-such-technique");
  vtkObject::GlobalWarningDisplayOn();
  ok = Check("Override(\"no-such-technique\") refused, nothing overridden",
         refused && !vtkDeepShadowVolumeMapperFactory::IsOverriding() &&
           !MadeByNew("vtkDeepShadowVolumeMapper")) && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
