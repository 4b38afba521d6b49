// Adaptive volumetric shadow maps (Salvi, Vidimce, Lauritzen and Lefohn, "Adaptive
// Volumetric Shadow Maps", EGSR 2010), CPU twin: a rival of the deep shadow map at a fixed
// number of nodes per texel, the representation games use. Each texel keeps its ray's
// transmittance as at most N nodes (depth, transmittance), linear between them, 1 before the
// first and the last's from there on. The ray is marched front to back: an absorbing sample
// appends a node at its end (and one at its start where the samples before it absorbed
// nothing); when a texel holds N + 1 nodes, the interior node whose removal changes the area
// under the curve least (the triangle it makes with its neighbours) goes, AVSM's
// compression. The first node and the newest stay. Unlike a deep shadow map's, the error is
// not bounded: N nodes are all there is, however much the ray needs.
//
// One texel is N nodes of two floats, two nodes per RGBA layer (N = 2, 4, 8 or 16: 16 to 128
// bytes); unused nodes have depth NoHit and the last node's transmittance. Casting meshes are
// steps beside it (SurfaceSteps, one more layer), as opacity levels keep them. Grey only;
// bilinear across the four nearest texels; rays stop below 1/512 of what the volume and the
// meshes let through together, like feelers.
// GLSL twins: Shaders/Shadows/AdaptiveVolumetricShadowMapBuild.glsl and ...Map.glsl.
#ifndef deepshadow_AdaptiveVolumetricShadowMap_h
#define deepshadow_AdaptiveVolumetricShadowMap_h

#include "Core/Shadows/LightSpace.h"
#include "Core/Shadows/SurfaceSteps.h"
#include "vtkDeepShadowCoreModule.h"

#include <vector>

namespace deepshadow
{

/** The registry's kind of adaptive volumetric shadow maps ("avsm"). */
constexpr ShadowKind AdaptiveVolumetricKind = ShadowKind(8);

/** The avsm-nodes parameter: nodes per texel (ShadowParameters::Extra). */
VTKDEEPSHADOWCORE_EXPORT int AdaptiveNodes(const ShadowParameters& parameters);

/** Builds one texel's nodes, sample by sample, front to back. */
class VTKDEEPSHADOWCORE_EXPORT AdaptiveNodesBuilder
{
public:
  explicit AdaptiveNodesBuilder(int nodes);
  /** A sample from depth `from` to `to` that lets through `transmission`. */
  void Add(double from, double to, double transmission);
  /** A sample (or a run of them) that absorbs nothing. */
  void AddClear() { this->Absorbing = false; }
  /** Depth, transmittance of each node, as the map stores them (2 N floats). */
  std::vector<float> Finish() const;

private:
  void Append(double depth, double transmittance);
  int Nodes;
  bool Absorbing = false;
  double Transmittance = 1.0;
  std::vector<float> Depth; // at most Nodes + 1 while building; floats, as the GPU keeps them
  std::vector<float> Value;
};

/** The transmittance a texel's stored nodes give at `depth`. */
VTKDEEPSHADOWCORE_EXPORT double EvaluateAdaptiveNodes(const float* nodes, int count, double depth);

class VTKDEEPSHADOWCORE_EXPORT AdaptiveVolumetricShadowMap : public LightSpaceShadow
{
public:
  AdaptiveVolumetricShadowMap(const ShadowParameters& parameters, const ShadowCaster& caster,
    const Light& light, double step, int threads);
  /** As the GPU stores it: the nodes' layers, and one of steps with casting meshes. */
  size_t Bytes() const override
  {
    return (this->Nodes.size() + this->Steps.size() * 4) * sizeof(float);
  }

protected:
  glm::dvec3 MapVisibility(const MapPoint& point) const override;

private:
  int Count; // nodes per texel
  std::vector<float> Nodes;
  std::vector<SurfaceSteps> Steps; // per texel, when meshes cast; else empty
};

}
#endif
