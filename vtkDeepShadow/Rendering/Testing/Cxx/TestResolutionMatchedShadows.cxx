// Resolution-matched shadow maps (vtkDeepShadowResolutionMatchedTechnique, paper 004) on the
// GPU: the shadow scene's volume, a small caster, over a large ground mesh, the camera close
// to the ground where the volume's shadow ends. The GPU matches its CPU twin (which makes the
// same page requests from the same camera) within the binary tolerances of
// TestShadowTechniques; against exact opaque visibility (the CPU's opaque rays) its error is
// well below a 512^2 shadow map's; a second frame builds no page, a turned camera only the
// pages it newly needs, and without kept pages every frame builds them all (the same
// picture); an atlas too small for the pages coarsens the finest level; one too small for
// the base level is a clear error. The page table's upload leaves GL's pixel store as it
// found it.
#include "DeepShadowTestUtilities.h"
#include "vtkDeepShadowPass.h"
#include "vtkDeepShadowPolyDataMapper.h"
#include "vtkDeepShadowRayTechnique.h"
#include "vtkDeepShadowResolutionMatchedTechnique.h"
#include "vtkDeepShadowShadowMapTechnique.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkPlaneSource.h"
#include "vtkProperty.h"
#include "vtk_glew.h"

#include <string>

using deepshadow::testing::Check;
using deepshadow::testing::Grab;
using deepshadow::testing::WithinTolerance;

namespace
{
std::string Counts(vtkDeepShadowResolutionMatchedTechnique* rmsm)
{
  return std::to_string(rmsm->GetPagesRequested()) + " requests, " + std::to_string(rmsm->GetRequestsAfterComponents()) +
    " after components, " + std::to_string(rmsm->GetPagesUnique()) + " unique, " +
    std::to_string(rmsm->GetPagesRendered()) + " built in " + std::to_string(rmsm->GetSuperpages()) +
    " superpages, " + std::to_string(rmsm->GetPagesResident()) + " resident";
}
}

