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

// Refuses, before any work, a --size whose frame buffers exceed the memory budget.
void RequireFrameBudget(const Options& options)
{
  const std::string problem = CheckMemoryBudget("--size " + std::to_string(options.Width) + "x" +
      std::to_string(options.Height) + " (the frame's buffers)",
    FrameBytes(options, options.Width, options.Height, false), MemoryBudget(options));
  if (!problem.empty())
  {
    throw UsageError(problem + " (--memory-budget BYTES to change it)");
  }
}

// The window both mappers render in: --backend and --size.
void SetUpWindow(const Options& options, vtkDeepShadowRenderWindow* window)
{
  if (!options.Backend.empty())
  {
    window->SetBackend(vtkDeepShadowRenderWindow::BackendFromString(options.Backend.c_str()));
  }
  window->SetSize(options.Width, options.Height);
}

// The cases to time: with --blend-modes, the head at the first --bench-sizes size in each
// mode; without, each size on the sparse spheres and the dense head, shaded, and the head
// unshaded.
std::vector<BenchCase> BenchCases(const Options& options)
{
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
  return cases;
}

// Builds the case's scene at its scale and shading (an isosurface at half the peak opacity);
// returns the scene's suggested sample distance, which both mappers use.
double SetUpScene(vtkDeepShadowStandardScene* scene, const BenchCase& c)
{
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
  return step;
}

// Lights the scene with its key light alone, from the key light's direction towards the
// volume's centre (the renderer keeps the light).
void AddKeyLight(vtkRenderer* renderer, vtkDeepShadowStandardScene* scene)
{
  vtkImageData* data = scene->GetVolume();
  double direction[3], center[3];
  scene->GetLightDirection(direction);
  data->GetCenter(center);
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetFocalPoint(center);
  light->SetPosition(center[0] + direction[0], center[1] + direction[1], center[2] + direction[2]);
  renderer->AddLight(light);
}

// Both mappers on the same data, sample distance and blend mode; VTK's without automatic
// sample distances or jittering, so that both take the same samples.
void SetUpMappers(vtkDeepShadowVolumeMapper* ours, vtkGPUVolumeRayCastMapper* theirs,
  vtkImageData* data, double step, const std::string& blend)
{
  ours->SetInputData(data);
  ours->SetSampleDistance(step);
  theirs->SetInputData(data);
  theirs->SetAutoAdjustSampleDistances(0);
  theirs->SetSampleDistance(step);
  theirs->SetUseJittering(0);
  ours->SetBlendMode(BlendModeOf(blend));
  theirs->SetBlendMode(BlendModeOf(blend));
}

// What one case measured.
struct BenchTimes
{
  double OursMs = 0.0;
  double NoSkipMs = 0.0; // ours without empty-space skipping
  double VtkMs = 0.0;
  double EmptyFraction = 0.0; // of ours' blocks
};

// Times our mapper, then ours without empty-space skipping, then VTK's; throws UsageError if
// ours failed (a lost context, or its own error).
BenchTimes TimeMappers(vtkDeepShadowRenderWindow* window, vtkRenderer* renderer, vtkVolume* volume,
  vtkDeepShadowVolumeMapper* ours, vtkGPUVolumeRayCastMapper* theirs,
  vtkDeepShadowStandardScene* scene, int frames)
{
  BenchTimes times;
  times.OursMs = TimeMapper(window, renderer, volume, ours, scene, frames);
  RequireContext(window);
  if (!ours->GetLastError().empty())
  {
    throw UsageError("bench: " + ours->GetLastError());
  }
  times.EmptyFraction = ours->GetEmptyBlockFraction();
  ours->EmptySpaceSkippingOff(); // the same work as VTK's mapper: every sample taken
  times.NoSkipMs = TimeMapper(window, renderer, volume, ours, scene, frames);
  ours->EmptySpaceSkippingOn();
  times.VtkMs = TimeMapper(window, renderer, volume, theirs, scene, frames);
  volume->SetMapper(nullptr);
  return times;
}

