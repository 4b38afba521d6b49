#include "Core/ShadowTechniques.h"

#include "Core/Shadows/AdaptiveVolumetricShadowMap.h"
#include "Core/Shadows/DeepShadowMap.h"
#include "Core/Shadows/FixedBudgetDeepShadowMap.h"
#include "Core/Shadows/FourierOpacityMap.h"
#include "Core/Shadows/OpacitySlices.h"
#include "Core/Shadows/OpacityLevels.h"
#include "Core/Shadows/PowerMomentMap.h"
#include "Core/Shadows/ResolutionMatched.h"
#include "Core/Shadows/ShadowMap.h"
#include "Core/Shadows/StochasticShadowMap.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace deepshadow
{
namespace
{
using Type = ShadowParameterInfo::Type;
constexpr double Infinity = std::numeric_limits<double>::infinity();

// Whole numbers in full (2147483647, not 2.14748e+09), others as %g (0.01).
std::string Number(double value)
{
  char text[32];
  if (value == std::floor(value) && std::abs(value) < 1e15)
  {
    std::snprintf(text, sizeof(text), "%.0f", value);
  }
  else
  {
    std::snprintf(text, sizeof(text), "%g", value);
  }
  return text;
}

// "a, b or c"
std::string Alternatives(const std::vector<std::string>& items)
{
  std::string text;
  for (size_t i = 0; i < items.size(); ++i)
  {
    text += (i == 0 ? "" : (i + 1 == items.size() ? " or " : ", ")) + items[i];
  }
  return text;
}

double ParseReal(const std::string& key, const std::string& text)
{
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(value))
  {
    throw std::invalid_argument(key + " expects a number, got '" + text + "'");
  }
  return value;
}

// Accessors of one ShadowParameters field, as the vector of doubles a parameter's value is.
template <typename T>
ShadowParameterInfo Field(ShadowParameterInfo info, T ShadowParameters::*member)
{
  info.Get = [member](const ShadowParameters& p) {
    return std::vector<double>{ static_cast<double>(p.*member) };
  };
  info.Set = [member](ShadowParameters& p, const std::vector<double>& v) {
    p.*member = static_cast<T>(v.at(0));
  };
  return info;
}

ShadowParameterInfo Numeric(const char* key, Type type, double low, double high,
  const char* metavar, const char* help)
{
  ShadowParameterInfo info;
  info.Key = key;
  info.Kind = type;
  info.Low = low;
  info.High = high;
  info.Metavar = metavar;
  info.Help = help;
  return info;
}

ShadowParameterInfo Choice(const char* key, std::vector<std::string> choices, const char* help)
{
  ShadowParameterInfo info;
  info.Key = key;
  info.Kind = Type::Choice;
  info.Choices = std::move(choices);
  info.Help = help;
  return info;
}

// The parameters, in --help's order. Each range lives here only: the tool refuses values
// outside it, the VTK setters clamp to it, ShadowParameters::Validate() checks it.
std::vector<ShadowParameterInfo> MakeParameters()
{
  std::vector<ShadowParameterInfo> list;
  list.push_back(Field(Numeric("shadow-threshold", Type::Number, 0.0, 1.0, "T",
                         "rays-opaque, shadowmap: occluder threshold"),
    &ShadowParameters::Threshold));
  list.push_back(Field(Choice("threshold-on", { "accumulated", "opacity", "scalar" },
                         "what the threshold is compared with: the opacity accumulated along the "
                         "light ray (default: a translucent body's hard shadow), each sample's "
                         "opacity, or each sample's normalized scalar"),
    &ShadowParameters::Mode));
  list.push_back(Field(Numeric("shadow-step-factor", Type::Number, 0.01, 100.0, "F",
                         "feeler / light-ray step as a factor of the sample distance"),
    &ShadowParameters::StepFactor));
  auto volume = Numeric("shadow-volume-size", Type::Integer, 2, 2048, "N",
    "*-cached: shadow volume nodes along the longest axis");
  volume.DefaultText = "128 for rays, 64 for the map techniques";
  list.push_back(Field(volume, &ShadowParameters::VolumeSize));
  list.push_back(Field(Numeric("shadow-map-size", Type::Integer, 1, 65536, "N",
                         "texels per side"),
    &ShadowParameters::MapSize));
  list.push_back(Field(Numeric("clusters", Type::Integer, 0, 8, "M",
                         "clustered maps per light, fitted to groups of objects (0: one map)"),
    &ShadowParameters::Clusters));
  list.push_back(Field(Numeric("cluster-distance", Type::Number, 0.0, 2.0, "D",
                         "clusters: objects farther apart (light space, in face half-widths) "
                         "get maps of their own"),
    &ShadowParameters::ClusterDistance));
  list.push_back(Field(Numeric("epsilon", Type::Number, 0.0, 1.0, "E",
                         "bound on the compressed visibility's error"),
    &ShadowParameters::Epsilon));
  list.push_back(Field(Numeric("layers", Type::Integer, 1, 256, "N", "nodes per texel"),
    &ShadowParameters::Layers));
  list.push_back(Field(Numeric("chunk-nodes", Type::Integer, 0, 64, "N",
                         "chunked node memory: nodes per chunk, any number of chunks per texel "
                         "(0: layers per texel)"),
    &ShadowParameters::ChunkNodes));
  list.push_back(Field(Numeric("node-pool-mb", Type::Number, 0.0, 65536.0, "MB",
                         "chunked: the node pool per light (0: the memory of the layers)"),
    &ShadowParameters::PoolMegabytes));
  auto levels = Numeric("opacity-levels", Type::Levels, 0.0, 1.0, "A,B,C", "opacity levels");
  levels.Get = [](const ShadowParameters& p) {
    return std::vector<double>(p.Levels.begin(), p.Levels.end());
  };
  levels.Set = [](ShadowParameters& p, const std::vector<double>& v) {
    std::copy_n(v.begin(), 3, p.Levels.begin());
  };
  list.push_back(levels);
  auto offsets = Numeric("cssm-offsets", Type::Integer, 7, 21, "M",
    "texel offsets averaged per lookup");
  offsets.Allowed = { 7, 13, 21 };
  list.push_back(Field(offsets, &ShadowParameters::Offsets));
  list.push_back(Field(Numeric("cssm-seed", Type::Integer, 0, 2147483647, "S",
                         "seed of the random thresholds"),
    &ShadowParameters::Seed));
  list.push_back(Field(Numeric("cssm-photons", Type::Integer, 1, 64, "N", "photons per texel"),
    &ShadowParameters::Photons));
  list.push_back(Field(Choice("pcf", { "none", "2x2", "3x3", "poisson" }, "filter"),
    &ShadowParameters::Filter));
  list.push_back(Field(Numeric("bias", Type::Number, 0.0, Infinity, "B",
                         "depth bias in feeler steps"),
    &ShadowParameters::Bias));
  auto pageSize = Numeric("page-size", Type::Integer, 16, 128, "N", "texels per page side");
  pageSize.Allowed = { 16, 32, 64, 128 };
  list.push_back(Field(pageSize, &ShadowParameters::PageSize));
  list.push_back(Field(Numeric("atlas-size", Type::Integer, 64, 16384, "N",
                         "texels per side of the page atlas"),
    &ShadowParameters::AtlasSize));
  auto finest = Numeric("max-resolution", Type::Integer, 1024, 32768, "N",
    "texels per side of the finest level (the virtual map)");
  finest.Allowed = { 1024, 2048, 4096, 8192, 16384, 32768 };
  list.push_back(Field(finest, &ShadowParameters::MaxResolution));
  auto downsample = Numeric("analysis-downsample", Type::Integer, 1, 8, "N",
    "every N-th pixel of the image asks for pages");
  downsample.Allowed = { 1, 2, 4, 8 };
  list.push_back(Field(downsample, &ShadowParameters::AnalysisDownsample));
  list.push_back(Field(Numeric("keep-pages", Type::Integer, 0, 1, "0|1",
                         "keep pages across frames while the light and casters stay"),
    &ShadowParameters::KeepPages));
  auto fourierTerms = Numeric("fom-terms", Type::Integer, 1, 15, "N",
    "cosine-sine pairs per texel, 8 bytes each besides 8 for the ray's end and optical depth");
  fourierTerms.Allowed = { 1, 3, 7, 15 };
  fourierTerms.ExtraDefault = { 7 };
  list.push_back(fourierTerms);
  auto adaptiveNodes = Numeric("avsm-nodes", Type::Integer, 2, 16, "N",
    "nodes (depth, transmittance) per texel, 8 bytes each");
  adaptiveNodes.Allowed = { 2, 4, 8, 16 };
  adaptiveNodes.ExtraDefault = { 8 };
  list.push_back(adaptiveNodes);
  auto fixedBits = Numeric("dsm-bits", Type::Integer, 64, 512, "B",
    "bits per texel, 32 per node (16-bit depth and visibility)");
  fixedBits.Allowed = { 64, 128, 256, 512 };
  fixedBits.ExtraDefault = { 256 };
  list.push_back(fixedBits);
  auto fixedError = Numeric("dsm-fixed-error", Type::Number, 0.0, 0.5, "E",
    "an error bound instead of dsm-bits: nodes per texel from the 99th percentile of what each "
    "texel needs to stay within it (0: the budget dsm-bits)");
  fixedError.ExtraDefault = { 0.0 };
  list.push_back(fixedError);
  auto slices = Numeric("slices", Type::Integer, 8, 64, "N",
    "transmittances per texel, a byte each, evenly spaced over the light's depth range");
  slices.Allowed = { 8, 16, 32, 64 };
  slices.ExtraDefault = { 32 };
  list.push_back(slices);
  auto moments = Numeric("moments", Type::Integer, 2, 6, "N",
    "power moments per texel, 4 bytes each besides 8 for the ray's end and optical depth");
  moments.Allowed = { 2, 4, 6 };
  moments.ExtraDefault = { 6 };
  list.push_back(moments);
  // Keys without a field of their own live in ShadowParameters::Extra.
  for (ShadowParameterInfo& info : list)
  {
    if (!info.Get)
    {
      info.Get = [key = info.Key, fallback = info.ExtraDefault](const ShadowParameters& p) {
        const auto at = p.Extra.find(key);
        return at == p.Extra.end() ? fallback : at->second;
      };
      info.Set = [key = info.Key](ShadowParameters& p, const std::vector<double>& v) { p.Extra[key] = v; };
    }
  }
  return list;
}

template <typename Twin>
std::unique_ptr<LightShadow> MakeTwin(const ShadowParameters& parameters,
  const ShadowCaster& caster, const Light& light, double step, int threads)
{
  return std::make_unique<Twin>(parameters, caster, light, step, threads);
}

// Light-space maps need a smaller cache: their maps already bound the shadows' detail.
void MapDefaults(ShadowParameters& p)
{
  p.VolumeSize = 64;
}

ShadowTechniqueInfo Technique(const char* name, const char* summary, ShadowKind kind,
  std::vector<std::string> keys, std::vector<ShadowSweepEntry> sweep)
{
  ShadowTechniqueInfo info;
  info.Name = name;
  info.Summary = summary;
  info.Kind = kind;
  info.Keys = std::move(keys);
  info.Sweep = std::move(sweep);
  info.TexelBytes = [](const ShadowParameters&) -> std::uint64_t { return 0; };
  info.FixedBytes = [](const ShadowParameters&, int) -> std::uint64_t { return 0; };
  info.StatedError = [](const ShadowParameters&, const StatedErrorCase&) { return 0.0; };
  return info;
}

ShadowTechniqueInfo Rays(const char* name, const char* summary, bool opaque, bool colored,
  std::vector<ShadowSweepEntry> sweep)
{
  ShadowTechniqueInfo info = Technique(name, summary, ShadowKind::Rays, {}, std::move(sweep));
  info.Opaque = opaque;
  info.Colored = colored;
  info.MakeShadow = MakeRayShadow;
  return info;
}

ShadowTechniqueInfo LightSpaceMap(ShadowTechniqueInfo info)
{
  info.Keys.insert(info.Keys.begin(), "shadow-map-size");
  info.Defaults = MapDefaults;
  info.LookupTexels = 1.5; // bilinear
  return info;
}

// |V' - V| <= epsilon at every sample depth, per map; clustered maps multiply up to one
// lookup per cluster along the ray, each within epsilon of its factor.
double DeepShadowMapError(const ShadowParameters& p, const StatedErrorCase&)
{
  return p.Epsilon * std::max(1, p.Clusters);
}

// What a menu shows for it (ParaView's technique list): the group it is listed under, one of
// ShadowTechniqueGroups() ("" for none), and a label.
ShadowTechniqueInfo Menu(ShadowTechniqueInfo info, const char* group, const char* label)
{
  info.Group = group;
  info.Label = label;
  return info;
}

// The techniques, in the order the tool lists them. A technique is one entry here (and its
// GPU class, which registers itself with vtkDeepShadowTechniqueFactory under the same kind).
std::vector<ShadowTechniqueInfo> MakeTechniques()
{
  std::vector<ShadowTechniqueInfo> list;
  list.push_back(Menu(Technique("none", "default", ShadowKind::None, {}, {}), "", "No shadows"));
  list.push_back(Menu(Rays("rays", "translucent shadow rays", false, false,
                        { { "", true }, { ":shadow-step-factor=0.5" }, { ":shadow-step-factor=2" },
                          { ":shadow-step-factor=4" }, { "-cached", true }, { "-cached:shadow-volume-size=64" },
                          { "-cached:shadow-volume-size=256" } }),
    "Exact", "Shadow rays"));
  auto opaque = Rays("rays-opaque", "", true, false, { { "" } });
  opaque.Binary = true;
  list.push_back(Menu(opaque, "Exact", "Shadow rays, opaque occluders"));
  list.push_back(Menu(Rays("rays-color", "coloured", false, true, { { "" } }), "Exact", "Shadow rays, coloured"));

  auto map = LightSpaceMap(Technique("shadowmap", "", ShadowKind::ShadowMap, { "pcf", "bias" },
    { { "", true }, { ":shadow-map-size=256" }, { ":shadow-map-size=1024" },
      { ":shadow-map-size=2048" }, { ":pcf=none" }, { ":pcf=2x2" }, { ":pcf=poisson" },
      { "-cached" } }));
  map.Binary = true;
  map.LookupTexels = 2.5; // PCF 3x3 around the nearest texel
  map.MakeShadow = MakeTwin<ShadowMapShadow>;
  map.TexelBytes = [](const ShadowParameters&) -> std::uint64_t { return 4; };
  list.push_back(Menu(map, "Maps", "Shadow map"));

  for (const bool colored : { false, true })
  {
    auto dsm = LightSpaceMap(Technique(colored ? "dsm-color" : "dsm",
      colored ? "" : "deep shadow map", ShadowKind::DeepShadowMap, { "epsilon", "layers", "chunk-nodes", "node-pool-mb" },
      colored ? std::vector<ShadowSweepEntry>{ { "", true }, { "-cached" } }
              : std::vector<ShadowSweepEntry>{ { "", true }, { ":epsilon=0" }, { ":epsilon=0.01" },
                  { ":epsilon=0.05" }, { ":epsilon=0.1" }, { ":layers=1" }, { ":layers=2", true },
                  { ":layers=4" }, { ":layers=16" }, { ":chunk-nodes=2" }, { ":chunk-nodes=4", true },
                  { ":chunk-nodes=8" }, { ":shadow-map-size=256" },
                  { ":shadow-map-size=1024" }, { ":shadow-step-factor=2" }, { "-cached", true },
                  { "-cached:shadow-volume-size=128" } }));
    dsm.Colored = colored;
    dsm.StatedError = DeepShadowMapError;
    dsm.MakeShadow = MakeTwin<DeepShadowMap>;
    dsm.TexelBytes = [colored](const ShadowParameters& p) -> std::uint64_t {
      // Chunked: a start entry, and at most the pool the layers would take (automatic).
      return (colored ? 16 : 8) * static_cast<std::uint64_t>(p.Layers) + (p.ChunkNodes > 0 ? 4 : 0);
    };
    list.push_back(Menu(dsm, "Deep maps", colored ? "Deep shadow map, coloured" : "Deep shadow map"));
  }
  // Clustered deep shadow maps (paper 000, section 4): at most 4 maps of 256^2 per light, the
  // memory of one 512^2 map, each fitted to a cluster of the volume's objects.
  auto clustered = LightSpaceMap(Technique("dsm-clustered", "", ShadowKind::DeepShadowMap,
    { "epsilon", "layers", "chunk-nodes", "node-pool-mb", "clusters", "cluster-distance" },
    { { "", true }, { ":clusters=2" }, { ":clusters=8", true }, { ":cluster-distance=0.1" },
      { ":cluster-distance=0.5" }, { ":shadow-map-size=512" } }));
  clustered.Clustered = true;
  clustered.StatedError = DeepShadowMapError;
  clustered.Defaults = [](ShadowParameters& p) {
    MapDefaults(p);
    p.Clusters = 4;
    p.MapSize = 256;
  };
  clustered.MakeShadow = MakeTwin<DeepShadowMap>;
  clustered.TexelBytes = [](const ShadowParameters& p) -> std::uint64_t {
    return 8 * static_cast<std::uint64_t>(p.Layers) * static_cast<std::uint64_t>(std::max(1, p.Clusters));
  };
  list.push_back(Menu(clustered, "Deep maps", "Deep shadow maps, clustered"));

  // Deep shadow maps at a fixed memory budget: per texel the smallest bound whose nodes fit.
  auto fixed = LightSpaceMap(Technique("dsm-fixed", "deep shadow map, fixed budget", FixedBudgetKind,
    { "dsm-bits", "dsm-fixed-error" },
    { { "", true }, { ":dsm-bits=64" }, { ":dsm-bits=128", true }, { ":dsm-bits=512" }, { ":dsm-fixed-error=0.02" },
      { "-cached" } }));
  // N nodes fit an exponential within about 1 / (2 N^2) (linear segments through a convex
  // curve), and each texel's bound is the smallest that fits; not a bound stated in
  // advance. What the closed-form bodies show, with room. With an error E instead, 99 % of
  // the texels keep it; a smooth body's all do.
  fixed.StatedError = [](const ShadowParameters& p, const StatedErrorCase&) {
    if (FixedBudgetError(p) > 0.0)
    {
      return FixedBudgetError(p);
    }
    const double nodes = FixedBudgetNodes(p);
    return 0.8 / (nodes * nodes);
  };
  fixed.MakeShadow = MakeTwin<FixedBudgetDeepShadowMap>;
  fixed.TexelBytes = [](const ShadowParameters& p) -> std::uint64_t {
    // With an error, the most it may ask for (the memory budget's worst case).
    return static_cast<std::uint64_t>(FixedBudgetError(p) > 0.0 ? 32 * MaxFixedNodes : FixedBudgetBits(p)) / 8;
  };
  list.push_back(Menu(fixed, "Deep maps", "Deep shadow map, fixed budget"));

  auto levels = LightSpaceMap(Technique("dsm3", "opacity levels", ShadowKind::OpacityLevels,
    { "opacity-levels" }, { { "", true }, { ":shadow-map-size=256" }, { "-cached" } }));
  // Three levels joined by smoothsteps (paper 001) approximate an exponential opacity inside
  // a medium within 0.1 (before 10 %, and between 50 and 90 %); past the medium (none of it
  // behind the point) the maximum is exact.
  levels.StatedError = [](const ShadowParameters&, const StatedErrorCase& at) {
    return at.MediumBehind ? 0.1 : 0.0;
  };
  levels.MakeShadow = MakeTwin<OpacityLevelsShadow>;
  levels.TexelBytes = [](const ShadowParameters&) -> std::uint64_t { return 16; };
  list.push_back(Menu(levels, "Approximate", "Opacity levels"));

  // Fourier opacity maps (Jansen and Bavoil 2010), a rival at a fixed number of bits per texel.
  auto fourier = LightSpaceMap(Technique("fom", "Fourier opacity map", FourierOpacityKind, { "fom-terms" },
    { { "", true }, { ":fom-terms=1" }, { ":fom-terms=3", true }, { ":fom-terms=15" }, { "-cached" } }));
  // A series cut after N pairs rings around the medium's fronts. Not a bound: what the
  // closed-form bodies show, with room (N = 1, 3, 7: 0.13, 0.041, 0.013 with sampling).
  fourier.StatedError = [](const ShadowParameters& p, const StatedErrorCase&) {
    return 0.3 / (FourierTerms(p) + 1);
  };
  fourier.Monotone = false;
  fourier.MakeShadow = MakeTwin<FourierOpacityMap>;
  fourier.TexelBytes = [](const ShadowParameters& p) -> std::uint64_t {
    return 16 * static_cast<std::uint64_t>(FourierLayers(FourierTerms(p)));
  };
  list.push_back(Menu(fourier, "Approximate", "Fourier opacity map"));

  // Adaptive volumetric shadow maps (Salvi et al. 2010), a rival at a fixed number of nodes.
  auto adaptive = LightSpaceMap(Technique("avsm", "adaptive volumetric shadow map", AdaptiveVolumetricKind,
    { "avsm-nodes" }, { { "", true }, { ":avsm-nodes=2" }, { ":avsm-nodes=4", true }, { ":avsm-nodes=16" }, { "-cached" } }));
  // N nodes, linear between them, fit an exponential within about 1 / N^2; not a bound (the
  // closed-form bodies: 0.17, 0.040 and 0.0085 with sampling at 2, 4 and 8 nodes). Neighbours
  // that keep different nodes blend into a curve that may rise along an oblique ray.
  adaptive.StatedError = [](const ShadowParameters& p, const StatedErrorCase&) {
    const double nodes = AdaptiveNodes(p);
    return 0.8 / (nodes * nodes);
  };
  adaptive.Monotone = false;
  adaptive.MakeShadow = MakeTwin<AdaptiveVolumetricShadowMap>;
  adaptive.TexelBytes = [](const ShadowParameters& p) -> std::uint64_t {
    return 8 * static_cast<std::uint64_t>(AdaptiveNodes(p));
  };
  list.push_back(Menu(adaptive, "Approximate", "Adaptive volumetric shadow map"));

  // Uniform opacity slices (Kim and Neumann 2001), the simplest rival at a fixed number of
  // bits per texel.
  auto sliced = LightSpaceMap(Technique("slices", "uniform opacity slices", OpacitySlicesKind, { "slices" },
    { { "", true }, { ":slices=8" }, { ":slices=16", true }, { ":slices=64" }, { "-cached" } }));
  // Linear between slices a range / N apart, read one slice towards the light: inside a
  // medium (or in front of more of it) the shadow lags by a slice's absorption; elsewhere 8
  // bits and the interpolation. Not a bound: what the closed-form bodies show, with room
  // (0.10 in the slab at 32 slices).
  sliced.StatedError = [](const ShadowParameters& p, const StatedErrorCase& at) {
    return (at.MediumBehind ? 4.0 : 1.0) / OpacitySliceCount(p);
  };
  sliced.ResolvesThinLayers = false;
  sliced.MakeShadow = MakeTwin<OpacitySlicesShadow>;
  sliced.TexelBytes = [](const ShadowParameters& p) -> std::uint64_t {
    return static_cast<std::uint64_t>(OpacitySliceCount(p));
  };
  list.push_back(Menu(sliced, "Approximate", "Uniform opacity slices"));

  // Power moments (MBOIT, Muenstermann et al. 2018), a rival at a fixed number of bits per texel.
  auto powers = LightSpaceMap(Technique("moments", "power-moment transmittance", PowerMomentKind,
    { "moments" }, { { "", true }, { ":moments=2" }, { ":moments=4", true }, { "-cached" } }));
  // M moments bound where the optical depth lies, not its shape: a front is smeared over about
  // 1 / (M / 2 + 1) of the ray. Not a bound: what the closed-form bodies show, with room.
  powers.StatedError = [](const ShadowParameters& p, const StatedErrorCase&) {
    return 0.6 / (PowerMomentCount(p) / 2 + 1);
  };
  powers.Monotone = false;
  powers.MakeShadow = MakeTwin<PowerMomentMap>;
  powers.TexelBytes = [](const ShadowParameters& p) -> std::uint64_t {
    return 16 * static_cast<std::uint64_t>(PowerMomentLayers(PowerMomentCount(p)));
  };
  list.push_back(Menu(powers, "Approximate", "Power-moment transmittance"));

  auto cssm = LightSpaceMap(Technique("cssm", "coloured stochastic shadow map",
    ShadowKind::Stochastic, { "cssm-offsets", "cssm-seed", "cssm-photons" },
    { { "", true }, { ":cssm-offsets=7" }, { ":cssm-offsets=21" }, { ":cssm-photons=4" },
      { "-cached", true } }));
  // Unbiased: 4 standard errors of the mean of offsets x photons Bernoulli tests; its
  // offsets reach 7 texels (the farthest of 13) around the nearest one.
  cssm.StatedError = [](const ShadowParameters& p, const StatedErrorCase& at) {
    const double tests = static_cast<double>(StochasticOffsets(p.Offsets).size()) * p.Photons;
    return 4.0 * std::sqrt(at.Visibility * (1.0 - at.Visibility) / tests);
  };
  cssm.LookupTexels = 7.5;
  cssm.MakeShadow = MakeTwin<StochasticShadowMap>;
  cssm.TexelBytes = [](const ShadowParameters& p) -> std::uint64_t {
    return 16 * static_cast<std::uint64_t>(p.Photons);
  };
  list.push_back(Menu(cssm, "Approximate", "Coloured stochastic shadow map"));

  // Resolution-matched shadow maps (paper 004): pages of a virtual map, where pixels need them.
  auto rmsm = Technique("rmsm", "resolution-matched shadow map", ShadowKind::ResolutionMatched,
    { "pcf", "bias", "page-size", "atlas-size", "max-resolution", "analysis-downsample", "keep-pages" },
    { { "", true }, { ":max-resolution=4096" }, { ":max-resolution=32768" }, { ":atlas-size=512" },
      { ":analysis-downsample=4", true }, { ":page-size=64" }, { ":pcf=none" }, { ":keep-pages=0" } });
  rmsm.Binary = true;
  rmsm.FollowsView = true;
  rmsm.Defaults = MapDefaults;
  rmsm.LookupTexels = 2.5; // PCF 3x3 around the nearest texel
  rmsm.MakeShadow = MakeTwin<ResolutionMatchedShadow>;
  rmsm.FixedBytes = [](const ShadowParameters& p, int faces) -> std::uint64_t {
    // The atlas, shared by every light, and a page table per face (a 32-bit entry per cell).
    const PageLayout layout = PageLayout::Of(p);
    const std::uint64_t cells = static_cast<std::uint64_t>(layout.TableSize()) * layout.TableSize();
    return 4 * static_cast<std::uint64_t>(layout.AtlasSize) * layout.AtlasSize + 4 * cells * faces;
  };
  list.push_back(Menu(rmsm, "Maps", "Resolution-matched shadow map"));
  return list;
}
}

