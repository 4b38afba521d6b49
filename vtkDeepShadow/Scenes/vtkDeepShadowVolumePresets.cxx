#include "vtkDeepShadowVolumePresets.h"

#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkVolumeProperty.h"
#include "vtk_jsoncpp.h"

#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

vtkStandardNewMacro(vtkDeepShadowVolumePresets);

namespace
{
// A transfer function ready to load: opacity nodes (x, y, midpoint, sharpness), colour nodes
// (x, r, g, b), the interval window/level maps, and the lighting of a named preset.
struct Functions
{
  std::vector<double> Opacity;
  std::vector<double> Color;
  int ColorSpace = VTK_CTF_RGB;
  bool HasLighting = false;
  double Ambient = 0.1, Diffuse = 0.9, Specular = 0.2, SpecularPower = 10.0;
  bool Shade = true;
};

struct Preset
{
  const char* Name;
  const char* Description;
  std::vector<double> Opacity; // x, opacity pairs
  std::vector<double> Color;   // x, r, g, b
  double Ambient, Diffuse, Specular, SpecularPower;
  bool Shade;
};

// 3D Slicer's volume rendering presets (Modules/Loadable/VolumeRendering/Resources/
// presets.xml), except CT-Skin, which is ours: the air-to-skin boundary made opaque.
const std::vector<Preset>& Presets()
{
  static const std::vector<Preset> presets = {
    { "CT-Bone", "CT, Hounsfield units: bone white over faint red soft tissue",
      { -3024, 0, -16.4458, 0, 641.385, 0.715686, 3071, 0.705882 },
      { -3024, 0, 0, 0, -16.4458, 0.729412, 0.254902, 0.301961, 641.385, 0.905882, 0.815686,
        0.552941, 3071, 1, 1, 1 },
      0.1, 0.9, 0.2, 10, true },
    { "CT-Skin", "CT, Hounsfield units: the skin surface (air to tissue at -500 HU), opaque",
      { -3024, 0, -700, 0, -400, 0.8, 3071, 0.8 },
      { -3024, 0, 0, 0, -700, 0.55, 0.35, 0.3, -400, 0.93, 0.75, 0.65, 3071, 1, 0.9, 0.85 },
      0.15, 0.85, 0.15, 10, true },
    { "CT-Muscle", "CT, Hounsfield units: muscle red to brown, bone pale",
      { -3024, 0, -155.407, 0, 217.641, 0.676471, 419.736, 0.833333, 3071, 0.803922 },
      { -3024, 0, 0, 0, -155.407, 0.54902, 0.25098, 0.14902, 217.641, 0.882353, 0.603922,
        0.290196, 419.736, 1, 0.937033, 0.954531, 3071, 0.827451, 0.658824, 1 },
      0.1, 0.9, 0.2, 10, true },
    { "CT-Soft-Tissue", "CT, Hounsfield units: everything above fat, grey, unshaded",
      { -2048, 0, -167.01, 0, -160, 1, 240, 1, 3661, 1 },
      { -2048, 0, 0, 0, -167.01, 0, 0, 0, -160, 0.0556356, 0.0556356, 0.0556356, 240, 1, 1, 1,
        3661, 1, 1, 1 },
      0.2, 1, 0, 1, false },
    { "CT-Lung", "CT, Hounsfield units: lung parenchyma (-600 to -400 HU) in blue to yellow",
      { -1000, 0, -600, 0, -599, 0.15, -400, 0.15, -399, 0, 2952, 0 },
      { -1000, 0.3, 0.3, 1, -600, 0, 0, 1, -530, 0.134704, 0.781726, 0.0724558, -460, 0.929244,
        1, 0.109473, -400, 0.888889, 0.254949, 0.0240258, 2952, 1, 0.3, 0.3 },
      0.2, 1, 0, 1, true },
    { "MR-Default", "MR, intensity (0 to about 1000): tissue brown to white",
      { 0, 0, 20, 0, 40, 0.15, 120, 0.3, 220, 0.375, 1024, 0.5 },
      { 0, 0, 0, 0, 20, 0.168627, 0, 0, 40, 0.403922, 0.145098, 0.0784314, 120, 0.780392,
        0.607843, 0.380392, 220, 0.847059, 0.835294, 0.788235, 1024, 1, 1, 1 },
      0.2, 1, 0, 1, true },
    { "MR-Angio", "MR angiography, intensity: bright vessels (above 150) orange to white",
      { -2048, 0, 151.354, 0, 158.279, 0.4375, 190.112, 0.580357, 200.873, 0.732143, 3661,
        0.741071 },
      { -2048, 0, 0, 0, 151.354, 0, 0, 0, 158.279, 0.74902, 0.376471, 0, 190.112, 1, 0.866667,
        0.733333, 200.873, 0.937255, 0.937255, 0.937255, 3661, 1, 1, 1 },
      0.2, 1, 0, 1, true },
  };
  return presets;
}

// "CT-Bone, CT-Skin, ...", for the messages.
std::string PresetList()
{
  std::string names;
  for (const Preset& preset : Presets())
  {
    names += (names.empty() ? "" : ", ") + std::string(preset.Name);
  }
  return names;
}

const Preset* FindPreset(const std::string& name)
{
  const std::string lower = vtksys::SystemTools::LowerCase(name);
  for (const Preset& preset : Presets())
  {
    if (vtksys::SystemTools::LowerCase(preset.Name) == lower)
    {
      return &preset;
    }
  }
  return nullptr;
}

Functions FromPreset(const Preset& preset)
{
  Functions f;
  for (size_t i = 0; i + 1 < preset.Opacity.size(); i += 2)
  {
    f.Opacity.insert(f.Opacity.end(), { preset.Opacity[i], preset.Opacity[i + 1], 0.5, 0.0 });
  }
  f.Color = preset.Color;
  f.HasLighting = true;
  f.Ambient = preset.Ambient;
  f.Diffuse = preset.Diffuse;
  f.Specular = preset.Specular;
  f.SpecularPower = preset.SpecularPower;
  f.Shade = preset.Shade;
  return f;
}

// The interval window/level maps: the opacity nodes without the two ends (the padding out to
// the data type's range), else all of them; the colour nodes for a file without opacity.
void Interval(const Functions& f, double& low, double& high)
{
  const std::vector<double>& nodes = f.Opacity.empty() ? f.Color : f.Opacity;
  const size_t count = nodes.size() / 4;
  const size_t first = count >= 4 ? 1 : 0, last = count >= 4 ? count - 2 : count - 1;
  low = nodes[4 * first];
  high = nodes[4 * last];
}

void MapOnto(Functions& f, double window, double level)
{
  double low, high;
  Interval(f, low, high);
  const double width = high > low ? high - low : 1.0;
  const double scale = window / width, start = level - 0.5 * window;
  for (std::vector<double>* nodes : { &f.Opacity, &f.Color })
  {
    for (size_t i = 0; i < nodes->size(); i += 4)
    {
      (*nodes)[i] = start + ((*nodes)[i] - low) * scale;
    }
  }
}

void Load(const Functions& f, vtkVolumeProperty* property)
{
  vtkNew<vtkColorTransferFunction> color;
  color->SetColorSpace(f.ColorSpace);
  for (size_t i = 0; i + 3 < f.Color.size(); i += 4)
  {
    color->AddRGBPoint(f.Color[i], f.Color[i + 1], f.Color[i + 2], f.Color[i + 3]);
  }
  property->SetColor(color);
  if (!f.Opacity.empty())
  {
    vtkNew<vtkPiecewiseFunction> opacity;
    for (size_t i = 0; i + 3 < f.Opacity.size(); i += 4)
    {
      opacity->AddPoint(f.Opacity[i], f.Opacity[i + 1], f.Opacity[i + 2], f.Opacity[i + 3]);
    }
    property->SetScalarOpacity(opacity);
  }
  property->SetInterpolationTypeToLinear();
  if (f.HasLighting)
  {
    property->SetShade(f.Shade ? 1 : 0);
    property->SetAmbient(f.Ambient);
    property->SetDiffuse(f.Diffuse);
    property->SetSpecular(f.Specular);
    property->SetSpecularPower(f.SpecularPower);
  }
}

// One numeric array of a ParaView preset: finite numbers, whole nodes of `stride` values,
// x never decreasing, the other values in [0, 1]. Empty `error` when it is all of that.
std::vector<double> NodeArray(const Json::Value& value, const char* key, std::string& error)
{
  std::vector<double> nodes;
  if (!value.isArray())
  {
    error = std::string("\"") + key + "\" is not an array of numbers";
    return nodes;
  }
  if (value.size() / 4 > static_cast<Json::ArrayIndex>(vtkDeepShadowVolumePresets::MaximumNodes))
  {
    error = std::string("\"") + key + "\" has " + std::to_string(value.size() / 4) +
      " nodes; at most " + std::to_string(vtkDeepShadowVolumePresets::MaximumNodes) +
      " are loaded (VTK sorts its nodes again at each one added)";
    return nodes;
  }
  for (Json::ArrayIndex i = 0; i < value.size(); ++i)
  {
    if (!value[i].isNumeric() || !std::isfinite(value[i].asDouble()))
    {
      error = std::string("\"") + key + "\"[" + std::to_string(i) + "] is not a finite number";
      return {};
    }
    nodes.push_back(value[i].asDouble());
  }
  if (nodes.empty() || nodes.size() % 4 != 0)
  {
    error = std::string("\"") + key + "\" has " + std::to_string(nodes.size()) +
      " values; it needs whole nodes of 4";
    return {};
  }
  for (size_t i = 0; i < nodes.size(); i += 4)
  {
    if (i > 0 && nodes[i] < nodes[i - 4])
    {
      error = std::string("\"") + key + "\": node " + std::to_string(i / 4) +
        " is left of the one before (x must not decrease)";
      return {};
    }
    for (size_t c = 1; c < 4; ++c)
    {
      if (nodes[i + c] < 0.0 || nodes[i + c] > 1.0)
      {
        error = std::string("\"") + key + "\": node " + std::to_string(i / 4) +
          " has a value outside [0, 1]";
        return {};
      }
    }
  }
  return nodes;
}

// The finite values of an image's first component as a histogram of `bins` between their
// smallest and largest, with those two.
struct Histogram
{
  std::vector<double> Counts;
  double Low = 0.0, High = 0.0, Total = 0.0;

