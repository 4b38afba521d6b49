// Deep shadow maps (Lokovic and Veach 2000; Ropinski et al., section 3), CPU twin.
//
// Per light-space texel, the visibility V(z) (transmittance from the light to depth z along
// the texel's ray) is sampled by marching the ray and compressed into a piecewise-linear V'
// with the guarantee |V'(z) - V(z)| <= epsilon at every sample depth. At most `Layers` nodes
// are stored per texel; a texel that needs more at the requested epsilon is compressed again
// with a doubled bound (epsilon' = max(2 epsilon', 1/1024)) until its nodes fit, so its error
// grows in steps instead of its shadow being cut off; the nodes needed at the requested bound
// and the largest bound actually used are reported. Coloured deep shadow maps keep one
// visibility per RGB channel, (1 - alpha (1 - c)) per sample, with nodes at shared depths
// (a segment ends where any channel leaves its bound).
//
// Lookup: linear in depth between the two nodes that bracket the point (1 before the first
// node, the last value after the last), bilinear across the four nearest texels.
//
// With ShadowParameters::ChunkNodes, nodes go to a pool of chunks instead (NodeChunks.h): any
// number per texel, and a pool too small for them all has the whole map built again with a
// doubled bound (ChunkedBuildBound).
//
// GLSL twins: Shaders/Shadows/DeepShadowMapBuild.glsl (sampling and compression, in float)
// and Shaders/Shadows/DeepShadowMap.glsl (lookup).
#ifndef deepshadow_DeepShadowMap_h
#define deepshadow_DeepShadowMap_h

#include "Core/Shadows/LightSpace.h"
#include "vtkDeepShadowCoreModule.h"

#include <array>
#include <memory>
#include <vector>

namespace deepshadow
{

/**
 * A node of a piecewise-linear visibility function, as the GPU stores it: depth and value
 * per channel (a grey function repeats channel 0).
 */
struct VisibilityNode
{
  float Depth;
  std::array<float, 3> Value;
};

/** V(z) of one texel, sampled: 1 at the ray's entry, then after each sample. */
struct VTKDEEPSHADOWCORE_EXPORT VisibilitySamples
{
  std::vector<double> Depths;     // increasing
  std::vector<glm::dvec3> Values; // per channel, non-increasing
  /**
   * The march stopped early, once every channel was at or below the bound: beyond the last
   * depth V lies somewhere in [0, last value], which the compression accounts for.
   */
  bool Truncated = false;
};

/**
 * Samples V along a texel's ray: the entry (value 1), then the far end of every sample
 * (t + step / 2) with the transmittance so far; a run of empty blocks adds one point. Stops
 * once every channel is at or below `stopAt` (then Truncated).
 */
VTKDEEPSHADOWCORE_EXPORT VisibilitySamples SampleVisibility(const ShadowCaster& caster,
  const glm::dvec3& origin, const glm::dvec3& direction, double step, bool colored, double stopAt);

/**
 * Where nodes are stored, when not as 32-bit floats: depths on a grid of `Depth` (a world
 * step: the light's depth range over 65535 for 16-bit unorm depths) and values on one of
 * `Value` (1/65535 for 16-bit unorm); 0 keeps floats.
 */
struct NodeGrid
{
  double Depth = 0.0;
  double Value = 0.0;
};

/**
 * Greedy compression into linear segments (Lokovic and Veach): a segment from its start node
 * is extended sample by sample while some line from that node stays within every sample's
 * bounds (the feasible slopes form an interval per channel); when the next sample would empty
 * it, the segment ends at the previous sample, at the feasible value nearest that sample's
 * value. Node depths and values are 32-bit floats chosen inside the feasible intervals, so the
 * bound holds for the nodes as stored, not just before rounding (unless epsilon is so small
 * that an interval holds no float: then within half a float ulp). With a NodeGrid, depths
 * and values are grid points instead (samples at the stored depth, values inside the
 * intervals where the grid has a point there, else within half a grid step).
 */
class VTKDEEPSHADOWCORE_EXPORT VisibilityCompressor
{
public:
  VisibilityCompressor(double epsilon, int channels, NodeGrid grid = {});
  /** A sample of V: V' must stay within epsilon of `value` at `depth`. */
  void Add(double depth, const glm::dvec3& value);
  /** A sample known only to lie in [low, high] per channel; nodes prefer `preferred`. */
  void AddBounded(double depth, const glm::dvec3& low, const glm::dvec3& high,
    const glm::dvec3& preferred);
  /** Ends the last segment (no end node if it can stay level) and returns the nodes. */
  std::vector<VisibilityNode> Finish();

private:
  void EndSegment();
  /** The stored value nearest `preferred` inside [low, high]. */
  float StoredValue(double low, double high, double preferred) const;