std::string ShadowParameterInfo::RangeText() const
{
  switch (this->Kind)
  {
    case Type::Choice:
      return Alternatives(this->Choices);
    case Type::Levels:
      return "(" + Number(this->Low) + ", " + Number(this->High) + "]";
    default:
      break;
  }
  if (!this->Allowed.empty())
  {
    std::vector<std::string> items;
    for (double value : this->Allowed)
    {
      items.push_back(Number(value));
    }
    return Alternatives(items);
  }
  if (std::isinf(this->High))
  {
    return "not negative";
  }
  return "[" + Number(this->Low) + ", " + Number(this->High) + "]";
}

std::string ShadowParameterInfo::Check(const std::vector<double>& v) const
{
  const std::string& key = this->Key;
  switch (this->Kind)
  {
    case Type::Number:
      if (v.size() == 1 && std::isfinite(v[0]) && v[0] >= this->Low && v[0] <= this->High)
      {
        return std::string();
      }
      return key + (std::isinf(this->High) && this->Low == 0.0 ? " must not be negative"
                                                               : " must be in " + this->RangeText());
    case Type::Integer:
      if (v.size() != 1 || v[0] != std::floor(v[0]) || !(v[0] >= this->Low && v[0] <= this->High))
      {
        return key + " must be a whole number in [" + Number(this->Low) + ", " + Number(this->High) + "]";
      }
      if (!this->Allowed.empty() &&
        std::find(this->Allowed.begin(), this->Allowed.end(), v[0]) == this->Allowed.end())
      {
        return key + " must be " + this->RangeText();
      }
      return std::string();
    case Type::Choice:
      if (v.size() == 1 && v[0] >= 0.0 && v[0] < static_cast<double>(this->Choices.size()) &&
        v[0] == std::floor(v[0]))
      {
        return std::string();
      }
      return key + " must be " + this->RangeText();
    case Type::Levels:
      if (v.size() == 3 && v[0] > this->Low && v[0] < v[1] && v[1] < v[2] && v[2] <= this->High)
      {
        return std::string();
      }
      return key + " must increase strictly within " + this->RangeText();
  }
  return std::string();
}

