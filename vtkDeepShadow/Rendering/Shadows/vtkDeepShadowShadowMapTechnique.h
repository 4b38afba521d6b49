/**
 * @class   vtkDeepShadowShadowMapTechnique
 * @brief   Shadow maps with percentage-closer filtering (Ropinski et al., section 3.2).
 *
 * Per shadow-casting light (at most 4), a light-space map holds the depth of the first
 * sample above the threshold along each texel's ray: one orthographic face for a directional
 * light, one perspective face for a positional or spot light outside the volume's bounding
 * sphere, a cube of six faces for one inside it. A sample is lit if its depth minus the bias
 * (Bias feeler steps) is not behind the stored depth; percentage-closer filtering averages
 * that test over the nearest texel (None), the 4 nearest with bilinear weights (2x2), the
 * 3x3 block (3x3) or a 12-tap Poisson disc of radius 2 texels: hard to soft-looking shadows.
 * Opaque occluders only: shadows are binary before filtering. Maps are rebuilt only when the
 * light, data, transform, opacity function or the build parameters change.
 */
#ifndef vtkDeepShadowShadowMapTechnique_h
#define vtkDeepShadowShadowMapTechnique_h

#include "vtkDeepShadowRenderingModule.h" // For export macro
#include "vtkDeepShadowTechnique.h"

#include <memory> // For std::unique_ptr

class VTKDEEPSHADOWRENDERING_EXPORT vtkDeepShadowShadowMapTechnique : public vtkDeepShadowTechnique
{
public:
  static vtkDeepShadowShadowMapTechnique* New();
  vtkTypeMacro(vtkDeepShadowShadowMapTechnique, vtkDeepShadowTechnique);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Texels per side of each face (default 512). Below 1 is clamped to 1 with a warning;
   * above the GL's texture limit is an error at render time (the volume is then drawn
   * without shadows).
   */
  void SetMapSize(int size);
  vtkGetMacro(MapSize, int);
  ///@}

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

  deepshadow::ShadowParameters GetParameters() const override;

  bool Prepare(deepshadow::ShadowContext& context) override;
  std::string GetShaderFeatureSource() const override;
  void Bind(deepshadow::UniformSink& sink, const deepshadow::ShadowContext& context) override;
  void Unbind() override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkDeepShadowShadowMapTechnique();
  ~vtkDeepShadowShadowMapTechnique() override;

  int MapSize = 512;
  double Bias = 2.0;
  int Filter = PCF3x3;

private:
  vtkDeepShadowShadowMapTechnique(const vtkDeepShadowShadowMapTechnique&) = delete;
  void operator=(const vtkDeepShadowShadowMapTechnique&) = delete;

  class Maps;
  std::unique_ptr<Maps> ShadowMaps;
};

#endif