  double Epsilon;
  int Channels;
  NodeGrid Grid;
  bool Started = false;
  bool HasSegment = false; // a sample after the start node
  double StartDepth = 0.0;
  glm::dvec3 StartValue{ 1.0 };
  double LastDepth = 0.0;
  glm::dvec3 LastPreferred{ 1.0 };
  glm::dvec3 SlopeLow{ 0.0 }, SlopeHigh{ 0.0 };
  std::vector<VisibilityNode> Nodes;
};

/** The compressed function of one texel, and how it was made to fit. */
struct CompressedVisibility
{
  std::vector<VisibilityNode> Nodes; // at most maxNodes
  int NodesNeeded = 0;               // at the requested epsilon
  double Epsilon = 0.0;              // the bound that holds (requested, or doubled to fit)
};

/**
 * Compresses `samples` (channels 1 or 3) within `epsilon` into at most `maxNodes` (>= 1)
 * nodes, doubling the bound as described above when they do not fit.
 */
VTKDEEPSHADOWCORE_EXPORT CompressedVisibility CompressVisibility(
  const VisibilitySamples& samples, int channels, double epsilon, int maxNodes);

/** How many of `count` nodes in increasing depth lie at or before `depth`. */
VTKDEEPSHADOWCORE_EXPORT int NodesAtOrBefore(const VisibilityNode* nodes, int count, double depth);
/** Linear between node a (at or before `depth`) and node b (beyond it). */
VTKDEEPSHADOWCORE_EXPORT glm::dvec3 InterpolateNodes(const VisibilityNode& a, const VisibilityNode& b, double depth);
/** V'(depth) from `count` nodes in increasing depth (unused trailing nodes at NoHit are fine). */
VTKDEEPSHADOWCORE_EXPORT glm::dvec3 EvaluateVisibility(
  const VisibilityNode* nodes, int count, double depth);

/** What compressing a whole map took, as in Table 4 of Ropinski et al. */
struct DeepShadowMapStatistics
{
  long TexelsHit = 0;         // texels whose ray meets the volume's box
  double NodesAverage = 0.0;  // nodes needed at the requested epsilon, over those texels
  int NodesMax = 0;
  long TexelsOverflowed = 0;  // texels that needed more than Layers nodes (chunked: than the pool held)
  double EpsilonMax = 0.0;    // the largest bound a texel ended with
  long long ChunksUsed = 0;   // chunked: chunks taken from the pool
  long long ChunksCapacity = 0; // chunked: the pool's chunks
};

class NodeChunks;

class VTKDEEPSHADOWCORE_EXPORT DeepShadowMap : public LightSpaceShadow
{
public:
  DeepShadowMap(const ShadowParameters& parameters, const ShadowCaster& caster,
    const Light& light, double step, int threads);
  ~DeepShadowMap() override;
  /** As the GPU stores it: per node a depth and 1 or 3 values, 32-bit floats. */
  size_t Bytes() const override;
  const DeepShadowMapStatistics& GetStatistics() const { return this->Statistics; }

protected:
  glm::dvec3 MapVisibility(const MapPoint& point) const override;

private:
  /** Chunked memory: builds until the pool holds the nodes, doubling the bound. */
  void BuildChunked(const ShadowParameters& parameters, double step, int threads);

  int Channels;
  int Layers;
  std::vector<VisibilityNode> Nodes; // per texel, Layers nodes (not chunked)
  std::unique_ptr<NodeChunks> Chunks; // chunked
  DeepShadowMapStatistics Statistics;
};

}
#endif
