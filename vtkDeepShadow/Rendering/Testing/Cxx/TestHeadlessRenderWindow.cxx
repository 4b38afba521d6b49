// An ordinary VTK pipeline renders with DISPLAY unset: the module's factory makes
// vtkRenderWindow::New() headless, the image is not empty, and the OSMesa and EGL backends
// give the same pixels: for polygons, and for a shadowed volume whose shadows are built by
// compute passes (a deep shadow map's light-space build, a cached technique's shadow cache).
#include "DeepShadowTestUtilities.h"
#include "vtkDeepShadowDeepShadowMapTechnique.h"
#include "vtkDeepShadowRayTechnique.h"
#include "vtkDeepShadowRenderWindow.h"

#include "vtkActor.h"
#include "vtkConeSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkSphereSource.h"

#include <cstdlib>
#include <string>

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


vtkSmartPointer<vtkDeepShadowTechnique> MakeDeepShadowMap()
{
  auto dsm = vtkSmartPointer<vtkDeepShadowDeepShadowMapTechnique>::New();
  dsm->SetMapSize(128);
  dsm->ColoredOn();
  return dsm;
}

vtkSmartPointer<vtkDeepShadowTechnique> MakeCachedRays()
{
  auto rays = vtkSmartPointer<vtkDeepShadowRayTechnique>::New();
  rays->CachedOn();
  rays->SetShadowVolumeSize(48);
  return rays;
}

// The shadow test scene rendered with `technique` on `backend`: its picture, whether the
// frame ran `pass` (a compute pass of the technique), and the context's GL_RENDERER.
deepshadow::Image RenderShadowScene(
  int backend, vtkDeepShadowTechnique* technique, const char* pass, bool& ran, std::string& driver)
{
  deepshadow::testing::ShadowScene scene;
  vtkNew<deepshadow::testing::MessageCapture> messages; // "no OSMesa" is checked in part 1
  messages->Watch(scene.Window);
  scene.Window->SetBackend(backend);
  scene.Mapper->SetShadowTechnique(technique);
  scene.Window->Render();
  const auto& passes = scene.Mapper->GetLastPasses();
  ran = std::find(passes.begin(), passes.end(), pass) != passes.end() &&
    scene.Mapper->GetLastError().empty() && scene.Window->HasContext();
  driver = scene.Window->GetOpenGLRenderer();
  return deepshadow::testing::Grab(scene.Window);
}

bool IsLlvmpipe(const std::string& driver)
{
  return driver.find("llvmpipe") != std::string::npos;
}

