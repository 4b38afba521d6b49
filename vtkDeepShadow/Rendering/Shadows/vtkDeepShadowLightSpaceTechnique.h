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

  /** GL internal format of its texels (GL_R32F, GL_RG32F or GL_RGBA32F). */
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
  long long GetStructureBytes() const override;
  std::string GetLookupSource() const override;
  void UnbindLookup() override;

  int MapSize = 512;

private:
  vtkDeepShadowLightSpaceTechnique(const vtkDeepShadowLightSpaceTechnique&) = delete;
  void operator=(const vtkDeepShadowLightSpaceTechnique&) = delete;

  class Maps;
  std::unique_ptr<Maps> LightMaps;
};

#endif
