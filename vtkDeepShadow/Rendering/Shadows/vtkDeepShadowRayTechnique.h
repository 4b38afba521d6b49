/**
 * @class   vtkDeepShadowRayTechnique
 * @brief   Shadow rays: a feeler from each sample to each light (Ropinski et al., section 3.1).
 *
 * Translucent (the default, "A"): the feeler multiplies (1 - opacity) of the samples it
 * crosses, opacity corrected for its step as on the view ray, and stops once less than
 * 1/512 of the light is left (EarlyTermination). Opaque ("B"): the light is blocked at the
 * first sample above the threshold. Cached ("PP"): the feeler's answer is computed once per
 * node of a 3D shadow volume over the volume's box (ShadowVolumeSize nodes along its longest
 * axis) and fetched trilinearly; rebuilt only when the light, the data, the transform, the
 * opacity function or the parameters change. Feelers skip empty blocks (exactly).
 */
#ifndef vtkDeepShadowRayTechnique_h
#define vtkDeepShadowRayTechnique_h

#include "vtkDeepShadowRenderingModule.h" // For export macro
#include "vtkDeepShadowTechnique.h"

#include <memory> // For std::unique_ptr

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
  /** Cache the feelers' answers in a 3D shadow volume ("PP"). Default off. */
  vtkSetMacro(Cached, bool);
  vtkGetMacro(Cached, bool);
  vtkBooleanMacro(Cached, bool);
  ///@}

  ///@{
  /**
   * Shadow-volume nodes along the volume's longest axis, at most as many as the data has
   * (default 128; [2, 2048], warned).
   */
  void SetShadowVolumeSize(int size);
  vtkGetMacro(ShadowVolumeSize, int);
  ///@}

  ///@{
  /** Stop translucent feelers below 1/512 transmittance (default on; off is exact). */
  vtkSetMacro(EarlyTermination, bool);
  vtkGetMacro(EarlyTermination, bool);
  vtkBooleanMacro(EarlyTermination, bool);
  ///@}

  deepshadow::ShadowParameters GetParameters() const override;

  bool Prepare(deepshadow::ShadowContext& context) override;
  std::string GetShaderFeatureSource() const override;
  bool NeedsFeeler() const override { return !this->Cached; }
  void Bind(deepshadow::UniformSink& sink, const deepshadow::ShadowContext& context) override;
  void Unbind() override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkDeepShadowRayTechnique();
  ~vtkDeepShadowRayTechnique() override;

  bool Opaque = false;
  bool Cached = false;
  int ShadowVolumeSize = 128;
  bool EarlyTermination = true;

private:
  vtkDeepShadowRayTechnique(const vtkDeepShadowRayTechnique&) = delete;
  void operator=(const vtkDeepShadowRayTechnique&) = delete;

  class Cache;
  std::unique_ptr<Cache> ShadowCache;
};

#endif
