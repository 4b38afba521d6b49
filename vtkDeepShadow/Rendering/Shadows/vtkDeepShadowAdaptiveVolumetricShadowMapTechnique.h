/**
 * @class   vtkDeepShadowAdaptiveVolumetricShadowMapTechnique
 * @brief   Adaptive volumetric shadow maps (Salvi et al. 2010, "avsm"): each light-space
 *          texel's transmittance as a fixed number of nodes.
 *
 * A rival of the deep shadow map at a fixed number of nodes per texel (see
 * deepshadow::AdaptiveVolumetricShadowMap, its CPU twin): per light-space texel (see
 * vtkDeepShadowLightSpaceTechnique) Nodes (depth, transmittance) pairs, linear between them,
 * built front to back and compressed by removing the node whose triangle with its
 * neighbours has the smallest area whenever one too many arrives. 2, 4, 8 or 16 nodes are 16,
 * 32, 64 or 128 bytes per texel. The lookup is a fixed loop over the nodes. Unlike a deep
 * shadow map's, its error has no bound. Casting meshes (vtkDeepShadowPass) are steps beside
 * the nodes, one more layer, as opacity levels keep them. Grey only.
 */
#ifndef vtkDeepShadowAdaptiveVolumetricShadowMapTechnique_h
#define vtkDeepShadowAdaptiveVolumetricShadowMapTechnique_h

#include "vtkDeepShadowLightSpaceTechnique.h"
#include "vtkDeepShadowRenderingModule.h" // For export macro

class VTKDEEPSHADOWRENDERING_EXPORT vtkDeepShadowAdaptiveVolumetricShadowMapTechnique
  : public vtkDeepShadowLightSpaceTechnique
{
public:
  static vtkDeepShadowAdaptiveVolumetricShadowMapTechnique* New();
  vtkTypeMacro(vtkDeepShadowAdaptiveVolumetricShadowMapTechnique, vtkDeepShadowLightSpaceTechnique);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Nodes per texel: 2, 4, 8 (default) or 16. Other values are refused with an error and
   * the count stays as it was.
   */
  void SetNodes(int nodes);
  vtkGetMacro(Nodes, int);
  ///@}

  deepshadow::ShadowParameters GetParameters() const override;
  void SetParameters(const deepshadow::ShadowParameters& parameters) override;

protected:
  vtkDeepShadowAdaptiveVolumetricShadowMapTechnique();
  ~vtkDeepShadowAdaptiveVolumetricShadowMapTechnique() override = default;

  std::vector<double> GetStructureKey() const override;
  unsigned int GetTexelFormat() const override;
  std::string GetBuildSource() const override;
  std::string GetMapLookupSource() const override;

  int Nodes = 8;

private:
  // Its hooks that take internal types (vtkDeepShadowTechniqueInternals.h), in the .cxx.
  class Hooks;

  vtkDeepShadowAdaptiveVolumetricShadowMapTechnique(const vtkDeepShadowAdaptiveVolumetricShadowMapTechnique&) = delete;
  void operator=(const vtkDeepShadowAdaptiveVolumetricShadowMapTechnique&) = delete;
};

#endif
