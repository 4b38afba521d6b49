// Defined behaviour at the edges of the deep, opacity-level and stochastic shadow maps:
// - out-of-range parameters are clamped with a warning (epsilon, layers, photons), invalid
//   ones refused with an error (CSSM offsets, opacity levels) and the old value kept;
// - more light-space layers than the GL allows is an error, said once, and the volume is
//   drawn unshadowed;
// - lights at the extremes give the CPU twin's picture: a positional light inside the
//   volume (a cube of faces), a directional light along a face, a positional light 1e-6
//   from the volume (near/far 1e-6) and one 1e6 volume sizes away (an orthographic face);
// - one layer, whose overflowing texels keep no shadow, is said once;
// - opacity 0 everywhere (nothing drawn) and 1 everywhere (shadows saturate).
// Tolerance vs CPU twin: as for translucent techniques (RMSE <= 2/255, <= 1% of pixels
// beyond 12/255).
#include "DeepShadowTestUtilities.h"
#include "vtkDeepShadowDeepShadowMapTechnique.h"
#include "vtkDeepShadowOpacityLevelsTechnique.h"
#include "vtkDeepShadowStochasticShadowMapTechnique.h"

#include <cmath>
#include <functional>

using deepshadow::testing::Check;
using deepshadow::testing::MessageCapture;

