/**
 * @class   vtkDeepShadowFourierOpacityMapTechnique
 * @brief   Fourier opacity maps (Jansen and Bavoil 2010, "fom"): the optical depth along
 *          each light-space texel's ray as a truncated Fourier series.
 *
 * A rival of the deep shadow map at a fixed number of bits per texel (see
 * deepshadow::FourierOpacityMap, its CPU twin, for the series). Per light-space texel (see
 * vtkDeepShadowLightSpaceTechnique) the ray's end and total optical depth and Terms
 * cosine-sine pairs, in (2 + 2 Terms) / 4 RGBA layers: 1, 3, 7 or 15 pairs are 16, 32, 64
 * or 128 bytes. A truncated series rings around sharp fronts of the medium; the lookup
 * clamps the optical depth to [0, total]. Casting meshes (vtkDeepShadowPass) are steps,
 * not extinction: one more layer holds them as at most two steps, as opacity levels keep
 * them. Grey only.
 */
#ifndef vtkDeepShadowFourierOpacityMapTechnique_h
#define vtkDeepShadowFourierOpacityMapTechnique_h

#include "vtkDeepShadowLightSpaceTechnique.h"
#include "vtkDeepShadowRenderingModule.h" // For export macro

class VTKDEEPSHADOWRENDERING_EXPORT vtkDeepShadowFourierOpacityMapTechnique
  : public vtkDeepShadowLightSpaceTechnique
{
public:
  static vtkDeepShadowFourierOpacityMapTechnique* New();
  vtkTypeMacro(vtkDeepShadowFourierOpacityMapTechnique, vtkDeepShadowLightSpaceTechnique);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Cosine-sine pairs per texel: 1, 3, 7 (default) or 15. Other values are refused with an
   * error and the count stays as it was.
   */
  void SetTerms(int terms);
  vtkGetMacro(Terms, int);
  ///@}

  deepshadow::ShadowParameters GetParameters() const override;
  void SetParameters(const deepshadow::ShadowParameters& parameters) override;

protected:
  vtkDeepShadowFourierOpacityMapTechnique();
  ~vtkDeepShadowFourierOpacityMapTechnique() override = default;

  std::vector<double> GetStructureKey() const override;
  unsigned int GetTexelFormat() const override;
  std::string GetBuildSource() const override;
  std::string GetMapLookupSource() const override;

  int Terms = 7;

private:
  // Its hooks that take internal types (vtkDeepShadowTechniqueInternals.h), in the .cxx.
  class Hooks;

  vtkDeepShadowFourierOpacityMapTechnique(const vtkDeepShadowFourierOpacityMapTechnique&) = delete;
  void operator=(const vtkDeepShadowFourierOpacityMapTechnique&) = delete;
};

#endif