// With Mesa behind both backends (llvmpipe) the pixels must be identical. On a machine whose
// EGL is a GPU's driver, which rounds differently, each backend that exists must run the
// pass and draw the volume; OSMesa may be missing there.
bool SameOnBothBackends(
  const char* name, vtkSmartPointer<vtkDeepShadowTechnique> (*make)(), const char* pass)
{
  bool ranOSMesa = false, ranEGL = false;
  std::string osmesaDriver, eglDriver;
  // One backend at a time: each scene (and its context) is gone before the next.
  const deepshadow::Image osmesa =
    RenderShadowScene(vtkDeepShadowRenderWindow::OSMesa, make(), pass, ranOSMesa, osmesaDriver);
  const deepshadow::Image egl =
    RenderShadowScene(vtkDeepShadowRenderWindow::EGL, make(), pass, ranEGL, eglDriver);
  const double covered = deepshadow::testing::CoveredFraction(egl, { 0.05, 0.05, 0.08 });
  if (!IsLlvmpipe(eglDriver))
  {
    return deepshadow::testing::Check(std::string("EGL on ") + eglDriver + ", " + name + ": ran " +
        pass + ", " + std::to_string(100.0 * covered).substr(0, 4) + "% covered" +
        (ranOSMesa ? ", and on OSMesa" : " (no OSMesa here)"),
      ranEGL && covered > 0.05);
  }
  const deepshadow::ImageDifference d = deepshadow::Compare(osmesa, egl);
  return deepshadow::testing::Check(std::string("OSMesa vs EGL, ") + name + ": ran " + pass +
      " on both, " + std::to_string(100.0 * covered).substr(0, 4) + "% covered, max difference " +
      std::to_string(d.MaxAbs),
    ranOSMesa && ranEGL && covered > 0.05 && d.MaxAbs == 0.0);
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

  // 1. The factory override: a plain vtkRenderWindow is the headless one. Without libOSMesa
  // (a GPU machine) Render() draws nothing and says why: no signal, no abort.
  deepshadow::Image osmesa;
  std::string osmesaError;
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
    vtkNew<deepshadow::testing::MessageCapture> messages;
    messages->Watch(headless);
    window->Render();
    osmesaError = headless->HasContext() ? "" : headless->GetLastError();
    if (osmesaError.empty())
    {
      osmesa = deepshadow::testing::Grab(window);
      std::printf("%s", window->ReportCapabilities());
      const double covered = deepshadow::testing::CoveredFraction(osmesa, { 0.1, 0.2, 0.4 });
      std::printf("OSMesa: %.1f%% of pixels show geometry\n", 100.0 * covered);
      ok = ok && covered > 0.05 && covered < 0.9;
    }
    else
    {
      window->Render(); // a second frame neither retries, nor says it again, nor crashes
      // Reading the picture back (vtkWindowToImageFilter) and the depth gives black, no signal.
      const deepshadow::Image black = deepshadow::testing::Grab(window);
      float depth = -1.0f;
      unsigned char rgb[3] = { 1, 2, 3 };
      float rgba[4] = { 1.0f, 1.0f, 1.0f, 1.0f };
      const bool refused = headless->GetZbufferData(0, 0, 0, 0, &depth) == VTK_ERROR &&
        headless->SetZbufferData(0, 0, 0, 0, &depth) == VTK_ERROR &&
        headless->SetPixelData(0, 0, 0, 0, rgb, 0, 0) == VTK_ERROR &&
        headless->SetRGBAPixelData(0, 0, 0, 0, rgba, 0) == VTK_ERROR &&
        headless->SetRGBACharPixelData(0, 0, 0, 0, rgb, 0) == VTK_ERROR;
      ok = deepshadow::testing::Check("pixel and depth I/O refused, depth the far plane",
             refused && depth == 1.0f) && ok;
      ok = deepshadow::testing::Check("no OSMesa here, said once: " + osmesaError,
             osmesaError.find("OSMesa") != std::string::npos && !headless->HasContext() &&
               messages->Errors.size() == 1) && ok;
      ok = deepshadow::testing::Check("its picture read back is black",
             deepshadow::Compare(black, deepshadow::Image(black.Width, black.Height)).MaxAbs == 0.0) && ok;
    }
    // Linked with DeepShadow::Rendering first, the linker already bound VTK's GL calls to
    // the window's entry points: nothing had to be rewritten (Python's imports do need it).
    const int rewritten = vtkDeepShadowRenderWindow::GetRewrittenGLImports();
    std::printf("GL imports rewritten in this linked program: %d\n", rewritten);
    ok = ok && rewritten == 0;
  }

  // 2. EGL (surfaceless) renders the same pixels once the OSMesa context is gone, when Mesa
  // is behind both; a GPU's EGL must draw the scene.
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
    const double covered = deepshadow::testing::CoveredFraction(egl, { 0.1, 0.2, 0.4 });
    if (IsLlvmpipe(window->GetOpenGLRenderer()))
    {
      // Debian's Mesa ships OSMesa with EGL: on a llvmpipe machine both must be there.
      ok = deepshadow::testing::Check("OSMesa beside llvmpipe's EGL", osmesaError.empty()) && ok;
      if (osmesaError.empty())
      {
        const deepshadow::ImageDifference d = deepshadow::Compare(osmesa, egl);
        std::printf("OSMesa vs EGL: max difference %.4f\n", d.MaxAbs);
        ok = ok && d.MaxAbs == 0.0;
      }
    }
    ok = deepshadow::testing::Check("EGL: " + std::to_string(100.0 * covered).substr(0, 4) +
           "% of pixels show geometry", covered > 0.05 && covered < 0.9) && ok;
  }

  // 3. A shadowed volume: the same pixels from both backends, compute passes included.
  ok = SameOnBothBackends("deep shadow map", MakeDeepShadowMap, "light-space-build") && ok;
  ok = SameOnBothBackends("cached shadow rays", MakeCachedRays, "shadow-cache") && ok;

  // 4. The picture itself, against the baseline.
  vtkNew<vtkDeepShadowRenderWindow> window;
  BuildScene(window);
  window->Render();
  const int result = deepshadow::testing::RegressionTestImage(window, argc, argv);
  return ok && result != vtkTesting::FAILED ? EXIT_SUCCESS : EXIT_FAILURE;
}
