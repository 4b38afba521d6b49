// deepshadow gallery: the main job's page. Every standard, bounded and hybrid scene
// unshadowed, with its default shadows and with the ground truth, in DIR/index.html with
// frame times and errors, in a few minutes on two cores (errors at a small size: the ground
// truth is the CPU's translucent shadow rays at a quarter step).
#include "Commands.h"

#include "Json.h"
#include "Measure.h"
#include "Outputs.h"
#include "SceneSetup.h"

#include "Core/Image.h"
#include "vtkDeepShadowBoundedScene.h"
#include "vtkDeepShadowHybridScene.h"
#include "vtkDeepShadowImageConversion.h"
#include "vtkDeepShadowStandardScene.h"
#include "vtkDeepShadowTechniqueFactory.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <sstream>
#include <sys/stat.h>

namespace deepshadow
{
namespace tool
{
namespace
{
struct GalleryScene
{
  std::string Name;
  std::string Family; // standard, bounded, hybrid
  std::string Description;
};

std::vector<GalleryScene> AllScenes()
{
  std::vector<GalleryScene> scenes;
  for (const auto& name : vtkDeepShadowStandardScene::GetSceneNames())
  {
    scenes.push_back({ name, "standard", vtkDeepShadowStandardScene::GetSceneDescription(name) });
  }
  for (const auto& name : vtkDeepShadowBoundedScene::GetSceneNames())
  {
    scenes.push_back({ name, "bounded", vtkDeepShadowBoundedScene::GetSceneDescription(name) });
  }
  for (const auto& name : vtkDeepShadowHybridScene::GetSceneNames())
  {
    scenes.push_back({ name, "hybrid", vtkDeepShadowHybridScene::GetSceneDescription(name) });
  }
  return scenes;
}

std::string Html(const std::string& text)
{
  std::string out;
  for (char c : text)
  {
    out += c == '&' ? "&amp;" : c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '"' ? "&quot;" : std::string(1, c);
  }
  return out;
}

std::string Fixed(double value, int digits)
{
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.*f", digits, value);
  return buffer;
}

struct Row
{
  GalleryScene Scene;
  std::string Technique;
  Measurement Unshadowed, Shadowed;
  double TruthMs = 0.0;
  ImageDifference UnshadowedError, ShadowedError;
};

// The scenes to show: every scene, or those --scenes names (each name checked first), in the
// order of AllScenes().
std::vector<GalleryScene> SelectScenes(const Options& options)
{
  for (const auto& name : options.BenchScenes)
  {
    RequireSceneName(name);
  }
  std::vector<GalleryScene> scenes;
  for (const GalleryScene& scene : AllScenes())
  {
    if (options.BenchScenes.empty() ||
      std::find(options.BenchScenes.begin(), options.BenchScenes.end(), scene.Name) != options.BenchScenes.end())
    {
      scenes.push_back(scene);
    }
  }
  return scenes;
}

// What the scenes gather for the page and summary.json.
struct Results
{
  std::vector<Row> Rows;
  std::vector<Json> Summary;
  std::string Renderer; // the first scene's
};

// A row's numbers as summary.json lists them.
Json SceneSummary(const Row& row)
{
  Json stats;
  stats.Set("scene", row.Scene.Name)
    .Set("family", row.Scene.Family)
    .Set("technique", row.Technique)
    .Set("unshadowed_ms", row.Unshadowed.CameraMs)
    .Set("shadowed_ms", row.Shadowed.CameraMs)
    .Set("build_ms", row.Shadowed.BuildMs)
    .Set("shadow_bytes", row.Shadowed.ShadowBytes)
    .Set("ground_truth_ms", row.TruthMs)
    .Set("rmse_unshadowed", row.UnshadowedError.RMSE)
    .Set("rmse_shadowed", row.ShadowedError.RMSE)
    .Set("max_abs_shadowed", row.ShadowedError.MaxAbs);
  return stats;
}

// A row's line of the table on stdout, flushed: progress while the gallery runs.
void PrintSceneLine(const Row& row)
{
  std::printf("%-14s %-10s %9.1f %9.1f %9.1f %10.0f %10.5f %10.5f\n", row.Scene.Name.c_str(),
    row.Technique.c_str(), row.Unshadowed.CameraMs, row.Shadowed.CameraMs,
    row.Shadowed.BuildMs, row.TruthMs, row.UnshadowedError.RMSE, row.ShadowedError.RMSE);
  std::fflush(stdout);
}

// One scene measured without shadows and with its default technique (dsm, dsm-color for the
// hybrid scenes' coloured volumes), against the ground truth; its three pictures staged in
// `outputs`, its line printed, its row and summary added to `results`.
void RunScene(const Options& options, const GalleryScene& scene, Outputs& outputs, Results& results)
{
  Row row;
  row.Scene = scene;
  row.Technique = scene.Family == "hybrid" ? "dsm-color" : "dsm";
  SceneBench bench(options, scene.Name);
  if (results.Renderer.empty())
  {
    results.Renderer = RendererString(bench.Setup().Window);
  }
  auto technique = vtkDeepShadowTechniqueFactory::New(row.Technique);
  auto second = vtkDeepShadowTechniqueFactory::New(row.Technique);
  // Camera-moving frames only: a gallery shows a view, shadows built once.
  row.Unshadowed = bench.Measure(nullptr, false, nullptr, false);
  row.Shadowed = bench.Measure(technique, false, second, false);
  const GroundTruth& truth = bench.Truth(scene.Family == "hybrid");
  row.TruthMs = truth.Milliseconds;
  row.UnshadowedError = Compare(row.Unshadowed.Picture, truth.Picture);
  row.ShadowedError = Compare(row.Shadowed.Picture, truth.Picture);

  const std::string stem = options.OutDir + "/" + scene.Name;
  outputs.Write(stem + "-none.png", PNGBytes(ToImageData(bench.Picture(nullptr))));
  outputs.Write(stem + "-shadows.png", PNGBytes(ToImageData(bench.Picture(technique, second))));
  outputs.Write(stem + "-truth.png", PNGBytes(ToImageData(truth.Picture)));

  results.Summary.push_back(SceneSummary(row));
  PrintSceneLine(row);
  results.Rows.push_back(std::move(row));
}

// index.html up to its table's heading: the style, the title, and how it was made.
void WritePageHead(
  std::ostream& page, const Options& options, const std::string& renderer, double seconds)
{
  page << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
       << "<title>vtkDeepShadow: the scenes</title>\n<style>\n"
       << "body{font-family:sans-serif;margin:1.5em;background:#fafafa;color:#222}\n"
       << "table{border-collapse:collapse}td,th{padding:4px 8px;border-bottom:1px solid #ddd;"
          "vertical-align:top;text-align:left}\n"
       << "img{width:" << options.Width << "px;image-rendering:auto;display:block}\n"
       << ".num{text-align:right;font-variant-numeric:tabular-nums}\n"
       << "td table td{white-space:nowrap;border:none;padding:1px 6px}\n</style></head><body>\n"
       << "<h1>vtkDeepShadow: every scene, without shadows, with them, and the ground truth</h1>\n"
       << "<p>Rendered headless by <code>deepshadow gallery</code> on " << Html(renderer) << ", "
       << options.Width << "x" << options.Height << "; frame times are medians of "
       << options.Frames << " frames of a slow orbit (shadows built once, reused); errors are "
       << "RMSE against the ground truth (CPU, double precision, translucent shadow rays at a "
       << "quarter step) at " << options.ErrorWidth << "x" << options.ErrorHeight
       << ", the size the ground truth is shown at here. All of it took " << Fixed(seconds, 0)
       << " s.</p>\n<table>\n<tr><th>scene</th><th>no shadows</th><th>shadows</th>"
       << "<th>ground truth</th><th>numbers</th></tr>\n";
}

// One scene's row of index.html: its name, its three pictures and its numbers.
void WritePageRow(std::ostream& page, const Row& row)
{
  const std::string& name = row.Scene.Name;
  page << "<tr><td><b>" << Html(name) << "</b><br>" << Html(row.Scene.Family) << "<br><small>"
       << Html(row.Scene.Description) << "</small></td>\n"
       << "<td><img src=\"" << Html(name) << "-none.png\" alt=\"" << Html(name) << " without shadows\"></td>\n"
       << "<td><img src=\"" << Html(name) << "-shadows.png\" alt=\"" << Html(name) << " with " << row.Technique << "\"></td>\n"
       << "<td><img src=\"" << Html(name) << "-truth.png\" alt=\"" << Html(name) << " ground truth\"></td>\n"
       << "<td><table>"
       << "<tr><td>technique</td><td>" << row.Technique << "</td></tr>"
       << "<tr><td>frame, no shadows</td><td class=num>" << Fixed(row.Unshadowed.CameraMs, 1) << " ms</td></tr>"
       << "<tr><td>frame, shadows</td><td class=num>" << Fixed(row.Shadowed.CameraMs, 1) << " ms</td></tr>"
       << "<tr><td>shadow build</td><td class=num>" << Fixed(row.Shadowed.BuildMs, 1) << " ms</td></tr>"
       << "<tr><td>shadow memory</td><td class=num>" << Fixed(row.Shadowed.ShadowBytes / 1048576.0, 1) << " MiB</td></tr>"
       << "<tr><td>ground truth</td><td class=num>" << Fixed(row.TruthMs / 1000.0, 1) << " s</td></tr>"
       << "<tr><td>RMSE, no shadows</td><td class=num>" << Fixed(row.UnshadowedError.RMSE, 4) << "</td></tr>"
       << "<tr><td>RMSE, shadows</td><td class=num>" << Fixed(row.ShadowedError.RMSE, 4) << "</td></tr>"
       << "</table></td></tr>\n";
}

// The text of index.html: every scene's pictures and numbers in one table.
std::string PageText(
  const Options& options, const std::vector<Row>& rows, const std::string& renderer, double seconds)
{
  std::ostringstream page;
  WritePageHead(page, options, renderer, seconds);
  for (const Row& row : rows)
  {
    WritePageRow(page, row);
  }
  page << "</table>\n<p>Per scene: <code>&lt;scene&gt;-none.png</code>, <code>-shadows.png</code>, "
       << "<code>-truth.png</code>; all numbers in <code>summary.json</code>. The report of "
       << "every technique and parameter is <code>scripts/report.sh</code>.</p>\n</body></html>\n";
  return page.str();
}
}

int RunGallery(const Options& options)
{
  const auto start = std::chrono::steady_clock::now();
  if (mkdir(options.OutDir.c_str(), 0755) != 0 && errno != EEXIST)
  {
    throw UsageError("cannot create directory " + options.OutDir);
  }
  const std::vector<GalleryScene> scenes = SelectScenes(options);

  Outputs outputs; // every file appears at the end, or none
  Results results;
  std::printf("%-14s %-10s %9s %9s %9s %10s %10s %10s\n", "scene", "technique", "none_ms",
    "shadow_ms", "build_ms", "truth_ms", "rmse_none", "rmse_shadow");
  for (const GalleryScene& scene : scenes)
  {
    RunScene(options, scene, outputs, results);
  }

  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  outputs.Write(
    options.OutDir + "/index.html", PageText(options, results.Rows, results.Renderer, seconds));
  Json all;
  all.Set("scenes", results.Summary).Set("seconds", seconds).Set("gl_renderer", results.Renderer);
  outputs.Write(options.OutDir + "/summary.json", all.FileText());
  outputs.Commit();
  std::printf("%zu scenes in %.0f s: %s/index.html\n", results.Rows.size(), seconds,
    options.OutDir.c_str());
  return 0;
}

}
}
