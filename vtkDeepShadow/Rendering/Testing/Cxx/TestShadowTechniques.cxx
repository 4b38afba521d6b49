// Every shadow technique on the GPU against its CPU twin, on a ball over a floor lit from
// above: shadows appear where they should (the floor under the ball darkens), and GPU and
// twin agree within the stated tolerance.
//
// Stated tolerances (GPU vs CPU twin): translucent techniques RMSE <= 2/255 and <= 1% of
// pixels off by more than 12/255; binary techniques (opaque rays, shadow maps) RMSE <= 4/255
// and <= 3% of pixels beyond 24/255, because a feeler or light ray whose sample sits on the
// threshold can fall either side in float and in double, which flips a whole shadow texel or
// a pixel's visibility.
//
// Unshaded, a directional light that casts no shadow is added once, outside the lights' loop
// (LoopedLights); without positional lights their code is not composed.
#include "DeepShadowTestUtilities.h"
#include "vtkDeepShadowRayTechnique.h"
#include "vtkDeepShadowRenderWindow.h"
#include "vtkDeepShadowShadowMapTechnique.h"
#include "vtkDeepShadowTechniqueFactory.h"
#include "vtkDeepShadowVolumeMapper.h"

#include "vtkLight.h"

using deepshadow::testing::Grab;
using deepshadow::testing::WithinTolerance;

namespace
{
struct Case
{
  const char* Name;
  vtkSmartPointer<vtkDeepShadowTechnique> Technique;
  bool Binary;
};

vtkSmartPointer<vtkDeepShadowTechnique> Rays(bool opaque, bool cached)
{
  auto rays = vtkSmartPointer<vtkDeepShadowRayTechnique>::New();
  rays->SetOpaque(opaque);
  rays->SetCached(cached);
  rays->SetShadowVolumeSize(48);
  rays->SetThreshold(0.3);
  return rays;
}

vtkSmartPointer<vtkDeepShadowTechnique> Map(int filter)
{
  auto map = vtkSmartPointer<vtkDeepShadowShadowMapTechnique>::New();
  map->SetMapSize(128);
  map->SetFilter(filter);
  map->SetThreshold(0.3);
  return map;
}
}

int TestShadowTechniques(int argc, char* argv[])
{
  deepshadow::testing::ShadowScene scene;
  vtkDeepShadowRenderWindow* window = scene.Window;
  vtkRenderer* renderer = scene.Renderer;
  vtkDeepShadowVolumeMapper* mapper = scene.Mapper;
  vtkVolumeProperty* property = scene.Property;

  window->Render();
  const deepshadow::Image unshadowed = Grab(window);

  const Case cases[] = { { "rays", Rays(false, false), false },
    { "rays-opaque", Rays(true, false), true }, { "rays-cached", Rays(false, true), false },
    { "rays-opaque-cached", Rays(true, true), true },
    { "shadowmap, no filter", Map(vtkDeepShadowShadowMapTechnique::NoFilter), true },
    { "shadowmap, 2x2", Map(vtkDeepShadowShadowMapTechnique::PCF2x2), true },
    { "shadowmap, 3x3", Map(vtkDeepShadowShadowMapTechnique::PCF3x3), true },
    { "shadowmap, Poisson", Map(vtkDeepShadowShadowMapTechnique::PoissonDisc), true },
    { "rmsm", vtkDeepShadowTechniqueFactory::New("rmsm"), true } };
  bool ok = true;
  for (const Case& c : cases)
  {
    deepshadow::Image gpu;
    ok = scene.MatchesTwin(c.Name, c.Technique, (c.Binary ? 4.0 : 2.0) / 255.0,
           (c.Binary ? 24.0 : 12.0) / 255.0, c.Binary ? 0.03 : 0.01, gpu) && ok;
    // The floor in the ball's shadow darkens.
    const double before = scene.FloorUnderBall(unshadowed).r, after = scene.FloorUnderBall(gpu).r;
    std::printf("  floor under the ball: %.3f without shadows, %.3f with\n", before, after);
    ok = after < 0.5 * before && ok;
  }
  // Several lights of every kind at once (each shadowed), then an unshaded volume that is
  // lit isotropically because it receives shadows.
  vtkNew<vtkLight> point, spot;
  point->SetLightTypeToSceneLight();
  point->SetPositional(true);
  point->SetConeAngle(180.0);
  point->SetPosition(-60.0, -20.0, 70.0);
  point->SetDiffuseColor(0.5, 0.7, 1.0);
  spot->SetLightTypeToSceneLight();
  spot->SetPositional(true);
  spot->SetPosition(40.0, 30.0, 90.0);
  spot->SetFocalPoint(0.0, 0.0, -30.0);
  spot->SetConeAngle(25.0);
  spot->SetIntensity(0.8);
  renderer->AddLight(point);
  renderer->AddLight(spot);
  for (const Case& c : { cases[0], cases[6] })
  {
    mapper->SetShadowTechnique(c.Technique);
    for (bool shade : { true, false })
    {
      property->SetShade(shade);
      window->Render();
      const std::string name = std::string(c.Name) + ", three lights" + (shade ? "" : ", unshaded");
      ok = WithinTolerance(name.c_str(), Grab(window), deepshadow::testing::Reference(renderer, true),
             (c.Binary ? 4.0 : 2.0) / 255.0, (c.Binary ? 24.0 : 12.0) / 255.0,
             c.Binary ? 0.03 : 0.01) && ok;
    }
    // Unshaded, the key light casting none: lit isotropically and unshadowed, beside the two
    // lights that cast.
    scene.Light->SetShadowAttenuation(0.0);
    window->Render();
    ok = WithinTolerance((std::string(c.Name) + ", three lights, unshaded, the key casting none").c_str(),
           Grab(window), deepshadow::testing::Reference(renderer, true), (c.Binary ? 4.0 : 2.0) / 255.0,
           (c.Binary ? 24.0 : 12.0) / 255.0, c.Binary ? 0.03 : 0.01) && ok;
    scene.Light->SetShadowAttenuation(1.0);
  }
  // With the positional lights, their code is composed; without them it is left out, and the
  // key light alone, casting none, leaves the lights' loop empty (its share added once).
  const auto composed = [&](const char* define) {
    return mapper->GetFragmentShaderSource().find(define) != std::string::npos;
  };
  ok = deepshadow::testing::Check("positional lights' code composed", composed("#define POSITIONAL_LIGHTS 1")) && ok;
  renderer->RemoveLight(point);
  renderer->RemoveLight(spot);
  property->ShadeOff();
  scene.Light->SetShadowAttenuation(0.0);
  window->Render();
  ok = WithinTolerance("the key light alone, unshaded, casting none", Grab(window),
         deepshadow::testing::Reference(renderer, true), 2.0 / 255.0, 12.0 / 255.0, 0.01) && ok;
  ok = deepshadow::testing::Check("directional lights only: no positional code",
         composed("#define POSITIONAL_LIGHTS 0") && composed("#define LIGHT_FROM_EYE 0")) && ok;
  scene.Light->SetShadowAttenuation(1.0);
  property->ShadeOn();

  mapper->SetShadowTechnique(cases[7].Technique);
  window->Render();
  const int result = deepshadow::testing::RegressionTestImage(window, argc, argv);
  return ok && result != vtkTesting::FAILED ? EXIT_SUCCESS : EXIT_FAILURE;
}