  explicit Histogram(vtkImageData* image, int bins = 1024)
    : Counts(static_cast<size_t>(bins), 0.0)
  {
    vtkDataArray* values = image ? image->GetPointData()->GetScalars() : nullptr;
    const vtkIdType n = values ? values->GetNumberOfTuples() : 0;
    this->Low = std::numeric_limits<double>::infinity();
    this->High = -this->Low;
    for (vtkIdType i = 0; i < n; ++i)
    {
      const double v = values->GetComponent(i, 0);
      if (std::isfinite(v))
      {
        this->Low = std::min(this->Low, v);
        this->High = std::max(this->High, v);
      }
    }
    if (!(this->Low < this->High))
    {
      return;
    }
    const double scale = (bins - 1) / (this->High - this->Low);
    for (vtkIdType i = 0; i < n; ++i)
    {
      const double v = values->GetComponent(i, 0);
      if (std::isfinite(v))
      {
        this->Counts[static_cast<size_t>((v - this->Low) * scale)] += 1.0;
        this->Total += 1.0;
      }
    }
  }
  bool Empty() const { return this->Total == 0.0; }
  double Value(size_t bin) const
  {
    return this->Low + (this->High - this->Low) * static_cast<double>(bin) / (this->Counts.size() - 1.0);
  }
  double Percentile(double fraction) const
  {
    double seen = 0.0;
    for (size_t b = 0; b < this->Counts.size(); ++b)
    {
      seen += this->Counts[b];
      if (seen >= fraction * this->Total)
      {
        return this->Value(b);
      }
    }
    return this->High;
  }
  // Otsu's threshold: the split with the largest variance between the two classes.
  double Otsu() const
  {
    double sum = 0.0;
    for (size_t b = 0; b < this->Counts.size(); ++b)
    {
      sum += this->Value(b) * this->Counts[b];
    }
    double below = 0.0, belowSum = 0.0, best = -1.0, threshold = this->Low;
    for (size_t b = 0; b + 1 < this->Counts.size(); ++b)
    {
      below += this->Counts[b];
      belowSum += this->Value(b) * this->Counts[b];
      const double above = this->Total - below;
      if (below == 0.0 || above == 0.0)
      {
        continue;
      }
      const double difference = belowSum / below - (sum - belowSum) / above;
      const double variance = below * above * difference * difference;
      if (variance > best)
      {
        best = variance;
        threshold = this->Value(b + 1);
      }
    }
    return threshold;
  }
};

// Hounsfield units: air (about -1000) in the data, and values above it.
bool LooksLikeHounsfield(const Histogram& h)
{
  return !h.Empty() && h.Percentile(0.01) <= -500.0 && h.High > 0.0;
}
}

