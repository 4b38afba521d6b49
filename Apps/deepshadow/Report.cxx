// deepshadow report: what every shadow technique costs and how wrong it is, over a sweep of
// its parameters, on the standard scenes, against the CPU ground truth. Writes
//   DIR/results.csv                one row per (scene, technique, parameters);
//   DIR/<scene>/error-vs-time.png  error against frame time, one marker series per
//                                  technique, the Pareto front dashed (vtkChartXY, headless);
//   DIR/<scene>/*.png              each technique's image and its difference (x10) from the
//                                  ground truth, and the ground truth itself;
//   DIR/README.md                  the tables, the pictures side by side, and which technique
//                                  is on the Pareto front for which budget.
// Progress goes to stderr. --quick runs a short sweep at smaller sizes (the README's main
// command runs it).
#include "Commands.h"
#include "Json.h"
#include "Measure.h"
#include "ReportChart.h"

#include "Core/ShadowTechniques.h"
#include "vtkDeepShadowImageConversion.h"
#include "vtkDeepShadowStandardScene.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <sys/stat.h>

namespace deepshadow
{
namespace tool
{
namespace
{
// Every technique over its parameters (the registry's sweeps: step factors, cache and map
// sizes, PCF kernels, epsilon and layers, CSSM offsets and photons, cached and recomputed);
// `quick`: one or two settings per technique, a first look in a few minutes.
std::vector<std::string> Sweep(bool quick)
{
  std::vector<std::string> specs;
  for (const ShadowTechniqueInfo& technique : ShadowTechniques())
  {
    for (const ShadowSweepEntry& entry : technique.Sweep)
    {
      if (entry.Quick || !quick)
      {
        specs.push_back(technique.Name + entry.Suffix);
      }
    }
  }
  return specs;
}

// The guard: a translucent technique (every one but opaque rays and shadow maps) at its
// defaults must be at least as accurate as no shadows at all; its error is the image's RMSE
// against the ground truth of its kind, grey or coloured.
bool GuardedByNone(const std::string& technique, const std::string& parameters)
{
  const ShadowTechniqueInfo* info = FindShadowTechnique(technique);
  return parameters == "defaults" && info && info->Kind != ShadowKind::None && !info->Binary;
}

struct Row
{
  std::string Scene;
  std::string Spec;
  std::string Technique;  // the spec's name: rays, dsm-cached, ...
  std::string Parameters; // the spec's options, "epsilon=0.01 layers=2", or "defaults"
  bool Colored = false;
  double Baseline = 0.0; // the unshadowed camera-moving frame of the same run
  Measurement M;
  ImageDifference Error;
  ImageDifference ShadowError;
  bool ParetoCamera = false;
  bool ParetoLight = false;
  /** The unshadowed picture's RMSE against the same ground truth (grey or coloured). */
  double UnshadowedError = 0.0;
  /** A translucent technique at its defaults less accurate than no shadows (a defect). */
  bool WorseThanNone = false;
  std::string Slug; // file names of its pictures
};

std::string Slug(const std::string& spec)
{
  std::string slug = spec;
  for (char& c : slug)
  {
    if (c == ':' || c == '=' || c == ',')
    {
      c = c == '=' ? '-' : '_';
    }
  }
  return slug;
}

std::string Join(const std::vector<std::string>& parts, const char* separator)
{
  std::string text;
  for (const std::string& part : parts)
  {
    text += (text.empty() ? "" : separator) + part;
  }
  return text;
}

std::string CsvField(const std::string& text)
{
  if (text.find_first_of(",\"\n") == std::string::npos)
  {
    return text;
  }
  std::string quoted = "\"";
  for (char c : text)
  {
    quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  }
  return quoted + "\"";
}

std::string Number(double value, const char* format = "%.6g")
{
  if (std::isnan(value))
  {
    return "-"; // not measured
  }
  char text[64];
  std::snprintf(text, sizeof(text), format, value);
  return text;
}

void MakeDirectory(const std::string& path)
{
  if (mkdir(path.c_str(), 0755) != 0 && errno != EEXIST)
  {
    throw UsageError("cannot create directory " + path);
  }
}

void WriteCsv(const std::string& path, const std::vector<Row>& rows, const Options& options)
{
  std::ofstream csv(path);
  if (!csv)
  {
    throw UsageError("cannot write " + path);
  }
  // The techniques' own statistics follow the common columns: every name any row reports, in
  // the order first reported; a row whose technique does not report one leaves it empty.
  std::vector<std::string> statistics;
  for (const Row& r : rows)
  {
    for (const auto& statistic : r.M.Statistics)
    {
      if (std::find(statistics.begin(), statistics.end(), statistic.first) == statistics.end())
      {
        statistics.push_back(statistic.first);
      }
    }
  }
  csv << "scene,technique,parameters,spec,colored,width,height,error_width,error_height,frames,"
         "unshadowed_ms,build_ms,render_ms,render_ratio,light_frame_ms,light_ratio,shadow_bytes,"
         "rmse,max_abs,shadow_rmse,shadow_max_abs,pareto_camera,pareto_light,"
         "rebuilt_when_camera_moved,camera_frame_passes,shader_features,worse_than_none";
  for (const std::string& name : statistics)
  {
    csv << ',' << name;
  }
  csv << '\n';
  for (const Row& r : rows)
  {
    csv << CsvField(r.Scene) << ',' << CsvField(r.Technique) << ',' << CsvField(r.Parameters) << ','
        << CsvField(r.Spec) << ',' << (r.Colored ? 1 : 0) << ',' << options.Width << ','
        << options.Height << ',' << options.ErrorWidth << ',' << options.ErrorHeight << ','
        << options.Frames << ',' << Number(r.Baseline, "%.3f") << ',' << Number(r.M.BuildMs, "%.3f")
        << ',' << Number(r.M.CameraMs, "%.3f") << ',' << Number(r.M.CameraMs / r.Baseline, "%.4f")
        << ',' << Number(r.M.LightMs, "%.3f") << ',' << Number(r.M.LightMs / r.Baseline, "%.4f")
        << ',' << r.M.ShadowBytes << ',' << Number(r.Error.RMSE) << ',' << Number(r.Error.MaxAbs)
        << ',' << Number(r.ShadowError.RMSE) << ',' << Number(r.ShadowError.MaxAbs) << ','
        << (r.ParetoCamera ? 1 : 0) << ',' << (r.ParetoLight ? 1 : 0) << ','
        << (r.M.RebuiltForCamera ? 1 : 0) << ',' << CsvField(Join(r.M.CameraPasses, " ")) << ','
        << CsvField(Join(r.M.Features, " ")) << ',' << (r.WorseThanNone ? 1 : 0);
    for (const std::string& name : statistics)
    {
      csv << ',';
      const auto found = std::find_if(r.M.Statistics.begin(), r.M.Statistics.end(),
        [&](const std::pair<std::string, double>& statistic) { return statistic.first == name; });
      if (found != r.M.Statistics.end())
      {
        csv << Number(found->second, "%.10g");
      }
    }
    csv << '\n';
  }
}

// Marks the Pareto fronts of one scene's rows and draws its chart.
void ChartScene(const std::string& directory, const std::string& scene, std::vector<Row*>& rows)
{
  ChartPanel camera{ scene + ": only the camera moves", "frame time / unshadowed frame",
    "RMSE of the image against the ground truth", {} };
  ChartPanel light{ scene + ": the light moves every frame", "frame time / unshadowed frame",
    "RMSE of the image against the ground truth", {} };
  for (const Row* r : rows)
  {
    // Log axes: an error of exactly 0 (never seen) would sit at the bottom edge.
    const double error = std::max(r->Error.RMSE, 1e-6);
    camera.Points.push_back({ r->Technique, r->M.CameraMs / r->Baseline, error });
    light.Points.push_back({ r->Technique, r->M.LightMs / r->Baseline, error });
  }
  for (size_t i : ParetoFront(camera.Points))
  {
    rows[i]->ParetoCamera = true;
  }
  for (size_t i : ParetoFront(light.Points))
  {
    rows[i]->ParetoLight = true;
  }
  WriteErrorVsTimeChart(directory + "/error-vs-time.png", { camera, light });
}

// "Which technique for which budget": the Pareto front read from the fastest up.
void WriteBudgets(std::ostream& md, std::vector<const Row*> rows, bool cameraOnly)
{
  std::sort(rows.begin(), rows.end(), [&](const Row* a, const Row* b) {
    return cameraOnly ? a->M.CameraMs < b->M.CameraMs : a->M.LightMs < b->M.LightMs;
  });
  md << "| frame budget (x unshadowed) | most accurate within it | RMSE | shadow-term RMSE |\n"
        "|---|---|---|---|\n";
  for (const Row* r : rows)
  {
    if (cameraOnly ? r->ParetoCamera : r->ParetoLight)
    {
      const double ratio = (cameraOnly ? r->M.CameraMs : r->M.LightMs) / r->Baseline;
      md << "| >= " << Number(ratio, "%.2f") << " | `" << r->Spec << "` | "
         << Number(r->Error.RMSE, "%.5f") << " | " << Number(r->ShadowError.RMSE, "%.5f") << " |\n";
    }
  }
  md << "\n";
}

// One table for all scenes: per frame budget, the most accurate row within it (the Pareto
// front sampled at fixed budgets).
void WriteBudgetMatrix(std::ostream& md, const std::vector<Row>& rows,
  const std::vector<std::string>& scenes, bool cameraOnly)
{
  md << "| frame budget (x unshadowed) |";
  for (const std::string& scene : scenes)
  {
    md << " " << scene << " |";
  }
  md << "\n|---|";
  for (size_t i = 0; i < scenes.size(); ++i)
  {
    md << "---|";
  }
  md << "\n";
  for (double budget : { 1.1, 1.25, 1.5, 2.0, 3.0, 5.0, HUGE_VAL })
  {
    md << "| " << (std::isinf(budget) ? std::string("any") : "<= " + Number(budget, "%.3g")) << " |";
    for (const std::string& scene : scenes)
    {
      const Row* best = nullptr;
      for (const Row& r : rows)
      {
        const double ratio = (cameraOnly ? r.M.CameraMs : r.M.LightMs) / r.Baseline;
        if (r.Scene == scene && ratio <= budget && (!best || r.Error.RMSE < best->Error.RMSE))
        {
          best = &r;
        }
      }
      md << " " << (best ? "`" + best->Spec + "` " + Number(best->Error.RMSE, "%.4f") : std::string("-")) << " |";
    }
    md << "\n";
  }
  md << "\n";
}

// The README's opening: how it was made, and what each column means.
void WriteMarkdownIntro(std::ostream& md, const Options& options, const std::string& renderer,
  const std::string& command, double minutes)
{
  const bool timed = options.Frames > 0;
  md << "# vtkDeepShadow: error against run time\n\n"
     << "Written by `" << command << "` in " << Number(minutes, "%.1f") << " minutes on "
     << renderer << ". Images " << options.Width << "x" << options.Height << " (maps "
     << "at their own sizes), errors at " << options.ErrorWidth << "x" << options.ErrorHeight << ", "
     << (timed ? "medians of " + std::to_string(options.Frames) + " frames after a warm-up, GL finished"
               : "errors only (--frames 0: no timing)")
     << ".\n\n"
     << "- *frame / unshadowed*: frame time over the unshadowed frame of the same run, while "
        "only the camera orbits (structures reused) and while the key light turns 3 degrees a "
        "frame (structures rebuilt every frame). *build*: median build time of those frames "
        "(map and cache for cached techniques).\n"
     << "- *RMSE*, *max*: the image against the ground truth, in linear RGB in [0, 1] (the "
        "values the renderer computes; no gamma is applied). The ground truth is the CPU "
        "reference in double precision: exact transfer functions, translucent shadow rays at "
        "a quarter of the sample distance, no early termination, coloured for coloured "
        "techniques.\n"
     << "- *shadow RMSE*: the same for the shadow term alone (each sample's colour replaced "
        "by 1 - attenuation (1 - visibility), composited with the volume's opacity; "
        "`vtkDeepShadowVolumeMapper::OutputShadowTerm`, and `vtkDeepShadowPolyDataMapper`'s for "
        "meshes): the technique's error without shading or colour mixed in.\n"
     << "- Scenes with a second volume (hybrid-smoke): it gets a technique of the same kind and "
        "parameters; *build* and *MiB* are both techniques' together, with the grids that carry "
        "each volume's shadows to the other.\n"
     << "- *Pareto*: no other row is both at least as fast and at least as accurate (C: "
        "camera moves, L: light moves). `results.csv` has every figure.\n\n";
}

// The guard's section: every translucent technique at its defaults that is less accurate
// than no shadows at all, or "None here".
void WriteGuardSection(std::ostream& md, const std::vector<Row>& rows)
{
  std::vector<const Row*> defects;
  for (const Row& r : rows)
  {
    if (r.WorseThanNone)
    {
      defects.push_back(&r);
    }
  }
  md << "## Guard: no translucent technique worse than no shadows\n\n"
     << "A translucent technique (rays, rays-color, dsm, dsm-color, dsm3, cssm and their cached "
        "forms) at its defaults whose RMSE exceeds the unshadowed picture's (against the ground "
        "truth of its kind) is a defect. ";
  if (defects.empty())
  {
    md << "None here.\n\n";
  }
  else
  {
    md << "**" << defects.size() << " here:**\n\n| scene | technique | RMSE | unshadowed RMSE |\n|---|---|---|---|\n";
    for (const Row* r : defects)
    {
      md << "| " << r->Scene << " | `" << r->Spec << "` | " << Number(r->Error.RMSE, "%.5f") << " | "
         << Number(r->UnshadowedError, "%.5f") << " |\n";
    }
    md << "\n";
  }
}

// "Which technique for which budget": the matrices over all scenes, then each scene's Pareto
// fronts. Only for timed runs (the caller's choice): without frame times there is no budget.
void WriteBudgetSection(std::ostream& md, const std::vector<Row>& rows,
  const std::vector<std::string>& scenes)
{
  for (const std::string& scene : scenes)
  {
    if (scene == scenes.front())
    {
      md << "## Which technique for which budget\n\n"
         << "The most accurate technique (and its RMSE) whose frame fits the budget, when only the "
            "camera moves (structures reused):\n\n";
      WriteBudgetMatrix(md, rows, scenes, true);
      md << "The same when the light moves every frame (a build every frame):\n\n";
      WriteBudgetMatrix(md, rows, scenes, false);
      md << "Per scene, the whole Pareto front read from the fastest up:\n\n";
    }
    std::vector<const Row*> sceneRows;
    for (const Row& r : rows)
    {
      if (r.Scene == scene)
      {
        sceneRows.push_back(&r);
      }
    }
    md << "### " << scene << "\n\nOnly the camera moves:\n\n";
    WriteBudgets(md, sceneRows, true);
    md << "The light moves every frame:\n\n";
    WriteBudgets(md, sceneRows, false);
  }
}

// A scene's heading, its chart (timed runs only) and the table of its rows' figures.
void WriteSceneTable(
  std::ostream& md, const std::vector<Row>& rows, const std::string& scene, bool timed)
{
  md << "## " << scene << "\n\n" << (timed ? "![error against time](" + scene + "/error-vs-time.png)\n\n" : "")
     << "| technique | parameters | build ms | frame ms | frame / unshadowed | light moves | "
        "MiB | RMSE | max | shadow RMSE | shadow max | Pareto |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Row& r : rows)
  {
    if (r.Scene != scene)
    {
      continue;
    }
    md << "| " << r.Technique << (r.WorseThanNone ? " **(worse than none)**" : "") << " | " << r.Parameters << " | "
       << (r.M.BuildMs > 0.0 ? Number(r.M.BuildMs, "%.1f") : "-") << " | "
       << Number(r.M.CameraMs, "%.1f") << " | " << Number(r.M.CameraMs / r.Baseline, "%.2f")
       << " | " << Number(r.M.LightMs / r.Baseline, "%.2f") << " | "
       << Number(static_cast<double>(r.M.ShadowBytes) / (1024.0 * 1024.0), "%.1f") << " | "
       << Number(r.Error.RMSE, "%.5f") << " | " << Number(r.Error.MaxAbs, "%.3f") << " | "
       << Number(r.ShadowError.RMSE, "%.5f") << " | " << Number(r.ShadowError.MaxAbs, "%.3f")
       << " | " << (r.ParetoCamera ? "C" : "") << (r.ParetoLight ? "L" : "") << " |\n";
  }
}

// A scene's pictures side by side (each row's image, its ground truth and their difference),
// then the ground truth's CPU time and its shadow term.
void WriteScenePictures(std::ostream& md, const std::vector<Row>& rows, const std::string& scene,
  const std::map<std::string, GroundTruth>& truths)
{
  md << "\nPictures at the error size: technique | ground truth | difference x10.\n\n"
     << "| technique | image | ground truth | difference x10 |\n|---|---|---|---|\n";
  for (const Row& r : rows)
  {
    if (r.Scene != scene)
    {
      continue;
    }
    const std::string truth = r.Colored ? "truth-color.png" : "truth.png";
    md << "| `" << r.Spec << "` | <img src=\"" << scene << "/" << r.Slug
       << ".png\" width=\"160\"> | <img src=\"" << scene << "/" << truth
       << "\" width=\"160\"> | <img src=\"" << scene << "/" << r.Slug
       << "-diff.png\" width=\"160\"> |\n";
  }
  const auto truth = truths.find(scene);
  md << "\nGround truth " << Number(truth != truths.end() ? truth->second.Milliseconds : 0.0, "%.0f")
     << " ms on the CPU; its shadow term: <img src=\"" << scene << "/truth-shadow.png\" width=\"160\">\n\n";
}

void WriteMarkdown(const std::string& path, const std::vector<Row>& rows,
  const std::vector<std::string>& scenes, const std::map<std::string, GroundTruth>& truths,
  const Options& options, const std::string& renderer, const std::string& command, double minutes)
{
  std::ofstream md(path);
  if (!md)
  {
    throw UsageError("cannot write " + path);
  }
  const bool timed = options.Frames > 0;
  WriteMarkdownIntro(md, options, renderer, command, minutes);
  WriteGuardSection(md, rows);
  if (timed)
  {
    WriteBudgetSection(md, rows, scenes);
  }
  for (const std::string& scene : scenes)
  {
    WriteSceneTable(md, rows, scene, timed);
    WriteScenePictures(md, rows, scene, truths);
  }
}

// Progress lines on stderr: the step count and the seconds since the report started.
class Progress
{
public:
  Progress(std::chrono::steady_clock::time_point start, size_t steps)
    : Start(start)
    , Steps(steps)
  {
  }

