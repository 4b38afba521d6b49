// Defined behaviour at the edges of the shadow techniques:
// - parameters out of range are clamped with a warning (threshold, step factor, sizes, bias);
// - a shadow map larger than the GL allows is an error, and the volume is drawn unshadowed;
// - a positional light inside the volume (a cube of shadow-map faces; feelers stop at the
//   light), a directional light exactly along a face, opacity 0 everywhere (nothing drawn)
//   and opacity 1 everywhere (the shadows saturate) all give the CPU twin's picture.
// Tolerance vs CPU twin: as for binary techniques in TestShadowTechniques (RMSE <= 4/255,
// <= 3% of pixels beyond 24/255).
#include "DeepShadowTestUtilities.h"
#include "vtkDeepShadowRayTechnique.h"
#include "vtkDeepShadowRenderWindow.h"
#include "vtkDeepShadowShadowMapTechnique.h"
#include "vtkDeepShadowVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkPiecewiseFunction.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

using deepshadow::testing::MessageCapture;

namespace
{
bool Clamped(const char* what, MessageCapture* capture, size_t warningsBefore, double value, double expected)
{
  const bool ok = capture->Warnings.size() == warningsBefore + 1 && value == expected;
  std::printf("%-34s -> %g with a warning: %s\n", what, value, ok ? "ok" : "FAILED");
  return ok;
}
}

int TestShadowEdgeCases(int, char*[])
{
  bool ok = true;
  vtkNew<MessageCapture> capture;
  vtkNew<vtkDeepShadowRayTechnique> rays;
  vtkNew<vtkDeepShadowShadowMapTechnique> map;
  capture->Watch(rays);
  capture->Watch(map);
  size_t n = capture->Warnings.size();
  rays->SetThreshold(1.5);
  ok = Clamped("threshold 1.5", capture, n, rays->GetThreshold(), 1.0) && ok;
  n = capture->Warnings.size();
  rays->SetThreshold(-0.5);
  ok = Clamped("threshold -0.5", capture, n, rays->GetThreshold(), 0.0) && ok;
  n = capture->Warnings.size();
  rays->SetStepFactor(0.0);
  ok = Clamped("step factor 0", capture, n, rays->GetStepFactor(), 0.01) && ok;
  n = capture->Warnings.size();
  rays->SetShadowVolumeSize(0);
  ok = Clamped("shadow volume size 0", capture, n, rays->GetShadowVolumeSize(), 2) && ok;
  n = capture->Warnings.size();
  map->SetMapSize(0);
  ok = Clamped("map size 0", capture, n, map->GetMapSize(), 1) && ok;
  n = capture->Warnings.size();
  map->SetBias(-1.0);
  ok = Clamped("bias -1", capture, n, map->GetBias(), 0.0) && ok;

  auto data = deepshadow::testing::MakeShadowVolume(32);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0, 0.0);
  opacity->AddPoint(40, 0.0);
  opacity->AddPoint(200, 0.8);
  vtkNew<vtkVolumeProperty> property;
  property->SetScalarOpacity(opacity);
  property->ShadeOn();
  vtkNew<vtkDeepShadowRenderWindow> window;
  window->SetSize(96, 96);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.1, 0.1, 0.1);
  window->AddRenderer(renderer);
  vtkNew<vtkDeepShadowVolumeMapper> mapper;
  mapper->SetInputData(data);
  vtkNew<MessageCapture> mapperMessages;
  mapperMessages->Watch(mapper);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  renderer->AddVolume(volume);
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  renderer->AddLight(light);
  renderer->GetActiveCamera()->SetPosition(0.4, -1.0, 0.6);
  renderer->GetActiveCamera()->SetViewUp(0.0, 0.0, 1.0);
  renderer->ResetCamera();

  // Too large a map: a clear error, the volume still drawn (without shadows).
  light->SetPosition(0.3, 0.2, 1.0);
  light->SetFocalPoint(0.0, 0.0, 0.0);
  map->SetMapSize(100000);
  map->SetBias(2.0);
  map->SetThreshold(0.3);
  mapper->SetShadowTechnique(map);
  window->Render();
  const bool tooLarge = mapperMessages->ErrorContains("exceeds this GL's texture limit") &&
    deepshadow::testing::CoveredFraction(deepshadow::testing::Grab(window), { 0.1, 0.1, 0.1 }) > 0.05;
  std::printf("map size 100000: error and unshadowed picture: %s\n", tooLarge ? "ok" : "FAILED");
  ok = tooLarge && ok;
  map->SetMapSize(96);

  struct Setup
  {
    const char* Name;
    bool Positional;
    double Position[3];
  };
  const Setup lights[] = { { "positional light inside the volume", true, { 2.0, 1.0, -10.0 } },
    { "directional light along a face", false, { 1.0, 0.0, 0.0 } } };
  rays->SetThreshold(0.3);
  rays->SetStepFactor(1.0);
  rays->SetShadowVolumeSize(32);
  for (const Setup& setup : lights)
  {
    light->SetPositional(setup.Positional);
    light->SetConeAngle(180.0);
    light->SetPosition(setup.Position[0], setup.Position[1], setup.Position[2]);
    light->SetFocalPoint(0.0, 0.0, 0.0);
    for (vtkDeepShadowTechnique* technique :
      { static_cast<vtkDeepShadowTechnique*>(rays), static_cast<vtkDeepShadowTechnique*>(map) })
    {
      for (bool cached : { false, true })
      {
        if (cached && technique == map)
        {
          continue;
        }
        rays->SetCached(cached);
        mapper->SetShadowTechnique(technique);
        window->Render();
        const std::string name = std::string(setup.Name) + ", " + technique->GetName();
        ok = deepshadow::testing::WithinTolerance(name.c_str(), deepshadow::testing::Grab(window),
               deepshadow::testing::Reference(renderer, true), 4.0 / 255.0, 24.0 / 255.0, 0.03) && ok;
      }
    }
  }
  // Only the map-size error, said once.
  std::printf("mapper errors: %zu (expected 1)\n", mapperMessages->Errors.size());
  ok = mapperMessages->Errors.size() == 1 && ok;

  // Opacity 0 everywhere: nothing to see or to shadow. Opacity 1 everywhere: saturated.
  light->SetPositional(false);
  light->SetPosition(0.3, 0.2, 1.0);
  rays->SetCached(false);
  mapper->SetShadowTechnique(rays);
  for (double everywhere : { 0.0, 1.0 })
  {
    opacity->RemoveAllPoints();
    opacity->AddPoint(0, everywhere);
    opacity->AddPoint(255, everywhere);
    window->Render();
    const deepshadow::Image image = deepshadow::testing::Grab(window);
    const double covered = deepshadow::testing::CoveredFraction(image, { 0.1, 0.1, 0.1 });
    const bool drawn = everywhere == 0.0 ? covered == 0.0 : covered > 0.05;
    std::printf("opacity %g everywhere: %.1f%% covered: %s\n", everywhere, 100.0 * covered, drawn ? "ok" : "FAILED");
    ok = drawn && ok;
    ok = deepshadow::testing::WithinTolerance(everywhere == 0.0 ? "opacity 0 everywhere" : "opacity 1 everywhere",
           image, deepshadow::testing::Reference(renderer, true), 4.0 / 255.0, 24.0 / 255.0, 0.03) && ok;
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
