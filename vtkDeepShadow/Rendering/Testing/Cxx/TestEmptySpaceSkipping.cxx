// Empty-space skipping is exact: with and without it the GPU takes the same samples, so the
// images are bit-identical; on a sparse scene most blocks are skipped.
#include "DeepShadowTestUtilities.h"
#include "vtkDeepShadowRenderWindow.h"
#include "vtkDeepShadowStandardScene.h"
#include "vtkDeepShadowVolumeMapper.h"

#include "vtkVolume.h"

int TestEmptySpaceSkipping(int, char*[])
{
  vtkNew<vtkDeepShadowRenderWindow> window;
  window->SetSize(160, 160);
  deepshadow::testing::StandardSceneView view("spheres", 0.5, false);
  vtkRenderer* renderer = view.Renderer;
  vtkDeepShadowVolumeMapper* mapper = view.Mapper;
  window->AddRenderer(renderer);
  renderer->ResetCameraClippingRange();

  bool ok = true;
  for (bool jitter : { false, true })
  {
    mapper->SetJitter(jitter);
    mapper->EmptySpaceSkippingOn();
    window->Render();
    const deepshadow::Image skipping = deepshadow::testing::Grab(window);
    const double fraction = mapper->GetEmptyBlockFraction();
    mapper->EmptySpaceSkippingOff();
    window->Render();
    const deepshadow::Image marching = deepshadow::testing::Grab(window);
    const double difference = deepshadow::Compare(skipping, marching).MaxAbs;
    std::printf("jitter %d: %.0f%% of blocks empty, max difference %.6f\n", jitter,
      100.0 * fraction, difference);
    ok = ok && difference == 0.0 && fraction > 0.3 &&
      deepshadow::testing::CoveredFraction(skipping, { 0.0, 0.0, 0.0 }) > 0.05;
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
