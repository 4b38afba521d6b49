// The shadow technique registry, CPU side: every technique's name, the parameter keys it
// reads (each with its one range and default), its CPU twin and its report sweep, declared
// once in ShadowTechniques.cxx. The tool's options and specs, its --help, the report, the
// GPU factory (vtkDeepShadowTechniqueFactory.h) and ShadowParameters::Validate() all read
// these tables, so a range or a name lives in one place.
#ifndef deepshadow_ShadowTechniques_h
#define deepshadow_ShadowTechniques_h

#include "Core/Shadows.h"
#include "vtkDeepShadowCoreModule.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace deepshadow
{

/** One tunable parameter: its key (the tool's --KEY and a spec's KEY=VALUE), range, default. */
struct VTKDEEPSHADOWCORE_EXPORT ShadowParameterInfo
{
  enum class Type
  {
    Number,  // a finite real in [Low, High] (High may be infinite)
    Integer, // a whole number in [Low, High], one of Allowed if given
    Choice,  // one of Choices, stored as its index
    Levels   // three reals increasing strictly within (Low, High]
  };
  std::string Key;
  Type Kind = Type::Number;
  double Low = 0.0;
  double High = 0.0;
  std::vector<double> Allowed;
  std::vector<std::string> Choices;
  std::string Metavar;     // --help: "--KEY METAVAR"
  std::string Help;        // --help: what it is (who reads it, range and default are added)
  std::string DefaultText; // --help, when the default is not ShadowParameters{}'s
  /** A key with no field in ShadowParameters: its default; Get/Set use ShadowParameters::Extra. */
  std::vector<double> ExtraDefault;
  std::function<std::vector<double>(const ShadowParameters&)> Get;
  std::function<void(ShadowParameters&, const std::vector<double>&)> Set;

  /** Empty if `values` are in range, else "KEY must ..." (the one validation). */
  std::string Check(const std::vector<double>& values) const;
  /** Parses the text of a value and checks it; throws std::invalid_argument("KEY ..."). */
  std::vector<double> Parse(const std::string& text) const;
  /** The value as the tool writes it (a choice's name, levels as A,B,C). */
  std::string Format(const std::vector<double>& values) const;
  /** [lo, hi], "7, 13 or 21", "none|2x2|...": the range for --help. */
  std::string RangeText() const;
};

/** A line of the report's sweep: a spec suffix after the name ("", ":epsilon=0", "-cached"). */
struct ShadowSweepEntry
{
  std::string Suffix;
  bool Quick = false; // also in the short sweep (report --quick)
};

/**
 * Where a lookup is judged against a closed-form answer (a homogeneous body lit by one
 * light): the true visibility there and whether more of the medium lies behind the point,
 * away from the light (it is inside the body or in front of more of it).
 */
struct StatedErrorCase
{
  double Visibility = 1.0;
  bool MediumBehind = false;
};

/** One shadow technique. Its "-cached" variant is the same technique with Cached set. */
struct VTKDEEPSHADOWCORE_EXPORT ShadowTechniqueInfo
{
  std::string Name;    // none, rays, rays-opaque, ..., without "-cached"
  std::string Summary; // --help: what it is
  std::string Label;   // what a menu shows: "Deep shadow map"
  std::string Group;   // a menu's heading: "Exact", "Maps", "Deep maps", "Approximate"
  ShadowKind Kind = ShadowKind::None;
  bool Opaque = false;
  bool Colored = false;
  bool Clustered = false; // its maps are clustered (ShadowParameters::Clusters > 0)
  /** A hard shadow (lit or not, by the threshold), not a translucent one. */
  bool Binary = false;
  /**
   * Its visibility never increases away from the light along a light ray. False for a
   * truncated Fourier series, which ripples (fom), and for fixed nodes that differ between
   * neighbouring texels (avsm); the rise stays within its StatedError.
   */
  bool Monotone = true;
  /**
   * Whether its depths resolve any layer: false for uniform opacity slices, whose depth
   * resolution is a slice (the light's depth range over their count), so that a layer
   * thinner than that shadows nothing within a slice behind it.
   */
  bool ResolvesThinLayers = true;
  /** Its structures follow the camera (rmsm's pages): a moved camera may build some. */
  bool FollowsView = false;
  /** Parameter keys it reads besides the shared ones (SharedShadowParameterKeys()). */
  std::vector<std::string> Keys;
  /** Its defaults where they differ from ShadowParameters{} (e.g. a smaller cache). */
  std::function<void(ShadowParameters&)> Defaults;
  /** The CPU twin of one light's shadow; `step` is the feeler step. */
  std::function<std::unique_ptr<LightShadow>(const ShadowParameters&, const ShadowCaster&,
    const Light&, double step, int threads)>
    MakeShadow;
  /** Bytes per light-space texel (0: no light-space map), for the memory budget. */
  std::function<std::uint64_t(const ShadowParameters&)> TexelBytes;
  /**
   * Bytes of what the map size does not size, for `faces` light faces in all (rmsm's atlas
   * and page tables); 0 by default. For the memory budget.
   */
  std::function<std::uint64_t(const ShadowParameters&, int faces)> FixedBytes;
  std::vector<ShadowSweepEntry> Sweep;
  /**
   * What its representation may be off by, beyond what every technique shares (the march's
   * sampling, feeler termination, the lookup's footprint): deep shadow maps their epsilon,
   * CSSM four standard errors of its estimate; 0 by default. The closed-form suites add it to
   * their tolerance, and the documentation states it.
   */
  std::function<double(const ShadowParameters&, const StatedErrorCase&)> StatedError;
  /** Radius, in texels, of what a lookup reads around its point (bilinear 1.5, PCF 3x3 2.5). */
  double LookupTexels = 0.0;

  /** Whether it reads `key` (its own keys or a shared one). */
  bool Reads(const std::string& key) const;
  /** Its parameters at their defaults, Cached as asked. */
  ShadowParameters DefaultParameters(bool cached = false) const;
};

/** Every technique, "none" first, in the order the tool lists them. */
VTKDEEPSHADOWCORE_EXPORT const std::vector<ShadowTechniqueInfo>& ShadowTechniques();
/** Every parameter, in the order --help lists them. */
VTKDEEPSHADOWCORE_EXPORT const std::vector<ShadowParameterInfo>& ShadowParameterInfos();
/** The keys every technique but none reads (step factor, threshold, cache size...). */
VTKDEEPSHADOWCORE_EXPORT const std::vector<std::string>& SharedShadowParameterKeys();

/** The technique called `name` (NAME or NAME-cached), or null; `cached` says which. */
VTKDEEPSHADOWCORE_EXPORT const ShadowTechniqueInfo* FindShadowTechnique(
  const std::string& name, bool* cached = nullptr);
/** The technique `parameters` describe (by kind and flags); never null. */
VTKDEEPSHADOWCORE_EXPORT const ShadowTechniqueInfo& ShadowTechniqueOf(const ShadowParameters& parameters);
/** The parameter with this key, or null. */
VTKDEEPSHADOWCORE_EXPORT const ShadowParameterInfo* FindShadowParameter(const std::string& key);
/** Every name the tool accepts: none, then each technique and its -cached variant. */
VTKDEEPSHADOWCORE_EXPORT std::vector<std::string> ShadowTechniqueNames();
/** The menu headings of ShadowTechniqueInfo::Group, in menu order. */
VTKDEEPSHADOWCORE_EXPORT const std::vector<std::string>& ShadowTechniqueGroups();
/** What a menu shows for `name`: "Deep shadow map, cached (dsm-cached)"; empty if unknown. */
VTKDEEPSHADOWCORE_EXPORT std::string ShadowTechniqueLabel(const std::string& name);

}
#endif
