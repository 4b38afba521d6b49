// vtkDeepShadowPolyDataMapper against VTK's own vtkPolyDataMapper, without shadows: the same
// mesh, property and lights give the same picture. Cases: the headlight; vtkLightKit (its two
// back lights sit behind what the camera sees: a surface is lit one-sided, as VTK lights it,
// not by |N.L|); a light from the side, with two-sided lighting and without; a plane seen from
// behind (two-sided lighting turns its normal to the viewer); scalars mapped through a lookup
// table with InterpolateScalarsBeforeMapping on (ParaView's default).
//
// Stated tolerance: RMSE <= 0.004 and <= 0.5 % of pixels off by more than 8/255 (measured:
// 0 to 0.00001, and 0.00145 for the scalars: VTK interpolates them as texture coordinates, we
// as colours). Before the mesh was lit as VTK lights polygons (one-sided per light after a back
// face's normal is turned, Phong's reflection, VTK's lone-headlight path, the property's
// specular colour), the light kit's sphere was 202 against 170 of 255 at its centre (RMSE
// 0.021), the side light lit its far side, and the mapped scalars came out in the property's
// colour.
// The check must fail: the control draws ours with the diffuse light 0.8 of VTK's.
#include "DeepShadowTestUtilities.h"
#include "vtkDeepShadowPolyDataMapper.h"
#include "vtkDeepShadowRenderWindow.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkElevationFilter.h"
#include "vtkLight.h"
#include "vtkLightKit.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"

#include <cstdio>
#include <cstdlib>
#include <string>

namespace
{
enum class Lights
{
  Headlight,
  Kit,
  Side
};

struct Case
{
  const char* Name;
  Lights Lighting;
  bool TwoSided;
  bool Plane;  // a plane seen from behind, instead of the sphere
  bool Scalars; // coloured by the elevation through a lookup table, interpolated before mapping
};

deepshadow::Image Draw(vtkRenderWindow* window, vtkPolyDataMapper* mapper, const Case& c, double diffuse)
{
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.1, 0.1, 0.2);
  renderer->SetTwoSidedLighting(c.TwoSided);
  window->GetRenderers()->RemoveAllItems();
  window->AddRenderer(renderer);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(64);
  sphere->SetPhiResolution(64);
  vtkNew<vtkPlaneSource> plane; // normal +z: the camera below sees its back
  vtkNew<vtkElevationFilter> elevation;
  elevation->SetInputConnection(c.Plane ? plane->GetOutputPort() : sphere->GetOutputPort());
  elevation->SetLowPoint(0.0, -0.5, 0.0);
  elevation->SetHighPoint(0.0, 0.5, 0.0);
  vtkNew<vtkLookupTable> table;
  table->SetHueRange(0.66, 0.0);
  table->Build();
  mapper->SetInputConnection(elevation->GetOutputPort());
  mapper->SetScalarVisibility(c.Scalars);
  mapper->SetLookupTable(table);
  mapper->SetScalarRange(0.0, 1.0);
  mapper->SetInterpolateScalarsBeforeMapping(c.Scalars);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.85, 0.85, 0.8);
  actor->GetProperty()->SetSpecular(0.3);
  actor->GetProperty()->SetSpecularPower(20.0);
  actor->GetProperty()->SetDiffuse(diffuse);
  renderer->AddActor(actor);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, 0.0, c.Plane ? -3.0 : 3.0);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  if (c.Lighting == Lights::Kit)
  {
    vtkNew<vtkLightKit> kit;
    kit->AddLightsToRenderer(renderer);
  }
  else if (c.Lighting == Lights::Side)
  {
    vtkNew<vtkLight> light; // a scene light from +x, a little in front
    light->SetLightTypeToSceneLight();
    light->SetPosition(1.0, 0.2, 0.3);
    light->SetFocalPoint(0.0, 0.0, 0.0);
    light->SetPositional(false);
    renderer->AddLight(light);
  }
  renderer->ResetCamera();
  window->Render();
  return deepshadow::testing::Grab(window);
}
}

int TestMeshesMatchVTK(int, char*[])
{
  const Case cases[] = {
    { "headlight", Lights::Headlight, true, false, false },
    { "vtkLightKit", Lights::Kit, true, false, false },
    { "side light, two-sided", Lights::Side, true, false, false },
    { "side light, one-sided", Lights::Side, false, false, false },
    { "plane seen from behind, two-sided", Lights::Kit, true, true, false },
    { "scalars interpolated before mapping", Lights::Kit, true, false, true },
  };
  vtkNew<vtkDeepShadowRenderWindow> window;
  window->SetSize(200, 200);
  bool ok = true;
  for (const Case& c : cases)
  {
    vtkNew<vtkDeepShadowPolyDataMapper> ours;
    vtkNew<vtkPolyDataMapper> theirs;
    vtkNew<vtkDeepShadowPolyDataMapper> dimmer;
    const deepshadow::Image a = Draw(window, ours, c, 1.0);
    if (!ours->GetLastError().empty())
    {
      std::printf("%s: %s\n", c.Name, ours->GetLastError().c_str());
      return EXIT_FAILURE;
    }
    const deepshadow::Image b = Draw(window, theirs, c, 1.0);
    const deepshadow::Image control = Draw(window, dimmer, c, 0.8);
    ok = deepshadow::testing::WithinTolerance(c.Name, a, b, 0.004, 8.0 / 255.0, 0.005) && ok;
    const std::string name = std::string(c.Name) + ", diffuse 0.8 (must fail)";
    ok = !deepshadow::testing::WithinTolerance(name.c_str(), control, b, 0.004, 8.0 / 255.0, 0.005) && ok;
    ok = deepshadow::testing::Check(std::string(c.Name) + ": drawn",
           deepshadow::testing::CoveredFraction(a, { 0.1, 0.1, 0.2 }) > 0.1) && ok;
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