std::string vtkDeepShadowVolumePresets::ApplyDefault(
  const std::string& modality, vtkImageData* image, vtkVolumeProperty* property)
{
  this->LastError.clear();
  const Histogram histogram(image);
  if (histogram.Empty() || !property)
  {
    this->Fail(histogram.Empty() ? "the image has no finite values to choose a look for"
                                 : "no vtkVolumeProperty to load the default look into");
    return std::string();
  }
  const bool ct = modality == "CT" || (modality.empty() && LooksLikeHounsfield(histogram));
  if (ct)
  {
    this->ClearWindowLevel();
    return this->ApplyPreset("CT-Bone", property) ? "CT-Bone" : std::string();
  }
  // MR-Default's interval (20 to 220) from the background/tissue threshold to the brightest
  // tissue; the padding ends beyond stay as the preset scales them.
  const double low = histogram.Otsu(), high = std::max(histogram.Percentile(0.995), low + 1e-6 * std::abs(low) + 1e-12);
  this->SetWindowLevel(high - low, 0.5 * (low + high));
  if (!this->LastError.empty() || !this->ApplyPreset("MR-Default", property))
  {
    return std::string();
  }
  this->ClearWindowLevel();
  std::ostringstream chosen;
  chosen << "MR-Default, window " << (high - low) << " level " << 0.5 * (low + high);
  return chosen.str();
}

