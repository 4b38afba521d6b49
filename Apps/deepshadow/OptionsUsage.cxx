// deepshadow --help and `deepshadow COMMAND --help`: the usage text, with the technique
// options written from the registry (names, keys, ranges, defaults).
#include "Look.h"
#include "Options.h"

#include <algorithm>
#include <sstream>

namespace deepshadow
{
namespace tool
{
namespace
{
// --help's lines for one option: "  --KEY METAVAR", then `text` wrapped from column 26.
std::string OptionHelp(const std::string& option, const std::string& text)
{
  constexpr size_t column = 26, width = 94;
  std::string help = "  " + option;
  size_t at = help.size();
  if (at + 2 > column)
  {
    help += "\n";
    at = 0;
  }
  std::istringstream words(text);
  bool lineStart = true;
  for (std::string word; words >> word;)
  {
    if (!lineStart && at + 1 + word.size() > width)
    {
      help += "\n";
      at = 0;
      lineStart = true;
    }
    if (lineStart)
    {
      help += std::string(column - at, ' ');
      at = column;
    }
    else
    {
      help += ' ';
      ++at;
    }
    help += word;
    at += word.size();
    lineStart = false;
  }
  std::replace(help.begin(), help.end(), '\x01', ' ');
  return help + "\n";
}

// The technique options, from the registry: names, who reads each key, ranges, defaults.
std::string TechniqueUsage()
{
  std::string names;
  for (const ShadowTechniqueInfo& technique : ShadowTechniques())
  {
    names += (names.empty() ? "" : ", ") + technique.Name +
      (technique.Summary.empty() ? "" : " (" + technique.Summary + ")");
  }
  std::string usage = OptionHelp("--technique NAME", "shadow technique: " + names +
      "; NAME-cached caches any of them in a 3D shadow volume (e.g. dsm-cached)");
  const ShadowParameters defaults;
  const auto& shared = SharedShadowParameterKeys();
  for (const ShadowParameterInfo& parameter : ShadowParameterInfos())
  {
    std::string readers;
    if (std::find(shared.begin(), shared.end(), parameter.Key) == shared.end())
    {
      for (const ShadowTechniqueInfo& technique : ShadowTechniques())
      {
        if (technique.Reads(parameter.Key))
        {
          readers += (readers.empty() ? "" : ", ") + technique.Name;
        }
      }
      readers += ": ";
    }
    using Type = ShadowParameterInfo::Type;
    const bool choice = parameter.Kind == Type::Choice;
    std::string metavar = parameter.Metavar;
    for (size_t c = 0; choice && c < parameter.Choices.size(); ++c)
    {
      metavar += (c == 0 ? "" : "|") + parameter.Choices[c];
    }
    const std::string text = parameter.RangeText();
    const std::string range = choice ? std::string()
      : parameter.Kind == Type::Levels ? ", increasing within " + text
                                       : (text[0] == '[' ? ", in " : ", ") + text;
    std::string unbroken = range; // a range is not broken across lines
    std::replace(unbroken.begin() + (unbroken.empty() ? 0 : 2), unbroken.end(), ' ', '\x01');
    const std::string fallback = parameter.Format(parameter.Get(defaults));
    usage += OptionHelp("--" + parameter.Key + " " + metavar,
      readers + parameter.Help + unbroken + " (default " +
        (parameter.DefaultText.empty() ? fallback : parameter.DefaultText) + ")");
  }
  return usage;
}

// The synopsis of every command.
std::string UsageSynopsis()
{
  return R"(deepshadow: volume rendering with shadows, headless (vtkDeepShadow)

Usage:
  deepshadow render    [SCENE] [VIEW] [RENDERING] --out image.png [--json stats.json] [--frames N]
  deepshadow reference [SCENE] [VIEW] [RENDERING] --out image.png [--json stats.json]
                       [--gpu-twin | --ground-truth] [--threads N]
  deepshadow all       --out DIR [VIEW] [--frames N]
  deepshadow view     [SCENE] [VIEW] [RENDERING] [--keys K,K,...] [--screenshots DIR]
  deepshadow gallery   --out DIR [--scenes a,b] [--size WxH] [--error-size WxH] [--frames N]
  deepshadow bench     [--bench-sizes 128,256] [--blend-modes LIST|all] [--size WxH] [--frames N]
                       [--json bench.json]
  deepshadow shadow-bench [--scenes a,b] [--techniques t,u] [--size WxH] [--error-size WxH]
                       [--frames N] [--receiver-error] [--charts DIR] [--json shadows.json]
  deepshadow report    --out DIR [--quick] [--scenes a,b] [--techniques t,u] [--size WxH]
                       [--error-size WxH] [--frames N]
  deepshadow scenes
  deepshadow presets
  deepshadow series    --volume DIR
  deepshadow --version
  deepshadow --help

)";
}

// What each command does.
std::string UsageCommands()
{
  return R"(Commands:
  render      GPU ray casting with vtkDeepShadowVolumeMapper; writes the image and, with
              --json, the frame statistics.
  reference   The same scene rendered by the CPU reference in double precision (the ground
              truth of every reported error), with the CPU twin of the chosen technique;
              --gpu-twin reproduces the GPU's approximations (transfer table, early
              termination) instead of the exact model; --ground-truth renders the exact
              shadows (translucent shadow rays at a quarter step) whatever the technique.
  view        The scene in a window (needs a display): the mouse orbits, Ctrl + left drag
              or the arrow keys move the key light, t switches the technique, e/E halve or
              double epsilon, m/M the map size, g toggles the meshes (--ground for a floor),
              s saves a screenshot, q quits. --keys t,Left,s feeds keys without a person;
              --screenshots DIR is where s writes view-N.png and view-N.json.
  gallery     Every standard, bounded and hybrid scene unshadowed, with its default shadows
              (dsm; dsm-color for hybrid scenes) and the ground truth, side by side in
              DIR/index.html with frame times and errors (the main job; 256x256, errors at
              96x96, 2 frames; --scenes a,b for some).
  all         Renders every standard scene into DIR (DIR/<scene>.png and .json), with the
              CPU reference and the error against it.
  bench       Our mapper against VTK's vtkGPUVolumeRayCastMapper in one run, same scenes,
              same sample distance; prints the ratio of median frame times. --blend-modes:
              the shaded head in each blend mode instead (isosurface: at the scalar where
              the opacity first reaches half its maximum).
  shadow-bench  Per scene and technique: frame time when only the camera moves and when
              the light moves, as ratios to the unshadowed frame of the same run, build time,
              memory, and the error against the ground truth (CPU, translucent shadow rays at
              a quarter step, coloured for coloured techniques) at --error-size (default
              256x256). --techniques takes technique specs, NAME[:OPTION=VALUE...] with any
              technique option below without its dashes, e.g. dsm:layers=2:epsilon=0.05.
              With --volume and no --scenes, the file alone. --receiver-error: also the
              error of the shadow term alone at each pixel's first receiver (where the view
              ray's opacity reaches 1/2), the technique's CPU twin against the ground
              truth's shadows (slower: a CPU render per technique). --charts DIR: per scene
              DIR/SCENE.png, the error against bits per light-space texel and against the
              frame ratio, one series per technique, Pareto fronts dashed.
  report      Error against run time for every technique over a sweep of its parameters
              (step factors, cache and map sizes, PCF kernels, epsilon and layers, CSSM
              offsets and photons, cached and recomputed) on the standard scenes: writes
              DIR/results.csv (build and frame times, ratios to the unshadowed frame,
              memory, RMSE and maximum error of the image and of the shadow term against
              the ground truth), DIR/<scene>/error-vs-time.png (Pareto front dashed), the
              pictures, and DIR/README.md (tables, pictures side by side, the best technique
              per budget). Defaults 512x512, errors at 256x256, 5 frames; --quick: a short
              sweep at 256x256, errors at 128x128, 3 frames. Progress on stderr.
  scenes      Lists the standard scenes.
  presets     Lists the transfer-function presets --tf takes.
  series      Lists the DICOM series of a folder (number, modality, description, slices,
              size, UID), as --series takes them.

)";
}