std::vector<double> ShadowParameterInfo::Parse(const std::string& text) const
{
  const std::string& key = this->Key;
  std::vector<double> values;
  if (this->Kind == Type::Choice)
  {
    const auto at = std::find(this->Choices.begin(), this->Choices.end(), text);
    if (at == this->Choices.end())
    {
      throw std::invalid_argument(key + " must be " + this->RangeText() + ", got '" + text + "'");
    }
    return { static_cast<double>(at - this->Choices.begin()) };
  }
  if (this->Kind == Type::Levels)
  {
    std::stringstream stream(text);
    std::vector<std::string> parts;
    for (std::string part; std::getline(stream, part, ',');)
    {
      parts.push_back(part);
    }
    if (parts.size() != 3)
    {
      throw std::invalid_argument(key + " expects A,B,C");
    }
    for (const std::string& part : parts)
    {
      values.push_back(ParseReal(key, part));
    }
  }
  else
  {
    values.push_back(ParseReal(key, text));
    if (this->Kind == Type::Integer &&
      (values[0] != std::floor(values[0]) || values[0] < this->Low || values[0] > this->High))
    {
      throw std::invalid_argument(key + " expects a whole number in [" + Number(this->Low) + ", " +
        Number(this->High) + "], got '" + text + "'");
    }
  }
  const std::string problem = this->Check(values);
  if (!problem.empty())
  {
    throw std::invalid_argument(problem);
  }
  return values;
}

