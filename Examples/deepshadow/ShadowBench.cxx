// deepshadow shadow-bench: what each shadow technique costs and how wrong it is, per scene,
// in one run (the structure of Ropinski et al.'s Tables 1-2, plus errors):
//   - unshadowed frame time while the camera orbits (the baseline of the ratios);
//   - per technique, frame time while only the camera orbits (structures reused) and while
//     the key light turns (structures rebuilt every frame), as ratios to the baseline;
//   - the build time (median over the light-moving frames) and the shadow memory;
//   - RMSE and maximum error of the image against the ground truth: the CPU reference with
//     translucent shadow rays at a quarter step (coloured for coloured techniques), at
//     --error-size;
//   - for deep shadow maps, the nodes needed per texel (average and maximum, as in Ropinski
//     et al.'s Table 4).
#include "Commands.h"
#include "Json.h"
#include "SceneSetup.h"

#include "Image.h"
#include "Shadows.h"
#include "vtkDeepShadowDeepShadowMapTechnique.h"
#include "vtkDeepShadowImageConversion.h"
#include "vtkDeepShadowRayTechnique.h"
#include "vtkDeepShadowReferenceRenderer.h"
#include "vtkDeepShadowRenderWindow.h"
#include "vtkDeepShadowStandardScene.h"
#include "vtkDeepShadowTechnique.h"
#include "vtkDeepShadowVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkNew.h"
#include "vtkRenderer.h"
#include "vtkTransform.h"

#include <chrono>
#include <cstdio>