// The scene options.
std::string UsageScene()
{
  return R"(SCENE (default: --scene box):
  --scene NAME            a standard scene (see `deepshadow scenes`)
  --scale S               voxels per axis of the scene times S (0.01-2, default 1)
  --objects N             sparse: its first N objects (1-24; default its 19; above 19,
                          smaller ones between its cells), for scaling studies
  --volume FILE|DIR       a volume file instead: .vti, .mhd/.mha, .nrrd/.nhdr, .nii/.nii.gz
                          (placed by its s/q-form), a DICOM folder (read with GDCM; placed
                          by its slices' positions), or a multi-frame DICOM file
  --series N|UID          the DICOM series of the folder to read, by its number or UID (a
                          folder of several: see `deepshadow series`)
  --volume-index N        the volume of a 4D NIfTI file to read (default 0, the first)
  --replace-nonfinite     render NaN/Inf samples as the data's extremes instead of failing
  --mask FILE             a binary mask, a volume file of the data's dimensions: samples whose
                          nearest mask voxel is 0 or less are clear, drawn and cast (VTK's
                          SetMaskInput)
  --bound FILE            the volume exists only inside this closed mesh (.vtp, .vtk, .stl,
                          .ply, .obj; in the volume's data coordinates); repeatable: the
                          bounds are named A, B, C... in the order given
  --csg EXPR              how the bounds combine, e.g. union(A,diff(B,C)) with union,
                          intersection/inter, difference/diff (default: the union of all).
                          The bounds are checked with CGAL first (closed, not
                          self-intersecting, bounding a volume): a bad one exits with code 2
  --csg-mesh              bound the volume by the CGAL result mesh of the expression
                          instead of evaluating the expression per ray (same picture)
  --csg-max-work N        refuse an expression whose CGAL operations would take more than N
                          triangles of work (each operation's operands, summed; 7 to 130 s
                          a million here); default 500000, 0: no limit
  --mesh FILE             a mesh (.vtp, .vtk, .stl, .ply, .obj; world coordinates) that casts
                          shadows into the volume and receives the scene's; repeatable. The
                          options below apply to the --mesh before them:
  --mesh-opacity A        its opacity in [0, 1] (default 1; below 1 it is translucent)
  --mesh-color R,G,B      its colour, also what it lets through (default 0.8,0.8,0.8)
  --mesh-transform TX,TY,TZ[,S]  scale by S about the origin, then translate
  --ground                a ground plane under the volume, on the far side from the light
  --translucent-layers N  layers the translucent meshes are peeled into, to be composited at
                          their depths inside the volume (0 to 8, default 4; 0: VTK's order,
                          translucent meshes first and the volume over them)
  --volume-segments N     pieces a second volume (hybrid-smoke's smoke) is cut into along each
                          view ray, to be composited at their depths inside the first (0 to 8,
                          default 8; 0: VTK's order, the second volume over the first)

)";
}

// The view and rendering options (the technique and look options from their tables).
std::string UsageViewAndRendering()
{
  return R"(VIEW:
  --size WxH              image size (default 512x512)
  --light-dir X,Y,Z       a directional light from that direction (world; towards the light)
  --light-pos X,Y,Z       a positional (point) light at that world position
  --light SPEC            a light: dir:X,Y,Z | pos:X,Y,Z | spot:X,Y,Z:ANGLE, each with an
                          optional :INTENSITY; spots aim at the volume's centre. Repeatable;
                          all light options add up. Default: the scene's key light (the
                          headlight for files).

RENDERING:
  --sample-distance D     world distance between samples (default: half the smallest voxel edge)
)" + TechniqueUsage() + R"(  --no-shading            no gradient shading (emission and absorption only); the same
                          as --shade off
)" + LookUsage() + R"(  --shading MODEL         blinn-phong (default: the true gradient normal, Ka x colour x the
                          renderer's ambient light) or vtk (VTK 9.1's volume shading, as a
                          swapped-in mapper draws it; under scene lights no ambient term)
  --jitter SEED           jitter ray starts with a hash of the pixel and SEED (reproducible)
  --no-empty-space-skipping
  --backend osmesa|egl    headless OpenGL backend (default: VTK_DEEPSHADOW_BACKEND or osmesa)

)";
}

// The output options and the exit codes.
std::string UsageOutput()
{
  return R"(OUTPUT:
  --out FILE|DIR          PNG to write (render, reference) or directory (all)
  --json FILE             statistics as JSON: technique, width, height, frames, build_ms,
                          render_ms (median over frames after a warm-up, GL finished),
                          first_frame_ms, shadow_bytes, shadow_builds, and more
  --frames N              timed frames after one warm-up frame (default 5); report: 0
                          measures errors only (the guard against no shadows, no timing)
  --verbose               also print VTK's own error and warning messages (more output;
                          the exit code and the error line are the same); the module's
                          warnings ("deepshadow: warning: ...") are printed without it
  --memory-budget BYTES   the most memory the frame, the shadow structures and the volume
                          may take (suffix K, M, G, T; default half the machine's memory or
                          of `ulimit -v`); beyond it the command exits with code 2 naming
                          the bytes, before allocating them

Exit codes: 0 success, 2 bad arguments or input (one line on stderr), 1 other failures.
)";
}
}

