// Shadows while interacting from a coarser grid (vtkDeepShadowVolumeMapper::
// InteractiveShadowSubsampling), on the ball over a floor, unshaded (lit isotropically):
// 1. still frames keep a lookup per sample: no coarse pass, the picture of subsampling 1 bit
//    for bit, before and after interacting;
// 2. interactive frames draw the coarse pass, then every pixel without the technique, and
//    match the CPU twin of both passes (deepshadow::RenderShadowSubsampled) within the
//    translucent techniques' tolerance (grey, coloured and cached); against the ground truth
//    they stay within twice the still frame's error, and far below the picture without
//    shadows; the shader is composed once for all of them;
//    a structure rebuilt while interacting (its light moved) is built at 1/4 of the map size,
//    and in full on the next still frame;
//    shaded volumes too, their coarse rays lit again with the shadows off;
// 3. the shadow term keeps its lookup per sample while interacting, and its maps in full.
#include "DeepShadowTestUtilities.h"
#include "vtkDeepShadowReferenceRenderer.h"
#include "vtkDeepShadowTechniqueFactory.h"

#include <algorithm>
#include <cstdio>

using deepshadow::Image;
using deepshadow::testing::Check;
using deepshadow::testing::Grab;
using deepshadow::testing::HasFeature;
using deepshadow::testing::WithinTolerance;

namespace
{
constexpr double Still = 0.0001;    // frames a second a still render asks for
constexpr double Moving = 5.0;      // and an interactor's (ParaView's interactive renders)
constexpr int Subsampling = 4;

bool Ran(vtkDeepShadowVolumeMapper* mapper, const std::string& pass)
{
  const std::vector<std::string>& passes = mapper->GetLastPasses();
  return std::find(passes.begin(), passes.end(), pass) != passes.end();
}

Image Draw(deepshadow::testing::ShadowScene& scene, double rate)
{
  scene.Window->SetDesiredUpdateRate(rate);
  scene.Window->Render();
  return Grab(scene.Window);
}
}

