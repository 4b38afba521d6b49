// An ordinary VTK pipeline renders with DISPLAY unset: the module's factory makes
// vtkRenderWindow::New() headless, the image is not empty, and the OSMesa and EGL backends
// give the same pixels.
#include "DeepShadowTestUtilities.h"
#include "vtkDeepShadowRenderWindow.h"

#include "vtkActor.h"
#include "vtkConeSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkSphereSource.h"

#include <cstdlib>

namespace
{
void BuildScene(vtkRenderWindow* window)
{
  window->SetSize(200, 200);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.1, 0.2, 0.4);
  window->AddRenderer(renderer);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(32);
  vtkNew<vtkPolyDataMapper> sphereMapper;
  sphereMapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> sphereActor;
  sphereActor->SetMapper(sphereMapper);
  sphereActor->GetProperty()->SetColor(1.0, 0.6, 0.2);
  renderer->AddActor(sphereActor);
  vtkNew<vtkConeSource> cone;
  cone->SetResolution(24);
  cone->SetCenter(0.8, 0.3, 0.0);
  vtkNew<vtkPolyDataMapper> coneMapper;
  coneMapper->SetInputConnection(cone->GetOutputPort());
  vtkNew<vtkActor> coneActor;
  coneActor->SetMapper(coneMapper);
  renderer->AddActor(coneActor);
  renderer->ResetCamera();
}
}

int TestHeadlessRenderWindow(int argc, char* argv[])
{
  if (std::getenv("DISPLAY") && *std::getenv("DISPLAY"))
  {
    std::printf("DISPLAY is set; this test must run without one (ctest unsets it)\n");
    return EXIT_FAILURE;
  }
  bool ok = true;

  // 1. The factory override: a plain vtkRenderWindow is the headless one.
  deepshadow::Image osmesa;
  {
    vtkNew<vtkRenderWindow> window;
    auto* headless = vtkDeepShadowRenderWindow::SafeDownCast(window);
    if (!headless)
    {
      std::printf("vtkRenderWindow::New() returned %s, not vtkDeepShadowRenderWindow\n",
        window->GetClassName());
      return EXIT_FAILURE;
    }
    headless->SetBackendToOSMesa();
    BuildScene(window);
    window->Render();
    osmesa = deepshadow::testing::Grab(window);
    std::printf("%s", window->ReportCapabilities());
    const double covered = deepshadow::testing::CoveredFraction(osmesa, { 0.1, 0.2, 0.4 });
    std::printf("OSMesa: %.1f%% of pixels show geometry\n", 100.0 * covered);
    ok = ok && covered > 0.05 && covered < 0.9;
  }

  // 2. EGL (surfaceless) renders the same pixels once the OSMesa context is gone.
  {
    vtkNew<vtkDeepShadowRenderWindow> window;
    window->SetBackendToEGL();
    BuildScene(window);
    window->Render();
    if (!window->HasContext())
    {
      std::printf("EGL context: %s\n", window->GetLastError().c_str());
      return EXIT_FAILURE;
    }
    std::printf("%s", window->ReportCapabilities());
    const deepshadow::Image egl = deepshadow::testing::Grab(window);
    const deepshadow::ImageDifference d = deepshadow::Compare(osmesa, egl);
    std::printf("OSMesa vs EGL: max difference %.4f\n", d.MaxAbs);
    ok = ok && d.MaxAbs == 0.0;
  }

  // 3. The picture itself, against the baseline.
  vtkNew<vtkDeepShadowRenderWindow> window;
  BuildScene(window);
  window->Render();
  const int result = vtkRegressionTestImage(window);
  return ok && result != vtkTesting::FAILED ? EXIT_SUCCESS : EXIT_FAILURE;
}
