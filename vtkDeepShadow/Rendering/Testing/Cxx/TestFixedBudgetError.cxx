// Deep shadow maps at a fixed budget sized from an error (vtkDeepShadowFixedBudgetDeepShadow-
// MapTechnique::SetError), on the ball over a floor: the first build counts the nodes each
// texel needs, lays the maps out for their 99th percentile and builds again in the same frame;
// a light that moves a little rebuilds once at the same size; the picture matches the CPU
// twin (which counts the same way) within the translucent techniques' tolerance; a smaller
// error takes more nodes. (Against the ground truth both are 0.0175 here: the map's texels
// and the view's step, not the nodes, make this scene's error.)
#include "DeepShadowTestUtilities.h"
#include "vtkDeepShadowFixedBudgetDeepShadowMapTechnique.h"
#include "vtkDeepShadowReferenceRenderer.h"

#include <algorithm>
#include <cstdio>

using deepshadow::Image;
using deepshadow::testing::Check;
using deepshadow::testing::Grab;
using deepshadow::testing::WithinTolerance;

namespace
{
int Builds(vtkDeepShadowVolumeMapper* mapper)
{
  const std::vector<std::string>& passes = mapper->GetLastPasses();
  return static_cast<int>(std::count(passes.begin(), passes.end(), "light-space-build"));
}
}

int TestFixedBudgetError(int, char*[])
{
  bool ok = true;
  deepshadow::testing::ShadowScene scene;
  vtkNew<vtkDeepShadowReferenceRenderer> truth;
  truth->SetShadows(vtkDeepShadowReferenceRenderer::GroundTruthShadows);
  Image exact;
  ok = Check("the ground truth renders", truth->Render(scene.Renderer, exact)) && ok;
  int previousNodes = 0;
  for (double error : { 0.05, 0.005 })
  {
    vtkNew<vtkDeepShadowFixedBudgetDeepShadowMapTechnique> fixed;
    fixed->SetMapSize(256);
    fixed->SetError(error);
    scene.Mapper->SetShadowTechnique(fixed);
    scene.Window->Render();
    const int nodes = fixed->GetNodes();
    const int firstBuilds = Builds(scene.Mapper);
    std::printf("error %g: %d nodes (%g bits), %.4f of the texels beyond it, %d builds on the first frame\n", error,
      nodes, fixed->GetStatistic("texel_bits"), fixed->GetStatistic("fixed_nodes_beyond"), firstBuilds);
    ok = Check("  nodes even, 2 to 32, and 99 % of the texels within the error",
           nodes % 2 == 0 && nodes >= 2 && nodes <= 32 && fixed->GetStatistic("fixed_nodes_beyond") <= 0.01 &&
             fixed->GetStatistic("fixed_nodes") == nodes && scene.Mapper->GetLastError().empty()) && ok;
    ok = Check("  laid out again and built again on the first frame when the count is not the budget's",
           firstBuilds == (nodes == 8 ? 1 : 2)) && ok;
    const Image picture = Grab(scene.Window);
    ok = WithinTolerance(("  error " + std::to_string(error) + " vs its CPU twin").c_str(), picture,
           deepshadow::testing::Reference(scene.Renderer, true), 2.0 / 255.0, 12.0 / 255.0, 0.01) && ok;
    const double rmse = deepshadow::Compare(picture, exact).RMSE;
    std::printf("  RMSE against the ground truth %.5f\n", rmse);
    ok = Check("  a smaller error: more nodes", previousNodes == 0 || nodes > previousNodes) && ok;
    previousNodes = nodes;
    scene.Light->SetPosition(0.31, 0.2, 1.0);
    scene.Window->Render();
    ok = Check("  the light moved: built once, at the same nodes", Builds(scene.Mapper) == 1 && fixed->GetNodes() == nodes) &&
      ok;
    scene.Light->SetPosition(0.3, 0.2, 1.0);
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
