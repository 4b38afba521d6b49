// The shadow-term output (vtkDeepShadowVolumeMapper and vtkDeepShadowPolyDataMapper::
// OutputShadowTerm), which the report uses
// to measure a technique's error in the light-attenuation term alone:
// - without a technique it is the volume's coverage in grey (every sample's term is 1);
// - with one, it is never brighter than that (shadows only take light away) and darker under
//   the ball;
// - it composes no normal (Gradient) and shadow code only with a technique;
// - the GPU matches the CPU twin (vtkDeepShadowReferenceRenderer follows the mapper's
//   OutputMode) within the tolerances of TestShadowTechniques: translucent techniques RMSE
//   <= 2/255 and <= 1% of pixels beyond 12/255; binary ones (shadow maps) RMSE <= 4/255 and
//   <= 3% beyond 24/255, for the same reasons (float against double at the threshold).
#include "DeepShadowTestUtilities.h"
#include "vtkDeepShadowDeepShadowMapTechnique.h"
#include "vtkDeepShadowRayTechnique.h"
#include "vtkDeepShadowShadowMapTechnique.h"
#include "vtkDeepShadowPass.h"
#include "vtkDeepShadowPolyDataMapper.h"
#include "vtkDeepShadowStochasticShadowMapTechnique.h"

#include "vtkActor.h"
#include "vtkProperty.h"

#include <algorithm>

using deepshadow::testing::Check;
using deepshadow::testing::Grab;
using deepshadow::testing::HasFeature;

int TestShadowTermOutput(int, char*[])
{
  bool ok = true;
  deepshadow::testing::ShadowScene scene;
  scene.Renderer->SetBackground(0.0, 0.0, 0.0);
  scene.Mapper->SetOutputModeToShadowTerm();

  scene.Window->Render();
  const deepshadow::Image coverage = Grab(scene.Window);
  ok = Check("no technique: ShadowTerm composed, no Gradient, no shadow code",
         HasFeature(scene.Mapper, "ShadowTerm") && !HasFeature(scene.Mapper, "Gradient") &&
           scene.Mapper->GetFragmentShaderSource().find("lightVisibility") == std::string::npos) && ok;
  double grey = 0.0;
  for (int y = 0; y < coverage.Height; ++y)
    for (int x = 0; x < coverage.Width; ++x)
    {
      const glm::dvec3 c = coverage.At(x, y);
      grey = std::max({ grey, std::abs(c.x - c.y), std::abs(c.y - c.z) });
    }
  ok = Check("no technique: grey coverage (largest channel spread " + std::to_string(grey) + ")",
         grey <= 1.0 / 255.0) && ok;
  ok = deepshadow::testing::WithinTolerance("no technique vs twin", coverage,
         deepshadow::testing::Reference(scene.Renderer, true), 2.0 / 255.0, 12.0 / 255.0, 0.01) && ok;

  vtkNew<vtkDeepShadowRayTechnique> rays;
  vtkNew<vtkDeepShadowShadowMapTechnique> map;
  map->SetMapSize(128);
  map->SetThreshold(0.3);
  vtkNew<vtkDeepShadowDeepShadowMapTechnique> dsm;
  dsm->SetMapSize(128);
  vtkNew<vtkDeepShadowStochasticShadowMapTechnique> cssm;
  cssm->SetMapSize(128);
  struct Case
  {
    const char* Name;
    vtkDeepShadowTechnique* Technique;
    bool Binary;
  };
  for (const Case& c : { Case{ "rays", rays, false }, Case{ "shadowmap", map, true },
         Case{ "dsm", dsm, false }, Case{ "cssm", cssm, false } })
  {
    deepshadow::Image term;
    ok = scene.MatchesTwin(c.Name, c.Technique, (c.Binary ? 4.0 : 2.0) / 255.0,
           (c.Binary ? 24.0 : 12.0) / 255.0, c.Binary ? 0.03 : 0.01, term) && ok;
    double brighter = 0.0;
    for (int y = 0; y < term.Height; ++y)
      for (int x = 0; x < term.Width; ++x)
      {
        const glm::dvec3 excess = term.At(x, y) - coverage.At(x, y);
        brighter = std::max({ brighter, excess.x, excess.y, excess.z });
      }
    const double shadowed = deepshadow::testing::ShadowScene::FloorUnderBall(term).y;
    const double lit = deepshadow::testing::ShadowScene::FloorUnderBall(coverage).y;
    ok = Check(std::string(c.Name) + ": never brighter than the coverage (by " + std::to_string(brighter) +
           "), floor under the ball " + std::to_string(shadowed) + " of " + std::to_string(lit),
           brighter <= 1.0 / 255.0 && shadowed < 0.8 * lit) && ok;
  }

  // Meshes have a shadow term too (vtkDeepShadowPolyDataMapper::OutputShadowTerm): a ground
  // under the volume, white where the light reaches it, darker in the volume's shadow.
  vtkNew<vtkDeepShadowPass> pass;
  scene.Renderer->SetPass(pass);
  vtkNew<vtkDeepShadowPolyDataMapper> groundMapper;
  groundMapper->SetOutputModeToShadowTerm();
  vtkNew<vtkActor> ground;
  scene.AddGround(groundMapper, ground);
  ground->GetProperty()->SetColor(0.8, 0.6, 0.4); // not seen in the shadow term
  scene.Renderer->ResetCameraClippingRange();
  deepshadow::Image withGround;
  ok = scene.MatchesTwin("rays, with a ground mesh", rays, 2.0 / 255.0, 12.0 / 255.0, 0.01, withGround) && ok;
  // The ground's corners (bottom left and right of the picture) are in the open: white.
  const glm::dvec3 open = withGround.At(2, 2);
  ok = Check("the ground's term: white in the open (" + std::to_string(open.x) + "), grey, composed",
         open.x > 254.0 / 255.0 && std::abs(open.x - open.z) <= 1.0 / 255.0 &&
           HasFeature(groundMapper->GetShaderFeatures(), "ShadowTerm")) && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
