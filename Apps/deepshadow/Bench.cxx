// deepshadow bench: vtkDeepShadowVolumeMapper against VTK's vtkGPUVolumeRayCastMapper, in one
// run, on the same scenes, views, lights and sample distance. Ratios of median frame times.
#include "Budget.h"
#include "Commands.h"
#include "Json.h"
#include "Outputs.h"
#include "SceneSetup.h"

#include "vtkDeepShadowMemoryBudget.h"
#include "vtkDeepShadowRenderWindow.h"
#include "vtkDeepShadowStandardScene.h"
#include "vtkDeepShadowVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkContourValues.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cstdio>

namespace deepshadow
{
namespace tool
{
namespace
{
struct BenchCase
{
  std::string Scene;
  double Scale;
  bool Shade;
  std::string Blend = "composite";
};

int BlendModeOf(const std::string& name)
{
  return name == "maximum" ? vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND
    : name == "minimum"    ? vtkVolumeMapper::MINIMUM_INTENSITY_BLEND
    : name == "average"    ? vtkVolumeMapper::AVERAGE_INTENSITY_BLEND
    : name == "additive"   ? vtkVolumeMapper::ADDITIVE_BLEND
    : name == "isosurface" ? vtkVolumeMapper::ISOSURFACE_BLEND
                           : vtkVolumeMapper::COMPOSITE_BLEND;
}

// The scalar where the property's opacity first reaches half its maximum over `range`.
double HalfOpacityScalar(vtkVolumeProperty* property, const double range[2])
{
  vtkPiecewiseFunction* opacity = property->GetScalarOpacity();
  const int samples = 1024;
  double largest = 0.0;
  for (int i = 0; i < samples; ++i)
  {
    largest = std::max(largest, opacity->GetValue(range[0] + (range[1] - range[0]) * i / (samples - 1)));
  }
  for (int i = 0; i < samples; ++i)
  {
    const double scalar = range[0] + (range[1] - range[0]) * i / (samples - 1);
    if (opacity->GetValue(scalar) >= 0.5 * largest)
    {
      return scalar;
    }
  }
  return 0.5 * (range[0] + range[1]);
}

// Median frame time of `mapper` over a short orbit, after two warm-up frames.
double TimeMapper(vtkDeepShadowRenderWindow* window, vtkRenderer* renderer, vtkVolume* volume,
  vtkVolumeMapper* mapper, vtkDeepShadowStandardScene* scene, int frames)
{
  volume->SetMapper(mapper);
  scene->ApplyCamera(renderer->GetActiveCamera());
  renderer->ResetCameraClippingRange();
  RenderFrame(window);
  RenderFrame(window);
  std::vector<double> times;
  for (int f = 0; f < frames; ++f)
  {
    renderer->GetActiveCamera()->Azimuth(2.0);
    renderer->ResetCameraClippingRange();
    times.push_back(RenderFrame(window));
  }
  return Median(times);
}
}

int RunBench(const Options& options)
{
  const std::string problem = CheckMemoryBudget("--size " + std::to_string(options.Width) + "x" +
      std::to_string(options.Height) + " (the frame's buffers)",
    FrameBytes(options, options.Width, options.Height, false), MemoryBudget(options));
  if (!problem.empty())
  {
    throw UsageError(problem + " (--memory-budget BYTES to change it)");
  }
  vtkNew<vtkDeepShadowRenderWindow> window;
  if (!options.Backend.empty())
  {
    window->SetBackend(vtkDeepShadowRenderWindow::BackendFromString(options.Backend.c_str()));
  }
  window->SetSize(options.Width, options.Height);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.08, 0.09, 0.12);
  window->AddRenderer(renderer);

  std::vector<BenchCase> cases;
  for (const std::string& blend : options.BenchBlendModes)
  {
    cases.push_back({ "head", options.BenchSizes.front() / 256.0, true, blend });
  }
  for (int size : options.BenchBlendModes.empty() ? options.BenchSizes : std::vector<int>())
  {
    // spheres: sparse, native 128^3; head: dense CT-like, native 256x256x160.
    cases.push_back({ "spheres", size / 128.0, true });
    cases.push_back({ "head", size / 256.0, true });
    cases.push_back({ "head", size / 256.0, false });
  }

