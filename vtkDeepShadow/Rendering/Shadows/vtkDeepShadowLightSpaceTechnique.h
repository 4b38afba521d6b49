/**
 * @class   vtkDeepShadowLightSpaceTechnique
 * @brief   Base of the techniques that store something per light-space texel.
 *
 * Shadow maps, deep shadow maps, opacity levels and stochastic shadow maps all see the
 * volume from each shadow-casting light (at most 4) through faces: one orthographic face
 * for a directional light (or a positional one farther than 1000 bounding radii), one
 * perspective face for a positional or spot light outside the volume's bounding sphere, a
 * cube of six faces for one inside it. Each face has MapSize x MapSize texels whose rays are
 * marched through the volume by a compute pass; depths along them are linear distances from
 * the face's near boundary, 32-bit floats (see Core/Shadows/LightSpace.h for why that keeps
 * its precision at any near/far ratio). The texels of all faces of all lights live in one 2D
 * array texture, a technique-defined number of layers per face.
 */
#ifndef vtkDeepShadowLightSpaceTechnique_h
#define vtkDeepShadowLightSpaceTechnique_h

#include "vtkDeepShadowRenderingModule.h" // For export macro
#include "vtkDeepShadowTechnique.h"

#include <memory> // For std::unique_ptr
#include <vector> // For cluster counts

class vtkDeepShadowBrickExchange;

class VTKDEEPSHADOWRENDERING_EXPORT vtkDeepShadowLightSpaceTechnique : public vtkDeepShadowTechnique
{
public:
  vtkTypeMacro(vtkDeepShadowLightSpaceTechnique, vtkDeepShadowTechnique);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Texels per side of each face (default 512; [1, 65536], warned). Above the GL's texture
   * limit is an error at render time (the volume is then drawn without shadows).
   */
  void SetMapSize(int size);
  vtkGetMacro(MapSize, int);
  ///@}

  ///@{
  /**
   * Clustered maps (paper 000, section 4): at most this many faces per light, each fitted to
   * a cluster of the volume's objects (groups of non-empty blocks; the casting meshes' box is
   * one more), instead of one face over the whole box (0, the default; [0, 8], warned). A
   * lookup multiplies what every cluster casts along the light's ray. Sparse volumes get
   * their texels where the objects are. Needs empty blocks (empty-space skipping on, a
   * composite or MIP blend of one component, no separate shadow property); without them, and
   * for a positional light inside the casters' bounding sphere, one face (or cube) as before.
   */
  void SetClusters(int clusters);
  vtkGetMacro(Clusters, int);
  ///@}

  ///@{
  /**
   * Clustering's distance threshold d0: objects whose light-space extents differ by more
   * than this (in half-widths of the unclustered face) get clusters of their own while
   * Clusters allows (default 0.25; [0, 2], warned).
   */
  void SetClusterDistance(double distance);
  vtkGetMacro(ClusterDistance, double);
  ///@}

  /**
   * Texels per side of the maps in use: MapSize, or MapSize / N (down to 64) when rebuilt
   * while interacting with coarser shadows (vtkDeepShadowVolumeMapper::
   * InteractiveShadowSubsampling N); 0 before the first build. The statistic "map_size".
   */
  int GetBuiltMapSize() const;

  /** Clustered faces per shadowed light in the last frame (0 when not clustered). */
  std::vector<int> GetClusterCounts() const;

  ///@{
  /**
   * The bricks of one volume drawn by several processes (see vtkDeepShadowBrickExchange):
   * with an exchange of more than one brick, this brick's lookups are multiplied by the
   * transmittance of the bricks between it and each light. None by default.
   */
  void SetBrickExchange(vtkDeepShadowBrickExchange* exchange);
  vtkDeepShadowBrickExchange* GetBrickExchange();
  ///@}

  /** Adds the map size to the shared parameters. */
  void SetParameters(const deepshadow::ShadowParameters& parameters) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkDeepShadowLightSpaceTechnique();
  ~vtkDeepShadowLightSpaceTechnique() override;

  // ---- What a light-space technique provides ----

  /** GL internal format of its texels (GL_R32F, GL_RGBA8, GL_RG32F, GL_RGBA16 or GL_RGBA32F). */
  virtual unsigned int GetTexelFormat() const = 0;
  /** Its build: the parts Dec and Texel of vtkDeepShadowLightSpaceCS.glsl's runtime Build. */
  virtual std::string GetBuildSource() const = 0;
  /** Its lookup, over Shadows/LightSpace.glsl. */
  virtual std::string GetMapLookupSource() const = 0;
  /** Whether its build defers texels to a second dispatch (deferTexel() in the build). */
  virtual bool DefersTexels() const { return false; }
  /** Around the build pass's dispatches (the deep shadow map gathers statistics). */
  virtual void BeginMapBuild() {}
  virtual void EndMapBuild() {}
  /**
   * Its layers per face and its build and lookup uniforms take internal types: they are
   * Hooks's (vtkDeepShadowTechniqueInternals.h), which builds the maps.
   */
  class Hooks;

  // ---- vtkDeepShadowTechnique ----
  int GetMaxShadowLights() const override { return 4; }
  /** Maps N times smaller while interacting, when a light moved past the lag. */
  bool CoarsensWhileInteracting() const override { return true; }
  long long GetStructureBytes() const override;
#ifndef __VTK_WRAP__
  /** clusters (faces over all shadowed lights, 0 unclustered), cluster_texels and map_size. */
  void AddStatistics(Statistics& statistics) const override;
#endif
  std::string GetLookupSource() const override;
  void UnbindLookup() override;

  /**
   * Radius of the casters' bounding sphere that the faces were fitted to in the last frame
   * (with other bricks, their union's): every depth the faces see is below 2.06 of it. The
   * build and the lookup get deepshadow::LightDepthRange of it as u_lightDepthRange, for
   * techniques that store depths as fractions of it (dsm-fixed, slices).
   */
  double GetCasterRadius() const;

  /** Faces of shadowed light `slot` in the last frame (a cube: 6; clustered: one per cluster). */
  int GetFaceCount(int slot) const;

  /** The light-space fields of GetParameters(): map size and clustering. */
  void FillMapParameters(deepshadow::ShadowParameters& parameters) const;

  int MapSize = 512;
  int Clusters = 0;
  double ClusterDistance = 0.25;

private:
  vtkDeepShadowLightSpaceTechnique(const vtkDeepShadowLightSpaceTechnique&) = delete;
  void operator=(const vtkDeepShadowLightSpaceTechnique&) = delete;

  class Maps;
  std::unique_ptr<Maps> LightMaps;
};

#endif
