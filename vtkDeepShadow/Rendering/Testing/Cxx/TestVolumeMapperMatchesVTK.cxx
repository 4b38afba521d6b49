// vtkDeepShadowVolumeMapper against VTK's own vtkGPUVolumeRayCastMapper on the same scene,
// transfer functions, lights and sample distance.
//
// Stated tolerances (8-bit images in [0, 1]; measured values are printed):
// - emission/absorption: RMSE <= 0.005 and <= 1% of pixels off by more than 8/255;
// - Phong-shaded with the headlight: RMSE <= 0.006, <= 0.5% of pixels off by more than 16/255;
// - with an opaque sphere inside: same as shaded.
// Each must catch a density 1.5 times too high (checked: the control renders ours so and
// must fail). The shaded bounds were 0.01 and 2 %, which let that error pass with the sphere
// (RMSE 0.0093, 1.05 %), then 0.007, which VTK 9.3's headlight let pass without it (0.0069);
// measured now (VTK 9.1 and 9.3 alike): 0.0016 and 0.0045, 0.18 % at most; the controls
// 0.0069-0.0074.
// Why they are not zero: VTK puts the first sample one full step past the entry (we use the
// middle of the step), looks opacity up in a 1024-texel table whose texel centres are offset
// by half a texel (ours: 4096, centred), and lights a headlight as a point at the camera
// (ours: VTK's light semantics, a directional light).
#include "DeepShadowTestUtilities.h"
#include "vtkDeepShadowRenderWindow.h"
#include "vtkDeepShadowVolumeMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkSphereSource.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

using deepshadow::testing::Grab;
using deepshadow::testing::WithinTolerance;

namespace
{
struct Case
{
  const char* Name;
  bool Shade;
  bool Sphere;
  double MaxRMSE;
  double Threshold;
  double MaxFraction;
  bool LockToSpacing = false; // both: LockSampleDistanceToInputSpacing, SampleDistance ignored
  double Scale = 1.0;         // the vtkVolume's (uniform) scale
  double ControlDensity = 1.5; // the control's density factor (must fail)
};
}

int TestVolumeMapperMatchesVTK(int argc, char* argv[])
{
  auto volumeData = deepshadow::testing::MakeTestVolume(VTK_UNSIGNED_CHAR);
  vtkSmartPointer<vtkVolumeProperty> property = deepshadow::testing::MakeComparisonProperty(false);

  const Case cases[] = {
    { "emission-absorption", false, false, 0.005, 8.0 / 255.0, 0.01 },
    { "emission-absorption, sample distance locked to the spacing", false, false, 0.005,
      8.0 / 255.0, 0.01, true },
    // Opacity per dataset unit, as VTK's mapper integrates it; the control, density x3, is
    // ours integrating per world unit.
    { "emission-absorption, a prop scaled 3 times", false, false, 0.005, 8.0 / 255.0, 0.01, false,
      3.0, 3.0 },
    { "shaded", true, false, 0.006, 16.0 / 255.0, 0.005 },
    { "shaded, opaque sphere inside", true, true, 0.006, 16.0 / 255.0, 0.005 },
  };
  const double sampleDistance = 0.5;
  bool ok = true;
  vtkNew<vtkDeepShadowRenderWindow> window;
  window->SetSize(240, 240);
  // The control: ours with the density ControlDensity times too high (the opacity unit
  // distance divided by it) must fall outside each tolerance, or the tolerance would not catch
  // that error.
  vtkNew<vtkVolumeProperty> denser;
  for (const Case& c : cases)
  {
    property->SetShade(c.Shade);
    denser->DeepCopy(property);
    denser->SetScalarOpacityUnitDistance(property->GetScalarOpacityUnitDistance() / c.ControlDensity);
    deepshadow::Image images[3];
    for (int which = 0; which < 3; ++which)
    {
      vtkNew<vtkRenderer> renderer;
      renderer->SetBackground(0.1, 0.1, 0.2);
      window->GetRenderers()->RemoveAllItems();
      window->AddRenderer(renderer);
      vtkNew<vtkDeepShadowVolumeMapper> ours;
      ours->SetSampleDistance(sampleDistance);
      vtkNew<vtkGPUVolumeRayCastMapper> theirs;
      theirs->SetAutoAdjustSampleDistances(0);
      theirs->SetSampleDistance(sampleDistance);
      for (vtkGPUVolumeRayCastMapper* m : { static_cast<vtkGPUVolumeRayCastMapper*>(ours), theirs.Get() })
      {
        m->SetLockSampleDistanceToInputSpacing(c.LockToSpacing);
        m->SetSampleDistance(c.LockToSpacing ? 3.0f : m->GetSampleDistance());
      }
      vtkVolumeMapper* mapper = which == 1 ? static_cast<vtkVolumeMapper*>(theirs)
                                           : static_cast<vtkVolumeMapper*>(ours);
      mapper->SetInputData(volumeData);
      vtkNew<vtkVolume> volume;
      volume->SetMapper(mapper);
      volume->SetProperty(which == 2 ? denser.Get() : property.Get());
      volume->SetScale(c.Scale);
      renderer->AddVolume(volume);
      vtkNew<vtkSphereSource> sphere;
      sphere->SetRadius(10.0);
      sphere->SetCenter(0.0, 0.0, 12.0);
      sphere->SetThetaResolution(48);
      sphere->SetPhiResolution(48);
      vtkNew<vtkPolyDataMapper> sphereMapper;
      sphereMapper->SetInputConnection(sphere->GetOutputPort());
      vtkNew<vtkActor> actor;
      actor->SetMapper(sphereMapper);
      if (c.Sphere)
      {
        renderer->AddActor(actor);
      }
      deepshadow::testing::ApplyComparisonView(renderer);
      window->Render();
      images[which] = Grab(window);
      if (which == 0 && !ours->GetLastError().empty())
      {
        std::printf("%s\n", ours->GetLastError().c_str());
        return EXIT_FAILURE;
      }
    }
    ok = WithinTolerance(c.Name, images[0], images[1], c.MaxRMSE, c.Threshold, c.MaxFraction) && ok;
    const std::string control =
      std::string(c.Name) + ", density x" + std::to_string(c.ControlDensity).substr(0, 3) + " (must fail)";
    ok = !WithinTolerance(control.c_str(), images[2], images[1], c.MaxRMSE, c.Threshold, c.MaxFraction) && ok;
    ok = ok && deepshadow::testing::CoveredFraction(images[0], { 0.1, 0.1, 0.2 }) > 0.1;
  }

  // The last picture (ours: shaded, with the sphere) against the baseline.
  vtkRenderer* renderer = window->GetRenderers()->GetFirstRenderer();
  vtkVolume* volume = vtkVolume::SafeDownCast(renderer->GetVolumes()->GetItemAsObject(0));
  vtkNew<vtkDeepShadowVolumeMapper> ours;
  ours->SetSampleDistance(sampleDistance);
  ours->SetInputData(volumeData);
  volume->SetMapper(ours);
  volume->SetProperty(property); // not the control's
  window->Render();
  const int result = deepshadow::testing::RegressionTestImage(window, argc, argv);
  return ok && result != vtkTesting::FAILED ? EXIT_SUCCESS : EXIT_FAILURE;
}
