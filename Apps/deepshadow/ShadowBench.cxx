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
#include "Measure.h"
#include "Outputs.h"

#include "Core/Shadows.h"

#include "vtkDeepShadowStandardScene.h"
#include "Core/ShadowTechniques.h"
#include "vtkDeepShadowTechnique.h"

#include <cstdio>

namespace deepshadow
{
namespace tool
{
namespace
{
// The techniques measured when --techniques is not given: each at its defaults, and cached
// where the registry's quick sweep caches it.
std::vector<std::string> DefaultTechniques()
{
  std::vector<std::string> specs;
  for (const ShadowTechniqueInfo& technique : ShadowTechniques())
  {
    for (const ShadowSweepEntry& entry : technique.Sweep)
    {
      if (entry.Suffix.empty() || (entry.Suffix == "-cached" && entry.Quick))
      {
        specs.push_back(technique.Name + entry.Suffix);
      }
    }
  }
  return specs;
}

// A volume file's row label: its name without folders.
std::string FileLabel(const std::string& path)
{
  const size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}
}

int RunShadowBench(const Options& options)
{
  // --volume without --scenes: that file alone (an empty name keeps it).
  const bool file = !options.VolumeFile.empty() && options.BenchScenes.empty();
  const std::vector<std::string> scenes = file ? std::vector<std::string>{ "" }
    : options.BenchScenes.empty()              ? vtkDeepShadowStandardScene::GetSceneNames()
                                               : options.BenchScenes;
  const std::vector<std::string> techniques =
    options.BenchTechniques.empty() ? DefaultTechniques() : options.BenchTechniques;

  std::printf("%-8s %-24s %9s %8s %8s %9s %11s %9s %8s %s\n", "scene", "technique", "frame_ms",
    "camera", "light", "build_ms", "bytes", "rmse", "max", "nodes avg/max");
  std::vector<Json> rows;
  std::string renderer;
  for (const std::string& name : scenes)
  {
    SceneBench bench(options, name);
    const std::string label = name.empty() ? FileLabel(options.VolumeFile) : name;
    renderer = RendererString(bench.Setup().Window);
    const Measurement none = bench.Measure(nullptr, false);
    const double baseline = none.CameraMs;
    const GroundTruth& truth = bench.Truth(false);
    const ImageDifference unshadowedError = Compare(none.Picture, truth.Picture);
    std::printf("%-8s %-24s %9.1f %8s %8s %9s %11s %9.5f %8.4f   (ground truth %.0f ms)\n",
      label.c_str(), "none", baseline, "1.00", "1.00", "-", "0", unshadowedError.RMSE,
      unshadowedError.MaxAbs, truth.Milliseconds);
    std::fflush(stdout);

    for (const std::string& technique : techniques)
    {
      auto shadow = MakeTechnique(WithTechniqueSpec(bench.GetOptions(), technique));
      if (!shadow)
      {
        continue; // "none": the baseline, measured and printed above
      }
      const bool colored = shadow->GetParameters().IsColored();
      const Measurement m = bench.Measure(shadow, false);
      const ImageDifference error = Compare(m.Picture, bench.Truth(colored).Picture);
      // Nodes per texel, average/maximum, for techniques that count them.
      const double nodesMax = vtkDeepShadowTechnique::FindStatistic(m.Statistics, "dsm_nodes_max");
      char nodes[64] = "";
      if (nodesMax > 0.0)
      {
        std::snprintf(nodes, sizeof(nodes), "%.2f/%.0f",
          vtkDeepShadowTechnique::FindStatistic(m.Statistics, "dsm_nodes_avg"), nodesMax);
      }
      std::printf("%-8s %-24s %9.1f %8.2f %8.2f %9.1f %11lld %9.5f %8.4f %s%s\n", label.c_str(),
        technique.c_str(), m.CameraMs, m.CameraMs / baseline, m.LightMs / baseline, m.BuildMs,
        m.ShadowBytes, error.RMSE, error.MaxAbs, nodes,
        m.RebuiltForCamera && !ShadowTechniqueOf(shadow->GetParameters()).FollowsView ? "  (rebuilt when the camera moved!)" : "");
      std::fflush(stdout);
      Json row;
      row.Set("scene", label)
        .Set("technique", technique)
        .Set("unshadowed_ms", baseline)
        .Set("camera_ms", m.CameraMs)
        .Set("light_ms", m.LightMs)
        .Set("camera_ratio", m.CameraMs / baseline)
        .Set("light_ratio", m.LightMs / baseline)
        .Set("build_ms", m.BuildMs)
        .Set("shadow_bytes", m.ShadowBytes)
        .Set("colored", colored)
        .Set("rmse", error.RMSE)
        .Set("max_abs", error.MaxAbs)
        .Set("unshadowed_rmse", unshadowedError.RMSE)
        .Set("ground_truth_ms", bench.Truth(colored).Milliseconds)
        .Set("rebuilt_when_camera_moved", m.RebuiltForCamera);
      SetStatistics(row, m.Statistics);
      rows.push_back(row);
    }
  }
  if (!options.Json.empty())
  {
    Json all;
    all.Set("width", options.Width)
      .Set("height", options.Height)
      .Set("error_width", options.ErrorWidth)
      .Set("error_height", options.ErrorHeight)
      .Set("frames", options.Frames)
      .Set("gl_renderer", renderer)
      .Set("rows", rows);
    Outputs outputs;
    outputs.Write(options.Json, all.FileText());
    outputs.Commit();
  }
  return 0;
}

}
}
