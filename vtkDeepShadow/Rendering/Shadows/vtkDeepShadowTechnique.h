/**
 * @class   vtkDeepShadowTechnique
 * @brief   A shadow technique of vtkDeepShadowVolumeMapper: how the volume shadows itself.
 *
 * Set one on the mapper with vtkDeepShadowVolumeMapper::SetShadowTechnique(). A technique
 * knows its light-space pass (the shadow structure it builds per shadow-casting light), its
 * lookup shader code, its CPU twin (GetParameters() feeds deepshadow::MakeLightShadow) and
 * its memory; the mapper knows none of that. Structures are rebuilt only when what they
 * depend on changed: the light's position or direction, the volume's data or transform, the
 * casting transfer function's content (opacity, and colours for coloured techniques), the
 * sample distance or the technique's parameters; never because the camera moved (a light
 * that follows the camera, like the headlight, does change). GetBuildCount() counts builds.
 *
 * Every light with vtkLight::ShadowAttenuation > 0 casts shadows (VTK's default is 1); a
 * light's diffuse and specular light is scaled by 1 - attenuation * (1 - visibility), per
 * colour channel for coloured techniques. Ambient light is never shadowed. An unshaded
 * volume (vtkVolumeProperty::ShadeOff) with a technique is lit isotropically so that it can
 * receive shadows.
 *
 * Parameters shared by the techniques: the step of feelers and light rays as a factor of the
 * view ray's sample distance; the threshold that makes a sample an opaque occluder (opaque
 * rays, shadow maps), on the opacity or on the normalized scalar; caching ("PP" of Ropinski
 * et al.): the technique's answer evaluated once per node of a 3D shadow volume over the
 * volume's box and fetched trilinearly while rendering, which makes every frame whose lights
 * did not move as cheap as one texture fetch per sample and light; and a separate volume
 * property whose colour and opacity cast the shadows (by default the volume's own).
 */
#ifndef vtkDeepShadowTechnique_h
#define vtkDeepShadowTechnique_h

#include "vtkDeepShadowRenderingModule.h" // For export macro
#include "vtkObject.h"

#include <memory> // For std::unique_ptr
#include <string> // For std::string
#include <utility> // For std::pair
#include <vector> // For std::vector

class vtkVolumeProperty;
class vtkWindow;

namespace deepshadow
{
struct ShadowParameters; // DeepShadow::Core's Shadows.h (installed)
}

