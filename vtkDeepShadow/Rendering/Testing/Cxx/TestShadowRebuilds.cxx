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

#include <cmath>
#include <functional>
#include <vector>

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

// The volume, its two lights and the window every case renders; the cases run in order on
// the same objects (each expects the state the previous one left).
struct Scene
{
  vtkSmartPointer<vtkImageData> Data;
  vtkNew<vtkDeepShadowRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkDeepShadowVolumeMapper> Mapper;
  vtkNew<vtkPiecewiseFunction> Opacity;
  vtkNew<vtkColorTransferFunction> Color;
  vtkNew<vtkVolumeProperty> Property;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkLight> Key, Fill;
  // The techniques the cases made, kept to the end as when one function held them all.
  std::vector<vtkSmartPointer<vtkObject>> Techniques;
};

void SetUp(Scene& s)
{
  s.Data = deepshadow::testing::MakeShadowVolume(32);
  s.Window->SetSize(80, 80);
  s.Window->AddRenderer(s.Renderer);
  s.Mapper->SetInputData(s.Data);
  s.Opacity->AddPoint(0, 0.0);
  s.Opacity->AddPoint(40, 0.0);
  s.Opacity->AddPoint(200, 0.8);
  s.Color->AddRGBPoint(0, 1, 1, 1);
  s.Property->SetScalarOpacity(s.Opacity);
  s.Property->SetColor(s.Color);
  s.Property->ShadeOn();
  s.Volume->SetMapper(s.Mapper);
  s.Volume->SetProperty(s.Property);
  s.Renderer->AddVolume(s.Volume);
  for (vtkLight* light : { s.Key.Get(), s.Fill.Get() })
  {
    light->SetLightTypeToSceneLight();
    light->SetFocalPoint(0.0, 0.0, 0.0);
    s.Renderer->AddLight(light);
  }
  s.Key->SetPosition(0.3, 0.2, 1.0);
  s.Fill->SetPosition(-1.0, 0.5, 0.5);
  s.Fill->SetIntensity(0.4);
  s.Renderer->ResetCamera();
}

bool NoTechnique(Scene& s)
{
  bool ok = true;
  // No technique: no shadow code at all.
  s.Window->Render();
  ok = !Contains(s.Mapper->GetFragmentShaderSource(), "u_shadow") &&
    !Contains(s.Mapper->GetFragmentShaderSource(), "feeler") && ok;
  ok = Expect("no technique", s.Mapper, 0) && ok;
  return ok;
}

// The shadow map: rebuilt per light for what its maps depend on, never for the camera.
bool ShadowMap(Scene& s)
{
  bool ok = true;
  vtkNew<vtkDeepShadowShadowMapTechnique> map;
  map->SetMapSize(64);
  s.Mapper->SetShadowTechnique(map);
  s.Window->Render();
  const std::string& source = s.Mapper->GetFragmentShaderSource();
  const bool mapOnly = Contains(source, "filteredShadow") && !Contains(source, "u_shadowVolume") &&
    !Contains(source, "feelerTowardsLight");
  std::printf("shadow-map shader holds only the map lookup: %s\n", mapOnly ? "ok" : "FAILED");
  ok = mapOnly && ok;
  ok = Expect("shadow map, two lights", s.Mapper, 2) && ok;

  for (int i = 0; i < 4; ++i)
  {
    s.Renderer->GetActiveCamera()->Azimuth(20.0);
    s.Renderer->GetActiveCamera()->Elevation(5.0);
    s.Window->Render();
  }
  ok = Expect("camera moved 4 times", s.Mapper, 2) && ok;

  s.Key->SetPosition(0.5, 0.2, 1.0);
  s.Window->Render();
  ok = Expect("key light moved: only its map", s.Mapper, 3) && ok;

  s.Color->AddRGBPoint(200, 1, 0, 0);
  s.Window->Render();
  ok = Expect("colour changed: nothing", s.Mapper, 3) && ok;

  map->SetFilter(vtkDeepShadowShadowMapTechnique::PoissonDisc);
  map->SetBias(3.0);
  s.Window->Render();
  ok = Expect("filter and bias changed: lookup only", s.Mapper, 3) && ok;

  s.Opacity->AddPoint(120, 0.5);
  s.Window->Render();
  ok = Expect("opacity changed: both maps", s.Mapper, 5) && ok;

  map->SetThreshold(0.4);
  s.Window->Render();
  ok = Expect("threshold changed: both maps", s.Mapper, 7) && ok;

  s.Volume->SetPosition(3.0, 0.0, 0.0);
  s.Window->Render();
  ok = Expect("volume moved: both maps", s.Mapper, 9) && ok;

  s.Data->Modified();
  s.Window->Render();
  ok = Expect("data modified: both maps", s.Mapper, 11) && ok;

  s.Fill->SetShadowAttenuation(0.0);
  s.Window->Render();
  ok = Expect("fill light casts no shadow: nothing built", s.Mapper, 11) && ok;
  s.Techniques.push_back(map.Get());
  return ok;
}

