// A grid of light visibilities over a box, trilinear between its nodes: the CPU twin of the
// GPU's 3D shadow textures. Two things are stored that way: a cached technique's answers over
// its own volume ("PP"; Shaders/Shadows/CachedShadow.glsl), and the shadows that other
// volumes cast onto a receiver (Shaders/Features/OtherVolumeShadows.glsl).
#ifndef deepshadow_ShadowGrid_h
#define deepshadow_ShadowGrid_h

#include "Core/Shadows.h"
#include "vtkDeepShadowCoreModule.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <functional>
#include <vector>

namespace deepshadow
{

/** Where a grid's nodes are: node (i, j, k) sits at NodeToWorld * (i, j, k, 1). */
struct VTKDEEPSHADOWCORE_EXPORT GridFrame
{
  glm::ivec3 Dims{ 2 };
  glm::dmat4 NodeToWorld{ 1.0 };
  glm::dmat4 WorldToNode{ 1.0 };

  /**
   * Over a volume's box [0, dataDims - 1] in index space: ShadowVolumeDims(dataDims, size)
   * nodes, the first and last on the box's faces. A flat axis (one sample thick) keeps its
   * node 0 on the slab and node 1 one voxel off it.
   */
  static GridFrame OverVolume(const glm::ivec3& dataDims, const glm::dmat4& indexToWorld, int size);
  /**
   * Over a world box [lo, hi] (e.g. a mesh's bounds): `size` nodes along its longest side,
   * the others in proportion, at least 2. A flat side is widened to a thousandth of the
   * longest one (at least 1e-9) so that the frame stays invertible; a box that is empty
   * (lo > hi) or not finite becomes such a flat box at the origin.
   */
  static GridFrame OverBox(const glm::dvec3& lo, const glm::dvec3& hi, int size);
};

class VTKDEEPSHADOWCORE_EXPORT ShadowGrid : public LightShadow
{
public:
  using Function = std::function<glm::dvec3(const glm::dvec3&)>;
  /** Evaluates `visibility` at every node (in parallel: it must be thread-safe). */
  ShadowGrid(const Function& visibility, const GridFrame& frame, bool colored, int threads = 0);

  /** Trilinear between the nodes; points outside the grid take its nearest face's value. */
  glm::dvec3 Visibility(const glm::dvec3& p) const override;
  /** As the GPU stores it: RGBA or R, 16-bit floats. */
  size_t Bytes() const override;

  const GridFrame& GetFrame() const { return this->Frame; }

private:
  size_t Node(int i, int j, int k) const;

  GridFrame Frame;
  bool Colored;
  std::vector<float> Values; // rgb per node
};

/** The product of several visibilities: light crosses every caster on its way. */
class VTKDEEPSHADOWCORE_EXPORT ProductShadow : public LightShadow
{
public:
  explicit ProductShadow(std::vector<const LightShadow*> factors)
    : Factors(std::move(factors))
  {
  }
  glm::dvec3 Visibility(const glm::dvec3& p) const override;

private:
  std::vector<const LightShadow*> Factors;
};

}
#endif
