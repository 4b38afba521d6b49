/**
 * @class   vtkDeepShadowStochasticShadowMapTechnique
 * @brief   Coloured stochastic shadow maps (CSSM, after McGuire and Enderton, for volumes).
 *
 * Per light-space texel (see vtkDeepShadowLightSpaceTechnique) a photon is traced through
 * the volume in segments (the samples of the texel's ray); in each segment it is stopped in
 * colour channel c with probability rho = opacity (1 - colour_c), decided against one random
 * threshold per segment, and the texel stores per channel the depth of the segment that
 * stopped it. The lookup averages, per channel, the tests "stopped beyond the point" over the
 * Offsets texel offsets around the nearest texel (7, 13 as in the paper, or 21) and the
 * Photons photons per texel: an unbiased, noisy estimate of the coloured transmittance that
 * more offsets smooth (and blur). Thresholds are hashes of texel, photon, segment and Seed:
 * images are reproducible. Always coloured; pair it with SetShadowProperty() to cast with
 * another transfer function. Memory: Photons x 16 bytes per texel.
 * deepshadow::StochasticShadowMap is the CPU twin.
 */
#ifndef vtkDeepShadowStochasticShadowMapTechnique_h
#define vtkDeepShadowStochasticShadowMapTechnique_h

#include "vtkDeepShadowLightSpaceTechnique.h"
#include "vtkDeepShadowRenderingModule.h" // For export macro

class VTKDEEPSHADOWRENDERING_EXPORT vtkDeepShadowStochasticShadowMapTechnique
  : public vtkDeepShadowLightSpaceTechnique
{
public:
  static vtkDeepShadowStochasticShadowMapTechnique* New();
  vtkTypeMacro(vtkDeepShadowStochasticShadowMapTechnique, vtkDeepShadowLightSpaceTechnique);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Texel offsets averaged by the lookup: 7, 13 (default) or 21; others are refused. */
  void SetOffsets(int offsets);
  vtkGetMacro(Offsets, int);
  ///@}

  ///@{
  /** Seed of the random thresholds (default 0). */
  vtkSetMacro(Seed, unsigned int);
  vtkGetMacro(Seed, unsigned int);
  ///@}

  ///@{
  /** Photons per texel (default 1; [1, 64], warned). */
  void SetPhotons(int photons);
  vtkGetMacro(Photons, int);
  ///@}

  deepshadow::ShadowParameters GetParameters() const override;
  void SetParameters(const deepshadow::ShadowParameters& parameters) override;
  std::vector<std::string> GetBuildFeatures() const override;

protected:
  vtkDeepShadowStochasticShadowMapTechnique();
  ~vtkDeepShadowStochasticShadowMapTechnique() override = default;

  std::vector<double> GetStructureKey() const override;
  std::vector<double> GetLookupKey() const override;
  unsigned int GetTexelFormat() const override;
  std::string GetBuildSource() const override;
  std::string GetMapLookupSource() const override;
  int LookupLoopIterations() const override;

  int Offsets = 13;
  unsigned int Seed = 0;
  int Photons = 1;

private:
  // Its hooks that take internal types (vtkDeepShadowTechniqueInternals.h), in the .cxx.
  class Hooks;

  vtkDeepShadowStochasticShadowMapTechnique(const vtkDeepShadowStochasticShadowMapTechnique&) = delete;
  void operator=(const vtkDeepShadowStochasticShadowMapTechnique&) = delete;
};

#endif