bool Rays(Scene& s)
{
  bool ok = true;
  // Cached rays: same rules; uncached rays build nothing and carry the feeler instead.
  vtkNew<vtkDeepShadowRayTechnique> rays;
  rays->CachedOn();
  rays->SetShadowVolumeSize(24);
  s.Mapper->SetShadowTechnique(rays);
  s.Window->Render();
  ok = Expect("cached rays, one shadow-casting light", s.Mapper, 1) && ok;
  s.Renderer->GetActiveCamera()->Azimuth(30.0);
  s.Window->Render();
  ok = Expect("camera moved", s.Mapper, 1) && ok;
  s.Key->SetPosition(0.5, 0.4, 1.0);
  s.Window->Render();
  ok = Expect("light moved", s.Mapper, 2) && ok;
  ok = Contains(s.Mapper->GetFragmentShaderSource(), "u_shadowVolume") &&
    !Contains(s.Mapper->GetFragmentShaderSource(), "feelerTowardsLight") && ok;

  rays->CachedOff();
  s.Window->Render();
  ok = Expect("uncached rays build nothing", s.Mapper, 2) && ok;
  ok = Contains(s.Mapper->GetFragmentShaderSource(), "feelerTowardsLight") && ok;
  s.Techniques.push_back(rays.Get());
  return ok;
}

bool LightSpaceTechniques(Scene& s)
{
  bool ok = true;
  // The other light-space techniques, uncached and cached, with both lights casting: the
  // same rules, their own parameters, and only their own lookup in the shader.
  s.Fill->SetShadowAttenuation(1.0);
  vtkNew<vtkDeepShadowDeepShadowMapTechnique> dsm, dsmColor;
  vtkNew<vtkDeepShadowOpacityLevelsTechnique> levels;
  vtkNew<vtkDeepShadowStochasticShadowMapTechnique> cssm;
  dsmColor->ColoredOn();
  const char* lookups[] = { "filteredShadow", "dsmSearchStep", "levelsVisibility", "CSSM_OFFSET",
    "u_shadowVolume", "feelerTowardsLight" };
  const struct
  {
    vtkDeepShadowLightSpaceTechnique* Technique;
    const char* Lookup;
    bool Colored;
    std::function<void()> ChangeStructure; // a parameter the maps depend on
    std::function<void()> ChangeLookup;    // one only the lookup depends on (may be none)
  } techniques[] = {
    { dsm, "dsmSearchStep", false, [&] { dsm->SetEpsilon(0.05); }, nullptr },
    { dsmColor, "dsmSearchStep", true, [&] { dsmColor->SetLayers(4); }, nullptr },
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
    s.Mapper->SetShadowTechnique(technique);
    const std::string name = technique->GetName();
    auto step = [&](const std::string& what, int expected) {
      const int before = technique->GetBuildCount();
      s.Window->Render();
      const int built = technique->GetBuildCount() - before;
      const bool good = built == expected;
      std::printf("%-10s %-42s built %d (expected %d) %s\n", name.c_str(), what.c_str(), built,
        expected, good ? "ok" : "FAILED");
      ok = good && ok;
    };
    step("first render: both lights", 2);
    const std::string& source = s.Mapper->GetFragmentShaderSource();
    for (const char* lookup : lookups)
    {
      if (Contains(source, lookup) != (std::string(lookup) == t.Lookup))
      {
        std::printf("%s: the shader %s %s: FAILED\n", name.c_str(),
          Contains(source, lookup) ? "holds" : "lacks", lookup);
        ok = false;
      }
    }
    s.Renderer->GetActiveCamera()->Azimuth(25.0);
    step("camera moved", 0);
    s.Fill->SetShadowAttenuation(0.5);
    step("a light's shadow attenuation changed", 0);
    s.Color->AddRGBPoint(200, 1.0, 0.2, 0.2);
    step(t.Colored ? "colour changed: both (coloured)" : "colour changed: nothing (grey)", t.Colored ? 2 : 0);
    s.Color->RemovePoint(200);
    step("colour restored", t.Colored ? 2 : 0);
    t.ChangeStructure();
    step("own parameter changed: both", 2);
    s.Key->SetPosition(0.2, 0.3 + move, 1.0);
    step("key light moved: its own", 1);
    if (t.ChangeLookup)
    {
      t.ChangeLookup();
      step("lookup-only parameter changed: nothing", 0);
    }
    technique->CachedOn();
    step("cached: both caches", 2);
    ok = Contains(s.Mapper->GetFragmentShaderSource(), "u_shadowVolume") &&
      !Contains(s.Mapper->GetFragmentShaderSource(), t.Lookup) && ok;
    s.Renderer->GetActiveCamera()->Azimuth(25.0);
    step("cached, camera moved", 0);
    technique->SetShadowVolumeSize(20);
    step("cached, shadow volume size changed: both", 2);
    if (t.ChangeLookup)
    {
      cssm->SetOffsets(7);
      step("cached, lookup-only parameter changed: caches", 2);
    }
    s.Fill->SetPosition(-1.0, 0.4 + move, 0.5);
    step("cached, fill light moved: its own", 1);
    technique->CachedOff();
  }
  s.Techniques.insert(s.Techniques.end(), { dsm.Get(), dsmColor.Get(), levels.Get(), cssm.Get() });
  return ok;
}

