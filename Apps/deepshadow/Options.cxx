#include "Options.h"

#include "Commands.h"
#include "Look.h"
#include "vtkDeepShadowStandardScene.h"
#include "vtkDeepShadowVolumePresets.h"
#include "vtkDeepShadowVolumeReader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <map>
#include <sstream>

namespace deepshadow
{
namespace tool
{
double ParseNumber(const std::string& option, const std::string& text)
{
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(value))
  {
    throw UsageError(option + " expects a number, got '" + text + "'");
  }
  return value;
}

namespace
{

int ParseInteger(const std::string& option, const std::string& text, int lo, int hi)
{
  const double value = ParseNumber(option, text);
  if (value != std::floor(value) || value < lo || value > hi)
  {
    throw UsageError(option + " expects a whole number in [" + std::to_string(lo) + ", " +
      std::to_string(hi) + "], got '" + text + "'");
  }
  return static_cast<int>(value);
}

// BYTES, or a number with the suffix K, M, G or T (powers of 1024).
unsigned long long ParseBytes(const std::string& option, const std::string& text)
{
  std::string number = text;
  double unit = 1.0;
  const std::string suffixes = "KMGT";
  const size_t at = text.empty() ? std::string::npos : suffixes.find(static_cast<char>(std::toupper(text.back())));
  if (at != std::string::npos)
  {
    number.pop_back();
    unit = std::pow(1024.0, static_cast<double>(at + 1));
  }
  const double value = ParseNumber(option, number) * unit;
  if (!(value >= 1.0 && value < 1.8e19))
  {
    throw UsageError(option + " expects a positive byte count (e.g. 4G), got '" + text + "'");
  }
  return static_cast<unsigned long long>(value);
}

std::vector<std::string> Split(const std::string& text, char separator)
{
  std::vector<std::string> parts;
  std::stringstream stream(text);
  std::string part;
  while (std::getline(stream, part, separator))
  {
    parts.push_back(part);
  }
  return parts;
}
}

namespace
{
std::array<double, 3> ParseVector(const std::string& option, const std::string& text)
{
  const auto parts = Split(text, ',');
  if (parts.size() != 3)
  {
    throw UsageError(option + " expects X,Y,Z, got '" + text + "'");
  }
  std::array<double, 3> v;
  for (int c = 0; c < 3; ++c)
  {
    v[c] = ParseNumber(option, parts[c]);
  }
  return v;
}

// A direction towards a light, normalised in double after dividing by its largest component
// (so 1e308,0,1e308 does not overflow to an infinite length); the zero vector is refused.
std::array<double, 3> Direction(const std::string& option, const std::array<double, 3>& v)
{
  const double largest = std::max({ std::abs(v[0]), std::abs(v[1]), std::abs(v[2]) });
  if (largest == 0.0)
  {
    throw UsageError(option + " must not be the zero vector");
  }
  std::array<double, 3> d{ { v[0] / largest, v[1] / largest, v[2] / largest } };
  const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  return { { d[0] / length, d[1] / length, d[2] / length } };
}

// A light's world position: beyond 1e18 its squared distances overflow in single precision
// on the GPU (measured: 1e19 renders as 1e3 does, 1e20 does not), so it is refused.
std::array<double, 3> Position(const std::string& option, const std::array<double, 3>& v)
{
  constexpr double limit = 1e18;
  if (std::max({ std::abs(v[0]), std::abs(v[1]), std::abs(v[2]) }) > limit)
  {
    throw UsageError(option + " coordinates must lie within +-1e18 (single-precision lighting); "
                              "for a light that far, give its direction (--light-dir)");
  }
  return v;
}

// dir:X,Y,Z[:I] | pos:X,Y,Z[:I] | spot:X,Y,Z:ANGLE[:I]
LightSpec ParseLight(const std::string& text)
{
  const auto parts = Split(text, ':');
  LightSpec light;
  if (parts.size() < 2)
  {
    throw UsageError("--light expects dir:X,Y,Z, pos:X,Y,Z or spot:X,Y,Z:ANGLE (optionally :INTENSITY), got '" + text + "'");
  }
  size_t next = 2;
  if (parts[0] == "dir")
  {
    light.Kind = LightSpec::Directional;
  }
  else if (parts[0] == "pos")
  {
    light.Kind = LightSpec::Positional;
  }
  else if (parts[0] == "spot")
  {
    light.Kind = LightSpec::Spot;
    if (parts.size() < 3)
    {
      throw UsageError("--light spot:X,Y,Z:ANGLE needs the cone angle");
    }
    light.ConeAngle = ParseNumber("--light", parts[2]);
    if (!(light.ConeAngle > 0.0 && light.ConeAngle < 90.0))
    {
      throw UsageError("--light spot cone angle must be in (0, 90) degrees");
    }
    next = 3;
  }
  else
  {
    throw UsageError("--light type must be dir, pos or spot, got '" + parts[0] + "'");
  }
  light.Vector = light.Kind == LightSpec::Directional
    ? Direction("--light dir", ParseVector("--light", parts[1]))
    : Position("--light " + parts[0], ParseVector("--light", parts[1]));
  if (parts.size() > next)
  {
    light.Intensity = ParseNumber("--light", parts[next]);
    if (light.Intensity < 0.0)
    {
      throw UsageError("--light intensity must not be negative");
    }
  }
  if (parts.size() > next + 1)
  {
    throw UsageError("--light has too many fields: '" + text + "'");
  }
  return light;
}
}

namespace
{
// The options that choose and tune a shadow technique; also the keys of a technique spec.
// Names, keys and ranges come from the technique registry (ShadowTechniques.h).
bool ParseTechniqueOption(Options& o, const std::string& key, const std::function<std::string()>& next)
{
  if (key == "--technique")
  {
    o.Technique = next();
    if (!FindShadowTechnique(o.Technique))
    {
      std::string list;
      for (const auto& name : ShadowTechniqueNames())
      {
        list += (list.empty() ? "" : ", ") + name;
      }
      throw UsageError("unknown technique '" + o.Technique + "' (available: " + list + ")");
    }
    return true;
  }
  const ShadowParameterInfo* parameter =
    key.rfind("--", 0) == 0 ? FindShadowParameter(key.substr(2)) : nullptr;
  if (!parameter)
  {
    return false;
  }
  const std::string text = next();
  try
  {
    o.TechniqueSettings.emplace_back(parameter->Key, parameter->Parse(text));
  }
  catch (const std::invalid_argument& error)
  {
    throw UsageError(std::string("--") + error.what());
  }
  return true;
}
}

std::vector<NamedFile> Options::InputFiles() const
{
  std::vector<NamedFile> files;
  for (const auto& volume : { NamedFile{ "--volume", this->VolumeFile }, NamedFile{ "--mask", this->MaskFile } })
  {
    if (!volume.Path.empty())
    {
      for (const std::string& path : vtkDeepShadowVolumeReader::GetFilesOf(volume.Path))
      {
        files.push_back({ volume.Option, path });
      }
    }
  }
  for (const std::string& bound : this->BoundFiles)
  {
    files.push_back({ "--bound", bound });
  }
  for (const MeshSpec& mesh : this->Meshes)
  {
    files.push_back({ "--mesh", mesh.File });
  }
  if (!this->TransferFunction.empty() && !vtkDeepShadowVolumePresets::IsPresetName(this->TransferFunction))
  {
    files.push_back({ "--tf", this->TransferFunction });
  }
  if (!this->CameraFile.empty())
  {
    files.push_back({ "--camera", this->CameraFile });
  }
  return files;
}

std::vector<NamedFile> Options::OutputFiles() const
{
  std::vector<NamedFile> files;
  if ((this->Command == "render" || this->Command == "reference") && !this->Out.empty())
  {
    files.push_back({ "--out", this->Out });
  }
  if (!this->Json.empty())
  {
    files.push_back({ "--json", this->Json });
  }
  return files;
}

const std::vector<double>* Options::Setting(const std::string& key) const
{
  for (auto at = this->TechniqueSettings.rbegin(); at != this->TechniqueSettings.rend(); ++at)
  {
    if (at->first == key)
    {
      return &at->second;
    }
  }
  return nullptr;
}

ShadowParameters Options::TechniqueParameters() const
{
  bool cached = false;
  const ShadowTechniqueInfo* technique = FindShadowTechnique(this->Technique, &cached);
  if (!technique)
  {
    throw UsageError("unknown technique '" + this->Technique + "'");
  }
  ShadowParameters parameters = technique->DefaultParameters(cached);
  for (const auto& [key, values] : this->TechniqueSettings)
  {
    if (technique->Reads(key))
    {
      FindShadowParameter(key)->Set(parameters, values);
    }
  }
  return parameters;
}

Options WithTechniqueSpec(const Options& base, const std::string& spec)
{
  Options o = base;
  const auto parts = Split(spec, ':');
  ParseTechniqueOption(o, "--technique", [&]() { return parts.empty() ? std::string() : parts[0]; });
  for (size_t k = 1; k < parts.size(); ++k)
  {
    const size_t equals = parts[k].find('=');
    const std::string key = "--" + parts[k].substr(0, equals);
    if (equals == std::string::npos || key == "--technique" ||
      !ParseTechniqueOption(o, key, [&]() { return parts[k].substr(equals + 1); }))
    {
      throw UsageError("'" + parts[k] + "' in technique spec '" + spec +
        "' is not OPTION=VALUE for a technique option (e.g. dsm:layers=4)");
    }
  }
  return o;
}

namespace
{
// The options every command reads, each key with what it sets (the shadow technique's,
// the viewer's and the look's are parsed by their own groups: ParseTechniqueOption,
// ParseViewerOption, ParseLookOption).
// An option's value: the next argument, or the text after "=".
using NextValue = std::function<std::string()>;

struct OptionEntry
{
  std::vector<std::string> Keys;
  std::function<void(Options&, const std::string&, const NextValue&)> Apply;
};

// The common shapes: a text, a switch, a whole number in [lo, hi].
OptionEntry Text(const char* key, std::string Options::*field)
{
  return { { key }, [field](Options& o, const std::string&, const NextValue& next) {
            o.*field = next();
          } };
}

OptionEntry Switch(const char* key, bool Options::*field, bool value = true)
{
  return { { key },
    [field, value](Options& o, const std::string&, const NextValue&) { o.*field = value; } };
}

OptionEntry Whole(const char* key, int Options::*field, int lo, int hi)
{
  return { { key }, [field, lo, hi](Options& o, const std::string& k, const NextValue& next) {
            o.*field = ParseInteger(k, next(), lo, hi);
          } };
}

// --mesh-opacity, --mesh-color, --mesh-transform: the look of the --mesh before them.
void ParseMeshOption(Options& o, const std::string& key, const NextValue& next)
{
  if (o.Meshes.empty())
  {
    throw UsageError(key + " applies to the --mesh before it, and none was given");
  }
  MeshSpec& mesh = o.Meshes.back();
  const std::string value = next();
  if (key == "--mesh-opacity")
  {
    mesh.Opacity = ParseNumber(key, value);
    if (!(mesh.Opacity >= 0.0 && mesh.Opacity <= 1.0))
    {
      throw UsageError("--mesh-opacity must lie in [0, 1], got '" + value + "'");
    }
  }
  else if (key == "--mesh-color")
  {
    mesh.Color = ParseVector(key, value);
    for (double c : mesh.Color)
    {
      if (!(c >= 0.0 && c <= 1.0))
      {
        throw UsageError("--mesh-color components must lie in [0, 1], got '" + value + "'");
      }
    }
  }
  else
  {
    const auto parts = Split(value, ',');
    if (parts.size() != 3 && parts.size() != 4)
    {
      throw UsageError("--mesh-transform expects TX,TY,TZ[,SCALE], got '" + value + "'");
    }
    for (int c = 0; c < 3; ++c)
    {
      mesh.Translate[c] = ParseNumber(key, parts[c]);
    }
    mesh.Scale = parts.size() == 4 ? ParseNumber(key, parts[3]) : 1.0;
    if (!(mesh.Scale > 0.0))
    {
      throw UsageError("--mesh-transform's scale must be positive, got '" + value + "'");
    }
  }
}

// --blend-modes: blend modes by name, or all.
void ParseBlendModes(Options& o, const NextValue& next)
{
  o.BenchBlendModes.clear();
  const std::string text = next();
  const std::vector<std::string> known = { "composite", "maximum", "minimum", "average", "additive",
    "isosurface" };
  for (const auto& part : text == "all" ? known : Split(text, ','))
  {
    if (std::find(known.begin(), known.end(), part) == known.end())
    {
      throw UsageError("--blend-modes: unknown blend mode '" + part +
        "' (composite, maximum, minimum, average, additive, isosurface or all)");
    }
    o.BenchBlendModes.push_back(part);
  }
}

// WxH into two whole numbers (--size, --error-size).
OptionEntry Size(const char* key, int Options::*width, int Options::*height)
{
  return { { key }, [width, height](Options& o, const std::string& k, const NextValue& next) {
            const std::string text = next();
            const auto parts = Split(text, 'x');
            if (parts.size() != 2)
            {
              throw UsageError(k + " expects WxH, got '" + text + "'");
            }
            o.*width = ParseInteger(k, parts[0], 1, 16384);
            o.*height = ParseInteger(k, parts[1], 1, 16384);
          } };
}

// One of `names` (--shading, --backend), kept as given.
OptionEntry OneOf(const char* key, std::vector<std::string> names, const char* said,
  std::function<void(Options&, const std::string&)> set)
{
  return { { key }, [key, names, said, set](Options& o, const std::string&, const NextValue& next) {
            const std::string value = next();
            if (std::find(names.begin(), names.end(), value) == names.end())
            {
              throw UsageError(std::string(key) + " must be " + said + ", got '" + value + "'");
            }
            set(o, value);
          } };
}

// What is drawn: the scene or the files, masks, meshes and bounds.
std::vector<OptionEntry> InputOptions()
{
  return {
    Text("--scene", &Options::Scene),
    Text("--volume", &Options::VolumeFile),
    Text("--mask", &Options::MaskFile),
    Text("--series", &Options::Series),
    Whole("--volume-index", &Options::VolumeIndex, 0, 1000000),
    { { "--bound" },
      [](Options& o, const std::string&, const NextValue& next) {
        o.BoundFiles.push_back(next());
      } },
    { { "--mesh" },
      [](Options& o, const std::string&, const NextValue& next) {
        o.Meshes.push_back(MeshSpec{ next() });
      } },
    { { "--mesh-opacity", "--mesh-color", "--mesh-transform" }, ParseMeshOption },
    Switch("--ground", &Options::Ground),
    Whole("--volume-segments", &Options::VolumeSegments, 0, 8),
    Whole("--translucent-layers", &Options::TranslucentLayers, 0, 8),
    Text("--csg", &Options::Csg),
    Switch("--csg-mesh", &Options::CsgMesh),
    { { "--csg-max-work" },
      [](Options& o, const std::string& key, const NextValue& next) {
        o.CsgMaxWork = ParseNumber(key, next());
        if (o.CsgMaxWork < 0.0)
        {
          throw UsageError("--csg-max-work must be 0 (no limit) or positive");
        }
      } },
    { { "--scale" },
      [](Options& o, const std::string& key, const NextValue& next) {
        o.SceneScale = ParseNumber(key, next());
        if (o.SceneScale < 0.01 || o.SceneScale > 2.0)
        {
          throw UsageError("--scale must be in [0.01, 2]");
        }
      } },
    { { "--objects" },
      [](Options& o, const std::string& key, const NextValue& next) {
        const double count = ParseNumber(key, next());
        if (count != std::floor(count) || count < 1 || count > vtkDeepShadowStandardScene::GetMaxObjectCount())
        {
          throw UsageError("--objects must be a whole number in [1, " +
            std::to_string(vtkDeepShadowStandardScene::GetMaxObjectCount()) + "]");
        }
        o.ObjectCount = static_cast<int>(count);
      } },
  };
}

// How it is drawn: size, sampling, lights and shading.
std::vector<OptionEntry> DrawingOptions()
{
  return {
    Size("--size", &Options::Width, &Options::Height),
    { { "--sample-distance" },
      [](Options& o, const std::string& key, const NextValue& next) {
        o.SampleDistance = ParseNumber(key, next());
        if (!(o.SampleDistance > 0.0))
        {
          throw UsageError("--sample-distance must be positive");
        }
      } },
    { { "--light-dir" },
      [](Options& o, const std::string& key, const NextValue& next) {
        LightSpec light;
        light.Vector = Direction(key, ParseVector(key, next()));
        o.Lights.push_back(light);
      } },
    { { "--light-pos" },
      [](Options& o, const std::string& key, const NextValue& next) {
        LightSpec light;
        light.Kind = LightSpec::Positional;
        light.Vector = Position(key, ParseVector(key, next()));
        o.Lights.push_back(light);
      } },
    { { "--light" },
      [](Options& o, const std::string&, const NextValue& next) {
        o.Lights.push_back(ParseLight(next()));
      } },
    Switch("--ground-truth", &Options::GroundTruth),
    { { "--no-shading" },
      [](Options& o, const std::string&, const NextValue&) {
        o.Shade = false;
        o.ShadeGiven = true;
      } },
    OneOf("--shading", { "vtk", "blinn-phong" }, "vtk or blinn-phong",
      [](Options& o, const std::string& model) { o.VTKShading = model == "vtk"; }),
    { { "--jitter" },
      [](Options& o, const std::string& key, const NextValue& next) {
        o.Jitter = true;
        o.JitterSeed = static_cast<unsigned int>(ParseInteger(key, next(), 0, 2147483647));
      } },
    Switch("--no-empty-space-skipping", &Options::EmptySpaceSkipping, false),
    Switch("--replace-nonfinite", &Options::ReplaceNonFinite),
    OneOf("--backend", { "osmesa", "egl" }, "osmesa or egl",
      [](Options& o, const std::string& backend) { o.Backend = backend; }),
  };
}

// What comes out, and what the benchmarks sweep.
std::vector<OptionEntry> OutputAndBenchOptions()
{
  return {
    Text("--out", &Options::Out),
    Text("--json", &Options::Json),
    Whole("--frames", &Options::Frames, 0, 100000),
    Switch("--verbose", &Options::Verbose),
    { { "--memory-budget" },
      [](Options& o, const std::string& key, const NextValue& next) {
        o.MemoryBudget = ParseBytes(key, next());
      } },
    Switch("--gpu-twin", &Options::GpuTwin),
    Whole("--threads", &Options::Threads, 0, 1024),
    { { "--scenes" },
      [](Options& o, const std::string&, const NextValue& next) {
        o.BenchScenes = Split(next(), ',');
      } },
    { { "--techniques" },
      [](Options& o, const std::string&, const NextValue& next) {
        o.BenchTechniques = Split(next(), ',');
        for (const auto& spec : o.BenchTechniques)
        {
          WithTechniqueSpec(o, spec); // throws for a bad spec
        }
      } },
    Size("--error-size", &Options::ErrorWidth, &Options::ErrorHeight),
    Switch("--receiver-error", &Options::ReceiverError),
    Text("--charts", &Options::ChartsDirectory),
    { { "--blend-modes" },
      [](Options& o, const std::string&, const NextValue& next) { ParseBlendModes(o, next); } },
    { { "--bench-sizes" },
      [](Options& o, const std::string& key, const NextValue& next) {
        o.BenchSizes.clear();
        for (const auto& part : Split(next(), ','))
        {
          o.BenchSizes.push_back(ParseInteger(key, part, 2, 2048));
        }
      } },
  };
}

const std::vector<OptionEntry>& GeneralOptions()
{
  static const std::vector<OptionEntry> entries = [] {
    std::vector<OptionEntry> all;
    for (auto group : { InputOptions(), DrawingOptions(), OutputAndBenchOptions() })
    {
      all.insert(all.end(), group.begin(), group.end());
    }
    return all;
  }();
  return entries;
}

bool ParseGeneralOption(Options& o, const std::string& key, const std::function<std::string()>& next)
{
  for (const OptionEntry& entry : GeneralOptions())
  {
    if (std::find(entry.Keys.begin(), entry.Keys.end(), key) != entry.Keys.end())
    {
      entry.Apply(o, key, next);
      return true;
    }
  }
  return false;
}

// A command's own defaults (the options given still override them).
void ApplyCommandDefaults(Options& o, const std::vector<std::string>& args)
{
  if (o.Command == "report")
  {
    // Its own defaults; explicit options below still override them.
    o.Quick = std::find(args.begin(), args.end(), "--quick") != args.end();
    o.Width = o.Height = o.Quick ? 256 : 512;
    o.ErrorWidth = o.ErrorHeight = o.Quick ? 128 : 256;
    o.Frames = o.Quick ? 3 : 5;
  }
  if (o.Command == "gallery")
  {
    // A page in a few minutes on two cores: small pictures, errors at a small size.
    o.Width = o.Height = 256;
    o.ErrorWidth = o.ErrorHeight = 96;
    o.Frames = 2;
  }
}

// What the options read together imply or refuse: the default scene, a command's --out, the
// look, a medical file's deep shadows, series' folder, errors-only frames.
void Complete(Options& o, const std::vector<std::string>& args)
{
  if (o.Scene.empty() && o.VolumeFile.empty())
  {
    o.Scene = "box";
  }
  if ((o.Command == "render" || o.Command == "reference" || o.Command == "all" ||
        o.Command == "report" || o.Command == "gallery") && o.Out.empty())
  {
    throw UsageError(o.Command + " needs --out");
  }
  if (o.Command == "all" || o.Command == "report" || o.Command == "gallery")
  {
    o.OutDir = o.Out;
  }
  ValidateLook(o, args);
  // A medical file is shown with its shadows unless asked otherwise: deep shadow maps, from
  // the key light a lone headlight becomes (vtkDeepShadowVolumeMapper::HeadlightKeyLight).
  const bool techniqueGiven = std::any_of(args.begin(), args.end(), [](const std::string& a) {
    return a == "--technique" || a.rfind("--technique=", 0) == 0;
  });
  if (!o.VolumeFile.empty() && !techniqueGiven &&
    (o.Command == "render" || o.Command == "reference" || o.Command == "view"))
  {
    o.Technique = "dsm";
  }
  if (o.Command == "series" && o.VolumeFile.empty())
  {
    throw UsageError("series needs --volume DIR (a DICOM folder)");
  }
  if (o.Frames == 0 && o.Command != "report")
  {
    throw UsageError("--frames 0 (errors only, no timing) is for report");
  }
}

}

Options Options::Parse(int argc, char* argv[])
{
  Options o;
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty())
  {
    throw UsageError("no command given (try deepshadow --help)");
  }
  size_t i = 0;
  if (args[0] == "--help" || args[0] == "-h" || args[0] == "help")
  {
    o.Command = "help";
    return o;
  }
  if (args[0] == "--version")
  {
    o.Command = "version";
    return o;
  }
  if (args[0].rfind("--", 0) == 0)
  {
    // Only options: render is the default command.
    o.Command = "render";
  }
  else
  {
    o.Command = args[0];
    i = 1;
  }
  static const char* const commands[] = { "render", "reference", "all", "bench", "shadow-bench",
    "report", "scenes", "presets", "series", "gallery", "view" };
  bool known = false;
  for (const char* c : commands)
  {
    known = known || o.Command == c;
  }
  if (!known)
  {
    throw UsageError("unknown command '" + o.Command + "' (try deepshadow --help)");
  }

