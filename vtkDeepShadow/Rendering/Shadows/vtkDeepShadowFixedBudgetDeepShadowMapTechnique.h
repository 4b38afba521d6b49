/**
 * @class   vtkDeepShadowFixedBudgetDeepShadowMapTechnique
 * @brief   Deep shadow maps at a fixed memory budget ("dsm-fixed"): per light-space texel
 *          the smallest error bound whose nodes fit a number of bits.
 *
 * The deep shadow map's compression (see vtkDeepShadowDeepShadowMapTechnique) given Bits per
 * texel instead of an error bound (see deepshadow::FixedBudgetDeepShadowMap, its CPU twin):
 * Bits / 32 nodes of a 16-bit depth (unorm over the light's depth range) and a 16-bit
 * visibility, the first of them exact where the ray first meets something absorbing; each
 * texel's bound is found by bisection (the finest that fits). 64, 128, 256 (default) or 512
 * bits are 2, 4, 8 or 16 nodes. Memory is known before the build; the lookup is a loop over
 * the nodes, no search (on a CPU rasterizer it stops at the first beyond the point). Casting meshes (vtkDeepShadowPass) are steps among the nodes.
 * Grey only.
 */
#ifndef vtkDeepShadowFixedBudgetDeepShadowMapTechnique_h
#define vtkDeepShadowFixedBudgetDeepShadowMapTechnique_h

#include "vtkDeepShadowLightSpaceTechnique.h"
#include "vtkDeepShadowRenderingModule.h" // For export macro

class VTKDEEPSHADOWRENDERING_EXPORT vtkDeepShadowFixedBudgetDeepShadowMapTechnique
  : public vtkDeepShadowLightSpaceTechnique
{
public:
  static vtkDeepShadowFixedBudgetDeepShadowMapTechnique* New();
  vtkTypeMacro(vtkDeepShadowFixedBudgetDeepShadowMapTechnique, vtkDeepShadowLightSpaceTechnique);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Bits per texel: 64, 128, 256 (default) or 512, 32 per node. Other values are refused
   * with an error and the budget stays as it was.
   */
  void SetBits(int bits);
  vtkGetMacro(Bits, int);
  ///@}

  deepshadow::ShadowParameters GetParameters() const override;
  void SetParameters(const deepshadow::ShadowParameters& parameters) override;

protected:
  vtkDeepShadowFixedBudgetDeepShadowMapTechnique();
  ~vtkDeepShadowFixedBudgetDeepShadowMapTechnique() override = default;

  std::vector<double> GetStructureKey() const override;
  unsigned int GetTexelFormat() const override;
  std::string GetBuildSource() const override;
  std::string GetMapLookupSource() const override;
  /** The nodes per texel, and the GLSL that says so. */
  int GetNodes() const { return this->Bits / 32; }
  std::string NodesDefine() const;

  int Bits = 256;

private:
  // Its hooks that take internal types (vtkDeepShadowTechniqueInternals.h), in the .cxx.
  class Hooks;

  vtkDeepShadowFixedBudgetDeepShadowMapTechnique(const vtkDeepShadowFixedBudgetDeepShadowMapTechnique&) = delete;
  void operator=(const vtkDeepShadowFixedBudgetDeepShadowMapTechnique&) = delete;
};

#endif
