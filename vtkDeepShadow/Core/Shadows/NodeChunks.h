// Chunked node memory for deep shadow maps (paper 000, section 5), CPU twin of the GPU's pool
// (Shaders/Shadows/DeepShadowMapBuild.glsl and DeepShadowMap.glsl under DSM_CHUNKED).
//
// Fixed layers give every texel `Layers` nodes, needed or not, and cut a texel that needs
// more (its bound is doubled until its nodes fit). Chunked memory gives a texel nodes only as
// it emits them: chunks of `ChunkNodes` nodes, taken from one pool by an atomic counter as a
// texel's previous chunk fills, linked texel by texel; a start table holds each texel's first
// chunk (NoChunk: no node, visibility 1). A texel may then have any number of nodes while the
// pool lasts, and an empty texel costs only its start entry: one whose ray meets nothing
// (its one node is 1) takes no chunk.
//
// Unlike the paper, a chunk belongs to one texel: the paper's chunks are shared by the 64
// texels of a block (each entry then links to its texel's next entry, a list walked node by
// node); here a lookup reads a chunk's last depth to skip it whole and searches inside the
// one chunk that brackets the depth, as fixed layers do. What it costs is the unused tail of
// a texel's last chunk, filled as fixed layers fill unused nodes (NoHit, the last value).
//
// Chunks are numbered in allocation order, so a link always points to a higher chunk: a walk
// ends even on a corrupt table. A pool that runs out keeps counting the chunks asked for
// (Requested()), and a texel then keeps the whole chunks it got: a shorter function, never a
// wrong link. DeepShadowMap builds again with a doubled bound instead (ChunkedBuildBound).
#ifndef deepshadow_NodeChunks_h
#define deepshadow_NodeChunks_h

#include "Core/Shadows/DeepShadowMap.h"
#include "vtkDeepShadowCoreModule.h"

#include <atomic>
#include <cstdint>
#include <vector>

namespace deepshadow
{

class VTKDEEPSHADOWCORE_EXPORT NodeChunks
{
public:
  static constexpr std::int32_t NoChunk = -1;

  /**
   * A pool of at most `capacity` chunks of `chunkNodes` (>= 1) nodes for `texels` texels.
   * Memory is taken for `expected` chunks (at most `capacity`; -1: all of it): the chunks
   * the texels will ask for (ChunksFor), so that a large limit costs nothing unused.
   */
  NodeChunks(size_t texels, int chunkNodes, long long capacity, long long expected = -1);

  /** The chunks a texel with these nodes asks for (none for one node of value 1). */
  static long long ChunksFor(const std::vector<VisibilityNode>& nodes, int chunkNodes);

  /**
   * Stores a texel's nodes (in increasing depth), a chunk each `ChunkNodes` nodes, the last
   * one's tail filled with (NoHit, last value). Texels may be stored from several threads at
   * once (each texel once). False when the pool ran out: the texel keeps the chunks it got.
   */
  bool Store(size_t texel, const std::vector<VisibilityNode>& nodes);

  /** V'(depth) of a texel: its chunks walked while their last node lies at or before depth. */
  glm::dvec3 Evaluate(size_t texel, double depth) const;

  /** A texel's nodes as stored (the tail of its last chunk included). */
  std::vector<VisibilityNode> NodesOf(size_t texel) const;

  int ChunkNodes() const { return this->Nodes; }
  long long Capacity() const { return this->Limit; }
  /** Chunks asked for, granted or not (the GPU's counter). */
  long long Requested() const { return this->Counter.load(); }
  long long Used() const;

private:
  int Nodes;
  long long Limit;
  std::atomic<long long> Counter{ 0 };
  std::vector<std::int32_t> Start;   // per texel
  std::vector<std::int32_t> Next;    // per chunk granted
  std::vector<VisibilityNode> Entries; // per chunk granted, ChunkNodes each
};

/** Bytes of one chunk on the GPU: its nodes and a link stored as one more node. */
VTKDEEPSHADOWCORE_EXPORT long long ChunkBytes(int chunkNodes, bool colored);

/**
 * The most chunks a pool holds (all lights together on the GPU): the GPU stores a texel's
 * start as the float 2 x chunk + 1 (whether a second chunk follows), exact below 2^24.
 */
constexpr long long MaxPoolChunks = 1LL << 23;

/**
 * The pool's chunks for one light of `texels` texels: `megabytes` of them, or with 0 as many
 * bytes as `layers` fixed layers would take. At least 1, at most MaxPoolChunks.
 */
VTKDEEPSHADOWCORE_EXPORT long long ChunkPoolCapacity(
  size_t texels, int chunkNodes, bool colored, int layers, double megabytes);

/**
 * After a build with `bound` asked for `requested` chunks of a pool of `capacity`: the bound
 * to build with again, doubled (at least 1/1024), or -1 when none is needed (they fit) or
 * none would help (a bound of 1 or more, one node per texel, did not fit either).
 */
VTKDEEPSHADOWCORE_EXPORT double ChunkedBuildBound(double bound, long long requested, long long capacity);

}
#endif
