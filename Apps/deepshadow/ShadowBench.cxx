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
//     et al.'s Table 4);
//   - with --receiver-error, the error of the shadow term alone at each pixel's first
//     receiver (where the view ray's opacity reaches one half), the technique's CPU twin
//     against the ground truth's shadows on the same exact march: what the representation
//     costs where a viewer sees it;
//   - with --charts DIR, per scene DIR/<scene>.png: RMSE against bits per light-space texel
//     and against the camera-only frame ratio, one series per technique, Pareto fronts drawn.
#include "Commands.h"
#include "Json.h"
#include "Measure.h"
#include "Outputs.h"
#include "ReportChart.h"

#include "Core/Shadows.h"

#include "vtkDeepShadowStandardScene.h"
#include "Core/ShadowTechniques.h"
#include "vtkDeepShadowTechnique.h"

#include <algorithm>
#include <cmath>
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

// The first-receiver error: over the pixels where both the twin and the ground truth have a
// receiver (-1 marks none), RMSE and largest difference of the shadow term.
struct ReceiverError
{
  double RMSE = 0.0;
  double MaxAbs = 0.0;
  long long Pixels = 0;
};

ReceiverError CompareReceivers(const Image& twin, const Image& truth)
{
  ReceiverError error;
  double squares = 0.0;
  for (int y = 0; y < truth.Height; ++y)
  {
    for (int x = 0; x < truth.Width; ++x)
    {
      const glm::dvec3 a = twin.At(x, y), b = truth.At(x, y);
      if (a.r < 0.0 || b.r < 0.0)
      {
        continue;
      }
      for (int c = 0; c < 3; ++c)
      {
        squares += (a[c] - b[c]) * (a[c] - b[c]);
        error.MaxAbs = std::max(error.MaxAbs, std::abs(a[c] - b[c]));
      }
      ++error.Pixels;
    }
  }
  error.RMSE = error.Pixels > 0 ? std::sqrt(squares / (3.0 * error.Pixels)) : 0.0;
  return error;
}

// One scene's chart: RMSE against bits per texel (map techniques) and against the
// camera-only frame ratio, one series per technique name.
void ChartScene(const std::string& directory, const std::string& label, const std::vector<ChartPoint>& bits,
  const std::vector<ChartPoint>& ratio)
{
  ChartPanel memory{ label + ": error against memory", "bits per light-space texel",
    "RMSE of the image against the ground truth", bits };
  ChartPanel time{ label + ": error against frame time", "frame time / unshadowed frame (camera moves)",
    "RMSE of the image against the ground truth", ratio };
  WriteErrorVsTimeChart(directory + "/" + label + ".png", { memory, time });
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
  if (!options.ChartsDirectory.empty())
  {
    // Before the work: the first scene's chart can be written there.
    const std::string first = scenes.front().empty() ? FileLabel(options.VolumeFile) : scenes.front();
    Outputs::RequireWritable(options.ChartsDirectory + "/" + first + ".png");
  }

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
    std::vector<ChartPoint> bitsPoints, ratioPoints;

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
      const ShadowTechniqueInfo& info = ShadowTechniqueOf(shadow->GetParameters());
      ReceiverError receiver;
      char receiverText[64] = "";
      if (options.ReceiverError)
      {
        receiver = CompareReceivers(bench.TwinSurfaceTerm(shadow), bench.Truth(colored).SurfaceTerm);
        std::snprintf(receiverText, sizeof(receiverText), "  receivers %.5f/%.4f", receiver.RMSE, receiver.MaxAbs);
      }
      std::printf("%-8s %-24s %9.1f %8.2f %8.2f %9.1f %11lld %9.5f %8.4f %s%s%s\n", label.c_str(),
        technique.c_str(), m.CameraMs, m.CameraMs / baseline, m.LightMs / baseline, m.BuildMs,
        m.ShadowBytes, error.RMSE, error.MaxAbs, nodes, receiverText,
        m.RebuiltForCamera && !info.FollowsView ? "  (rebuilt when the camera moved!)" : "");
      // Log axes: an error of exactly 0 would sit on the edge.
      const double chartError = std::max(error.RMSE, 1e-6);
      // The bits per texel as built where the technique says (dsm-fixed with an error), else
      // the registry's.
      const double builtBits = vtkDeepShadowTechnique::FindStatistic(m.Statistics, "texel_bits");
      if (builtBits > 0.0 || info.TexelBytes)
      {
        bitsPoints.push_back({ info.Name,
          builtBits > 0.0 ? builtBits : 8.0 * static_cast<double>(info.TexelBytes(shadow->GetParameters())), chartError });
      }
      ratioPoints.push_back({ info.Name, m.CameraMs / baseline, chartError });
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
      if (options.ReceiverError)
      {
        row.Set("receiver_rmse", receiver.RMSE).Set("receiver_max", receiver.MaxAbs).Set("receiver_pixels", receiver.Pixels);
      }
      SetStatistics(row, m.Statistics);
      rows.push_back(row);
    }
    if (!options.ChartsDirectory.empty())
    {
      ChartScene(options.ChartsDirectory, label, bitsPoints, ratioPoints);
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
