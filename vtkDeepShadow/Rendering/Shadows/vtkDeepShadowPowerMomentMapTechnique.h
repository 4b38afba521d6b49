/**
 * @class   vtkDeepShadowPowerMomentMapTechnique
 * @brief   Power-moment transmittance (MBOIT, Muenstermann et al. 2018, "moments"): the
 *          optical depth along each light-space texel's ray as its total and power moments.
 *
 * A rival of the deep shadow map at a fixed number of bits per texel (see
 * deepshadow::PowerMomentMap, its CPU twin, for the reconstruction). Per light-space texel
 * (see vtkDeepShadowLightSpaceTechnique) the ray's end, its total optical depth and Moments
 * normalized power moments of depth, in (2 + Moments) / 4 RGBA32F layers: 2, 4 or 6 moments
 * are 16, 32 or 32 bytes. Moments say where the optical depth lies, not its shape: a front
 * is smeared over a fraction of the ray. Casting meshes (vtkDeepShadowPass) are steps, not
 * extinction: one more layer holds them as at most two steps, as opacity levels keep them.
 * Grey only.
 */
#ifndef vtkDeepShadowPowerMomentMapTechnique_h
#define vtkDeepShadowPowerMomentMapTechnique_h

#include "vtkDeepShadowLightSpaceTechnique.h"
#include "vtkDeepShadowRenderingModule.h" // For export macro

class VTKDEEPSHADOWRENDERING_EXPORT vtkDeepShadowPowerMomentMapTechnique
  : public vtkDeepShadowLightSpaceTechnique
{
public:
  static vtkDeepShadowPowerMomentMapTechnique* New();
  vtkTypeMacro(vtkDeepShadowPowerMomentMapTechnique, vtkDeepShadowLightSpaceTechnique);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Power moments per texel: 2, 4 or 6 (default). Other values are refused with an error and
   * the count stays as it was.
   */
  void SetMoments(int moments);
  vtkGetMacro(Moments, int);
  ///@}

  deepshadow::ShadowParameters GetParameters() const override;
  void SetParameters(const deepshadow::ShadowParameters& parameters) override;

protected:
  vtkDeepShadowPowerMomentMapTechnique();
  ~vtkDeepShadowPowerMomentMapTechnique() override = default;

  std::vector<double> GetStructureKey() const override;
  unsigned int GetTexelFormat() const override;
  std::string GetBuildSource() const override;
  std::string GetMapLookupSource() const override;

  int Moments = 6;

private:
  // Its hooks that take internal types (vtkDeepShadowTechniqueInternals.h), in the .cxx.
  class Hooks;
  // The defines both GLSL sources start with.
  std::string GetDefines() const;

  vtkDeepShadowPowerMomentMapTechnique(const vtkDeepShadowPowerMomentMapTechnique&) = delete;
  void operator=(const vtkDeepShadowPowerMomentMapTechnique&) = delete;
};

#endif