int TestSubsampledShadows(int, char*[])
{
  bool ok = true;
  deepshadow::testing::ShadowScene scene;
  scene.Property->ShadeOff();
  scene.Mapper->SetShadowTechnique(vtkDeepShadowTechniqueFactory::New("dsm"));

  // 1. Still frames: per sample, whatever the subsampling.
  const Image perSample = Draw(scene, Still);
  scene.Mapper->SetInteractiveShadowSubsampling(Subsampling);
  const Image still = Draw(scene, Still);
  ok = Check("still frame: no coarse pass", !Ran(scene.Mapper, "ray-cast-coarse-shadows") &&
         !HasFeature(scene.Mapper, "ShadowRatio") && HasFeature(scene.Mapper, "Shadow:dsm")) && ok;
  ok = Check("still frame: the picture of subsampling 1, bit for bit", still.RGB == perSample.RGB) && ok;

  // 2. Interactive frames.
  const int compositions = scene.Mapper->GetShaderCompositions();
  const Image moving = Draw(scene, Moving);
  const std::vector<std::string>& passes = scene.Mapper->GetLastPasses();
  ok = Check("interactive frame: the coarse pass, then the ray cast",
         passes.size() >= 2 && passes[passes.size() - 2] == "ray-cast-coarse-shadows" && passes.back() == "ray-cast") && ok;
  ok = Check("  composed of ShadowRatio (coarse) and ShadowRatioApply (full)",
         HasFeature(scene.Mapper, "ShadowRatio") && HasFeature(scene.Mapper, "ShadowRatioApply") &&
           scene.Mapper->GetLastError().empty()) && ok;
  Draw(scene, Moving);
  const int afterTwo = scene.Mapper->GetShaderCompositions();
  Draw(scene, Moving);
  ok = Check("  composed on the first interactive frame only (" + std::to_string(afterTwo - compositions) + ")",
         scene.Mapper->GetShaderCompositions() == afterTwo) && ok;

  vtkNew<vtkDeepShadowReferenceRenderer> twin;
  twin->SetGpuTwin(true);
  twin->SetShadowSubsampling(Subsampling);
  Image expected;
  ok = Check("the twin of both passes renders", twin->Render(scene.Renderer, expected)) && ok;
  ok = WithinTolerance("interactive frame vs its CPU twin", moving, expected, 2.0 / 255.0, 12.0 / 255.0, 0.01) && ok;
  // Coloured shadows (a ratio per channel) and a cache.
  for (const char* name : { "dsm-color", "rays-cached" })
  {
    scene.Mapper->SetShadowTechnique(vtkDeepShadowTechniqueFactory::New(name));
    Draw(scene, Still); // built in full (a first build while interacting is coarser)
    const Image picture = Draw(scene, Moving);
    ok = Check(std::string(name) + ": the coarse pass", Ran(scene.Mapper, "ray-cast-coarse-shadows")) &&
      twin->Render(scene.Renderer, expected) &&
      WithinTolerance((std::string(name) + ", interactive frame vs its CPU twin").c_str(), picture, expected,
        2.0 / 255.0, 12.0 / 255.0, 0.01) && ok;
  }
  scene.Mapper->SetShadowTechnique(vtkDeepShadowTechniqueFactory::New("dsm"));

  // Against the ground truth (exact shadow rays): about as near as the still frame.
  vtkNew<vtkDeepShadowReferenceRenderer> truth;
  truth->SetShadows(vtkDeepShadowReferenceRenderer::GroundTruthShadows);
  Image exact;
  ok = Check("the ground truth renders", truth->Render(scene.Renderer, exact)) && ok;
  scene.Mapper->SetShadowTechnique(nullptr);
  const Image unshadowed = Draw(scene, Still);
  const double stillError = deepshadow::Compare(still, exact).RMSE;
  const double movingError = deepshadow::Compare(moving, exact).RMSE;
  const double unshadowedError = deepshadow::Compare(unshadowed, exact).RMSE;
  std::printf("RMSE against the ground truth: still %.4f, interactive %.4f, without shadows %.4f\n", stillError,
    movingError, unshadowedError);
  ok = Check("  interactive within 2x the still frame's error, and below a third of no shadow's",
         movingError <= 2.0 * stillError && movingError < unshadowedError / 3.0) && ok;
  scene.Mapper->SetShadowTechnique(vtkDeepShadowTechniqueFactory::New("dsm"));
  Draw(scene, Still);
  for (int other : { 2, 8 })
  {
    scene.Mapper->SetInteractiveShadowSubsampling(other);
    std::printf("  subsampling %d: interactive RMSE against the ground truth %.4f\n", other,
      deepshadow::Compare(Draw(scene, Moving), exact).RMSE);
  }
  scene.Mapper->SetInteractiveShadowSubsampling(Subsampling);
  Draw(scene, Moving);
  ok = Check("still again: the per-sample picture, bit for bit", Draw(scene, Still).RGB == perSample.RGB) && ok;

  // Rebuilt while interacting: the maps at half their size, and in full on the still frame.
  vtkDeepShadowTechnique* dsm = scene.Mapper->GetShadowTechnique();
  Draw(scene, Moving);
  const double kept = dsm->GetStatistic("map_size");
  scene.Light->SetPosition(0.35, 0.2, 1.0);
  const int builds = dsm->GetBuildCount();
  const Image turned = Draw(scene, Moving);
  const double coarse = dsm->GetStatistic("map_size");
  const Image turnedStill = Draw(scene, Still);
  std::printf("map size: %g kept while interacting, %g rebuilt while interacting, %g on the still frame after\n", kept,
    coarse, dsm->GetStatistic("map_size"));
  ok = Check("a light moved while interacting: rebuilt at a quarter of the map size, then in full",
         kept == 512.0 && coarse == 512.0 / Subsampling && dsm->GetStatistic("map_size") == 512.0 &&
           dsm->GetBuildCount() == builds + 2) && ok;
  ok = WithinTolerance("  the coarser maps' interactive frame vs the still one", turned, turnedStill, 0.05, 0.2, 0.05) && ok;

  // Shaded: the coarse rays' unshadowed colour is their samples lit with the shadows off, and
  // the full pass lights every sample without shadows.
  scene.Property->ShadeOn();
  const Image shadedStill = Draw(scene, Still);
  const Image shadedMoving = Draw(scene, Moving);
  ok = Check("shaded, interactive: the coarse pass", Ran(scene.Mapper, "ray-cast-coarse-shadows") &&
         HasFeature(scene.Mapper, "Gradient")) && ok;
  ok = twin->Render(scene.Renderer, expected) &&
    WithinTolerance("shaded, interactive frame vs its CPU twin", shadedMoving, expected, 2.0 / 255.0, 12.0 / 255.0, 0.01) &&
    ok;
  ok = Check("  the ground truth renders", truth->Render(scene.Renderer, exact)) && ok;
  std::printf("shaded, RMSE against the ground truth: still %.4f, interactive %.4f\n",
    deepshadow::Compare(shadedStill, exact).RMSE, deepshadow::Compare(shadedMoving, exact).RMSE);
  ok = Check("  interactive within 2x the still frame's error",
         deepshadow::Compare(shadedMoving, exact).RMSE <= 2.0 * deepshadow::Compare(shadedStill, exact).RMSE) && ok;
  // VTK's own shading (its quirks inside lightSample run again, with the shadows off).
  scene.Mapper->SetShadingModelToVTK();
  Draw(scene, Still);
  const Image vtkShaded = Draw(scene, Moving);
  ok = twin->Render(scene.Renderer, expected) &&
    WithinTolerance("VTK's shading, interactive frame vs its CPU twin", vtkShaded, expected, 2.0 / 255.0, 12.0 / 255.0,
      0.01) &&
    ok;
  scene.Mapper->SetShadingModelToBlinnPhong();

  // 3. Per sample while interacting: the shadow term, with the maps in full.
  scene.Mapper->SetOutputModeToShadowTerm();
  scene.Light->SetPosition(0.3, 0.25, 1.0);
  Draw(scene, Moving);
  ok = Check("the shadow term, interactive, the light moved: per sample, the maps in full",
         !Ran(scene.Mapper, "ray-cast-coarse-shadows") && dsm->GetStatistic("map_size") == 512.0) && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
