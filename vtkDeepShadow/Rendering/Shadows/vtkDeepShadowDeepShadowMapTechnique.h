/**
 * @class   vtkDeepShadowDeepShadowMapTechnique
 * @brief   Deep shadow maps with a guaranteed error bound (Lokovic and Veach; Ropinski et al.,
 *          section 3).
 *
 * Per light-space texel (see vtkDeepShadowLightSpaceTechnique), the visibility V(z) along the
 * texel's ray (transmittance from the light to depth z), sampled every feeler step and
 * compressed on the GPU into at most Layers nodes of a piecewise-linear V' with
 * |V' - V| <= Epsilon at every sample depth. A texel that needs more nodes is compressed
 * again with a doubled bound (Epsilon' = max(2 Epsilon', 1/1024)) until it fits: its error
 * grows instead of its shadow being cut off. The last build's statistics (nodes needed per
 * texel at Epsilon, average and maximum, texels that overflowed, the largest bound used) say
 * how many layers a scene needs, as Table 4 of Ropinski et al. does.
 *
 * Lookup: linear in depth between the two nodes that bracket the point, bilinear across the
 * four nearest texels. Coloured: one visibility per RGB channel, (1 - alpha (1 - colour)) per
 * sample, with nodes at shared depths. Memory: Layers x 8 bytes per texel (16 coloured).
 * deepshadow::DeepShadowMap (Core/Shadows/DeepShadowMap.h) is the CPU twin.
 */
#ifndef vtkDeepShadowDeepShadowMapTechnique_h
#define vtkDeepShadowDeepShadowMapTechnique_h

#include "vtkDeepShadowLightSpaceTechnique.h"
#include "vtkDeepShadowRenderingModule.h" // For export macro

#include <memory> // For std::unique_ptr

class VTKDEEPSHADOWRENDERING_EXPORT vtkDeepShadowDeepShadowMapTechnique
  : public vtkDeepShadowLightSpaceTechnique
{
public:
  static vtkDeepShadowDeepShadowMapTechnique* New();
  vtkTypeMacro(vtkDeepShadowDeepShadowMapTechnique, vtkDeepShadowLightSpaceTechnique);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The compression bound on |V' - V| ([0, 1], warned; 0 keeps every sample). The default,
   * 0.02, keeps the standard scenes' errors near those of exact shadow rays with 8 layers,
   * thin opaque rods included, while few texels overflow (Documentation/Measured.md: epsilon and layers).
   */
  void SetEpsilon(double epsilon);
  vtkGetMacro(Epsilon, double);
  ///@}

  ///@{
  /** Nodes stored per texel (default 8, as in Voreen; [1, 256], warned). */
  void SetLayers(int layers);
  vtkGetMacro(Layers, int);
  ///@}

  ///@{
  /**
   * Chunked node memory (paper 000, section 5): nodes go to chunks of this many, taken from a
   * pool as a texel needs them, so a texel holds any number of nodes while the pool lasts and
   * an empty one costs 4 bytes; 0 (the default) keeps Layers nodes per texel ([0, 64],
   * warned). Pictures are those of layers that never overflow.
   */
  void SetChunkNodes(int nodes);
  vtkGetMacro(ChunkNodes, int);
  ///@}

  ///@{
  /**
   * Chunked: the most memory one light's nodes may take, in MB; 0 (the default) is what
   * Layers fixed layers would take. The pool grows to what the maps need, up to this. A map
   * that needs more is built again with a doubled bound (GetEpsilonMax says which, warned).
   */
  void SetPoolMegabytes(double megabytes);
  vtkGetMacro(PoolMegabytes, double);
  ///@}

  ///@{
  /** Chunked: chunks in use after the last build, bytes per chunk, bytes of the pool. */
  long long GetChunksUsed() const;
  long long GetChunkBytes() const;
  long long GetPoolBytes() const;
  ///@}

  ///@{
  /** One visibility per colour channel (default off). */
  vtkSetMacro(Colored, bool);
  vtkGetMacro(Colored, bool);
  vtkBooleanMacro(Colored, bool);
  ///@}

  ///@{
  /** Statistics of the last build (over texels whose ray meets the volume). */
  double GetNodesAverage() const;
  int GetNodesMax() const;
  long long GetTexelsOverflowed() const;
  double GetEpsilonMax() const;
  ///@}

  deepshadow::ShadowParameters GetParameters() const override;
  void SetParameters(const deepshadow::ShadowParameters& parameters) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkDeepShadowDeepShadowMapTechnique();
  ~vtkDeepShadowDeepShadowMapTechnique() override;

  std::vector<double> GetStructureKey() const override;
  unsigned int GetTexelFormat() const override;
  bool DefersTexels() const override { return this->ChunkNodes == 0; }
  std::string GetBuildSource() const override;
  /** The shaders' defines of chunked node memory (none with fixed layers). */
  std::string ChunkDefines() const;
  /** After a chunked build: warns (once) about lights whose nodes the pool could not hold. */
  void SayPoolShort();
  /** After a fixed-layer build: warns (once while it lasts) when texels that overflowed had
   * their bound doubled to 1 or more, which keeps no shadow there. */
  void SayShadowLost();
  std::string GetMapLookupSource() const override;
  int LookupLoopIterations() const override;
  void BeginMapBuild() override;
  void EndMapBuild() override;
  long long GetStructureBytes() const override;
#ifndef __VTK_WRAP__
  /** The light-space ones and dsm_nodes_avg, dsm_nodes_max, dsm_texels_overflowed,
   * dsm_epsilon_max, chunks_used, chunk_bytes, pool_bytes. */
  void AddStatistics(Statistics& statistics) const override;
#endif
  void UnbindLookup() override;

  double Epsilon = 0.02;
  int Layers = 8;
  int ChunkNodes = 0;
  double PoolMegabytes = 0.0;
  bool Colored = false;

private:
  // Its hooks that take internal types (vtkDeepShadowTechniqueInternals.h), in the .cxx.
  class Hooks;

  vtkDeepShadowDeepShadowMapTechnique(const vtkDeepShadowDeepShadowMapTechnique&) = delete;
  void operator=(const vtkDeepShadowDeepShadowMapTechnique&) = delete;

  class NodeCounter; // reads back the build's node counts
  std::unique_ptr<NodeCounter> Stats;
  class Chunks;
  std::unique_ptr<Chunks> Pool;
};

#endif
