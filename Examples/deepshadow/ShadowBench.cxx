// deepshadow shadow-bench: what each shadow technique costs and how wrong it is, per scene,
// in one run (the structure of Ropinski et al.'s Tables 1-2, plus errors):
//   - unshadowed frame time while the camera orbits (the baseline of the ratios);
//   - per technique, frame time while only the camera orbits (structures reused) and while
//     the key light turns (structures rebuilt every frame), as ratios to the baseline;
//   - the last build's time and the shadow memory;
//   - RMSE and maximum error of the image against the ground truth: the CPU reference with
//     translucent shadow rays at a quarter step, at --error-size.
#include "Commands.h"
#include "Json.h"
#include "SceneSetup.h"

#include "Image.h"
#include "vtkDeepShadowImageConversion.h"
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
}

int RunShadowBench(const Options& options)
{
  const std::vector<std::string> scenes =
    options.BenchScenes.empty() ? vtkDeepShadowStandardScene::GetSceneNames() : options.BenchScenes;
  std::vector<std::string> techniques = options.BenchTechniques;
  if (techniques.empty())
  {
    for (const auto& name : TechniqueNames())
    {
      if (name != "none")
      {
        techniques.push_back(name);
      }
    }
  }

  std::printf("%-8s %-18s %9s %8s %8s %9s %11s %9s %8s\n", "scene", "technique", "frame_ms",
    "camera", "light", "build_ms", "bytes", "rmse", "max");
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

    // The ground truth at the error size, from the start view.
    setup.Window->SetSize(options.ErrorWidth, options.ErrorHeight);
    RenderFrame(setup.Window); // lights and clipping as the GPU frames have them
    vtkNew<vtkDeepShadowReferenceRenderer> reference;
    reference->SetShadows(vtkDeepShadowReferenceRenderer::GroundTruthShadows);
    Image truth;
    const auto truthStart = std::chrono::steady_clock::now();
    reference->Render(setup.Renderer, truth);
    const double truthMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - truthStart).count();
    setup.Window->SetSize(options.Width, options.Height);
    const Image unshadowed = CaptureAt(setup, options.ErrorWidth, options.ErrorHeight, options.Width, options.Height);
    const ImageDifference unshadowedError = Compare(unshadowed, truth);
    std::printf("%-8s %-18s %9.1f %8s %8s %9s %11s %9.5f %8.4f   (ground truth %.0f ms)\n",
      name.c_str(), "none", baseline, "1.00", "1.00", "-", "0", unshadowedError.RMSE,
      unshadowedError.MaxAbs, truthMs);
    std::fflush(stdout);

    for (const std::string& technique : techniques)
    {
      Options techniqueOptions = sceneOptions;
      techniqueOptions.Technique = technique;
      auto shadow = MakeTechnique(techniqueOptions);
      setup.Mapper->SetShadowTechnique(shadow);
      restore();
      RenderFrame(setup.Window); // builds
      RequireDrawn(setup);
      const int builds = shadow->GetBuildCount();
      const double cameraMs = TimeFrames(setup, options.Frames, orbit);
      const bool rebuiltForCamera = shadow->GetBuildCount() != builds;
      restore();
      const double lightMs = TimeFrames(setup, options.Frames, turnLight);
      const double buildMs = shadow->GetLastBuildMilliseconds();
      restore();
      const Image image = CaptureAt(setup, options.ErrorWidth, options.ErrorHeight, options.Width, options.Height);
      const ImageDifference error = Compare(image, truth);
      std::printf("%-8s %-18s %9.1f %8.2f %8.2f %9.1f %11lld %9.5f %8.4f%s\n", name.c_str(),
        technique.c_str(), cameraMs, cameraMs / baseline, lightMs / baseline, buildMs,
        shadow->GetShadowBytes(), error.RMSE, error.MaxAbs,
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
        .Set("rmse", error.RMSE)
        .Set("max_abs", error.MaxAbs)
        .Set("unshadowed_rmse", unshadowedError.RMSE)
        .Set("ground_truth_ms", truthMs)
        .Set("rebuilt_when_camera_moved", rebuiltForCamera);
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
