// Shadow structures are rebuilt only when what they depend on changed, per light, and never
// because the camera moved; shader code exists only for the technique chosen.
#include "DeepShadowTestUtilities.h"
#include "vtkDeepShadowRayTechnique.h"
#include "vtkDeepShadowRenderWindow.h"
#include "vtkDeepShadowShadowMapTechnique.h"
#include "vtkDeepShadowVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkLight.h"
#include "vtkPiecewiseFunction.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

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
  const bool mapOnly = Contains(source, "mapVisibility") && !Contains(source, "cachedVisibility") &&
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
  ok = Contains(mapper->GetFragmentShaderSource(), "cachedVisibility") &&
    !Contains(mapper->GetFragmentShaderSource(), "feelerTowardsLight") && ok;

  rays->CachedOff();
  window->Render();
  ok = Expect("uncached rays build nothing", mapper, 2) && ok;
  ok = Contains(mapper->GetFragmentShaderSource(), "feelerTowardsLight") && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
