// Clustered deep shadow maps on the GPU (vtkDeepShadowLightSpaceTechnique::SetClusters) on the
// sparse scene: against their CPU twin and the ground truth, better than one map of the same
// size, composed only when in use, and rebuilt only when the clustering changes.
#include "DeepShadowTestUtilities.h"
#include "vtkDeepShadowDeepShadowMapTechnique.h"
#include "vtkDeepShadowReferenceRenderer.h"
#include "vtkDeepShadowRenderWindow.h"
#include "vtkDeepShadowStandardScene.h"
#include "vtkDeepShadowVolumeMapper.h"

#include "vtkCamera.h"

using deepshadow::testing::Check;
using deepshadow::testing::Grab;
using deepshadow::testing::WithinTolerance;

namespace
{
deepshadow::Image GroundTruth(vtkRenderer* renderer)
{
  vtkNew<vtkDeepShadowReferenceRenderer> reference;
  reference->SetShadows(vtkDeepShadowReferenceRenderer::GroundTruthShadows);
  deepshadow::Image image;
  reference->Render(renderer, image);
  return image;
}
}

int TestClusteredShadows(int, char*[])
{
  vtkNew<vtkDeepShadowRenderWindow> window;
  window->SetSize(160, 160);
  deepshadow::testing::StandardSceneView view("sparse", 0.5, true);
  window->AddRenderer(view.Renderer);
  view.Renderer->SetBackground(0.08, 0.09, 0.12);
  view.Renderer->ResetCameraClippingRange();
  vtkNew<vtkDeepShadowDeepShadowMapTechnique> dsm;
  dsm->SetMapSize(128);
  view.Mapper->SetShadowTechnique(dsm);
  bool ok = true;

  window->Render();
  const deepshadow::Image single = Grab(window);
  ok = Check("one map: no clustered lookup composed",
         view.Mapper->GetFragmentShaderSource().find("#define LIGHT_SPACE_CLUSTERS") == std::string::npos) && ok;

  dsm->SetClusters(4);
  window->Render();
  const deepshadow::Image clustered = Grab(window);
  const std::vector<int> counts = dsm->GetClusterCounts();
  std::printf("clusters of the key light: %d\n", counts.empty() ? 0 : counts.front());
  ok = Check("2 to 4 clusters", counts.size() == 1 && counts.front() >= 2 && counts.front() <= 4) && ok;
  ok = Check("clustered lookup composed",
         view.Mapper->GetFragmentShaderSource().find("#define LIGHT_SPACE_CLUSTERS") != std::string::npos) && ok;
  ok = Check("something drawn", deepshadow::testing::CoveredFraction(clustered, { 0.08, 0.09, 0.12 }) > 0.05) && ok;

  // Against the CPU twin (the same clusters, faces and lookup in double precision), and the
  // ground truth: closer to it than one map of the same size.
  ok = WithinTolerance("clustered vs CPU twin", clustered, deepshadow::testing::Reference(view.Renderer, true),
         2.0 / 255.0, 8.0 / 255.0, 0.01) && ok;
  const deepshadow::Image truth = GroundTruth(view.Renderer);
  const double clusteredError = deepshadow::Compare(clustered, truth, 2.0 / 255.0).RMSE;
  const double singleError = deepshadow::Compare(single, truth, 2.0 / 255.0).RMSE;
  std::printf("against the ground truth: RMSE %.5f clustered, %.5f one map of 128^2\n", clusteredError, singleError);
  ok = Check("clusters closer to the ground truth than one map", clusteredError < singleError) && ok;

  // An unchanged frame, and a small camera move, keep the clustering and rebuild nothing;
  // fewer clusters rebuild.
  const int builds = view.Mapper->GetShadowBuilds();
  window->Render();
  ok = Check("unchanged frame: no rebuild", view.Mapper->GetShadowBuilds() == builds) && ok;
  view.Renderer->GetActiveCamera()->Azimuth(1.0);
  window->Render();
  ok = Check("camera moved by 1 degree: clustering kept, no rebuild", view.Mapper->GetShadowBuilds() == builds) && ok;
  dsm->SetClusters(2);
  window->Render();
  ok = Check("two clusters at most: rebuilt", view.Mapper->GetShadowBuilds() > builds &&
         dsm->GetClusterCounts().front() == 2) && ok;
  ok = Check("no error", view.Mapper->GetLastError().empty()) && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
