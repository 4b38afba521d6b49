// Deep shadow maps at a fixed memory budget ("dsm-fixed"), CPU twin: the deep shadow map's
// compression (VisibilityCompressor, Lokovic and Veach) given a number of nodes per texel
// instead of an error bound. Each texel finds the smallest bound whose nodes fit: first the
// finest (2^-14), then a bisection of log2 epsilon over [-14, 0] in 7 steps (1/9 of an
// octave), keeping the last bound that fitted (at 1, one node always does). So every texel
// spends its nodes where its own visibility needs them, and a texel that needs few keeps a
// bound near zero, where the variable-node map doubles its bound until the nodes fit.
//
// The first node is exact: where the ray first meets something absorbing (a sample's start,
// rounded down to the depth grid, or a casting mesh), with visibility 1; in front of it
// nothing is stored. (The variable-node map starts at the volume's box, so that two nodes
// make one line from the box's entry to the ground behind an empty box.)
//
// Storage: `dsm-bits` bits per texel (64, 128, 256, 512) are N = bits / 32 nodes of a 16-bit
// unorm depth over the light's depth range (LightDepthRange: every depth its faces see) and a
// 16-bit unorm visibility, two nodes per RGBA16 layer; unused nodes lie at the range's end
// with the last value. The lookup is a loop over the nodes in order, no search:
// V(z) = 1 + sum over i >= 1 of (v_i - v_{i-1}) clamp((z - z_{i-1}) / (z_i - z_{i-1}), 0, 1),
// bilinear across the four nearest texels (on a CPU rasterizer the GLSL stops at the first
// node beyond z, whose later terms are 0: in front of a medium one texel fetch). Casting meshes are steps among the nodes, as in
// the deep shadow map. Grey only.
//
// An error instead of a budget (`dsm-fixed-error` E > 0): each texel whose ray absorbs
// something is first compressed within E alone, its nodes counted; N is the 99th percentile
// of those counts (FixedNodesForError: rounded up to even, two nodes a layer, 2 to
// MaxFixedNodes), and the map is then fitted at N nodes as above. So 99 % of the texels keep
// E or better, and the 1 % that need more nodes (the tail a layout sized from the mean loses)
// get the finest bound N nodes fit.
// GLSL twins: Shaders/Shadows/FixedBudgetDeepShadowMapBuild.glsl and ...Map.glsl.
#ifndef deepshadow_FixedBudgetDeepShadowMap_h
#define deepshadow_FixedBudgetDeepShadowMap_h

#include "Core/Shadows/LightSpace.h"
#include "vtkDeepShadowCoreModule.h"

#include <cstdint>
#include <vector>

namespace deepshadow
{

/** The registry's kind of fixed-budget deep shadow maps ("dsm-fixed"). */
constexpr ShadowKind FixedBudgetKind = ShadowKind(9);

/** The dsm-bits parameter: bits per texel (ShadowParameters::Extra). */
VTKDEEPSHADOWCORE_EXPORT int FixedBudgetBits(const ShadowParameters& parameters);
/** The dsm-fixed-error parameter: a bound instead of a budget (0: the budget dsm-bits). */
VTKDEEPSHADOWCORE_EXPORT double FixedBudgetError(const ShadowParameters& parameters);
/**
 * Nodes per texel of the budget, 32 bits each (with an error instead, as many as the build
 * finds: see FixedNodesForError).
 */
inline int FixedBudgetNodes(const ShadowParameters& parameters)
{
  return FixedBudgetBits(parameters) / 32;
}

/** The most nodes an error may ask for per texel (1024 bits), and the share that must fit. */
constexpr int MaxFixedNodes = 32;
constexpr double FixedNodePercentile = 0.99;
/**
 * N for an error: the smallest count at or above which FixedNodePercentile of the texels
 * lie, from `histogram` (texels by the nodes they need within the error, the last bin for
 * that many or more), rounded up to even and clamped to [2, MaxFixedNodes]; 2 with no texel.
 */
VTKDEEPSHADOWCORE_EXPORT int FixedNodesForError(const std::vector<long long>& histogram);

/** Nodes the texel's ray needs to stay within `bound` (0 where it absorbs nothing). */
VTKDEEPSHADOWCORE_EXPORT int FixedNodesWithin(const ShadowCaster& caster, const glm::dvec3& origin,
  const glm::dvec3& direction, double step, double bound, double depthRange);

/** The bisection: the finest bound tried first, and the steps of log2 epsilon after it. */
constexpr int FixedBoundLog2Min = -14;
constexpr int FixedBisectionSteps = 7;

/** One texel as stored: N (depth, value) pairs of 16-bit unorms, and the bound it reached. */
struct FixedBudgetTexel
{
  std::vector<std::uint16_t> Nodes; // 2 N
  double Epsilon = 0.0;             // 0 where the ray absorbs nothing
  bool Hit = false;                 // something absorbing on the ray
};

/**
 * Fits one texel's ray into `nodes` nodes as described above; `depthRange` is
 * LightDepthRange's.
 */
VTKDEEPSHADOWCORE_EXPORT FixedBudgetTexel FitFixedBudget(const ShadowCaster& caster,
  const glm::dvec3& origin, const glm::dvec3& direction, double step, int nodes, double depthRange);

/** The lookup's loop: V at `depth` (normalized by the depth range) from N stored nodes. */
VTKDEEPSHADOWCORE_EXPORT double EvaluateFixedNodes(const std::uint16_t* nodes, int count, double depth);

/** What a build reached. */
struct FixedBudgetStatistics
{
  long TexelsHit = 0;       // texels whose ray meets something absorbing
  double EpsilonMean = 0.0; // over them
  double EpsilonMax = 0.0;
  int Nodes = 0;            // per texel: the budget's, or what the error asked for
  /** With an error: the share of TexelsHit that needed more than Nodes to stay within it. */
  double BeyondError = 0.0;
};

class VTKDEEPSHADOWCORE_EXPORT FixedBudgetDeepShadowMap : public LightSpaceShadow
{
public:
  FixedBudgetDeepShadowMap(const ShadowParameters& parameters, const ShadowCaster& caster,
    const Light& light, double step, int threads);
  /** As the GPU stores it: 4 bytes per node. */
  size_t Bytes() const override { return this->Nodes.size() * sizeof(std::uint16_t); }
  const FixedBudgetStatistics& GetStatistics() const { return this->Statistics; }

protected:
  glm::dvec3 MapVisibility(const MapPoint& point) const override;

private:
  int Count;         // nodes per texel (with an error, found by the build)
  double DepthRange; // world depth of unorm 1
  std::vector<std::uint16_t> Nodes;
  FixedBudgetStatistics Statistics;
};

}
#endif
