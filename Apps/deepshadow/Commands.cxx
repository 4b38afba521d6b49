#include "Commands.h"

#include "Look.h"
#include "Measure.h"
#include "Messages.h"

#include "Json.h"
#include "Outputs.h"
#include "SceneSetup.h"

#include "Core/Image.h"
#include "vtkDeepShadowBoundedScene.h"
#include "vtkDeepShadowHybridScene.h"
#include "vtkDeepShadowPass.h"
#include "vtkDeepShadowImageConversion.h"
#include "vtkDeepShadowReferenceRenderer.h"
#include "vtkDeepShadowRenderWindow.h"
#include "vtkDeepShadowStandardScene.h"
#include "vtkDeepShadowVolumePresets.h"
#include "vtkDeepShadowVolumeReader.h"
#include "vtkDeepShadowTechnique.h"
#include "vtkDeepShadowVolumeMapper.h"

#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <sys/stat.h>

namespace deepshadow
{
namespace tool
{
namespace
{
struct GpuRun
{
  double FirstFrameMs = 0.0;
  std::vector<double> FrameMs;
  Json Stats;
};

// One warm-up frame (uploads, shader compilation), then timed frames of the same view.
GpuRun RenderGPU(SceneSetup& setup, const Options& options)
{
  GpuRun run;
  run.FirstFrameMs = RenderFrame(setup.Window);
  RequireDrawn(setup);
  const std::vector<std::string> firstPasses = setup.Mapper->GetLastPasses();
  // The technique's statistics of the first frame, the one that built (a resolution-matched
  // technique's analysis: frames of the same view run none).
  const vtkDeepShadowTechnique::Statistics statistics =
    setup.Technique ? setup.Technique->GetStatistics() : vtkDeepShadowTechnique::Statistics();
  for (int f = 0; f < options.Frames; ++f)
  {
    run.FrameMs.push_back(RenderFrame(setup.Window));
  }
  vtkDeepShadowVolumeMapper* mapper = setup.Mapper;
  const int boundBuilds = mapper->GetBoundBuilds();
  const int shadowBuilds = mapper->GetShadowBuilds();
  const std::vector<std::string> features = mapper->GetShaderFeatures();
  const std::vector<std::string> passes = mapper->GetLastPasses();
  const long long memory = mapper->GetGPUMemoryBytes();
  // A bounded volume is also timed unbounded in the same run, for the ratio.
  std::vector<double> unboundedMs;
  if (mapper->GetNumberOfBounds() > 0)
  {
    std::vector<vtkSmartPointer<vtkPolyData>> bounds;
    for (int b = 0; b < mapper->GetNumberOfBounds(); ++b)
    {
      bounds.emplace_back(mapper->GetBound(b));
    }
    mapper->RemoveAllBounds();
    RenderFrame(setup.Window); // the shadows rebuild without the bound
    for (int f = 0; f < options.Frames; ++f)
    {
      unboundedMs.push_back(RenderFrame(setup.Window));
    }
    for (const auto& bound : bounds)
    {
      mapper->AddBound(bound);
    }
    RenderFrame(setup.Window);
  }
  run.Stats.Set("command", options.Command)
    .Set("scene", setup.Name)
    .Set("modality", setup.Modality)
    .Set("look", setup.Look)
    .Set("technique", options.Technique)
    .Set("width", options.Width)
    .Set("height", options.Height)
    .Set("frames", options.Frames)
    .Set("build_ms", setup.Technique ? setup.Technique->GetLastBuildMilliseconds() : 0.0)
    .Set("render_ms", Median(run.FrameMs))
    .Set("render_ms_frames", run.FrameMs)
    .Set("first_frame_ms", run.FirstFrameMs)
    .Set("shadow_bytes", setup.Technique ? setup.Technique->GetShadowBytes() : 0LL)
    .Set("shadow_builds", shadowBuilds)
    .Set("first_frame_passes", firstPasses)
    .Set("passes", passes) // of the last timed frame
    .Set("camera", CameraJson(setup.Renderer->GetActiveCamera()))
    .Set("shader_features", features)
    .Set("sample_distance", mapper->GetEffectiveSampleDistance())
    .Set("empty_block_fraction", mapper->GetEmptyBlockFraction())
    .Set("volume_uploads", mapper->GetVolumeUploads())
    .Set("transfer_table_builds", mapper->GetTransferTableBuilds())
    .Set("shader_compositions", mapper->GetShaderCompositions())
    .Set("gpu_memory_bytes", memory)
    .Set("generation_ms", 1000.0 * setup.GenerationSeconds)
    .Set("bounds", static_cast<int>(setup.Bounds.size()))
    .Set("bound_expression", setup.BoundExpression)
    .Set("bound_mode", setup.Bounds.empty() ? "none" : options.CsgMesh ? "cgal-mesh" : "per-ray")
    .Set("bound_builds", boundBuilds)
    .Set("unbounded_render_ms", unboundedMs.empty() ? 0.0 : Median(unboundedMs))
    .Set("bounded_to_unbounded", unboundedMs.empty() ? 0.0 : Median(run.FrameMs) / Median(unboundedMs))
    .Set("bound_is_empty", setup.BoundIsEmpty)
    .Set("csg_ms", setup.CsgMilliseconds)
    .Set("meshes", static_cast<int>(setup.Meshes.size()))
    .Set("casting_meshes", setup.Pass ? setup.Pass->GetCastingMeshes() : 0)
    .Set("surface_uploads", mapper->GetSurfaceUploads())
    .Set("peeled_layers", setup.Pass ? setup.Pass->GetPeeledLayers() : 0)
    .Set("translucent_layers_overflowed", setup.Pass ? setup.Pass->GetTranslucentLayersOverflowed() : false)
    .Set("translucent_layer_bytes", setup.Pass ? setup.Pass->GetTranslucentLayerBytes() : 0LL)
    .Set("volumes", setup.SecondVolume ? 2 : 1)
    .Set("second_volume_shadow_bytes", setup.SecondTechnique ? setup.SecondTechnique->GetShadowBytes() : 0LL)
    .Set("merged_volumes", setup.Pass ? setup.Pass->GetMergedVolumes() : 0)
    .Set("volume_segment_bytes", setup.Pass ? setup.Pass->GetVolumeSegmentBytes() : 0LL)
    .Set("other_volume_shadow_builds", setup.Pass ? setup.Pass->GetOtherVolumeShadowBuilds() : 0)
    .Set("other_volume_shadow_bytes", setup.Pass ? setup.Pass->GetOtherVolumeShadowBytes() : 0LL)
    .Set("backend", setup.Window->GetBackendAsString())
    .Set("context", setup.Window->GetContextDescription())
    .Set("gl_renderer", RendererString(setup.Window));
  SetStatistics(run.Stats, statistics);
  run.Stats.Set("warnings", ModuleWarnings());
  return run;
}

Image RenderReference(SceneSetup& setup, const Options& options, double& milliseconds)
{
  vtkDeepShadowReferenceRenderer::PrepareRenderer(setup.Renderer);
  vtkNew<vtkDeepShadowReferenceRenderer> reference;
  reference->SetGpuTwin(options.GpuTwin);
  reference->SetThreads(options.Threads);
  reference->SetReplaceNonFiniteScalars(options.ReplaceNonFinite);
  reference->SetShadows(options.GroundTruth ? vtkDeepShadowReferenceRenderer::GroundTruthShadows
                                            : vtkDeepShadowReferenceRenderer::TechniqueShadows);
  Image image;
  const auto start = std::chrono::steady_clock::now();
  if (!reference->Render(setup.Renderer, image))
  {
    throw UsageError("cannot render " + setup.Name + ": " + reference->GetLastError());
  }
  milliseconds =
    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return image;
}

// Where the line saying what was written goes: standard error when the picture or the
// statistics went to standard output.
std::FILE* SummaryStream(const Options& options)
{
  for (const NamedFile& output : options.OutputFiles())
  {
    if (Outputs::IsStandardOutput(output.Path))
    {
      return stderr;
    }
  }
  return stdout;
}
}

int RunRender(const Options& options)
{
  Outputs outputs;
  SceneSetup setup = SceneSetup::Build(options);
  GpuRun run = RenderGPU(setup, options);
  outputs.Write(options.Out, PNGBytes(setup.Window));
  if (!options.Json.empty())
  {
    outputs.Write(options.Json, run.Stats.FileText());
  }
  outputs.Commit();
  std::fprintf(SummaryStream(options), "%s: %dx%d, median %.1f ms over %d frames (first %.1f ms) -> %s\n",
    setup.Name.c_str(), options.Width, options.Height, Median(run.FrameMs), options.Frames,
    run.FirstFrameMs, options.Out.c_str());
  return 0;
}

int RunReference(const Options& options)
{
  Outputs outputs;
  SceneSetup setup = SceneSetup::Build(options);
  double milliseconds = 0.0;
  const Image image = RenderReference(setup, options, milliseconds);
  outputs.Write(options.Out, PNGBytes(ToImageData(image)));
  if (!options.Json.empty())
  {
    Json stats;
    stats.Set("command", options.Command)
      .Set("scene", setup.Name)
      .Set("technique", options.Technique)
      .Set("renderer", options.GpuTwin ? "cpu-reference-gpu-twin" : "cpu-reference-exact")
      .Set("shadows", options.GroundTruth ? "ground-truth" : options.Technique)
      .Set("width", options.Width)
      .Set("height", options.Height)
      .Set("frames", 1)
      .Set("build_ms", 0.0)
      .Set("render_ms", milliseconds)
      .Set("shadow_bytes", 0)
      .Set("shadow_builds", 0)
      .Set("threads", options.Threads)
      .Set("sample_distance", setup.Mapper->GetSampleDistance());
    outputs.Write(options.Json, stats.FileText());
  }
  outputs.Commit();
  std::fprintf(SummaryStream(options), "%s: CPU reference (%s) %dx%d in %.0f ms -> %s\n", setup.Name.c_str(),
    options.GpuTwin ? "GPU twin" : "exact", options.Width, options.Height, milliseconds,
    options.Out.c_str());
  return 0;
}

int RunAll(const Options& options)
{
  if (mkdir(options.OutDir.c_str(), 0755) != 0 && errno != EEXIST)
  {
    throw UsageError("cannot create directory " + options.OutDir);
  }
  Outputs outputs; // every file appears at the end, or none
  std::vector<Json> summary;
  std::printf("%-8s %10s %10s %12s %10s %10s\n", "scene", "gpu_ms", "first_ms", "reference_ms",
    "rmse", "max_abs");
  for (const std::string& name : vtkDeepShadowStandardScene::GetSceneNames())
  {
    Options sceneOptions = options;
    sceneOptions.Scene = name;
    sceneOptions.VolumeFile.clear();
    SceneSetup setup = SceneSetup::Build(sceneOptions);
    GpuRun run = RenderGPU(setup, sceneOptions);
    const std::string stem = options.OutDir + "/" + name;
    outputs.Write(stem + ".png", PNGBytes(setup.Window));
    const Image gpu = CaptureWindow(setup.Window);

    double referenceMs = 0.0;
    const Image reference = RenderReference(setup, sceneOptions, referenceMs);
    outputs.Write(stem + "-reference.png", PNGBytes(ToImageData(reference)));
    outputs.Write(stem + "-difference-x10.png",
      PNGBytes(ToImageData(AbsoluteDifference(gpu, reference, 10.0))));
    const ImageDifference error = Compare(gpu, reference, 2.0 / 255.0);

    run.Stats.Set("reference_ms", referenceMs)
      .Set("rmse_vs_reference", error.RMSE)
      .Set("max_abs_vs_reference", error.MaxAbs)
      .Set("fraction_above_2_of_255", error.FractionAbove);
    outputs.Write(stem + ".json", run.Stats.FileText());
    summary.push_back(run.Stats);
    std::printf("%-8s %10.1f %10.1f %12.0f %10.5f %10.4f\n", name.c_str(), Median(run.FrameMs),
      run.FirstFrameMs, referenceMs, error.RMSE, error.MaxAbs);
    std::fflush(stdout);
  }
  Json all;
  all.Set("scenes", summary);
  outputs.Write(options.OutDir + "/summary.json", all.FileText());
  outputs.Commit();
  std::printf("images, references, differences (x10) and statistics in %s\n",
    options.OutDir.c_str());
  return 0;
}

int RunPresets(const Options&)
{
  for (const std::string& name : vtkDeepShadowVolumePresets::GetPresetNames())
  {
    std::printf("%-15s %s\n", name.c_str(),
      vtkDeepShadowVolumePresets::GetPresetDescription(name).c_str());
  }
  std::printf("\n--tf also takes a ParaView JSON preset file (RGBPoints, Points).\n");
  return 0;
}

int RunSeries(const Options& options)
{
  std::string problem;
  const std::vector<std::string> lines =
    vtkDeepShadowVolumeReader::GetSeriesDescriptions(options.VolumeFile, problem);
  if (lines.empty())
  {
    throw UsageError("cannot list the series of '" + options.VolumeFile + "': " + problem);
  }
  for (const std::string& line : lines)
  {
    std::printf("%s\n", line.c_str());
  }
  return 0;
}

int RunScenes(const Options&)
{
  for (const std::string& name : vtkDeepShadowStandardScene::GetSceneNames())
  {
    vtkNew<vtkDeepShadowStandardScene> scene;
    scene->SetScene(name);
    int dims[3];
    scene->GetDimensions(dims);
    std::printf("%-8s %4dx%4dx%4d  %s\n", name.c_str(), dims[0], dims[1], dims[2],
      vtkDeepShadowStandardScene::GetSceneDescription(name).c_str());
  }
  std::printf("\nBounded (a standard volume inside closed meshes):\n");
  for (const std::string& name : vtkDeepShadowBoundedScene::GetSceneNames())
  {
    std::printf("%-13s %s (%s of the %s scene)\n", name.c_str(),
      vtkDeepShadowBoundedScene::GetSceneDescription(name).c_str(),
      vtkDeepShadowBoundedScene::GetBoundExpression(name).c_str(),
      vtkDeepShadowBoundedScene::GetVolumeSceneName(name).c_str());
  }
  std::printf("\nHybrid (a standard volume with meshes that cast and receive shadows):\n");
  for (const std::string& name : vtkDeepShadowHybridScene::GetSceneNames())
  {
    std::printf("%-13s %s (the %s scene)\n", name.c_str(),
      vtkDeepShadowHybridScene::GetSceneDescription(name).c_str(),
      vtkDeepShadowHybridScene::GetVolumeSceneName(name).c_str());
  }
  return 0;
}

}
}
