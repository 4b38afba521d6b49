// Internal: a light-space technique's clustered faces (deepshadow::ClusterFaces, paper 000's
// clustered maps) on the GPU. Per shadowed light (slot): its faces, the box each marches, the
// depth its box starts at, whether the casting meshes are its, and a block-label texture
// (R8: 0, or 1 + face) through which a face's build takes only its own blocks
// (vtkDeepShadowLightSpaceCS.glsl, LIGHT_SPACE_CLIP). The lookup loops over a light's faces
// (Shaders/Shadows/LightSpace.glsl, LIGHT_SPACE_CLUSTERS).
#ifndef vtkDeepShadowLightSpaceClusters_h
#define vtkDeepShadowLightSpaceClusters_h

#include "Core/Light.h"
#include "Core/Shadows/Clusters.h"

#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

namespace deepshadow
{
class ComputeProgram;
class UniformSink;

class LightSpaceClusters
{
public:
  /**
   * The clustered faces of `light` (slot `slot`) into `faces`; `faces` is left empty where the
   * light is not clustered (the caller takes the unclustered faces). Call for every slot, in
   * order, between BeginFrame and EndFrame.
   */
  void BeginFrame(int slots);
  void Cluster(int slot, const Light& light, const glm::dmat4& indexToWorld, const glm::ivec3& dims,
    const EmptySpaceMap& empty, const SurfaceSet* surfaces, int maxClusters, double distance,
    const glm::dvec3& eye, std::vector<ShadowMapFace>& faces);
  /**
   * True if the clustering differs from the last frame's (every map must be rebuilt); the
   * label textures are then uploaded.
   */
  bool EndFrame(vtkOpenGLRenderWindow* window, const glm::ivec3& blockCount);

  /** Whether some light is clustered (the build clips, the lookup loops). */
  bool Any() const;
  /** Clustered faces per slot (0: not clustered). */
  std::vector<int> Counts() const;

  /** The build's define, and its uniforms for face `face` of slot `slot` (labels active). */
  std::string BuildDefines() const;
  void ActivateLabels();
  void DeactivateLabels();
  void SetBuildUniforms(ComputeProgram& build, int slot, int face) const;

  /** The lookup's define (none while no light is clustered), and its uniforms. */
  std::string LookupDefines() const;
  void SetLookupUniforms(UniformSink& sink, const std::vector<std::vector<ShadowMapFace>>& faces) const;

  void Release(vtkWindow* window);

private:
  std::vector<ClusteredFaces> Slots;     // per slot; no faces: not clustered
  std::vector<ClusteredFaces> LastSlots; // the previous frame's, to compare
  std::vector<vtkSmartPointer<vtkTextureObject>> Labels; // per slot; null: not clustered
};

}
#endif
