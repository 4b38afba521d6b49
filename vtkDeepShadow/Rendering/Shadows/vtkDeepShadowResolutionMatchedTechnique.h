/**
 * @class   vtkDeepShadowResolutionMatchedTechnique
 * @brief   Resolution-matched shadow maps (Lefohn, Sengupta and Owens, paper 004).
 *
 * A shadow map as fine as MaxResolution^2 texels per light face, of which only the pages of
 * PageSize^2 texels that the camera's pixels need are built, each at the level of detail
 * that matches the pixel's footprint in light space (eq. 1). Every frame a compute pass finds
 * the receiver each AnalysisDownsample-th pixel shows (the first occluder along its ray, the
 * shadow map's test), another the page it needs; requests are deduplicated on the GPU
 * (connected components, compaction, bitonic sort, unique) and read back. The base level
 * (4 x 4 pages) is always built. Pages are built in superpages (one face, one level, 1024^2
 * texels: a dispatch each) into slots of an AtlasSize^2 atlas, with an apron of their
 * neighbours' texels so that percentage-closer filtering has no seams; a page table names,
 * per cell of the finest level, the finest page built over it. With KeepPages (the paper's
 * cached mode, the default) built pages stay while the light, casters and parameters do:
 * a camera that moves builds only the pages it newly needs; without, each new view builds
 * every page it needs. A frame whose camera, lights and casters are the last one's runs no
 * analysis and builds nothing. When the pages do not fit the atlas, the finest level is
 * coarsened until they do.
 *
 * Casters: the volume through the shadow map's occluder test (accumulated opacity above the
 * threshold by default) and the casting meshes, traced in the same march as `shadowmap`'s.
 * Receivers that are not casters (a mesh that receives but casts nothing) and volume samples
 * behind the first occluder read the finest page built where they fall, at least the base
 * level. Bias and Filter are the shadow map's. Memory: the atlas (4 bytes a texel) and the
 * page table (4 bytes per finest cell per face).
 */
#ifndef vtkDeepShadowResolutionMatchedTechnique_h
#define vtkDeepShadowResolutionMatchedTechnique_h

#include "vtkDeepShadowRenderingModule.h" // For export macro
#include "vtkDeepShadowTechnique.h"

#include <memory> // For std::unique_ptr

class VTKDEEPSHADOWRENDERING_EXPORT vtkDeepShadowResolutionMatchedTechnique : public vtkDeepShadowTechnique
{
public:
  static vtkDeepShadowResolutionMatchedTechnique* New();
  vtkTypeMacro(vtkDeepShadowResolutionMatchedTechnique, vtkDeepShadowTechnique);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Depth bias in feeler steps (default 2), as vtkDeepShadowShadowMapTechnique's. */
  void SetBias(double bias);
  vtkGetMacro(Bias, double);
  ///@}

  ///@{
  /** Percentage-closer filter (vtkDeepShadowShadowMapTechnique::Filters; default 3x3). */
  void SetFilter(int filter);
  vtkGetMacro(Filter, int);
  ///@}

  ///@{
  /** Texels per page side: 16, 32 (default), 64 or 128; others are an error, the old value kept. */
  void SetPageSize(int size);
  vtkGetMacro(PageSize, int);
  ///@}

  ///@{
  /** Texels per side of the atlas the pages live in (default 1024; [64, 16384]). */
  void SetAtlasSize(int size);
  vtkGetMacro(AtlasSize, int);
  ///@}

  ///@{
  /**
   * Texels per side of the finest level, the virtual map (default 16384; a power of 2 from
   * 1024 to 32768; others are an error, the old value kept).
   */
  void SetMaxResolution(int size);
  vtkGetMacro(MaxResolution, int);
  ///@}

  ///@{
  /**
   * Every N-th pixel of the image, each way, asks for pages: 1, 2, 4 (default) or 8 (others
   * are an error, the old value kept). On the hybrid-sparse scene at 512^2, 4 loses nothing
   * against 1 (the shadow edges' RMSE against exact visibility is 0.0700 either way; 8:
   * 0.0732) and its analysis costs a sixteenth.
   */
  void SetAnalysisDownsample(int n);
  vtkGetMacro(AnalysisDownsample, int);
  ///@}

  ///@{
  /** Keep built pages across frames while light, casters and parameters stay (default on). */
  vtkSetMacro(KeepPages, bool);
  vtkGetMacro(KeepPages, bool);
  vtkBooleanMacro(KeepPages, bool);
  ///@}

  ///@{
  /**
   * The last analysis (it runs when the camera, the viewport, a light or a caster changed):
   * pixel requests (one per pixel and light whose receiver lies on a face), those left after
   * connected components, unique pages, pages it built (base level included; 0 when every
   * page was kept), superpages they were built in, pages resident, and the finest level used
   * (coarsened when the pages did not fit the atlas; the finest level is
   * log2(MaxResolution / PageSize)). GetAnalyses() counts the analyses run.
   */
  long long GetPagesRequested() const;
  long long GetRequestsAfterComponents() const;
  int GetPagesUnique() const;
  int GetPagesRendered() const;
  int GetSuperpages() const;
  int GetPagesResident() const;
  int GetFinestLevelUsed() const;
  int GetAnalyses() const;
  ///@}

  /** Bytes of the atlas. */
  long long GetAtlasBytes() const;

  deepshadow::ShadowParameters GetParameters() const override;
  void SetParameters(const deepshadow::ShadowParameters& parameters) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkDeepShadowResolutionMatchedTechnique();
  ~vtkDeepShadowResolutionMatchedTechnique() override;

  int GetMaxShadowLights() const override { return 4; }
  std::vector<double> GetStructureKey() const override;
  std::vector<double> GetLookupKey() const override;
  long long GetStructureBytes() const override;
#ifndef __VTK_WRAP__
  /** The last analysis (see GetPagesRequested()): pages_requested, requests_after_components,
   * pages_unique, pages_rendered, superpages, pages_resident, finest_level_used, analyses,
   * atlas_bytes. */
  void AddStatistics(Statistics& statistics) const override;
#endif
  std::string GetLookupSource() const override;
  int LookupLoopIterations() const override;
  void UnbindLookup() override;

  double Bias = 2.0;
  int Filter = 2; // 3x3
  int PageSize = 32;
  int AtlasSize = 1024;
  int MaxResolution = 16384;
  int AnalysisDownsample = 4;
  bool KeepPages = true;

private:
  class Hooks;
  class Pages;
  std::unique_ptr<Pages> State;

  vtkDeepShadowResolutionMatchedTechnique(const vtkDeepShadowResolutionMatchedTechnique&) = delete;
  void operator=(const vtkDeepShadowResolutionMatchedTechnique&) = delete;
};

#endif