std::string ShadowParameterInfo::Format(const std::vector<double>& values) const
{
  if (this->Kind == Type::Choice)
  {
    return this->Choices.at(static_cast<size_t>(values.at(0)));
  }
  std::string text;
  for (double value : values)
  {
    text += (text.empty() ? "" : ",") + Number(value);
  }
  return text;
}

bool ShadowTechniqueInfo::Reads(const std::string& key) const
{
  if (this->Kind == ShadowKind::None)
  {
    return false;
  }
  const auto& shared = SharedShadowParameterKeys();
  return std::find(this->Keys.begin(), this->Keys.end(), key) != this->Keys.end() ||
    std::find(shared.begin(), shared.end(), key) != shared.end();
}

ShadowParameters ShadowTechniqueInfo::DefaultParameters(bool cached) const
{
  ShadowParameters p;
  p.Kind = this->Kind;
  p.Opaque = this->Opaque;
  p.Colored = this->Colored;
  p.Cached = cached;
  if (this->Defaults)
  {
    this->Defaults(p);
  }
  return p;
}

const std::vector<ShadowTechniqueInfo>& ShadowTechniques()
{
  static const std::vector<ShadowTechniqueInfo> techniques = MakeTechniques();
  return techniques;
}

const std::vector<ShadowParameterInfo>& ShadowParameterInfos()
{
  static const std::vector<ShadowParameterInfo> parameters = MakeParameters();
  return parameters;
}

