// Clustered light-space maps (paper 000, section 4). A single map over a sparse volume spends
// its texels on empty space between small objects: here each cluster of nearby objects gets a
// map of its own, fitted to it, and a lookup multiplies what every cluster casts along the
// light's ray. The objects are the volume's 26-connected groups of occupied blocks (the
// empty-space map's; Core/EmptySpace.h) and the casting surfaces' box. A face marches
// through its cluster's box (ShadowCaster::Clip) and samples only its own blocks: every
// sample with an opacity lies in exactly one object's blocks (the blocks' aprons make the
// empty ones exactly empty), so none is counted twice or missed. Clustering depends on the
// light, the occupancy, the casting surfaces and, in steps of a power of two, on the objects'
// sizes on screen, so a moving camera mostly reuses it.
#ifndef deepshadow_Clusters_h
#define deepshadow_Clusters_h

#include "Core/Shadows.h"
#include "Core/Shadows/LightSpace.h"
#include "vtkDeepShadowCoreModule.h"

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <functional>
#include <vector>

namespace deepshadow
{
class SurfaceSet;

/** The objects of a volume: 26-connected groups of occupied blocks. */
struct VolumeObjects
{
  /** Each object's box (index space, one voxel of apron, within the grid), in the order of their first block. */
  std::vector<IndexBox> Boxes;
  /** Per block (EmptySpaceMap order): its object, or -1 for an empty block. */
  std::vector<int> BlockObject;
};
VTKDEEPSHADOWCORE_EXPORT VolumeObjects OccupiedObjects(const EmptySpaceMap& empty, const glm::ivec3& dims);

/** Paper 000's eq. 2 between two light-space extents (min u, min v, max u, max v). */
VTKDEEPSHADOWCORE_EXPORT double ExtentDistance(const glm::dvec4& a, const glm::dvec4& b);

/**
 * Paper 000's greedy clustering of `count` objects by their light-space `distance` (eq. 2,
 * ExtentDistance; for a light that needs a cube of faces, the largest over the six): pairs
 * sorted by distance; an object joins the cluster all of whose members lie within `threshold`
 * of it (the nearest such), or opens a new one while fewer than `maxClusters` exist; the rest
 * join the cluster whose farthest member is nearest. Returns each object's cluster (0, 1, ...).
 *
 * `weights` (optional, >= 1 per object) say how much an object's shadow matters (what the
 * paper calls its contribution; ClusterFaces: its size on screen): the distance between two
 * objects is multiplied by the larger weight, and heavier objects are placed first, so that
 * they open clusters of their own that others do not join.
 */
VTKDEEPSHADOWCORE_EXPORT std::vector<int> ClusterObjects(size_t count,
  const std::function<double(size_t, size_t)>& distance, int maxClusters, double threshold,
  const std::vector<double>* weights = nullptr);

/**
 * A light's clustered faces: one per cluster, fitted to the box of its objects, and what its
 * rays march. Boxes may overlap: a face's rays take only the samples of its own blocks
 * (Occupied: the blocks of its objects, for ShadowCaster::Empty) and the casting surfaces'
 * crossings only if they belong to it, so that every sample is counted once.
 */
struct ClusteredFaces
{
  std::vector<ShadowMapFace> Faces;
  std::vector<IndexBox> Clips;
  /** Each face's depth of its box's nearest corner: a point nearer the light is not shadowed by it. */
  std::vector<double> Starts;
  std::vector<EmptySpaceMap> Occupied;
  std::vector<bool> CastsSurfaces;
  /** Per block: 0 empty, else 1 + the cluster it belongs to (the GPU's label texture). */
  std::vector<uint8_t> BlockLabels;
};

/**
 * The clusters of the volume's objects (and of the casting surfaces' box) as `light` sees
 * them, at most `maxClusters`, with `distance` in units of the unclustered face's half-width.
 * With `eye` (world; the centre of the camera's near plane), objects weigh their angular
 * size seen from it over the median object's, rounded to a power of two (at least 1): the
 * paper's view-dependent clustering (its Fig. 3), which a small camera move rarely changes.
 * One object gets one face fitted to it. A positional light among the objects gets one
 * perspective face per cluster (fewer than a cube's six where the clusters allow), and a spot
 * light none for a cluster wholly outside its cone (nothing there is lit, and light reaching
 * a lit point never crossed it). Empty when clustering does not apply: no object, or a
 * positional light inside a cluster's bounding sphere, which needs a cube of faces.
 */
VTKDEEPSHADOWCORE_EXPORT ClusteredFaces ClusterFaces(const Light& light, const glm::dmat4& indexToWorld,
  const glm::ivec3& dims, const EmptySpaceMap& empty, const SurfaceSet* surfaces, int maxClusters,
  double distance, const glm::dvec3* eye = nullptr);

}
#endif