std::string vtkDeepShadowVolumePresets::DataWarning(const std::string& preset, vtkImageData* image)
{
  if (vtksys::SystemTools::LowerCase(preset).rfind("ct-", 0) != 0 || !IsPresetName(preset))
  {
    return std::string();
  }
  const Histogram histogram(image);
  if (histogram.Empty() || LooksLikeHounsfield(histogram))
  {
    return std::string();
  }
  std::ostringstream text;
  text << "the CT preset " << preset << " is in Hounsfield units (air near -1000), and the data's "
       << "values span " << histogram.Low << " to " << histogram.High << " (1st percentile "
       << histogram.Percentile(0.01) << "): it may show nothing or a solid box; MR-Default with "
       << "--window/--level, or no --tf (a look chosen from the data), may suit it";
  return text.str();
}

std::vector<std::string> vtkDeepShadowVolumePresets::GetPresetNames()
{
  std::vector<std::string> names;
  for (const Preset& preset : Presets())
  {
    names.emplace_back(preset.Name);
  }
  return names;
}

std::string vtkDeepShadowVolumePresets::GetPresetDescription(const std::string& name)
{
  const Preset* preset = FindPreset(name);
  return preset ? preset->Description : "";
}

bool vtkDeepShadowVolumePresets::IsPresetName(const std::string& name)
{
  return FindPreset(name) != nullptr;
}

void vtkDeepShadowVolumePresets::SetWindowLevel(double window, double level)
{
  this->LastError.clear();
  if (!std::isfinite(window) || !std::isfinite(level) || window <= 0.0)
  {
    this->Fail("the window must be a positive number and the level a finite one");
    return;
  }
  const double smallest = std::max(MinimumRelativeWindow * std::abs(level), MinimumWindow);
  if (window < smallest)
  {
    std::ostringstream message;
    message << "the window " << window << " is narrower than the smallest the picture resolves at "
            << "level " << level << ": " << smallest << " (" << MinimumRelativeWindow
            << " of |level|, and at least " << MinimumWindow << ")";
    this->Fail(message.str());
    return;
  }
  this->Window = window;
  this->Level = level;
  this->UseWindowLevel = true;
  this->Modified();
}

void vtkDeepShadowVolumePresets::ClearWindowLevel()
{
  this->UseWindowLevel = false;
  this->Modified();
}

bool vtkDeepShadowVolumePresets::Fail(const std::string& message)
{
  this->LastError = message;
  vtkErrorMacro(<< message);
  return false;
}

bool vtkDeepShadowVolumePresets::ApplyPreset(const std::string& name, vtkVolumeProperty* property)
{
  this->LastError.clear();
  const Preset* preset = FindPreset(name);
  if (!preset)
  {
    return this->Fail("unknown transfer-function preset '" + name + "' (presets: " +
      PresetList() + ")");
  }
  if (!property)
  {
    return this->Fail("no vtkVolumeProperty to load preset '" + name + "' into");
  }
  Functions f = FromPreset(*preset);
  if (this->UseWindowLevel)
  {
    MapOnto(f, this->Window, this->Level);
  }
  Load(f, property);
  return true;
}