class VTKDEEPSHADOWRENDERING_EXPORT vtkDeepShadowTechnique : public vtkObject
{
public:
  vtkTypeMacro(vtkDeepShadowTechnique, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Step of feelers and light rays as a factor of the view ray's sample distance (default 1).
   * Values outside [0.01, 100] are clamped with a warning.
   */
  void SetStepFactor(double factor);
  vtkGetMacro(StepFactor, double);
  ///@}

  ///@{
  /**
   * Where binary techniques (opaque rays, shadow maps) put an occluder along a light ray
   * (default 0.5; values outside [0, 1] are clamped with a warning). ThresholdMode says what
   * is compared with it:
   * - AccumulatedThreshold (default): the opacity accumulated along the light ray,
   *   1 - transmittance, casting meshes included. A thick translucent body (a CT volume with
   *   a soft transfer function) casts the hard shadow of its bulk.
   * - OpacityThreshold: each sample's transfer-function opacity (per unit distance), each
   *   mesh's opacity: only samples denser than the threshold cast.
   * - ScalarThreshold: each sample's scalar, normalized to [0, 1] over the data range.
   */
  void SetThreshold(double threshold);
  vtkGetMacro(Threshold, double);
  enum ThresholdModes
  {
    OpacityThreshold = 0,
    ScalarThreshold = 1,
    AccumulatedThreshold = 2
  };
  vtkSetClampMacro(ThresholdMode, int, OpacityThreshold, AccumulatedThreshold);
  vtkGetMacro(ThresholdMode, int);
  void SetThresholdModeToOpacity() { this->SetThresholdMode(OpacityThreshold); }
  void SetThresholdModeToScalar() { this->SetThresholdMode(ScalarThreshold); }
  void SetThresholdModeToAccumulated() { this->SetThresholdMode(AccumulatedThreshold); }
  ///@}

  ///@{
  /** Cache the technique's answers in a 3D shadow volume ("PP"). Default off. */
  vtkSetMacro(Cached, bool);
  vtkGetMacro(Cached, bool);
  vtkBooleanMacro(Cached, bool);
  ///@}

  ///@{
  /**
   * Shadow-volume nodes along the volume's longest axis when cached, at most as many as the
   * data has ([2, 2048], warned). Default 128 for shadow rays; 64 for the light-space
   * techniques, whose maps already bound the shadows' detail.
   */
  void SetShadowVolumeSize(int size);
  vtkGetMacro(ShadowVolumeSize, int);
  ///@}

  ///@{
  /**
   * The volume property whose colour and scalar opacity cast shadows (and its opacity unit
   * distance), instead of the volume's own (null, the default). Only its first component's
   * functions are used. Rendering still uses the volume's property.
   */
  void SetShadowProperty(vtkVolumeProperty* property);
  vtkGetObjectMacro(ShadowProperty, vtkVolumeProperty);
  ///@}

  /** The parameters of the CPU twin (deepshadow::MakeLightShadow). */
  virtual deepshadow::ShadowParameters GetParameters() const = 0;
  /**
   * The inverse: sets every parameter of this technique from `parameters` through its
   * setters (clamped to the registry's ranges); the kind is the class's, not theirs.
   * vtkDeepShadowTechniqueFactory::New() uses it. Subclasses add theirs and call this.
   */
  virtual void SetParameters(const deepshadow::ShadowParameters& parameters);
  /** rays, rays-opaque, rays-color, shadowmap, dsm, dsm-color, dsm3, cssm; "-cached" if so. */
  std::string GetName() const;
  /**
   * A new technique from its registry name (one GetName() returns) at its defaults, for
   * Python and configuration files; null, with an error, for a name no class implements.
   */
  VTK_NEWINSTANCE static vtkDeepShadowTechnique* NewFromName(const char* name);

  ///@{
  /** Observability: structures built, time of the last build (GL finished), memory. */
  vtkGetMacro(BuildCount, int);
  vtkGetMacro(LastBuildMilliseconds, double);
  long long GetShadowBytes() const;
  const std::string& GetLastError() const { return this->LastError; }
  /**
   * The GPU passes the last frame ran for this technique, in order: "feeler-table" (the
   * feeler's transfer table re-uploaded), "light-space-build" and "light-space-deferred"
   * (per face built), "shadow-cache" (per light cached). Empty when nothing was rebuilt.
   */
  const std::vector<std::string>& GetLastPasses() const { return this->LastPasses; }
  ///@}

  ///@{
  /**
   * The technique's own statistics of its last build or analysis, as named values, for
   * code that does not know the class: the deepshadow tool's JSON and CSV (the names are
   * their keys), Python and ParaView read them this way. A light-space technique reports
   * its clusters, a deep shadow map its nodes per texel and node chunks, a resolution-
   * matched technique its pages; shadow rays report none. Names are lower_snake_case and
   * the same every frame; GetStatistic() of a name the technique does not report is 0.
   */
  std::vector<std::string> GetStatisticNames() const;
  double GetStatistic(const std::string& name) const;
  ///@}
#ifndef __VTK_WRAP__
  /** Name and value of each statistic, in GetStatisticNames()'s order. */
  using Statistics = std::vector<std::pair<std::string, double>>;
  Statistics GetStatistics() const;
  /** The value of `name` among `statistics` (0 if absent). */
  static double FindStatistic(const Statistics& statistics, const std::string& name);
#endif

  // ---- Used by vtkDeepShadowVolumeMapper, not by applications ----

  // Prepare, Bind and the grid evaluation take the module's internal types: they are
  // vtkDeepShadowTechnique::Internals's (vtkDeepShadowTechniqueInternals.h, not installed).
  class Internals;

  /**
   * Source of the "Shadow" shader feature for the ray caster. `direct`: the technique's own
   * lookup even when cached, for receivers outside the volume's box (meshes), which the
   * cache's grid does not cover.
   */
  std::string GetShaderFeatureSource(bool direct = false) const;
  /**
   * Loop iterations its lookup takes per sample and shadowed light where that number is
   * fixed (PCF taps, CSSM offsets and photons, deep shadow map searches); 0 for caches and
   * feelers, whose loops vary with the scene. llvmpipe counts them against the loop budget
   * of a view ray (deepshadow::MaxRayIterations).
   */
  int GetLookupLoopIterations() const { return this->Cached ? 0 : this->LookupLoopIterations(); }
  /** Whether the lookup also needs the Feeler feature. */
  bool NeedsFeeler(bool direct = false) const
  {
    return (!this->Cached || direct) && this->LookupNeedsFeeler();
  }
  /** Shader features its lookup needs (FeelerColored for coloured feelers). */
  std::vector<std::string> GetLookupFeatures(bool direct = false) const;
  /** Shader features its build passes need besides VolumeSampling, Feeler, EmptySpace. */
  virtual std::vector<std::string> GetBuildFeatures() const;
  /** Undoes Internals::Bind. */
  void Unbind(bool direct = false);
  virtual void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkDeepShadowTechnique();
  ~vtkDeepShadowTechnique() override;

  // ---- What a technique provides ----

  /** Shadow-casting lights it can serve at once. */
  virtual int GetMaxShadowLights() const = 0;
  /** The parameters its structures depend on (the base adds the shared ones). */
  virtual std::vector<double> GetStructureKey() const = 0;
  /** The parameters only its lookup depends on (a cache depends on them too). */
  virtual std::vector<double> GetLookupKey() const { return {}; }
  virtual long long GetStructureBytes() const { return 0; }
  /**
   * Whether its structures can be built coarser while interacting
   * (vtkDeepShadowVolumeMapper::InteractiveShadowSubsampling); then GetBuildCoarsening()
   * says how much.
   */
  virtual bool CoarsensWhileInteracting() const { return false; }
#ifndef __VTK_WRAP__
  /** Appends this technique's statistics (see GetStatistics(); an override calls its parent's first). */
  virtual void AddStatistics(Statistics&) const {}
#endif
  /**
   * GLSL defining vec3 lightVisibility(int slot, vec3 position, vec3 toLight,
   * float lightDistance, vec3 receiverNormal) and its uniforms (its declarations part), for the ray
   * caster and the cache (receiverNormal: a mesh point's normal, zero for volume samples).
   */
  virtual std::string GetLookupSource() const = 0;
  virtual bool LookupNeedsFeeler() const { return false; }
  /** See GetLookupLoopIterations(). */
  virtual int LookupLoopIterations() const { return 0; }
  virtual void UnbindLookup() {}
  /**
   * The hooks that take the module's internal types (structures' allocation and build, the
   * lookup's binding) are a Hooks object (vtkDeepShadowTechniqueInternals.h) that each
   * concrete technique installs in its constructor with Internals::SetHooks.
   */
  class Hooks;

  // ---- Helpers for techniques ----

  /** How many times coarser this frame's structures are built: 1, or the
   * ShadowContext's RebuildCoarsening (see CoarsensWhileInteracting()). */
  int GetBuildCoarsening() const;

  /** Sets `member` to `value` clamped to [low, high] (NaN to low), warning if it clamped. */
  template <typename T>
  void SetClamped(const char* name, T& member, T value, T low, T high)
  {
    const T clamped = !(value >= low) ? low : (value > high ? high : value);
    if (!(clamped == value))
    {
      vtkWarningMacro(<< name << " " << value << " is outside [" << low << ", " << high
                      << "]; using " << clamped);
    }
    if (clamped != member)
    {
      member = clamped;
      this->Modified();
    }
  }

  /**
   * SetClamped with the range the technique registry gives `key` (deepshadow::
   * ShadowParameterInfo), so that the setters, the tool and Validate() share one range.
   */
  template <typename T>
  void SetClamped(const char* name, const char* key, T& member, T value)
  {
    double low = 0.0, high = 0.0;
    RegistryRange(key, low, high);
    this->SetClamped(name, member, value, static_cast<T>(low), static_cast<T>(high));
  }
  static void RegistryRange(const char* key, double& low, double& high);

  /**
   * Sets `member` to `value` if the technique registry allows it for `key` (a whole number
   * among its allowed values: CSSM offsets, rmsm's powers of two); else one vtkErrorMacro and
   * the old value kept.
   */
  void SetAllowed(const char* key, int& member, int value);

  /** The common part of GetParameters(). */
  void FillParameters(deepshadow::ShadowParameters& parameters) const;
  void ActivateFeelerTable();
  void DeactivateFeelerTable();

  double StepFactor = 1.0;
  double Threshold = 0.5;
  int ThresholdMode = AccumulatedThreshold;
  bool Cached = false;
  int ShadowVolumeSize = 128;
  vtkVolumeProperty* ShadowProperty = nullptr;
  int BuildCount = 0;
  double LastBuildMilliseconds = 0.0;
  std::string LastError;
  std::vector<std::string> LastPasses;

private:
  vtkDeepShadowTechnique(const vtkDeepShadowTechnique&) = delete;
  void operator=(const vtkDeepShadowTechnique&) = delete;

  std::unique_ptr<Internals> Impl;
};

#endif
