/**
 * @class   vtkDeepShadowShadowMapTechnique
 * @brief   Shadow maps with percentage-closer filtering (Ropinski et al., section 3.2).
 *
 * Per light-space texel (see vtkDeepShadowLightSpaceTechnique), the depth of the first
 * sample above the threshold along the texel's ray. A sample is lit if its depth minus the
 * bias (Bias feeler steps) is not behind the stored depth; percentage-closer filtering
 * averages that test over the nearest texel (None), the 4 nearest with bilinear weights
 * (2x2), the 3x3 block (3x3) or a 12-tap Poisson disc of radius 2 texels: hard to
 * soft-looking shadows. Opaque occluders only: shadows are binary before filtering.
 * Memory: 4 bytes per texel.
 */
#ifndef vtkDeepShadowShadowMapTechnique_h
#define vtkDeepShadowShadowMapTechnique_h

#include "vtkDeepShadowLightSpaceTechnique.h"
#include "vtkDeepShadowRenderingModule.h" // For export macro

class VTKDEEPSHADOWRENDERING_EXPORT vtkDeepShadowShadowMapTechnique
  : public vtkDeepShadowLightSpaceTechnique
{
public:
  static vtkDeepShadowShadowMapTechnique* New();
  vtkTypeMacro(vtkDeepShadowShadowMapTechnique, vtkDeepShadowLightSpaceTechnique);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Depth bias in feeler steps (default 2); negative is clamped to 0 with a warning. */
  void SetBias(double bias);
  vtkGetMacro(Bias, double);
  ///@}

  ///@{
  /** Percentage-closer filter (default 3x3). */
  enum Filters
  {
    NoFilter = 0,
    PCF2x2 = 1,
    PCF3x3 = 2,
    PoissonDisc = 3
  };
  vtkSetClampMacro(Filter, int, NoFilter, PoissonDisc);
  vtkGetMacro(Filter, int);
  ///@}

  /**
   * The percentage-closer filter's GLSL (Shadows/ShadowMap.glsl with its filter and Poisson
   * disc defined from Core's tables), for `filter`; with `pages`, for resolution-matched
   * maps (SHADOW_MAP_PAGES).
   */
  static std::string GetFilterSource(int filter, bool pages = false);

  deepshadow::ShadowParameters GetParameters() const override;
  void SetParameters(const deepshadow::ShadowParameters& parameters) override;

protected:
  vtkDeepShadowShadowMapTechnique();
  ~vtkDeepShadowShadowMapTechnique() override = default;

  std::vector<double> GetStructureKey() const override;
  std::vector<double> GetLookupKey() const override;
  unsigned int GetTexelFormat() const override;
  std::string GetBuildSource() const override;
  std::string GetMapLookupSource() const override;
  int LookupLoopIterations() const override;

  double Bias = 2.0;
  int Filter = PCF3x3;

private:
  // Its hooks that take internal types (vtkDeepShadowTechniqueInternals.h), in the .cxx.
  class Hooks;

  vtkDeepShadowShadowMapTechnique(const vtkDeepShadowShadowMapTechnique&) = delete;
  void operator=(const vtkDeepShadowShadowMapTechnique&) = delete;
};

#endif
