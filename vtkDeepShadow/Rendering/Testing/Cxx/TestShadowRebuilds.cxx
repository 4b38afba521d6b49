// Shadow structures are rebuilt only when what they depend on changed, per light, and never
// because the camera moved; shader code exists only for the technique chosen.
#include "DeepShadowTestUtilities.h"
#include "vtkDeepShadowDeepShadowMapTechnique.h"
#include "vtkDeepShadowOpacityLevelsTechnique.h"
#include "vtkDeepShadowRayTechnique.h"
#include "vtkDeepShadowRenderWindow.h"
#include "vtkDeepShadowShadowMapTechnique.h"
#include "vtkDeepShadowStochasticShadowMapTechnique.h"
#include "vtkDeepShadowVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkLight.h"
#include "vtkPiecewiseFunction.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <functional>

namespace
{
bool Expect(const char* step, vtkDeepShadowVolumeMapper* mapper, int builds)
{
  const bool ok = mapper->GetShadowBuilds() == builds;
  std::printf("%-44s shadow builds %d (expected %d) %s\n", step, mapper->GetShadowBuilds(),
    builds, ok ? "ok" : "FAILED");
  return ok;
}

bool Contains(const std::string& source, const char* text)
{
  return source.find(text) != std::string::npos;
}
}

int TestShadowRebuilds(int, char*[])
{
  bool ok = true;
  auto data = deepshadow::testing::MakeShadowVolume(32);
  vtkNew<vtkDeepShadowRenderWindow> window;
  window->SetSize(80, 80);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkNew<vtkDeepShadowVolumeMapper> mapper;
  mapper->SetInputData(data);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0, 0.0);
  opacity->AddPoint(40, 0.0);
  opacity->AddPoint(200, 0.8);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0, 1, 1, 1);
  vtkNew<vtkVolumeProperty> property;
  property->SetScalarOpacity(opacity);
  property->SetColor(color);
  property->ShadeOn();
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  renderer->AddVolume(volume);
  vtkNew<vtkLight> key, fill;
  for (vtkLight* light : { key.Get(), fill.Get() })
  {
    light->SetLightTypeToSceneLight();
    light->SetFocalPoint(0.0, 0.0, 0.0);
    renderer->AddLight(light);
  }
  key->SetPosition(0.3, 0.2, 1.0);
  fill->SetPosition(-1.0, 0.5, 0.5);
  fill->SetIntensity(0.4);
  renderer->ResetCamera();

  // No technique: no shadow code at all.
  window->Render();
  ok = !Contains(mapper->GetFragmentShaderSource(), "u_shadow") &&
    !Contains(mapper->GetFragmentShaderSource(), "feeler") && ok;
  ok = Expect("no technique", mapper, 0) && ok;

  vtkNew<vtkDeepShadowShadowMapTechnique> map;
  map->SetMapSize(64);
  mapper->SetShadowTechnique(map);
  window->Render();
  const std::string& source = mapper->GetFragmentShaderSource();
  const bool mapOnly = Contains(source, "filteredShadow") && !Contains(source, "u_shadowVolume") &&
    !Contains(source, "feelerTowardsLight");
  std::printf("shadow-map shader holds only the map lookup: %s\n", mapOnly ? "ok" : "FAILED");
  ok = mapOnly && ok;
  ok = Expect("shadow map, two lights", mapper, 2) && ok;

  for (int i = 0; i < 4; ++i)
  {
    renderer->GetActiveCamera()->Azimuth(20.0);
    renderer->GetActiveCamera()->Elevation(5.0);
    window->Render();
  }
  ok = Expect("camera moved 4 times", mapper, 2) && ok;

  key->SetPosition(0.5, 0.2, 1.0);
  window->Render();
  ok = Expect("key light moved: only its map", mapper, 3) && ok;

  color->AddRGBPoint(200, 1, 0, 0);
  window->Render();
  ok = Expect("colour changed: nothing", mapper, 3) && ok;

  map->SetFilter(vtkDeepShadowShadowMapTechnique::PoissonDisc);
  map->SetBias(3.0);
  window->Render();
  ok = Expect("filter and bias changed: lookup only", mapper, 3) && ok;

  opacity->AddPoint(120, 0.5);
  window->Render();
  ok = Expect("opacity changed: both maps", mapper, 5) && ok;

  map->SetThreshold(0.4);
  window->Render();
  ok = Expect("threshold changed: both maps", mapper, 7) && ok;

  volume->SetPosition(3.0, 0.0, 0.0);
  window->Render();
  ok = Expect("volume moved: both maps", mapper, 9) && ok;

  data->Modified();
  window->Render();
  ok = Expect("data modified: both maps", mapper, 11) && ok;

  fill->SetShadowAttenuation(0.0);
  window->Render();
  ok = Expect("fill light casts no shadow: nothing built", mapper, 11) && ok;

  // Cached rays: same rules; uncached rays build nothing and carry the feeler instead.
  vtkNew<vtkDeepShadowRayTechnique> rays;
  rays->CachedOn();
  rays->SetShadowVolumeSize(24);
  mapper->SetShadowTechnique(rays);
  window->Render();
  ok = Expect("cached rays, one shadow-casting light", mapper, 1) && ok;
  renderer->GetActiveCamera()->Azimuth(30.0);
  window->Render();
  ok = Expect("camera moved", mapper, 1) && ok;
  key->SetPosition(0.5, 0.4, 1.0);
  window->Render();
  ok = Expect("light moved", mapper, 2) && ok;
  ok = Contains(mapper->GetFragmentShaderSource(), "u_shadowVolume") &&
    !Contains(mapper->GetFragmentShaderSource(), "feelerTowardsLight") && ok;

  rays->CachedOff();
  window->Render();
  ok = Expect("uncached rays build nothing", mapper, 2) && ok;
  ok = Contains(mapper->GetFragmentShaderSource(), "feelerTowardsLight") && ok;

  // The other light-space techniques, uncached and cached, with both lights casting: the
  // same rules, their own parameters, and only their own lookup in the shader.
  fill->SetShadowAttenuation(1.0);
  vtkNew<vtkDeepShadowDeepShadowMapTechnique> dsm, dsmColor;
  vtkNew<vtkDeepShadowOpacityLevelsTechnique> levels;
  vtkNew<vtkDeepShadowStochasticShadowMapTechnique> cssm;
  dsmColor->ColoredOn();
  const char* lookups[] = { "filteredShadow", "dsmTexel", "levelsVisibility", "CSSM_OFFSET",
    "u_shadowVolume", "feelerTowardsLight" };
  const struct
  {
    vtkDeepShadowLightSpaceTechnique* Technique;
    const char* Lookup;
    bool Colored;
    std::function<void()> ChangeStructure; // a parameter the maps depend on
    std::function<void()> ChangeLookup;    // one only the lookup depends on (may be none)
  } techniques[] = {
    { dsm, "dsmTexel", false, [&] { dsm->SetEpsilon(0.05); }, nullptr },
    { dsmColor, "dsmTexel", true, [&] { dsmColor->SetLayers(4); }, nullptr },
    { levels, "levelsVisibility", false, [&] { levels->SetLevels(0.2, 0.5, 0.8); }, nullptr },
    { cssm, "CSSM_OFFSET", true, [&] { cssm->SetSeed(3); }, [&] { cssm->SetOffsets(21); } },
  };
  double move = 0.0;
  for (const auto& t : techniques)
  {
    vtkDeepShadowLightSpaceTechnique* technique = t.Technique;
    move += 0.05;
    technique->SetMapSize(32);
    technique->SetShadowVolumeSize(16);
    mapper->SetShadowTechnique(technique);
    const std::string name = technique->GetName();
    auto step = [&](const std::string& what, int expected) {
      const int before = technique->GetBuildCount();
      window->Render();
      const int built = technique->GetBuildCount() - before;
      const bool good = built == expected;
      std::printf("%-10s %-42s built %d (expected %d) %s\n", name.c_str(), what.c_str(), built,
        expected, good ? "ok" : "FAILED");
      ok = good && ok;
    };
    step("first render: both lights", 2);
    const std::string& source = mapper->GetFragmentShaderSource();
    for (const char* lookup : lookups)
    {
      if (Contains(source, lookup) != (std::string(lookup) == t.Lookup))
      {
        std::printf("%s: the shader %s %s: FAILED\n", name.c_str(),
          Contains(source, lookup) ? "holds" : "lacks", lookup);
        ok = false;
      }
    }
    renderer->GetActiveCamera()->Azimuth(25.0);
    step("camera moved", 0);
    fill->SetShadowAttenuation(0.5);
    step("a light's shadow attenuation changed", 0);
    color->AddRGBPoint(200, 1.0, 0.2, 0.2);
    step(t.Colored ? "colour changed: both (coloured)" : "colour changed: nothing (grey)", t.Colored ? 2 : 0);
    color->RemovePoint(200);
    step("colour restored", t.Colored ? 2 : 0);
    t.ChangeStructure();
    step("own parameter changed: both", 2);
    key->SetPosition(0.2, 0.3 + move, 1.0);
    step("key light moved: its own", 1);
    if (t.ChangeLookup)
    {
      t.ChangeLookup();
      step("lookup-only parameter changed: nothing", 0);
    }
    technique->CachedOn();
    step("cached: both caches", 2);
    ok = Contains(mapper->GetFragmentShaderSource(), "u_shadowVolume") &&
      !Contains(mapper->GetFragmentShaderSource(), t.Lookup) && ok;
    renderer->GetActiveCamera()->Azimuth(25.0);
    step("cached, camera moved", 0);
    technique->SetShadowVolumeSize(20);
    step("cached, shadow volume size changed: both", 2);
    if (t.ChangeLookup)
    {
      cssm->SetOffsets(7);
      step("cached, lookup-only parameter changed: caches", 2);
    }
    fill->SetPosition(-1.0, 0.4 + move, 0.5);
    step("cached, fill light moved: its own", 1);
    technique->CachedOff();
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