int TestResolutionMatchedShadows(int argc, char* argv[])
{
  deepshadow::testing::ShadowScene scene;
  vtkDeepShadowRenderWindow* window = scene.Window;
  vtkRenderer* renderer = scene.Renderer;
  bool ok = true;
  vtkNew<vtkDeepShadowPass> pass;
  renderer->SetPass(pass);
  // The volume spans [-47, 47]^3; the ground, 8 times as wide, lies just under it.
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-400.0, -400.0, -52.0);
  plane->SetPoint1(400.0, -400.0, -52.0);
  plane->SetPoint2(-400.0, 400.0, -52.0);
  vtkNew<vtkDeepShadowPolyDataMapper> groundMapper;
  groundMapper->SetInputConnection(plane->GetOutputPort());
  vtkNew<vtkActor> ground;
  ground->SetMapper(groundMapper);
  ground->GetProperty()->SetColor(0.85, 0.85, 0.8);
  renderer->AddActor(ground);
  // Close to the ground by the volume's corner, looking along the edge of its shadow.
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(40.0, -110.0, -30.0);
  camera->SetFocalPoint(30.0, -40.0, -52.0);
  camera->SetViewUp(0.0, 0.0, 1.0);
  camera->SetViewAngle(30.0);
  renderer->ResetCameraClippingRange();
  window->SetSize(160, 160);

  window->Render(); // unshadowed: the GL state VTK keeps
  GLint unpackBefore = 0;
  glGetIntegerv(GL_UNPACK_ALIGNMENT, &unpackBefore);
  vtkNew<vtkDeepShadowResolutionMatchedTechnique> rmsm;
  deepshadow::Image gpu;
  ok = scene.MatchesTwin("rmsm vs CPU twin", rmsm, 4.0 / 255.0, 24.0 / 255.0, 0.03, gpu) && ok;
  const int pagesBuilt = rmsm->GetPagesRendered();
  // The page table's upload leaves GL's pixel store as it found it: with the unpack alignment
  // set to 4 behind VTK's state, a later texture of odd rows (a second volume's block map)
  // was read with padding that was not there, different in every run.
  GLint unpackAfter = 0;
  glGetIntegerv(GL_UNPACK_ALIGNMENT, &unpackAfter);
  ok = Check("GL's unpack alignment after the page table's upload (" + std::to_string(unpackAfter) +
               ") is the one before (" + std::to_string(unpackBefore) + ")",
         unpackAfter == unpackBefore) && ok;
  ok = Check("one analysis per frame, though the pass and the mapper both prepare", rmsm->GetAnalyses() == 1) && ok;
  ok = Check("the analysis deduplicates (" + Counts(rmsm) + ")",
         rmsm->GetPagesRequested() > 40 * 40 / 4 && rmsm->GetRequestsAfterComponents() < rmsm->GetPagesRequested() / 4 &&
           rmsm->GetPagesUnique() > 0 && rmsm->GetPagesUnique() <= rmsm->GetRequestsAfterComponents() &&
           pagesBuilt == rmsm->GetPagesResident() && pagesBuilt > 16 && rmsm->GetSuperpages() >= 1) && ok;
  ok = Check("the finest level is used (" + std::to_string(rmsm->GetFinestLevelUsed()) + ")",
         rmsm->GetFinestLevelUsed() == 9) && ok;

  // Against exact opaque visibility: the error is the 512^2 map's at most half.
  vtkNew<vtkDeepShadowRayTechnique> exact;
  exact->OpaqueOn();
  scene.Mapper->SetShadowTechnique(exact);
  const deepshadow::Image truth = deepshadow::testing::Reference(renderer, false);
  vtkNew<vtkDeepShadowShadowMapTechnique> map;
  scene.Mapper->SetShadowTechnique(map);
  window->Render();
  const double mapError = deepshadow::Compare(Grab(window), truth).RMSE, rmsmError = deepshadow::Compare(gpu, truth).RMSE;
  char text[160];
  std::snprintf(text, sizeof(text), "against exact visibility: RMSE %.4f, the 512^2 map's %.4f", rmsmError, mapError);
  ok = Check(text, rmsmError < 0.5 * mapError) && ok;

  // Kept pages: the same view builds none, a turned camera only the pages it newly needs.
  scene.Mapper->SetShadowTechnique(rmsm);
  window->Render();
  const int builds = rmsm->GetBuildCount();
  const int analyses = rmsm->GetAnalyses();
  window->Render();
  ok = Check("the same view runs no analysis and builds no page",
         rmsm->GetAnalyses() == analyses && rmsm->GetBuildCount() == builds) && ok;
  camera->Azimuth(3.0);
  window->Render();
  const deepshadow::Image turned = Grab(window);
  ok = Check("a turned camera builds only new pages (" + Counts(rmsm) + ")",
         rmsm->GetPagesRendered() > 0 && rmsm->GetPagesRendered() < rmsm->GetPagesResident() &&
           rmsm->GetBuildCount() == builds + 1) && ok;
  ok = WithinTolerance("rmsm, turned, vs CPU twin", turned, deepshadow::testing::Reference(renderer, true), 4.0 / 255.0,
         24.0 / 255.0, 0.03) && ok;
  // Without kept pages every frame builds all it needs: the same picture.
  vtkNew<vtkDeepShadowResolutionMatchedTechnique> fresh;
  fresh->KeepPagesOff();
  scene.Mapper->SetShadowTechnique(fresh);
  window->Render();
  window->Render();
  ok = Check("without kept pages every frame builds them all (" + Counts(fresh) + ")",
         fresh->GetPagesRendered() == fresh->GetPagesResident() && fresh->GetPagesRendered() > 16) && ok;
  ok = Check("and draws the same picture", deepshadow::Compare(Grab(window), turned).MaxAbs == 0.0) && ok;

  // An atlas of 8 x 8 slots cannot hold the finest pages: a coarser finest level.
  fresh->SetAtlasSize(8 * 34);
  window->Render();
  ok = Check("a small atlas coarsens the finest level (" + std::to_string(fresh->GetFinestLevelUsed()) + ", " +
      Counts(fresh) + ")",
         fresh->GetFinestLevelUsed() < 9 && fresh->GetPagesResident() <= 64 && scene.Mapper->GetLastError().empty()) && ok;
  // A page size that is no power of 2 is refused, the old one kept.
  vtkNew<deepshadow::testing::MessageCapture> refused;
  refused->Watch(fresh);
  fresh->SetPageSize(50);
  ok = Check("a page size of 50 is an error, 32 kept",
         fresh->GetPageSize() == 32 && refused->ErrorContains("page-size must be 16, 32, 64 or 128")) && ok;
  // One slot cannot hold the base level's 16 pages: said, nothing shadowed.
  fresh->SetAtlasSize(64);
  vtkNew<deepshadow::testing::MessageCapture> messages;
  messages->Watch(scene.Mapper);
  window->Render();
  ok = Check("an atlas too small for the base level is said (" + scene.Mapper->GetLastError() + ")",
         scene.Mapper->GetLastError().find("atlas") != std::string::npos) && ok;

  // Several lights at once: a positional one outside (a perspective face), one inside the
  // casters' bounding sphere (a cube of six faces) and the directional one; each light's
  // pages on its own faces, GPU against twin.
  vtkNew<vtkLight> outside, inside;
  outside->SetLightTypeToSceneLight();
  outside->SetPositional(true);
  outside->SetConeAngle(180.0);
  outside->SetPosition(-60.0, -200.0, 150.0);
  outside->SetDiffuseColor(0.5, 0.7, 1.0);
  inside->SetLightTypeToSceneLight();
  inside->SetPositional(true);
  inside->SetConeAngle(180.0);
  inside->SetPosition(20.0, -60.0, 10.0);
  inside->SetIntensity(0.6);
  renderer->AddLight(outside);
  renderer->AddLight(inside);
  vtkNew<vtkDeepShadowResolutionMatchedTechnique> lights;
  ok = scene.MatchesTwin("rmsm, three lights (a cube among them), vs CPU twin", lights, 4.0 / 255.0, 24.0 / 255.0,
         0.03, gpu) && ok;
  ok = Check("pages on the faces of three lights (" + Counts(lights) + ")", lights->GetPagesResident() > 16 * 8) && ok;
  renderer->RemoveLight(outside);
  renderer->RemoveLight(inside);

  scene.Mapper->SetShadowTechnique(rmsm);
  camera->Azimuth(-3.0);
  window->Render();
  const int result = deepshadow::testing::RegressionTestImage(window, argc, argv);
  return ok && result != vtkTesting::FAILED ? EXIT_SUCCESS : EXIT_FAILURE;
}