const std::vector<std::string>& SharedShadowParameterKeys()
{
  static const std::vector<std::string> keys{ "shadow-threshold", "threshold-on",
    "shadow-step-factor", "shadow-volume-size" };
  return keys;
}

const ShadowTechniqueInfo* FindShadowTechnique(const std::string& name, bool* cached)
{
  const std::string suffix = "-cached";
  const bool isCached = name.size() > suffix.size() &&
    name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
  const std::string base = isCached ? name.substr(0, name.size() - suffix.size()) : name;
  for (const ShadowTechniqueInfo& technique : ShadowTechniques())
  {
    if (technique.Name == base && !(isCached && technique.Kind == ShadowKind::None))
    {
      if (cached)
      {
        *cached = isCached;
      }
      return &technique;
    }
  }
  return nullptr;
}

const ShadowTechniqueInfo& ShadowTechniqueOf(const ShadowParameters& parameters)
{
  // The exact flags first; then the kind alone (a flag that kind does not vary).
  const ShadowTechniqueInfo* sameKind = nullptr;
  for (const ShadowTechniqueInfo& technique : ShadowTechniques())
  {
    if (technique.Kind != parameters.Kind)
    {
      continue;
    }
    if (technique.Opaque == parameters.Opaque && technique.Colored == parameters.Colored &&
      technique.Clustered == (parameters.Clusters > 0))
    {
      return technique;
    }
    if (!sameKind || (technique.Colored == parameters.Colored && sameKind->Colored != parameters.Colored))
    {
      sameKind = &technique;
    }
  }
  return sameKind ? *sameKind : ShadowTechniques().front();
}

const ShadowParameterInfo* FindShadowParameter(const std::string& key)
{
  for (const ShadowParameterInfo& parameter : ShadowParameterInfos())
  {
    if (parameter.Key == key)
    {
      return &parameter;
    }
  }
  return nullptr;
}

std::vector<std::string> ShadowTechniqueNames()
{
  std::vector<std::string> names;
  for (const ShadowTechniqueInfo& technique : ShadowTechniques())
  {
    names.push_back(technique.Name);
    if (technique.Kind != ShadowKind::None)
    {
      names.push_back(technique.Name + "-cached");
    }
  }
  return names;
}

const std::vector<std::string>& ShadowTechniqueGroups()
{
  static const std::vector<std::string> groups{ "Exact", "Maps", "Deep maps", "Approximate" };
  return groups;
}

std::string ShadowTechniqueLabel(const std::string& name)
{
  bool cached = false;
  const ShadowTechniqueInfo* technique = FindShadowTechnique(name, &cached);
  if (!technique)
  {
    return "";
  }
  return technique->Label + (cached ? ", cached" : "") + " (" + name + ")";
}

}