  std::printf("%-8s %-13s %-6s %-10s %8s %9s %9s %9s %7s %7s %6s\n", "scene", "dims", "shade", "blend",
    "step", "ours_ms", "noskip_ms", "vtk_ms", "ratio", "noskip", "empty");
  std::vector<Json> rows;
  for (const BenchCase& c : cases)
  {
    vtkNew<vtkDeepShadowStandardScene> scene;
    scene->SetScene(c.Scene);
    scene->SetResolutionScale(std::clamp(c.Scale, 0.01, 2.0));
    vtkImageData* data = scene->GetVolume();
    vtkVolumeProperty* property = scene->GetVolumeProperty();
    property->SetShade(c.Shade ? 1 : 0);
    const double step = scene->GetSuggestedSampleDistance();
    if (c.Blend == "isosurface")
    {
      property->GetIsoSurfaceValues()->SetValue(0, HalfOpacityScalar(property, data->GetScalarRange()));
    }

    renderer->RemoveAllViewProps();
    renderer->RemoveAllLights();
    vtkNew<vtkVolume> volume;
    volume->SetProperty(property);
    renderer->AddVolume(volume);
    double direction[3], center[3];
    scene->GetLightDirection(direction);
    data->GetCenter(center);
    vtkNew<vtkLight> light;
    light->SetLightTypeToSceneLight();
    light->SetFocalPoint(center);
    light->SetPosition(center[0] + direction[0], center[1] + direction[1], center[2] + direction[2]);
    renderer->AddLight(light);

    vtkNew<vtkDeepShadowVolumeMapper> ours;
    ours->SetInputData(data);
    ours->SetSampleDistance(step);
    vtkNew<vtkGPUVolumeRayCastMapper> theirs;
    theirs->SetInputData(data);
    theirs->SetAutoAdjustSampleDistances(0);
    theirs->SetSampleDistance(step);
    theirs->SetUseJittering(0);
    ours->SetBlendMode(BlendModeOf(c.Blend));
    theirs->SetBlendMode(BlendModeOf(c.Blend));

    const double oursMs = TimeMapper(window, renderer, volume, ours, scene, options.Frames);
    RequireContext(window);
    if (!ours->GetLastError().empty())
    {
      throw UsageError("bench: " + ours->GetLastError());
    }
    const double emptyFraction = ours->GetEmptyBlockFraction();
    ours->EmptySpaceSkippingOff(); // the same work as VTK's mapper: every sample taken
    const double noSkipMs = TimeMapper(window, renderer, volume, ours, scene, options.Frames);
    ours->EmptySpaceSkippingOn();
    const double vtkMs = TimeMapper(window, renderer, volume, theirs, scene, options.Frames);
    volume->SetMapper(nullptr);
    int dims[3];
    data->GetDimensions(dims);
    const std::string dimsText =
      std::to_string(dims[0]) + "x" + std::to_string(dims[1]) + "x" + std::to_string(dims[2]);
    std::printf("%-8s %-13s %-6s %-10s %8.3f %9.1f %9.1f %9.1f %7.3f %7.3f %6.2f\n", c.Scene.c_str(),
      dimsText.c_str(), c.Shade ? "yes" : "no", c.Blend.c_str(), step, oursMs, noSkipMs, vtkMs,
      oursMs / vtkMs, noSkipMs / vtkMs, emptyFraction);
    std::fflush(stdout);
    Json row;
    row.Set("scene", c.Scene)
      .Set("dims", dimsText)
      .Set("shade", c.Shade)
      .Set("blend", c.Blend)
      .Set("sample_distance", step)
      .Set("ours_ms", oursMs)
      .Set("ours_no_skipping_ms", noSkipMs)
      .Set("vtk_ms", vtkMs)
      .Set("ratio", oursMs / vtkMs)
      .Set("ratio_no_skipping", noSkipMs / vtkMs)
      .Set("empty_block_fraction", emptyFraction);
    rows.push_back(row);
  }
  if (!options.Json.empty())
  {
    Json all;
    all.Set("width", options.Width)
      .Set("height", options.Height)
      .Set("frames", options.Frames)
      .Set("backend", window->GetBackendAsString())
      .Set("rows", rows);
    Outputs outputs;
    outputs.Write(options.Json, all.FileText());
    outputs.Commit();
  }
  return 0;
}

}
}
