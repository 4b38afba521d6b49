/**
 * @class   vtkDeepShadowOpacitySlicesTechnique
 * @brief   Uniform opacity slices ("slices"; opacity shadow maps, Kim and Neumann 2001): each
 *          light-space texel's transmittance at evenly spaced depths, 8 bits each.
 *
 * A rival of the deep shadow map at a fixed number of bits per texel (see
 * deepshadow::OpacitySlicesShadow, its CPU twin): per light-space texel (see
 * vtkDeepShadowLightSpaceTechnique) the transmittance at Slices depths evenly spaced over the
 * light's depth range, linear between them. 8, 16, 32 (default) or 64 slices are 8 to 64
 * bytes per texel. The lookup reads the two slices around the point, no search; a front
 * between two slices is smeared over the slice's width. Grey only.
 */
#ifndef vtkDeepShadowOpacitySlicesTechnique_h
#define vtkDeepShadowOpacitySlicesTechnique_h

#include "vtkDeepShadowLightSpaceTechnique.h"
#include "vtkDeepShadowRenderingModule.h" // For export macro

class VTKDEEPSHADOWRENDERING_EXPORT vtkDeepShadowOpacitySlicesTechnique
  : public vtkDeepShadowLightSpaceTechnique
{
public:
  static vtkDeepShadowOpacitySlicesTechnique* New();
  vtkTypeMacro(vtkDeepShadowOpacitySlicesTechnique, vtkDeepShadowLightSpaceTechnique);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Slices per texel: 8, 16, 32 (default) or 64, a byte each. Other values are refused with
   * an error and the count stays as it was.
   */
  void SetSlices(int slices);
  vtkGetMacro(Slices, int);
  ///@}

  deepshadow::ShadowParameters GetParameters() const override;
  void SetParameters(const deepshadow::ShadowParameters& parameters) override;

protected:
  vtkDeepShadowOpacitySlicesTechnique();
  ~vtkDeepShadowOpacitySlicesTechnique() override = default;

  std::vector<double> GetStructureKey() const override;
  unsigned int GetTexelFormat() const override;
  std::string GetBuildSource() const override;
  std::string GetMapLookupSource() const override;
  int Slices = 32;

private:
  // Its hooks that take internal types (vtkDeepShadowTechniqueInternals.h), in the .cxx.
  class Hooks;

  vtkDeepShadowOpacitySlicesTechnique(const vtkDeepShadowOpacitySlicesTechnique&) = delete;
  void operator=(const vtkDeepShadowOpacitySlicesTechnique&) = delete;
};

#endif
