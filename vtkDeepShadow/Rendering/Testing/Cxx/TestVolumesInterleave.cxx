// Volumes that overlap along the view ray (vtkDeepShadowPass): a green smoke puff through the
// shadow scene's ball and pillar, and a translucent glass plane inside the smoke. The second
// volume is drawn into segments that the first merges into its march with the glass's layer,
// in either order of the volumes in the renderer; GPU against the CPU twin within the stated
// tolerances, and closer to the exact interleaving than blending the volumes in the
// renderer's order (VolumeSegments 0, what VTK does).
//
// Stated tolerances (GPU vs CPU twin), as TestHybridShadows: RMSE <= 2/255, at most 1% of
// pixels beyond 12/255.
#include "DeepShadowTestUtilities.h"
#include "vtkDeepShadowPass.h"
#include "vtkDeepShadowPolyDataMapper.h"

#include "vtkActor.h"
#include "vtkPlaneSource.h"
#include "vtkProperty.h"

#include <cstdlib>

using deepshadow::testing::Check;
using deepshadow::testing::Grab;
using deepshadow::testing::HasFeature;
using deepshadow::testing::Reference;
using deepshadow::testing::WithinTolerance;

int TestVolumesInterleave(int argc, char* argv[])
{
  deepshadow::testing::ShadowScene scene;
  vtkDeepShadowRenderWindow* window = scene.Window;
  vtkRenderer* renderer = scene.Renderer;
  bool ok = true;
  vtkNew<vtkDeepShadowPass> pass;
  renderer->SetPass(pass);
  window->SetSize(200, 160);

  // Green smoke around the ball (the volume spans [-47, 47]^3; the ball is near x = -5, z = 10).
  vtkNew<vtkColorTransferFunction> smokeColor;
  smokeColor->AddRGBPoint(0, 0.2, 0.9, 0.3);
  smokeColor->AddRGBPoint(255, 0.4, 1.0, 0.5);
  vtkNew<vtkPiecewiseFunction> smokeOpacity;
  smokeOpacity->AddPoint(0, 0.0);
  smokeOpacity->AddPoint(20, 0.0);
  smokeOpacity->AddPoint(255, 0.35);
  vtkNew<vtkVolumeProperty> smokeProperty;
  smokeProperty->SetColor(smokeColor);
  smokeProperty->SetScalarOpacity(smokeOpacity);
  vtkNew<vtkDeepShadowVolumeMapper> smokeMapper;
  smokeMapper->SetShadingModelToBlinnPhong(); // as the scene's
  smokeMapper->SetInputData(deepshadow::testing::MakeSmokeVolume({ 0.0, 0.0, 10.0 }));
  vtkNew<vtkVolume> smoke;
  smoke->SetMapper(smokeMapper);
  smoke->SetProperty(smokeProperty);
  renderer->AddVolume(smoke);
  // One sample distance for both volumes (the CPU twin marches every volume with one).
  scene.Mapper->SetSampleDistance(1.0);
  smokeMapper->SetSampleDistance(1.0);

  // A pale red glass standing in the smoke, facing the camera.
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-30.0, 5.0, -20.0);
  plane->SetPoint1(30.0, 5.0, -20.0);
  plane->SetPoint2(-30.0, 5.0, 40.0);
  vtkNew<vtkDeepShadowPolyDataMapper> glassMapper;
  glassMapper->SetInputConnection(plane->GetOutputPort());
  vtkNew<vtkActor> glass;
  glass->SetMapper(glassMapper);
  glass->GetProperty()->SetColor(1.0, 0.5, 0.5);
  glass->GetProperty()->SetOpacity(0.4);
  renderer->AddActor(glass);
  renderer->ResetCameraClippingRange();

  window->Render();
  const deepshadow::Image merged = Grab(window);
  const deepshadow::Image exact = Reference(renderer, false);
  ok = WithinTolerance("overlapping volumes and a glass: segments", merged, Reference(renderer, true),
         2.0 / 255.0, 12.0 / 255.0, 0.01) && ok;
  ok = Check("the smoke is drawn into segments the volume merges (" +
           std::to_string(pass->GetVolumeSegmentBytes()) + " bytes)",
         pass->GetMergedVolumes() == 1 && HasFeature(smokeMapper, "VolumeSegments") &&
           HasFeature(scene.Mapper, "TranslucentLayers") &&
           pass->GetVolumeSegmentBytes() == 16LL * 200 * 160 * pass->GetVolumeSegments() &&
           smokeMapper->GetLastPasses().back() == "ray-cast-segments") && ok;
  const double mergedError = deepshadow::Compare(merged, exact).RMSE;

  // A merged volume that draws nothing (bounded by an empty region) leaves no segments of
  // an earlier frame behind: the picture is the one without it.
  vtkNew<vtkPolyData> nothing;
  smokeMapper->AddBound(nothing);
  window->Render();
  const deepshadow::Image boundedAway = Grab(window);
  smokeMapper->RemoveAllBounds();
  smoke->VisibilityOff();
  window->Render();
  const deepshadow::Image withoutSmoke = Grab(window);
  smoke->VisibilityOn();
  ok = Check("a merged volume that draws nothing leaves nothing behind",
         deepshadow::Compare(boundedAway, withoutSmoke).MaxAbs <= 1.0 / 255.0 &&
           deepshadow::Compare(boundedAway, merged).MaxAbs > 0.1) && ok;

  // In the other order the smoke merges the volume's segments (the dense ball is then cut
  // into pieces, so the picture is near the exact one, not equal to the first).
  renderer->RemoveVolume(scene.Volume);
  renderer->AddVolume(scene.Volume);
  window->Render();
  const deepshadow::Image swapped = Grab(window);
  ok = WithinTolerance("the other order against its twin", swapped, Reference(renderer, true),
         2.0 / 255.0, 12.0 / 255.0, 0.01) && ok;
  const double swappedError = deepshadow::Compare(swapped, exact).RMSE;
  renderer->RemoveVolume(smoke);
  renderer->AddVolume(smoke);

  // Blended in the renderer's order, as VTK does: further from the exact picture.
  pass->SetVolumeSegments(0);
  window->Render();
  const deepshadow::Image blended = Grab(window);
  const double blendedError = deepshadow::Compare(blended, exact).RMSE;
  std::printf("RMSE against the exact interleaving: segments %.5f (other order %.5f), blended in order %.5f\n",
    mergedError, swappedError, blendedError);
  ok = Check("segments in either order are closer to the exact interleaving than blending",
         mergedError < 0.5 * blendedError && swappedError < 0.5 * blendedError && pass->GetMergedVolumes() == 0 &&
           pass->GetVolumeSegmentBytes() == 0 && !HasFeature(smokeMapper, "VolumeSegments")) && ok;
  if (const char* directory = std::getenv("DEEPSHADOW_TEST_IMAGES"))
  {
    deepshadow::WritePNG(blended, std::string(directory) + "/blended_in_order.png");
    deepshadow::WritePNG(exact, std::string(directory) + "/exact.png");
  }
  pass->SetVolumeSegments(8);

  window->Render();
  const int result = deepshadow::testing::RegressionTestImage(window, argc, argv);
  return ok && result != vtkTesting::FAILED ? EXIT_SUCCESS : EXIT_FAILURE;
}
