/**
 * @class   vtkDeepShadowRayTechnique
 * @brief   Shadow rays: a feeler from each sample to each light (Ropinski et al., section 3.1).
 *
 * Translucent (the default, "A"): the feeler multiplies (1 - opacity) of the samples it
 * crosses, opacity corrected for its step as on the view ray, and stops once less than
 * 1/512 of the light is left (EarlyTermination). Coloured: per colour channel
 * (1 - opacity (1 - colour)), a medium letting its own colour through. Opaque ("B"): the
 * light is blocked at the first sample above the threshold. Cached ("PP", see
 * vtkDeepShadowTechnique::SetCached): the feeler's answer is computed once per node of a 3D
 * shadow volume. Feelers skip empty blocks (exactly). Up to 8 shadow-casting lights.
 */
#ifndef vtkDeepShadowRayTechnique_h
#define vtkDeepShadowRayTechnique_h

#include "vtkDeepShadowRenderingModule.h" // For export macro
#include "vtkDeepShadowTechnique.h"

class VTKDEEPSHADOWRENDERING_EXPORT vtkDeepShadowRayTechnique : public vtkDeepShadowTechnique
{
public:
  static vtkDeepShadowRayTechnique* New();
  vtkTypeMacro(vtkDeepShadowRayTechnique, vtkDeepShadowTechnique);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Opaque ("B") instead of translucent ("A") feelers. Default off. */
  vtkSetMacro(Opaque, bool);
  vtkGetMacro(Opaque, bool);
  vtkBooleanMacro(Opaque, bool);
  ///@}

  ///@{
  /** A visibility per colour channel for translucent feelers. Default off. */
  vtkSetMacro(Colored, bool);
  vtkGetMacro(Colored, bool);
  vtkBooleanMacro(Colored, bool);
  ///@}

  ///@{
  /** Stop translucent feelers below 1/512 transmittance (default on; off is exact). */
  vtkSetMacro(EarlyTermination, bool);
  vtkGetMacro(EarlyTermination, bool);
  vtkBooleanMacro(EarlyTermination, bool);
  ///@}

  deepshadow::ShadowParameters GetParameters() const override;
  void SetParameters(const deepshadow::ShadowParameters& parameters) override;

protected:
  vtkDeepShadowRayTechnique();
  ~vtkDeepShadowRayTechnique() override = default;

  int GetMaxShadowLights() const override { return 8; }
  std::vector<double> GetStructureKey() const override;
  std::string GetLookupSource() const override;
  bool LookupNeedsFeeler() const override { return true; }

  bool Opaque = false;
  bool Colored = false;
  bool EarlyTermination = true;

private:
  // Its hooks that take internal types (vtkDeepShadowTechniqueInternals.h), in the .cxx.
  class Hooks;

  vtkDeepShadowRayTechnique(const vtkDeepShadowRayTechnique&) = delete;
  void operator=(const vtkDeepShadowRayTechnique&) = delete;
};

#endif
