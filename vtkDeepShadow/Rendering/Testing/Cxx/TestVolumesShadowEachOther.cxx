// Several volumes in one scene (vtkDeepShadowPass): a smoke puff above the shadow scene's
// volume and a ground mesh under both. The smoke shadows the volume and the ground, the
// volume shadows the ground, each with its own technique; GPU against the CPU twin within
// the stated tolerances; the grids that carry one volume's shadows to the others are rebuilt
// only when what they depend on changed.
//
// Stated tolerances (GPU vs CPU twin), as TestHybridShadows: RMSE <= 2/255, at most 1% of
// pixels beyond 12/255.
#include "DeepShadowTestUtilities.h"
#include "vtkDeepShadowDeepShadowMapTechnique.h"
#include "vtkDeepShadowPass.h"
#include "vtkDeepShadowPolyDataMapper.h"
#include "vtkDeepShadowRayTechnique.h"

#include "vtkActor.h"
#include "vtkProperty.h"

#include <cmath>
#include <cstdlib>

using deepshadow::testing::Check;
using deepshadow::testing::Grab;
using deepshadow::testing::HasFeature;
using deepshadow::testing::WithinTolerance;

int TestVolumesShadowEachOther(int argc, char* argv[])
{
  deepshadow::testing::ShadowScene scene;
  vtkDeepShadowRenderWindow* window = scene.Window;
  vtkRenderer* renderer = scene.Renderer;
  bool ok = true;
  vtkNew<vtkDeepShadowPass> pass;
  renderer->SetPass(pass);
  window->SetSize(200, 160);

  // The smoke above the volume (which spans [-47, 47]^3), grey and faint.
  vtkNew<vtkColorTransferFunction> smokeColor;
  smokeColor->AddRGBPoint(0, 0.8, 0.8, 0.85);
  smokeColor->AddRGBPoint(255, 0.95, 0.95, 1.0);
  vtkNew<vtkPiecewiseFunction> smokeOpacity;
  smokeOpacity->AddPoint(0, 0.0);
  smokeOpacity->AddPoint(20, 0.0);
  smokeOpacity->AddPoint(255, 0.8);
  vtkNew<vtkVolumeProperty> smokeProperty;
  smokeProperty->SetColor(smokeColor);
  smokeProperty->SetScalarOpacity(smokeOpacity);
  smokeProperty->SetAmbient(0.3);
  vtkNew<vtkDeepShadowVolumeMapper> smokeMapper;
  smokeMapper->SetShadingModelToBlinnPhong(); // as the scene's
  smokeMapper->SetInputData(deepshadow::testing::MakeSmokeVolume({ 25.0, 15.0, 80.0 })); // its shadow falls on the plate
  vtkNew<vtkVolume> smoke;
  smoke->SetMapper(smokeMapper);
  smoke->SetProperty(smokeProperty);
  renderer->AddVolume(smoke);
  // One sample distance for both volumes (the CPU twin marches every volume with one).
  scene.Mapper->SetSampleDistance(1.0);
  smokeMapper->SetSampleDistance(1.0);

  vtkNew<vtkDeepShadowPolyDataMapper> groundMapper;
  vtkNew<vtkActor> ground;
  scene.AddGround(groundMapper, ground);
  ground->GetProperty()->SetColor(0.85, 0.85, 0.8);

  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, -3.0, 1.2);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->ResetCamera();
  camera->Zoom(1.3);
  renderer->ResetCameraClippingRange();

  // The volume (added first: the meshes' source) with rays, the smoke with a deep shadow map.
  vtkNew<vtkDeepShadowRayTechnique> rays;
  vtkNew<vtkDeepShadowDeepShadowMapTechnique> dsm;
  scene.Mapper->SetShadowTechnique(rays);
  smokeMapper->SetShadowTechnique(dsm);
  window->Render();
  const deepshadow::Image gpu = Grab(window);
  ok = WithinTolerance("two volumes and a ground: rays + dsm", gpu,
         deepshadow::testing::Reference(renderer, true), 2.0 / 255.0, 12.0 / 255.0, 0.01) && ok;
  ok = Check("the volume and the ground read the smoke's shadows",
         HasFeature(scene.Mapper, "OtherVolumeShadows") && HasFeature(groundMapper->GetShaderFeatures(), "OtherVolumeShadows")) && ok;
  ok = Check("the smoke reads the volume's (" + std::to_string(pass->GetOtherVolumeShadowBuilds()) + " grids built, " +
           std::to_string(pass->GetOtherVolumeShadowBytes()) + " bytes)",
         HasFeature(smokeMapper, "OtherVolumeShadows") && pass->GetOtherVolumeShadowBuilds() == 3) && ok;

  // The smoke's shadow is there: pixels outside the smoke's own footprint (the volume and
  // the ground) are darker than when the smoke casts nothing (a shadow property of opacity 0).
  scene.Volume->VisibilityOff();
  ground->VisibilityOff();
  window->Render();
  const deepshadow::Image smokeOnly = Grab(window);
  scene.Volume->VisibilityOn();
  ground->VisibilityOn();
  vtkNew<vtkPiecewiseFunction> nothing;
  nothing->AddPoint(0, 0.0);
  nothing->AddPoint(255, 0.0);
  vtkNew<vtkVolumeProperty> castsNothing;
  castsNothing->SetScalarOpacity(nothing);
  dsm->SetShadowProperty(castsNothing);
  window->Render();
  const deepshadow::Image noSmokeShadow = Grab(window);
  if (const char* directory = std::getenv("DEEPSHADOW_TEST_IMAGES"))
  {
    deepshadow::WritePNG(noSmokeShadow, std::string(directory) + "/the_smoke_casting_nothing.png");
  }
  dsm->SetShadowProperty(nullptr);
  int darker = 0, brighter = 0, outside = 0;
  for (int y = 0; y < gpu.Height; ++y)
    for (int x = 0; x < gpu.Width; ++x)
    {
      if (glm::length(smokeOnly.At(x, y) - glm::dvec3(0.05, 0.05, 0.08)) > 0.01)
      {
        continue; // the smoke's own pixels
      }
      ++outside;
      const double change = glm::length(gpu.At(x, y) - noSmokeShadow.At(x, y));
      darker += change > 0.05 && gpu.At(x, y).g < noSmokeShadow.At(x, y).g ? 1 : 0;
      brighter += change > 0.02 && gpu.At(x, y).g > noSmokeShadow.At(x, y).g ? 1 : 0;
    }
  ok = Check("the smoke shadows the volume and the ground (" + std::to_string(darker) + " of " +
           std::to_string(outside) + " pixels darker, " + std::to_string(brighter) + " brighter)",
         darker > outside / 100 && brighter == 0) && ok;

  // Twins with other techniques: a cached receiver (its grid and the others' are separate)
  // and coloured smoke.
  {
    rays->CachedOn();
    dsm->ColoredOn();
    window->Render();
    ok = WithinTolerance("two volumes and a ground: rays-cached + dsm-color", Grab(window),
           deepshadow::testing::Reference(renderer, true), 2.0 / 255.0, 12.0 / 255.0, 0.01) && ok;
    rays->CachedOff();
    dsm->ColoredOff();
  }

  // Rebuilds. A second frame, a camera move or a colour the shadows do not depend on rebuild
  // no grid. Moving the smoke rebuilds all three: the two it casts into (the volume's and the
  // ground's) and its own, which moved with it. Moving the volume rebuilds two: its own and
  // the smoke's; not the ground's, which holds the smoke alone (the volume is its source).
  window->Render();
  int builds = pass->GetOtherVolumeShadowBuilds();
  window->Render();
  camera->Azimuth(5.0);
  window->Render();
  scene.Color->AddRGBPoint(60, 0.3, 0.9, 0.3);
  window->Render();
  ok = Check("frames, a camera move and a colour change rebuild no grid",
         pass->GetOtherVolumeShadowBuilds() == builds) && ok;
  smoke->SetPosition(5.0, 0.0, 0.0);
  window->Render();
  ok = Check("moving the smoke rebuilds the three grids (" +
           std::to_string(pass->GetOtherVolumeShadowBuilds() - builds) + ")",
         pass->GetOtherVolumeShadowBuilds() == builds + 3) && ok;
  builds = pass->GetOtherVolumeShadowBuilds();
  scene.Volume->SetPosition(0.0, 0.0, -2.0);
  window->Render();
  ok = Check("moving the volume rebuilds its grid and the smoke's (" +
           std::to_string(pass->GetOtherVolumeShadowBuilds() - builds) + ")",
         pass->GetOtherVolumeShadowBuilds() == builds + 2) && ok;
  scene.Volume->SetPosition(0.0, 0.0, 0.0);
  smoke->SetPosition(0.0, 0.0, 0.0);
  scene.Color->RemovePoint(60);
  camera->Azimuth(-5.0);

  // One shadowing volume: no grid, no feature; its shadows reach the ground directly.
  smokeMapper->SetShadowTechnique(nullptr);
  window->Render();
  ok = Check("with one shadowing volume no grid is read",
         !HasFeature(scene.Mapper, "OtherVolumeShadows") && !HasFeature(groundMapper->GetShaderFeatures(), "OtherVolumeShadows") &&
           pass->GetOtherVolumeShadowBytes() == 0) && ok;
  smokeMapper->SetShadowTechnique(dsm);

  window->Render();
  const int result = deepshadow::testing::RegressionTestImage(window, argc, argv);
  return ok && result != vtkTesting::FAILED ? EXIT_SUCCESS : EXIT_FAILURE;
}