int TestDeepShadowEdgeCases(int, char*[])
{
  bool ok = true;
  vtkNew<MessageCapture> capture;
  vtkNew<vtkDeepShadowDeepShadowMapTechnique> dsm;
  vtkNew<vtkDeepShadowOpacityLevelsTechnique> levels;
  vtkNew<vtkDeepShadowStochasticShadowMapTechnique> cssm;
  capture->Watch(dsm);
  capture->Watch(levels);
  capture->Watch(cssm);
  auto warned = [&](const char* what, const std::function<void()>& set, const std::function<bool()>& result) {
    const size_t before = capture->Warnings.size();
    set();
    ok = Check(what, result() && capture->Warnings.size() == before + 1) && ok;
  };
  warned("epsilon -1 -> 0, warned", [&] { dsm->SetEpsilon(-1.0); }, [&] { return dsm->GetEpsilon() == 0.0; });
  warned("epsilon NaN -> 0, warned", [&] { dsm->SetEpsilon(std::nan("")); }, [&] { return dsm->GetEpsilon() == 0.0; });
  warned("epsilon 2 -> 1, warned", [&] { dsm->SetEpsilon(2.0); }, [&] { return dsm->GetEpsilon() == 1.0; });
  warned("layers 0 -> 1, warned", [&] { dsm->SetLayers(0); }, [&] { return dsm->GetLayers() == 1; });
  warned("layers 1000 -> 256, warned", [&] { dsm->SetLayers(1000); }, [&] { return dsm->GetLayers() == 256; });
  warned("photons 0 -> 1, warned", [&] { cssm->SetPhotons(0); }, [&] { return cssm->GetPhotons() == 1; });
  cssm->SetOffsets(9);
  ok = Check("CSSM offsets 9: refused, 13 kept", cssm->GetOffsets() == 13 && capture->ErrorContains("7, 13 or 21")) && ok;
  levels->SetLevels(0.5, 0.2, 0.9);
  ok = Check("opacity levels 0.5, 0.2, 0.9: refused, kept",
         levels->GetLevels()[1] == 0.5 && capture->ErrorContains("increase strictly")) && ok;
  dsm->SetEpsilon(0.02);
  dsm->SetLayers(8);

  auto data = deepshadow::testing::MakeShadowVolume(32);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0, 0.0);
  opacity->AddPoint(40, 0.0);
  opacity->AddPoint(200, 0.8);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0, 1.0, 1.0, 1.0);
  color->AddRGBPoint(200, 1.0, 0.5, 0.2);
  vtkNew<vtkVolumeProperty> property;
  property->SetScalarOpacity(opacity);
  property->SetColor(color);
  property->ShadeOn();
  vtkNew<vtkDeepShadowRenderWindow> window;
  window->SetSize(96, 96);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.1, 0.1, 0.3); // unlike any ambient-only grey
  window->AddRenderer(renderer);
  vtkNew<vtkDeepShadowVolumeMapper> mapper;
  mapper->SetInputData(data);
  vtkNew<MessageCapture> mapperMessages;
  mapperMessages->Watch(mapper);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  renderer->AddVolume(volume);
  vtkNew<vtkLight> light, second;
  for (vtkLight* l : { light.Get(), second.Get() })
  {
    l->SetLightTypeToSceneLight();
    l->SetPositional(true);
    l->SetConeAngle(180.0);
    l->SetFocalPoint(0.0, 0.0, 0.0);
    renderer->AddLight(l);
  }
  light->SetPosition(2.0, 1.0, -10.0); // inside the volume: six faces each
  second->SetPosition(-5.0, 3.0, 0.0);
  renderer->GetActiveCamera()->SetPosition(0.4, -1.0, 0.6);
  renderer->GetActiveCamera()->SetViewUp(0.0, 0.0, 1.0);
  renderer->ResetCamera();

  // 2 lights x 6 faces x 256 layers = 3072 layers, more than a GL must offer (2048).
  dsm->SetLayers(256);
  dsm->SetMapSize(16);
  mapper->SetShadowTechnique(dsm);
  window->Render();
  window->Render();
  const bool tooMany = mapperMessages->ErrorContains("exceed this GL's limit") &&
    mapperMessages->Errors.size() == 1 &&
    deepshadow::testing::CoveredFraction(deepshadow::testing::Grab(window), { 0.1, 0.1, 0.3 }) > 0.05;
  ok = Check("3072 layers: one error, unshadowed picture", tooMany) && ok;
  renderer->RemoveLight(second);
  dsm->SetLayers(8);
  dsm->SetMapSize(96);
  levels->SetMapSize(96);
  cssm->SetMapSize(96);

  vtkNew<vtkDeepShadowDeepShadowMapTechnique> colored;
  colored->SetMapSize(96);
  colored->ColoredOn();
  vtkDeepShadowLightSpaceTechnique* techniques[] = { dsm, colored, levels, cssm };
  struct Setup
  {
    const char* Name;
    bool Positional;
    double Position[3];
  };
  // The volume spans [-31, 31]^3; its bounding radius is about 54.
  const Setup lights[] = { { "positional light inside the volume", true, { 2.0, 1.0, -10.0 } },
    { "directional light along a face", false, { 1.0, 0.0, 0.0 } },
    { "positional light 1e-6 from the volume", true, { 0.0, 0.0, 31.000001 } },
    { "positional light 1e6 radii away", true, { 3e7, 2e7, 4e7 } } };
  for (const Setup& setup : lights)
  {
    light->SetPositional(setup.Positional);
    light->SetPosition(setup.Position[0], setup.Position[1], setup.Position[2]);
    for (vtkDeepShadowLightSpaceTechnique* technique : techniques)
    {
      mapper->SetShadowTechnique(technique);
      window->Render();
      const std::string name = std::string(setup.Name) + ", " + technique->GetName();
      ok = deepshadow::testing::WithinTolerance(name.c_str(), deepshadow::testing::Grab(window),
             deepshadow::testing::Reference(renderer, true), 2.0 / 255.0, 12.0 / 255.0, 0.01) && ok;
    }
  }
  ok = Check("no other mapper error", mapperMessages->Errors.size() == 1) && ok;

  // One layer holds no shadow: overflowing texels double their bound past 1, which is said
  // once while it lasts; the default layers say nothing.
  light->SetPositional(false);
  light->SetPosition(0.3, 0.2, 1.0);
  mapper->SetShadowTechnique(dsm);
  const size_t heard = capture->Warnings.size();
  window->Render();
  ok = Check("8 layers: no bound of 1 or more, nothing said", capture->Warnings.size() == heard) && ok;
  dsm->SetLayers(1);
  window->Render();
  light->SetPosition(0.32, 0.2, 1.0); // rebuilt, the same again
  window->Render();
  ok = Check("1 layer: a bound of 1 or more said once over two builds", capture->Warnings.size() == heard + 1 &&
         capture->Warnings.back().find("keeps no shadow") != std::string::npos && dsm->GetEpsilonMax() >= 1.0) && ok;
  dsm->SetLayers(8);
  window->Render();
  ok = Check("8 layers again: nothing more said", capture->Warnings.size() == heard + 1) && ok;

  // Opacity 0 everywhere: nothing to see or to shadow. Opacity 1 everywhere: saturated.
  light->SetPositional(false);
  light->SetPosition(0.3, 0.2, 1.0);
  for (double everywhere : { 0.0, 1.0 })
  {
    opacity->RemoveAllPoints();
    opacity->AddPoint(0, everywhere);
    opacity->AddPoint(255, everywhere);
    for (vtkDeepShadowLightSpaceTechnique* technique : techniques)
    {
      mapper->SetShadowTechnique(technique);
      window->Render();
      const deepshadow::Image image = deepshadow::testing::Grab(window);
      const double covered = deepshadow::testing::CoveredFraction(image, { 0.1, 0.1, 0.3 });
      const std::string name = "opacity " + std::to_string(static_cast<int>(everywhere)) +
        " everywhere, " + technique->GetName();
      ok = Check((name + ": drawn as it should").c_str(), everywhere == 0.0 ? covered == 0.0 : covered > 0.05) && ok;
      ok = deepshadow::testing::WithinTolerance(name.c_str(), image,
             deepshadow::testing::Reference(renderer, true), 2.0 / 255.0, 12.0 / 255.0, 0.01) && ok;
    }
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
