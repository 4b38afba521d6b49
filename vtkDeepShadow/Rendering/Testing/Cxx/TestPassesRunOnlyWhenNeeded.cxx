// On every standard scene, the GPU passes a frame runs (vtkDeepShadowVolumeMapper::
// GetLastPasses()) are exactly those what changed needs:
// - an unshadowed render runs no light-space pass and composes no shadow code;
// - moving only the camera runs the ray cast alone, shadowed or not, cached or not;
// - moving the light rebuilds its map (and cache), nothing of the volume;
// - an opacity change rebuilds the drawn table, the block map, the feeler table and the map;
// - a colour change rebuilds only the drawn table for a grey technique;
// - the light's intensity rebuilds nothing.
// "light-space-deferred" (texels whose nodes overflowed) depends on the data and is left out
// of the comparison.
#include "DeepShadowTestUtilities.h"
#include "vtkDeepShadowDeepShadowMapTechnique.h"
#include "vtkDeepShadowStandardScene.h"

#include "vtkLightCollection.h"

#include <algorithm>

namespace
{
std::string Join(const std::vector<std::string>& passes)
{
  std::string text;
  for (const std::string& pass : passes)
  {
    if (pass != "light-space-deferred")
    {
      text += (text.empty() ? "" : " ") + pass;
    }
  }
  return text;
}

bool ExpectPasses(const std::string& scene, const char* step, vtkDeepShadowRenderWindow* window,
  vtkDeepShadowVolumeMapper* mapper, const std::string& expected)
{
  window->Render();
  const std::string passes = Join(mapper->GetLastPasses());
  const bool ok = passes == expected && mapper->GetLastError().empty();
  std::printf("%-8s %-28s %-70s %s\n", scene.c_str(), step, passes.c_str(), ok ? "ok" : "FAILED");
  if (!ok)
  {
    std::printf("         expected %s %s\n", expected.c_str(), mapper->GetLastError().c_str());
  }
  return ok;
}

bool HasShadowCode(vtkDeepShadowVolumeMapper* mapper)
{
  const auto& features = mapper->GetShaderFeatures();
  const bool feature = std::any_of(features.begin(), features.end(), [](const std::string& f) {
    return f.rfind("Shadow", 0) == 0 || f.rfind("Feeler", 0) == 0;
  });
  return feature || mapper->GetFragmentShaderSource().find("lightVisibility") != std::string::npos;
}
}

int TestPassesRunOnlyWhenNeeded(int, char*[])
{
  bool ok = true;
  for (const std::string& name : vtkDeepShadowStandardScene::GetSceneNames())
  {
    vtkNew<vtkDeepShadowRenderWindow> window;
    window->SetSize(48, 48);
    // The passes do not depend on the size; the time does.
    deepshadow::testing::StandardSceneView view(name, 0.25, true);
    vtkDeepShadowStandardScene* source = view.Scene;
    vtkDeepShadowVolumeMapper* mapper = view.Mapper;
    vtkLight* light = view.Light;
    window->AddRenderer(view.Renderer);
    double direction[3];
    source->GetLightDirection(direction);
    vtkCamera* camera = view.Renderer->GetActiveCamera();

    ok = ExpectPasses(name, "first frame, unshadowed", window, mapper,
           "volume-upload transfer-table occupancy ray-cast") && ok;
    ok = deepshadow::testing::Check(name + ": no shadow code composed", !HasShadowCode(mapper)) && ok;
    camera->Azimuth(10.0);
    ok = ExpectPasses(name, "camera moved", window, mapper, "ray-cast") && ok;

    vtkNew<vtkDeepShadowDeepShadowMapTechnique> dsm;
    dsm->SetMapSize(64);
    mapper->SetShadowTechnique(dsm);
    ok = ExpectPasses(name, "dsm chosen", window, mapper, "feeler-table light-space-build ray-cast") && ok;
    camera->Azimuth(10.0);
    ok = ExpectPasses(name, "dsm, camera moved", window, mapper, "ray-cast") && ok;
    light->SetPosition(direction[0] + 0.2, direction[1], direction[2]);
    ok = ExpectPasses(name, "dsm, light moved", window, mapper, "light-space-build ray-cast") && ok;
    light->SetIntensity(0.7);
    ok = ExpectPasses(name, "dsm, light intensity", window, mapper, "ray-cast") && ok;
    vtkPiecewiseFunction* opacity = source->GetVolumeProperty()->GetScalarOpacity();
    double range[2];
    opacity->GetRange(range);
    opacity->AddPoint(range[1], 1.0);
    ok = ExpectPasses(name, "dsm, opacity changed", window, mapper,
           "transfer-table occupancy feeler-table light-space-build ray-cast") && ok;
    source->GetVolumeProperty()->GetRGBTransferFunction()->AddRGBPoint(range[1], 0.2, 0.9, 0.1);
    ok = ExpectPasses(name, "dsm, colour changed", window, mapper, "transfer-table ray-cast") && ok;

    dsm->CachedOn();
    dsm->SetShadowVolumeSize(16);
    ok = ExpectPasses(name, "dsm cached", window, mapper, "shadow-cache ray-cast") && ok;
    camera->Azimuth(10.0);
    ok = ExpectPasses(name, "dsm cached, camera moved", window, mapper, "ray-cast") && ok;
    light->SetPosition(direction[0], direction[1] + 0.2, direction[2]);
    ok = ExpectPasses(name, "dsm cached, light moved", window, mapper,
           "light-space-build shadow-cache ray-cast") && ok;

    mapper->SetShadowTechnique(nullptr);
    ok = ExpectPasses(name, "shadows off again", window, mapper, "ray-cast") && ok;
    ok = deepshadow::testing::Check(name + ": no shadow code composed", !HasShadowCode(mapper)) && ok;
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
