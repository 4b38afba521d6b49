/**
 * @class   vtkDeepShadowTechnique
 * @brief   A shadow technique of vtkDeepShadowVolumeMapper: how the volume shadows itself.
 *
 * Set one on the mapper with vtkDeepShadowVolumeMapper::SetShadowTechnique(). A technique
 * knows its light-space pass (the shadow structure it builds per shadow-casting light), its
 * lookup shader code, its CPU twin (GetParameters() feeds deepshadow::MakeLightShadow) and
 * its memory; the mapper knows none of that. Structures are rebuilt only when what they
 * depend on changed: the light, the volume's data or transform, the opacity function, the
 * sample distance or the technique's parameters; never because the camera moved (a light
 * that follows the camera, like the headlight, does change). GetBuildCount() counts builds.
 *
 * Every light with vtkLight::ShadowAttenuation > 0 casts shadows (VTK's default is 1); a
 * light's diffuse and specular light is scaled by 1 - attenuation * (1 - visibility). Ambient
 * light is never shadowed. An unshaded volume (vtkVolumeProperty::ShadeOff) with a technique
 * is lit isotropically so that it can receive shadows.
 *
 * Parameters shared by the techniques: the step of feelers and light rays as a factor of the
 * view ray's sample distance, and the threshold that makes a sample an opaque occluder (for
 * opaque rays and shadow maps), on the opacity or on the normalized scalar.
 */
#ifndef vtkDeepShadowTechnique_h
#define vtkDeepShadowTechnique_h

#include "vtkDeepShadowRenderingModule.h" // For export macro
#include "vtkObject.h"

#include <memory> // For std::unique_ptr
#include <string> // For std::string

class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

namespace deepshadow
{
class ComputeProgram;
struct ShadowContext;
struct ShadowParameters;
class UniformSink;
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
   * Where a sample becomes an opaque occluder (opaque rays, shadow maps): its opacity, or its
   * scalar normalized to [0, 1] over the data range, exceeds this (default 0.5). Values
   * outside [0, 1] are clamped with a warning.
   */
  void SetThreshold(double threshold);
  vtkGetMacro(Threshold, double);
  enum ThresholdModes
  {
    OpacityThreshold = 0,
    ScalarThreshold = 1
  };
  vtkSetClampMacro(ThresholdMode, int, OpacityThreshold, ScalarThreshold);
  vtkGetMacro(ThresholdMode, int);
  void SetThresholdModeToOpacity() { this->SetThresholdMode(OpacityThreshold); }
  void SetThresholdModeToScalar() { this->SetThresholdMode(ScalarThreshold); }
  ///@}

  /** The parameters of the CPU twin (deepshadow::MakeLightShadow). */
  virtual deepshadow::ShadowParameters GetParameters() const = 0;
  /** none, rays, rays-opaque, rays-cached, rays-opaque-cached, shadowmap. */
  std::string GetName() const;

  ///@{
  /** Observability: structures built, time of the last build (GL finished), memory. */
  vtkGetMacro(BuildCount, int);
  vtkGetMacro(LastBuildMilliseconds, double);
  long long GetShadowBytes() const;
  const std::string& GetLastError() const { return this->LastError; }
  ///@}

  // ---- Used by vtkDeepShadowVolumeMapper, not by applications ----

  /** Brings the shadow structures up to date; false (and GetLastError()) on failure. */
  virtual bool Prepare(deepshadow::ShadowContext& context);
  /** Source of the "Shadow" shader feature for the ray caster. */
  virtual std::string GetShaderFeatureSource() const = 0;
  /** Whether the ray caster also needs the Feeler feature. */
  virtual bool NeedsFeeler() const { return false; }
  /** Sets the lookup's uniforms and binds its textures on the ray caster's program. */
  virtual void Bind(deepshadow::UniformSink& sink, const deepshadow::ShadowContext& context);
  virtual void Unbind();
  virtual void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkDeepShadowTechnique();
  ~vtkDeepShadowTechnique() override;

  /** The common part of GetParameters(). */
  void FillParameters(deepshadow::ShadowParameters& parameters) const;

  /** World step of feelers and light rays for the current context. */
  double FeelerStep(const deepshadow::ShadowContext& context) const;
  /** The Feeler feature's uniforms (table bound by Prepare/Bind). */
  void SetFeelerUniforms(deepshadow::UniformSink& sink, const deepshadow::ShadowContext& context,
    bool skipEmpty) const;
  /** Activates the feeler table's texture unit (Prepare does it for builds, Bind for lookups). */
  void ActivateFeelerTable();
  void DeactivateFeelerTable();

  /**
   * Starts a build pass: composes `shaderTemplate` with the volume-sampling, empty-space and
   * feeler features, compiles it into `program` if needed, binds the volume, block map and
   * feeler table, and sets their uniforms. False (and LastError) if it does not compile.
   */
  bool BeginBuildPass(deepshadow::ComputeProgram& program, const char* shaderTemplate,
    const deepshadow::ShadowContext& context);
  /** Ends it: waits for the GL, unbinds, and records `count` structures built. */
  void EndBuildPass(const deepshadow::ShadowContext& context, int count);

  double StepFactor = 1.0;
  double Threshold = 0.5;
  int ThresholdMode = OpacityThreshold;
  int BuildCount = 0;
  double LastBuildMilliseconds = 0.0;
  long long StructureBytes = 0; // set by subclasses
  std::string LastError;

private:
  double BuildStart = 0.0;
  vtkDeepShadowTechnique(const vtkDeepShadowTechnique&) = delete;
  void operator=(const vtkDeepShadowTechnique&) = delete;

  class FeelerTable;
  std::unique_ptr<FeelerTable> Feeler;
};

#endif