  o.Arguments.assign(args.begin() + static_cast<std::ptrdiff_t>(i), args.end());
  ApplyCommandDefaults(o, args);

  bool sawScene = false;
  for (; i < args.size(); ++i)
  {
    std::string key = args[i];
    std::string value;
    bool hasInlineValue = false;
    const size_t equals = key.find('=');
    if (key.rfind("--", 0) == 0 && equals != std::string::npos)
    {
      value = key.substr(equals + 1);
      key = key.substr(0, equals);
      hasInlineValue = true;
    }
    auto next = [&]() -> std::string {
      if (hasInlineValue)
      {
        return value;
      }
      if (i + 1 >= args.size())
      {
        throw UsageError(key + " needs a value");
      }
      return args[++i];
    };

    if (key == "--help" || key == "-h")
    {
      o.HelpCommand = o.Command; // `deepshadow render --help`: render's help
      o.Command = "help";
      return o;
    }
    sawScene = sawScene || key == "--scene";
    if (key == "--quick" && o.Command == "report")
    {
      o.Quick = true;
      continue;
    }
    const bool parsed = ParseGeneralOption(o, key, next) ||
      ParseTechniqueOption(o, key, next) || (o.Command == "view" && ParseViewerOption(o, key, next)) ||
      ParseLookOption(o, key, next);
    if (!parsed)
    {
      throw UsageError("unknown option '" + args[i] + "' (try deepshadow --help)");
    }
  }

  if (sawScene && !o.VolumeFile.empty())
  {
    throw UsageError("give either --scene or --volume, not both");
  }
  Complete(o, args);
  return o;
}

}
}