  double Elapsed() const
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - this->Start).count();
  }

  void Step(const std::string& scene, const std::string& what)
  {
    std::fprintf(stderr, "report: [%3zu/%zu] %6.0f s  %-8s %s\n", ++this->Done, this->Steps,
      this->Elapsed(), scene.c_str(), what.c_str());
    std::fflush(stderr);
  }

private:
  std::chrono::steady_clock::time_point Start;
  size_t Steps;
  size_t Done = 0;
};

// What the sweep gathers over all scenes, for the CSV and the README.
struct Results
{
  std::vector<Row> Rows;
  std::map<std::string, GroundTruth> Truths;
  std::string Renderer; // the first scene's
};

// --scenes, or every standard scene; each name checked before any work.
std::vector<std::string> ReportScenes(const Options& options)
{
  const std::vector<std::string> scenes =
    options.BenchScenes.empty() ? vtkDeepShadowStandardScene::GetSceneNames() : options.BenchScenes;
  for (const std::string& scene : scenes)
  {
    RequireSceneName(scene); // hybrid and bounded scenes too
  }
  return scenes;
}

// The scene's unshadowed row: the baseline every other row's frame times are divided by.
Row MeasureUnshadowed(SceneBench& bench, const std::string& scene)
{
  Row none;
  none.Scene = scene;
  none.Spec = none.Technique = "none";
  none.Parameters = "-";
  none.M = bench.Measure(nullptr, true);
  none.Baseline = none.M.CameraMs;
  none.Slug = "none";
  return none;
}

// One technique spec measured on the scene (and on its second volume, if it has one).
Row MeasureSpec(
  SceneBench& bench, const std::string& scene, const std::string& spec, double baseline)
{
  Row row;
  row.Scene = scene;
  row.Spec = spec;
  const size_t colon = spec.find(':');
  row.Technique = spec.substr(0, colon);
  row.Parameters = colon == std::string::npos ? "defaults" : spec.substr(colon + 1);
  std::replace(row.Parameters.begin(), row.Parameters.end(), ':', ' ');
  auto technique = MakeTechnique(WithTechniqueSpec(bench.GetOptions(), spec));
  auto second = bench.Setup().SecondMapper ? MakeTechnique(WithTechniqueSpec(bench.GetOptions(), spec))
                                           : nullptr; // a second volume's
  row.Colored = technique && technique->GetParameters().IsColored();
  row.M = bench.Measure(technique, true, second);
  row.Baseline = baseline;
  row.Slug = Slug(spec);
  return row;
}

// One row's errors against `truth`, the guard, and its pictures written to `directory`.
void ScoreRow(Row& r, const GroundTruth& truth, double unshadowedError, const std::string& scene,
  const std::string& directory)
{
  r.Error = Compare(r.M.Picture, truth.Picture);
  r.UnshadowedError = unshadowedError;
  r.WorseThanNone = GuardedByNone(r.Technique, r.Parameters) && r.Error.RMSE > r.UnshadowedError;
  if (r.WorseThanNone)
  {
    std::fprintf(stderr, "report: DEFECT: %s on %s is less accurate than no shadows (RMSE %.5f > %.5f)\n",
      r.Spec.c_str(), scene.c_str(), r.Error.RMSE, r.UnshadowedError);
  }
  r.ShadowError = Compare(r.M.ShadowTerm, truth.ShadowTerm);
  WritePNG(ToImageData(r.M.Picture), directory + "/" + r.Slug + ".png");
  WritePNG(ToImageData(AbsoluteDifference(r.M.Picture, truth.Picture, 10.0)),
    directory + "/" + r.Slug + "-diff.png");
  r.M.Picture = Image(); // the pictures are on disk; keep the memory of a long sweep flat
  r.M.ShadowTerm = Image();
}

// Errors against the ground truth of the same kind (grey or coloured), and the pictures, of
// the scene's rows (`rows` from `first` on, the unshadowed one first); the unshadowed
// picture's against both, for the guard. The coloured ground truth only if a row needs it.
void ScoreScene(SceneBench& bench, const GroundTruth& grey, const std::string& scene,
  const std::string& directory, std::vector<Row>& rows, size_t first)
{
  bool anyColored = false;
  for (size_t i = first; i < rows.size(); ++i)
  {
    anyColored = anyColored || rows[i].Colored;
  }
  const double unshadowedGrey = Compare(rows[first].M.Picture, grey.Picture).RMSE;
  const double unshadowedColored = anyColored ? Compare(rows[first].M.Picture, bench.Truth(true).Picture).RMSE : 0.0;
  for (size_t i = first; i < rows.size(); ++i)
  {
    Row& r = rows[i];
    const double unshadowed = r.Colored ? unshadowedColored : unshadowedGrey;
    ScoreRow(r, bench.Truth(r.Colored), unshadowed, scene, directory);
  }
  if (anyColored)
  {
    WritePNG(ToImageData(bench.Truth(true).Picture), directory + "/truth-color.png");
  }
}

// One scene: its ground truth, every spec measured and scored, its pictures and its chart
// written to DIR/<scene>; its rows appended to `results`.
void RunScene(const Options& options, const std::string& scene,
  const std::vector<std::string>& specs, Progress& progress, Results& results)
{
  std::vector<Row>& rows = results.Rows;
  const std::string directory = options.OutDir + "/" + scene;
  MakeDirectory(directory);
  progress.Step(scene, "unshadowed, and the ground truth on the CPU");
  SceneBench bench(options, scene);
  if (results.Renderer.empty())
  {
    results.Renderer = RendererString(bench.Setup().Window);
  }
  const size_t first = rows.size();
  const GroundTruth& grey = bench.Truth(false);
  WritePNG(ToImageData(grey.Picture), directory + "/truth.png");
  WritePNG(ToImageData(grey.ShadowTerm), directory + "/truth-shadow.png");
  results.Truths[scene] = grey;

  rows.push_back(MeasureUnshadowed(bench, scene));
  const double baseline = rows.back().M.CameraMs;
  for (const std::string& spec : specs)
  {
    progress.Step(scene, spec);
    rows.push_back(MeasureSpec(bench, scene, spec, baseline));
  }

  ScoreScene(bench, grey, scene, directory, rows, first);
  std::vector<Row*> sceneRows;
  for (size_t i = first; i < rows.size(); ++i)
  {
    sceneRows.push_back(&rows[i]);
  }
  if (options.Frames > 0)
  {
    ChartScene(directory, scene, sceneRows);
  }
}

// The command line as the README quotes it.
std::string CommandLine(const Options& options)
{
  std::string command = "deepshadow report";
  for (const std::string& arg : options.Arguments)
  {
    command += " " + arg;
  }
  return command;
}
}

int RunReport(const Options& options)
{
  const auto start = std::chrono::steady_clock::now();
  const std::vector<std::string> scenes = ReportScenes(options);
  std::vector<std::string> specs = options.BenchTechniques;
  if (specs.empty())
  {
    specs = Sweep(options.Quick);
  }
  MakeDirectory(options.OutDir);
  Progress progress(start, scenes.size() * (specs.size() + 1));

  Results results;
  for (const std::string& scene : scenes)
  {
    RunScene(options, scene, specs, progress, results);
  }

  const std::vector<Row>& rows = results.Rows;
  WriteCsv(options.OutDir + "/results.csv", rows, options);
  WriteMarkdown(options.OutDir + "/README.md", rows, scenes, results.Truths, options,
    results.Renderer, CommandLine(options), progress.Elapsed() / 60.0);
  std::fprintf(stderr, "report: %zu rows in %.0f s: %s/README.md, results.csv%s\n", rows.size(),
    progress.Elapsed(), options.OutDir.c_str(),
    options.Frames > 0 ? ", <scene>/error-vs-time.png" : " (errors only)");
  return 0;
}

}
}
