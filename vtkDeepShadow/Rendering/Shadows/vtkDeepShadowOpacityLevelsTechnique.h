/**
 * @class   vtkDeepShadowOpacityLevelsTechnique
 * @brief   The low-memory deep shadow map of "Deep Shadow Maps from Volumetric Data on the
 *          GPU" ("dsm3"): depths at three opacity levels and the maximum opacity.
 *
 * Per light-space texel (see vtkDeepShadowLightSpaceTechnique) one RGBA texel: the depths at
 * which the opacity accumulated along the texel's ray crosses the three levels (10, 50 and
 * 90 % by default) and the maximum opacity reached. The lookup follows the paper: 0 before
 * the first depth, a smoothstep in depth from one level to the next, the maximum from the
 * last depth on (never above it); bilinear across the four nearest texels. Grey only.
 * Casting meshes (vtkDeepShadowPass) are steps, not volumes: the levels hold the volume
 * alone, and the meshes' crossings go into a second texel as at most two steps (see
 * deepshadow::SurfaceSteps); the visibility is the product of both.
 * Memory: 16 bytes per texel, 32 with casting meshes. deepshadow::OpacityLevelsShadow is
 * the CPU twin.
 */
#ifndef vtkDeepShadowOpacityLevelsTechnique_h
#define vtkDeepShadowOpacityLevelsTechnique_h

#include "vtkDeepShadowLightSpaceTechnique.h"
#include "vtkDeepShadowRenderingModule.h" // For export macro

class VTKDEEPSHADOWRENDERING_EXPORT vtkDeepShadowOpacityLevelsTechnique
  : public vtkDeepShadowLightSpaceTechnique
{
public:
  static vtkDeepShadowOpacityLevelsTechnique* New();
  vtkTypeMacro(vtkDeepShadowOpacityLevelsTechnique, vtkDeepShadowLightSpaceTechnique);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The three opacity levels, strictly increasing in (0, 1] (default 0.1, 0.5, 0.9). Other
   * values are refused with an error and the levels stay as they were.
   */
  void SetLevels(double first, double second, double third);
  const double* GetLevels() const { return this->Levels; }
  ///@}

  deepshadow::ShadowParameters GetParameters() const override;
  void SetParameters(const deepshadow::ShadowParameters& parameters) override;

protected:
  vtkDeepShadowOpacityLevelsTechnique();
  ~vtkDeepShadowOpacityLevelsTechnique() override = default;

  std::vector<double> GetStructureKey() const override;
  unsigned int GetTexelFormat() const override;
  std::string GetBuildSource() const override;
  std::string GetMapLookupSource() const override;

  double Levels[3] = { 0.1, 0.5, 0.9 };

private:
  // Its hooks that take internal types (vtkDeepShadowTechniqueInternals.h), in the .cxx.
  class Hooks;

  vtkDeepShadowOpacityLevelsTechnique(const vtkDeepShadowOpacityLevelsTechnique&) = delete;
  void operator=(const vtkDeepShadowOpacityLevelsTechnique&) = delete;
};

#endif