bool vtkDeepShadowVolumePresets::ApplyFile(const std::string& path, vtkVolumeProperty* property)
{
  this->LastError.clear();
  const std::string where = "transfer-function file '" + path + "'";
  if (!property)
  {
    return this->Fail("no vtkVolumeProperty to load " + where + " into");
  }
  if (path.empty() || !vtksys::SystemTools::FileExists(path, true))
  {
    return this->Fail("cannot read " + where + ": no such file");
  }
  // At most the limit is read, whatever the file's size claims (/dev/zero claims none).
  std::ifstream file(path, std::ios::binary);
  std::string text(static_cast<size_t>(this->MaximumFileBytes) + 1, '\0');
  file.read(&text[0], static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<size_t>(std::max<std::streamsize>(file.gcount(), 0)));
  if (text.size() > this->MaximumFileBytes)
  {
    return this->Fail("cannot read " + where + ": it holds more than a preset file needs (limit " +
      std::to_string(static_cast<long long>(this->MaximumFileBytes)) + " bytes)");
  }
  std::istringstream stream(text);
  Json::CharReaderBuilder builder;
  builder["collectComments"] = false;
  builder["stackLimit"] = 64;
  Json::Value root;
  std::string parseErrors;
  bool parsed = false;
  try
  {
    parsed = Json::parseFromStream(builder, stream, &root, &parseErrors);
  }
  catch (const std::exception& e)
  {
    // jsoncpp throws past its nesting limit instead of returning false.
    parseErrors = e.what();
  }
  if (!parsed)
  {
    std::string first = parseErrors.substr(0, parseErrors.find('\n'));
    return this->Fail("cannot read " + where + ": not JSON (" + first + ")");
  }

  // ParaView writes a list of presets; a single object is accepted too.
  const Json::Value* chosen = nullptr;
  std::vector<const Json::Value*> candidates;
  if (root.isArray())
  {
    for (Json::ArrayIndex i = 0; i < root.size(); ++i)
    {
      candidates.push_back(&root[i]);
    }
  }
  else
  {
    candidates.push_back(&root);
  }
  for (const Json::Value* candidate : candidates)
  {
    if (!candidate->isObject())
    {
      continue;
    }
    const std::string name = (*candidate)["Name"].isString() ? (*candidate)["Name"].asString() : "";
    if (this->PresetName.empty() || vtksys::SystemTools::LowerCase(name) ==
        vtksys::SystemTools::LowerCase(this->PresetName))
    {
      chosen = candidate;
      break;
    }
  }
  if (!chosen)
  {
    return this->Fail("cannot use " + where + ": " +
      (this->PresetName.empty() ? std::string("it holds no preset object")
                                : "it has no preset named '" + this->PresetName + "'"));
  }

  Functions f;
  std::string error;
  if (!chosen->isMember("RGBPoints"))
  {
    return this->Fail("cannot use " + where + ": no \"RGBPoints\" (ParaView's colour nodes)");
  }
  f.Color = NodeArray((*chosen)["RGBPoints"], "RGBPoints", error);
  if (error.empty() && chosen->isMember("Points"))
  {
    f.Opacity = NodeArray((*chosen)["Points"], "Points", error);
  }
  if (!error.empty())
  {
    return this->Fail("cannot use " + where + ": " + error);
  }
  const std::string space = (*chosen)["ColorSpace"].isString()
    ? vtksys::SystemTools::LowerCase((*chosen)["ColorSpace"].asString())
    : "rgb";
  f.ColorSpace = space == "hsv" ? VTK_CTF_HSV
    : space == "lab"            ? VTK_CTF_LAB
    : space == "diverging"      ? VTK_CTF_DIVERGING
                                : VTK_CTF_RGB;
  if (this->UseWindowLevel)
  {
    MapOnto(f, this->Window, this->Level);
  }
  Load(f, property);
  return true;
}

bool vtkDeepShadowVolumePresets::Apply(const std::string& nameOrPath, vtkVolumeProperty* property)
{
  if (IsPresetName(nameOrPath))
  {
    return this->ApplyPreset(nameOrPath, property);
  }
  if (!vtksys::SystemTools::FileExists(nameOrPath, true))
  {
    return this->Fail("'" + nameOrPath + "' is neither a transfer-function preset (" +
      PresetList() + ") nor a file");
  }
  return this->ApplyFile(nameOrPath, property);
}

void vtkDeepShadowVolumePresets::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "PresetName: " << (this->PresetName.empty() ? "(first)" : this->PresetName)
     << "\n";
  os << indent << "WindowLevel: ";
  if (this->UseWindowLevel)
  {
    os << this->Window << " / " << this->Level << "\n";
  }
  else
  {
    os << "(the preset's own)\n";
  }
  os << indent << "MaximumFileBytes: " << this->MaximumFileBytes << "\n";
}