// Interactive frames (the window asks for 15 frames a second) keep a structure whose light
// turned less than InteractiveShadowLag; the next still frame rebuilds it.
bool InteractiveLag(Scene& s)
{
  bool ok = true;
  vtkNew<vtkDeepShadowDeepShadowMapTechnique> dsm;
  dsm->SetMapSize(32);
  s.Mapper->SetShadowTechnique(dsm);
  s.Mapper->SetInteractiveShadowLag(10.0);
  s.Fill->SetShadowAttenuation(0.0);
  double degrees = 0.0;
  auto step = [&](const char* what, double turn, double rate, int expected) {
    degrees += turn; // the key light turned in the xy plane, around its focal point
    const double radians = degrees * 3.14159265358979323846 / 180.0;
    s.Key->SetPosition(std::cos(radians), std::sin(radians), 0.0);
    s.Window->SetDesiredUpdateRate(rate);
    const int before = dsm->GetBuildCount();
    s.Window->Render();
    const int built = dsm->GetBuildCount() - before;
    const bool good = built == expected;
    std::printf("lag 10: %-46s built %d (expected %d) %s\n", what, built, expected, good ? "ok" : "FAILED");
    ok = good && ok;
  };
  const double still = 0.0001, interactive = 15.0;
  step("still frame", 0.0, still, 1);
  step("interactive, key turned 5 degrees: kept", 5.0, interactive, 0);
  step("interactive, 7 degrees from its build: kept", 2.0, interactive, 0);
  step("interactive, 11 degrees from its build: rebuilt", 4.0, interactive, 1);
  step("interactive, 3 degrees from that build: kept", 3.0, interactive, 0);
  step("still frame, the light as it was: rebuilt", 0.0, still, 1);
  step("still frame again: nothing", 0.0, still, 0);
  step("still frame, key turned 2 degrees: rebuilt", 2.0, still, 1);
  dsm->CachedOn();
  step("cached, still: the cache", 0.0, still, 1);
  step("cached, interactive, 4 degrees: kept", 4.0, interactive, 0);
  step("cached, still: rebuilt", 0.0, still, 1);
  s.Mapper->SetInteractiveShadowLag(0.0);
  step("lag 0, interactive, 1 degree: rebuilt", 1.0, interactive, 1);
  s.Window->SetDesiredUpdateRate(still);
  s.Techniques.push_back(dsm.Get());
  return ok;
}
}

int TestShadowRebuilds(int, char*[])
{
  bool ok = true;
  Scene s;
  SetUp(s);
  ok = NoTechnique(s) && ok;
  ok = ShadowMap(s) && ok;
  ok = Rays(s) && ok;
  ok = LightSpaceTechniques(s) && ok;
  ok = InteractiveLag(s) && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
