// The GPU mapper against the CPU reference on every standard scene (reduced resolution).
//
// Stated tolerances (printed with the measured values):
// - GPU vs its CPU twin (same table, termination and jitter; float vs double, GL's texture
//   filtering): RMSE <= 1.5/255 and <= 0.5% of pixels off by more than 6/255;
// - GPU vs the exact model (transfer functions evaluated exactly, no early termination):
//   RMSE <= 2/255 and <= 1% of pixels off by more than 8/255;
// - jitter: the same seed gives bit-identical GPU images, and the GPU's jitter matches the
//   CPU's hash (same tolerance as the twin).
#include "DeepShadowTestUtilities.h"
#include "vtkDeepShadowRenderWindow.h"
#include "vtkDeepShadowStandardScene.h"
#include "vtkDeepShadowVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <map>

using deepshadow::testing::Grab;
using deepshadow::testing::Reference;
using deepshadow::testing::WithinTolerance;

int TestVolumeMapperMatchesReference(int argc, char* argv[])
{
  // Voxels per axis kept small so the CPU reference stays quick.
  const std::map<std::string, double> scales = { { "box", 0.75 }, { "bucky", 1.0 },
    { "rods", 0.75 }, { "clouds", 0.2 }, { "spheres", 0.4 }, { "head", 0.25 },
    { "sparse", 0.5 } };
  vtkNew<vtkDeepShadowRenderWindow> window;
  window->SetSize(160, 160);
  bool ok = true;
  for (const std::string& name : vtkDeepShadowStandardScene::GetSceneNames())
  {
    deepshadow::testing::StandardSceneView view(name, scales.at(name), true);
    vtkRenderer* renderer = view.Renderer;
    vtkDeepShadowVolumeMapper* mapper = view.Mapper;
    renderer->SetBackground(0.08, 0.09, 0.12);
    window->GetRenderers()->RemoveAllItems();
    window->AddRenderer(renderer);
    renderer->ResetCameraClippingRange();

    window->Render();
    if (!mapper->GetLastError().empty())
    {
      std::printf("%s: %s\n", name.c_str(), mapper->GetLastError().c_str());
      return EXIT_FAILURE;
    }
    const deepshadow::Image gpu = Grab(window);
    ok = deepshadow::testing::CoveredFraction(gpu, { 0.08, 0.09, 0.12 }) > 0.05 && ok;
    ok = WithinTolerance((name + " vs CPU twin").c_str(), gpu, Reference(renderer, true),
           1.5 / 255.0, 6.0 / 255.0, 0.005) && ok;
    ok = WithinTolerance((name + " vs exact reference").c_str(), gpu, Reference(renderer, false),
           2.0 / 255.0, 8.0 / 255.0, 0.01) && ok;

    if (name == "spheres")
    {
      mapper->JitterOn();
      mapper->SetJitterSeed(7);
      window->Render();
      const deepshadow::Image first = Grab(window);
      window->Render();
      const deepshadow::Image second = Grab(window);
      const bool identical = deepshadow::Compare(first, second).MaxAbs == 0.0;
      std::printf("jitter seed 7: two renders identical: %s\n", identical ? "yes" : "NO");
      ok = identical && ok;
      ok = WithinTolerance("jittered spheres vs CPU twin", first, Reference(renderer, true),
             1.5 / 255.0, 6.0 / 255.0, 0.005) && ok;
      mapper->SetJitterSeed(8);
      window->Render();
      ok = deepshadow::Compare(first, Grab(window)).MaxAbs > 0.0 && ok; // seeds matter
      mapper->JitterOff();
    }
  }
  // The head, as the baseline picture.
  const int result = deepshadow::testing::RegressionTestImage(window, argc, argv);
  return ok && result != vtkTesting::FAILED ? EXIT_SUCCESS : EXIT_FAILURE;
}