std::string Options::Usage()
{
  return UsageSynopsis() + UsageCommands() + UsageScene() + UsageViewAndRendering() + UsageOutput();
}


std::string Options::CommandUsage(const std::string& command)
{
  // The command's synopsis and paragraph from the whole text, then the option sections.
  const std::string all = Usage();
  std::istringstream lines(all);
  std::string line, synopsis, paragraph, options;
  enum { Head, Synopsis, Commands, Sections } part = Head;
  bool inSynopsis = false, inParagraph = false;
  while (std::getline(lines, line))
  {
    if (line == "Usage:")
    {
      part = Synopsis;
      continue;
    }
    if (line == "Commands:")
    {
      part = Commands;
      continue;
    }
    if (part == Commands && !line.empty() && line[0] != ' ')
    {
      part = Sections;
    }
    if (part == Synopsis)
    {
      if (line.rfind("  deepshadow ", 0) == 0)
      {
        inSynopsis = line.rfind("  deepshadow " + command + " ", 0) == 0 ||
          line == "  deepshadow " + command;
      }
      synopsis += inSynopsis ? line + "\n" : "";
    }
    else if (part == Commands)
    {
      if (line.size() > 2 && line[2] != ' ')
      {
        inParagraph = line.rfind("  " + command + " ", 0) == 0;
      }
      paragraph += inParagraph ? line + "\n" : "";
    }
    else if (part == Sections)
    {
      options += line + "\n";
    }
  }
  const bool takesOptions = command != "scenes" && command != "presets" && command != "series";
  return "Usage:\n" + synopsis + "\n" + paragraph + (takesOptions ? "\n" + options : std::string());
}

}
}
