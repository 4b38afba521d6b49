// The light-space lookup compiles only the kinds of face its lights use (LIGHT_SPACE_
// ORTHOGRAPHIC, _PERSPECTIVE, _CUBES in Shaders/Shadows/LightSpace.glsl) and knows how many
// lights cast shadows (LIGHT_SPACE_SLOTS): a directional light, a point light outside the
// volume, one inside it (a cube of faces) and both kinds of light at once each compose their
// own lookup, and each picture still matches the CPU twin.
#include "DeepShadowTestUtilities.h"
#include "vtkDeepShadowDeepShadowMapTechnique.h"
#include "vtkDeepShadowRenderWindow.h"
#include "vtkDeepShadowVolumeMapper.h"

#include "vtkLight.h"

using deepshadow::testing::Check;

namespace
{
// The face kinds and the count of lights the volume's fragment shader defines, e.g.
// "ORTHOGRAPHIC PERSPECTIVE SLOTS 2".
std::string ComposedKinds(vtkDeepShadowVolumeMapper* mapper)
{
  const std::string& source = mapper->GetFragmentShaderSource();
  std::string kinds;
  for (const char* kind : { "ORTHOGRAPHIC", "PERSPECTIVE", "CUBES" })
  {
    if (source.find(std::string("#define LIGHT_SPACE_") + kind + "\n") != std::string::npos)
    {
      kinds += (kinds.empty() ? "" : " ") + std::string(kind);
    }
  }
  const std::string slots = "#define LIGHT_SPACE_SLOTS ";
  const size_t at = source.find(slots);
  if (at != std::string::npos)
  {
    kinds += " SLOTS " + source.substr(at + slots.size(), source.find('\n', at) - at - slots.size());
  }
  return kinds;
}

bool Expect(const char* step, deepshadow::testing::StandardSceneView& view, vtkRenderWindow* window,
  const std::string& expected)
{
  window->Render();
  const std::string kinds = ComposedKinds(view.Mapper);
  const bool composed = Check(std::string(step) + ": composes " + expected + " (got " + kinds + ")",
    kinds == expected && view.Mapper->GetLastError().empty());
  const deepshadow::Image gpu = deepshadow::testing::Grab(window);
  return deepshadow::testing::WithinTolerance(step, gpu, deepshadow::testing::Reference(view.Renderer, true),
           2.0 / 255.0, 8.0 / 255.0, 0.01) &&
    composed;
}
}

int TestLightSpaceFaceKinds(int, char*[])
{
  vtkNew<vtkDeepShadowRenderWindow> window;
  window->SetSize(96, 96);
  deepshadow::testing::StandardSceneView view("rods", 0.5, true);
  window->AddRenderer(view.Renderer);
  view.Renderer->SetBackground(0.08, 0.09, 0.12);
  view.Renderer->ResetCameraClippingRange();
  vtkNew<vtkDeepShadowDeepShadowMapTechnique> dsm;
  dsm->SetMapSize(96);
  view.Mapper->SetShadowTechnique(dsm);
  bool ok = true;

  ok = Expect("directional light", view, window, "ORTHOGRAPHIC SLOTS 1") && ok;

  const double* centre = view.Volume->GetCenter();
  const double radius = 0.5 * view.Volume->GetLength();
  double direction[3];
  view.Scene->GetLightDirection(direction);
  view.Light->SetPositional(true);
  view.Light->SetConeAngle(180.0);
  view.Light->SetFocalPoint(centre);
  view.Light->SetPosition(centre[0] + 3.0 * radius * direction[0], centre[1] + 3.0 * radius * direction[1],
    centre[2] + 3.0 * radius * direction[2]);
  ok = Expect("point light outside", view, window, "PERSPECTIVE SLOTS 1") && ok;

  view.Light->SetPosition(centre[0] + 0.2 * radius * direction[0], centre[1] + 0.2 * radius * direction[1],
    centre[2] + 0.2 * radius * direction[2]);
  ok = Expect("point light inside", view, window, "PERSPECTIVE CUBES SLOTS 1") && ok;

  vtkNew<vtkLight> sun;
  sun->SetLightTypeToSceneLight();
  sun->SetPosition(direction);
  sun->SetFocalPoint(0.0, 0.0, 0.0);
  sun->SetIntensity(0.5);
  view.Renderer->AddLight(sun);
  ok = Expect("point light inside and a directional one", view, window, "ORTHOGRAPHIC PERSPECTIVE CUBES SLOTS 2") && ok;

  view.Renderer->RemoveLight(view.Light);
  ok = Expect("the directional one alone again", view, window, "ORTHOGRAPHIC SLOTS 1") && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
