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
 * the nodes, no search (on a CPU rasterizer it stops at the first beyond the point). Casting
 * meshes (vtkDeepShadowPass) are steps among the nodes. Grey only.
 *
 * Or an error instead of a budget (SetError): the build counts, per texel whose ray absorbs
 * something, the nodes it needs within the error, and the map takes as many nodes as 99 % of
 * those texels need (rounded up to even, 2 to 32); the others get the finest bound that many
 * fit. When that count changes, the maps are laid out again and built again in the same
 * frame. Statistics: fixed_nodes, texel_bits (as built) and, with an error, fixed_nodes_beyond
 * (the share of texels that needed more).
 */
#ifndef vtkDeepShadowFixedBudgetDeepShadowMapTechnique_h
#define vtkDeepShadowFixedBudgetDeepShadowMapTechnique_h

#include "vtkDeepShadowLightSpaceTechnique.h"
#include "vtkDeepShadowRenderingModule.h" // For export macro

#include <memory> // For std::unique_ptr

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

  ///@{
  /**
   * An error bound instead of Bits (0, the default: Bits decides): nodes per texel from the
   * 99th percentile of what the texels need to stay within it. [0, 0.5]; other values are
   * refused with an error.
   */
  void SetError(double error);
  vtkGetMacro(Error, double);
  ///@}

  /** Nodes per texel of the maps: Bits / 32, or what the last build found for Error. */
  int GetNodes() const;

  deepshadow::ShadowParameters GetParameters() const override;
  void SetParameters(const deepshadow::ShadowParameters& parameters) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkDeepShadowFixedBudgetDeepShadowMapTechnique();
  ~vtkDeepShadowFixedBudgetDeepShadowMapTechnique() override;

  std::vector<double> GetStructureKey() const override;
  unsigned int GetTexelFormat() const override;
  std::string GetBuildSource() const override;
  std::string GetMapLookupSource() const override;
  /** The GLSL that says how many nodes per texel. */
  std::string NodesDefine() const;
#ifndef __VTK_WRAP__
  void AddStatistics(Statistics& statistics) const override;
#endif
  void BeginMapBuild() override;
  void EndMapBuild() override;

  int Bits = 256;
  double Error = 0.0;

private:
  // Its hooks that take internal types (vtkDeepShadowTechniqueInternals.h), in the .cxx.
  class Hooks;
  // With an error: the build's node counts (GPU buffer), per slot the last ones read, and the
  // nodes they asked for.
  class Counts;
  std::unique_ptr<Counts> NodeCounts;

  vtkDeepShadowFixedBudgetDeepShadowMapTechnique(const vtkDeepShadowFixedBudgetDeepShadowMapTechnique&) = delete;
  void operator=(const vtkDeepShadowFixedBudgetDeepShadowMapTechnique&) = delete;
};

#endif