// The volume's dimensions as the table shows them, "256x256x160".
std::string DimensionsText(vtkImageData* data)
{
  int dims[3];
  data->GetDimensions(dims);
  return std::to_string(dims[0]) + "x" + std::to_string(dims[1]) + "x" + std::to_string(dims[2]);
}

// A case's line of the table on stdout, flushed: progress while the bench runs.
void PrintCaseLine(
  const BenchCase& c, const std::string& dimsText, double step, const BenchTimes& t)
{
  std::printf("%-8s %-13s %-6s %-10s %8.3f %9.1f %9.1f %9.1f %7.3f %7.3f %6.2f\n", c.Scene.c_str(),
    dimsText.c_str(), c.Shade ? "yes" : "no", c.Blend.c_str(), step, t.OursMs, t.NoSkipMs, t.VtkMs,
    t.OursMs / t.VtkMs, t.NoSkipMs / t.VtkMs, t.EmptyFraction);
  std::fflush(stdout);
}

// A case's figures as the --json file lists them.
Json CaseJson(const BenchCase& c, const std::string& dimsText, double step, const BenchTimes& t)
{
  Json row;
  row.Set("scene", c.Scene)
    .Set("dims", dimsText)
    .Set("shade", c.Shade)
    .Set("blend", c.Blend)
    .Set("sample_distance", step)
    .Set("ours_ms", t.OursMs)
    .Set("ours_no_skipping_ms", t.NoSkipMs)
    .Set("vtk_ms", t.VtkMs)
    .Set("ratio", t.OursMs / t.VtkMs)
    .Set("ratio_no_skipping", t.NoSkipMs / t.VtkMs)
    .Set("empty_block_fraction", t.EmptyFraction);
  return row;
}

// One case: its scene staged in `renderer`, both mappers timed, its line printed; returns
// its figures for the --json file.
Json RunCase(const Options& options, vtkDeepShadowRenderWindow* window, vtkRenderer* renderer,
  const BenchCase& c)
{
  vtkNew<vtkDeepShadowStandardScene> scene;
  const double step = SetUpScene(scene, c);
  vtkImageData* data = scene->GetVolume();

  renderer->RemoveAllViewProps(); // the previous case's volume and light
  renderer->RemoveAllLights();
  vtkNew<vtkVolume> volume;
  volume->SetProperty(scene->GetVolumeProperty());
  renderer->AddVolume(volume);
  AddKeyLight(renderer, scene);

  vtkNew<vtkDeepShadowVolumeMapper> ours;
  vtkNew<vtkGPUVolumeRayCastMapper> theirs;
  SetUpMappers(ours, theirs, data, step, c.Blend);
  const BenchTimes times =
    TimeMappers(window, renderer, volume, ours, theirs, scene, options.Frames);
  const std::string dimsText = DimensionsText(data);
  PrintCaseLine(c, dimsText, step, times);
  return CaseJson(c, dimsText, step, times);
}
}

int RunBench(const Options& options)
{
  RequireFrameBudget(options);
  vtkNew<vtkDeepShadowRenderWindow> window;
  SetUpWindow(options, window);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.08, 0.09, 0.12);
  window->AddRenderer(renderer);
  const std::vector<BenchCase> cases = BenchCases(options);

  std::printf("%-8s %-13s %-6s %-10s %8s %9s %9s %9s %7s %7s %6s\n", "scene", "dims", "shade", "blend",
    "step", "ours_ms", "noskip_ms", "vtk_ms", "ratio", "noskip", "empty");
  std::vector<Json> rows;
  for (const BenchCase& c : cases)
  {
    rows.push_back(RunCase(options, window, renderer, c));
  }
  if (!options.Json.empty())
  {
    Json all;
    all.Set("width", options.Width)
      .Set("height", options.Height)
      .Set("frames", options.Frames)
      .Set("backend", window->GetBackendAsString())
      .Set("gl_renderer", RendererString(window))
      .Set("rows", rows);
    Outputs outputs;
    outputs.Write(options.Json, all.FileText());
    outputs.Commit();
  }
  return 0;
}

}
}