namespace deepshadow
{
namespace tool
{
namespace
{
// Median frame time over `frames` frames, each after `step` changes the view or light.
template <typename Step>
double TimeFrames(SceneSetup& setup, int frames, Step step)
{
  std::vector<double> times;
  for (int f = 0; f < frames; ++f)
  {
    step(f);
    times.push_back(RenderFrame(setup.Window));
  }
  return Median(times);
}

Image CaptureAt(SceneSetup& setup, int width, int height, int restoreWidth, int restoreHeight)
{
  setup.Window->SetSize(width, height);
  RenderFrame(setup.Window);
  Image image = CaptureWindow(setup.Window);
  setup.Window->SetSize(restoreWidth, restoreHeight);
  return image;
}

vtkLight* KeyLight(vtkRenderer* renderer)
{
  return vtkLight::SafeDownCast(renderer->GetLights()->GetItemAsObject(0));
}

// The techniques measured when --techniques is not given.
const std::vector<std::string> DefaultTechniques{ "rays", "rays-cached", "rays-opaque",
  "rays-color", "shadowmap", "dsm", "dsm-cached", "dsm-color", "dsm3", "cssm", "cssm-cached" };
}

int RunShadowBench(const Options& options)
{
  const std::vector<std::string> scenes =
    options.BenchScenes.empty() ? vtkDeepShadowStandardScene::GetSceneNames() : options.BenchScenes;
  const std::vector<std::string> techniques =
    options.BenchTechniques.empty() ? DefaultTechniques : options.BenchTechniques;

  std::printf("%-8s %-24s %9s %8s %8s %9s %11s %9s %8s %s\n", "scene", "technique", "frame_ms",
    "camera", "light", "build_ms", "bytes", "rmse", "max", "nodes avg/max");
  std::vector<Json> rows;
  for (const std::string& name : scenes)
  {
    Options sceneOptions = options;
    sceneOptions.Scene = name;
    sceneOptions.VolumeFile.clear();
    sceneOptions.Technique = "none";
    SceneSetup setup = SceneSetup::Build(sceneOptions);
    vtkCamera* camera = setup.Renderer->GetActiveCamera();
    vtkNew<vtkCamera> startCamera;
    startCamera->DeepCopy(camera);
    vtkLight* key = KeyLight(setup.Renderer);
    double startPosition[3];
    key->GetPosition(startPosition);
    auto restore = [&]() {
      camera->DeepCopy(startCamera);
      key->SetPosition(startPosition);
      setup.Renderer->ResetCameraClippingRange();
    };
    auto orbit = [&](int) {
      camera->Azimuth(3.0);
      setup.Renderer->ResetCameraClippingRange();
    };
    auto turnLight = [&](int) {
      // Turn the key light's direction by 3 degrees about the view-up.
      const double* focal = key->GetFocalPoint();
      double* up = camera->GetViewUp();
      vtkNew<vtkTransform> turn;
      turn->Translate(focal[0], focal[1], focal[2]);
      turn->RotateWXYZ(3.0, up);
      turn->Translate(-focal[0], -focal[1], -focal[2]);
      double position[3];
      key->GetPosition(position);
      turn->TransformPoint(position, position);
      key->SetPosition(position);
    };

    RenderFrame(setup.Window);
    RequireDrawn(setup);
    const double baseline = TimeFrames(setup, options.Frames, orbit);
    restore();

    // The ground truths at the error size, from the start view: grey, and coloured once a
    // coloured technique asks for it.
    double truthMs = 0.0;
    auto groundTruth = [&](bool colored) {
      vtkNew<vtkDeepShadowRayTechnique> model; // says only grey or coloured
      model->SetColored(colored);
      vtkSmartPointer<vtkDeepShadowTechnique> current = setup.Mapper->GetShadowTechnique();
      setup.Mapper->SetShadowTechnique(model);
      setup.Window->SetSize(options.ErrorWidth, options.ErrorHeight);
      RenderFrame(setup.Window); // lights and clipping as the GPU frames have them
      vtkNew<vtkDeepShadowReferenceRenderer> reference;
      reference->SetShadows(vtkDeepShadowReferenceRenderer::GroundTruthShadows);
      Image truth;
      const auto start = std::chrono::steady_clock::now();
      reference->Render(setup.Renderer, truth);
      truthMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      setup.Window->SetSize(options.Width, options.Height);
      setup.Mapper->SetShadowTechnique(current);
      return truth;
    };
    const Image truth = groundTruth(false);
    Image coloredTruth;
    const Image unshadowed = CaptureAt(setup, options.ErrorWidth, options.ErrorHeight, options.Width, options.Height);
    const ImageDifference unshadowedError = Compare(unshadowed, truth);
    std::printf("%-8s %-24s %9.1f %8s %8s %9s %11s %9.5f %8.4f   (ground truth %.0f ms)\n",
      name.c_str(), "none", baseline, "1.00", "1.00", "-", "0", unshadowedError.RMSE,
      unshadowedError.MaxAbs, truthMs);
    std::fflush(stdout);

    for (const std::string& technique : techniques)
    {
      const Options techniqueOptions = WithTechniqueSpec(sceneOptions, technique);
      auto shadow = MakeTechnique(techniqueOptions);
      const bool colored = shadow->GetParameters().IsColored();
      if (colored && coloredTruth.RGB.empty())
      {
        coloredTruth = groundTruth(true);
      }
      setup.Mapper->SetShadowTechnique(shadow);
      restore();
      RenderFrame(setup.Window); // builds
      RequireDrawn(setup);
      const int builds = shadow->GetBuildCount();
      const double cameraMs = TimeFrames(setup, options.Frames, orbit);
      const bool rebuiltForCamera = shadow->GetBuildCount() != builds;
      restore();
      // Every light-moving frame rebuilds: the build time is the median of theirs.
      std::vector<double> buildTimes;
      const double lightMs = TimeFrames(setup, options.Frames, [&](int f) {
        if (f > 0)
        {
          buildTimes.push_back(shadow->GetLastBuildMilliseconds());
        }
        turnLight(f);
      });
      buildTimes.push_back(shadow->GetLastBuildMilliseconds());
      const double buildMs = Median(buildTimes);
      restore();
      const Image image = CaptureAt(setup, options.ErrorWidth, options.ErrorHeight, options.Width, options.Height);
      const ImageDifference error = Compare(image, colored ? coloredTruth : truth);
      auto* dsm = vtkDeepShadowDeepShadowMapTechnique::SafeDownCast(shadow);
      char nodes[64] = "";
      if (dsm)
      {
        std::snprintf(nodes, sizeof(nodes), "%.2f/%d", dsm->GetNodesAverage(), dsm->GetNodesMax());
      }
      std::printf("%-8s %-24s %9.1f %8.2f %8.2f %9.1f %11lld %9.5f %8.4f %s%s\n", name.c_str(),
        technique.c_str(), cameraMs, cameraMs / baseline, lightMs / baseline, buildMs,
        shadow->GetShadowBytes(), error.RMSE, error.MaxAbs, nodes,
        rebuiltForCamera ? "  (rebuilt when the camera moved!)" : "");
      std::fflush(stdout);
      Json row;
      row.Set("scene", name)
        .Set("technique", technique)
        .Set("unshadowed_ms", baseline)
        .Set("camera_ms", cameraMs)
        .Set("light_ms", lightMs)
        .Set("camera_ratio", cameraMs / baseline)
        .Set("light_ratio", lightMs / baseline)
        .Set("build_ms", buildMs)
        .Set("shadow_bytes", shadow->GetShadowBytes())
        .Set("colored", colored)
        .Set("rmse", error.RMSE)
        .Set("max_abs", error.MaxAbs)
        .Set("unshadowed_rmse", unshadowedError.RMSE)
        .Set("ground_truth_ms", truthMs)
        .Set("rebuilt_when_camera_moved", rebuiltForCamera)
        .Set("dsm_nodes_avg", dsm ? dsm->GetNodesAverage() : 0.0)
        .Set("dsm_nodes_max", dsm ? dsm->GetNodesMax() : 0)
        .Set("dsm_texels_overflowed", dsm ? dsm->GetTexelsOverflowed() : 0LL)
        .Set("dsm_epsilon_max", dsm ? dsm->GetEpsilonMax() : 0.0);
      rows.push_back(row);
    }
    setup.Mapper->SetShadowTechnique(nullptr);
  }
  if (!options.Json.empty())
  {
    Json all;
    all.Set("width", options.Width)
      .Set("height", options.Height)
      .Set("error_width", options.ErrorWidth)
      .Set("error_height", options.ErrorHeight)
      .Set("frames", options.Frames)
      .Set("rows", rows);
    all.Write(options.Json);
  }
  return 0;
}

}
}
