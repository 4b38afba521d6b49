#include "Core/Shadows/NodeChunks.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace deepshadow
{

namespace
{

glm::dvec3 ValueOf(const VisibilityNode& node)
{
  return glm::dvec3(node.Value[0], node.Value[1], node.Value[2]);
}

}

NodeChunks::NodeChunks(size_t texels, int chunkNodes, long long capacity, long long expected)
  : Nodes(chunkNodes)
  , Limit(capacity)
  , Start(texels, NoChunk)
{
  if (chunkNodes < 1 || capacity < 0)
  {
    throw std::invalid_argument("NodeChunks needs chunkNodes >= 1 and capacity >= 0");
  }
  const size_t held = static_cast<size_t>(expected < 0 ? capacity : std::min(capacity, expected));
  this->Next.assign(held, NoChunk);
  this->Entries.assign(held * static_cast<size_t>(chunkNodes), VisibilityNode{ NoHit, { 1.0f, 1.0f, 1.0f } });
}

long long NodeChunks::ChunksFor(const std::vector<VisibilityNode>& nodes, int chunkNodes)
{
  // One node of value 1 (a ray through empty space, or lit all along) is V' = 1: no chunk.
  if (nodes.size() == 1 && nodes[0].Value == std::array<float, 3>{ { 1.0f, 1.0f, 1.0f } })
  {
    return 0;
  }
  return (static_cast<long long>(nodes.size()) + chunkNodes - 1) / chunkNodes;
}

bool NodeChunks::Store(size_t texel, const std::vector<VisibilityNode>& nodes)
{
  // As the GPU build emits them: a chunk is asked for as a node starts one, and once the
  // pool has run out the texel only counts what it would have asked for.
  if (ChunksFor(nodes, this->Nodes) == 0)
  {
    return true;
  }
  std::int32_t chunk = NoChunk;
  bool granted = true;
  for (size_t k = 0; k < nodes.size(); ++k)
  {
    const size_t slot = k % static_cast<size_t>(this->Nodes);
    if (slot == 0)
    {
      const long long asked = this->Counter.fetch_add(1);
      if (!granted || asked >= this->Limit)
      {
        granted = false;
        continue;
      }
      if (asked >= static_cast<long long>(this->Next.size()))
      {
        throw std::logic_error("NodeChunks: more chunks granted than the memory expected for them");
      }
      const auto next = static_cast<std::int32_t>(asked);
      (chunk == NoChunk ? this->Start[texel] : this->Next[static_cast<size_t>(chunk)]) = next;
      chunk = next;
    }
    if (granted)
    {
      this->Entries[static_cast<size_t>(chunk) * this->Nodes + slot] = nodes[k];
    }
  }
  if (granted)
  {
    // The last chunk's tail repeats the last value far away.
    for (size_t slot = nodes.size() % this->Nodes; slot != 0 && slot < static_cast<size_t>(this->Nodes); ++slot)
    {
      this->Entries[static_cast<size_t>(chunk) * this->Nodes + slot] = VisibilityNode{ NoHit, nodes.back().Value };
    }
  }
  return granted;
}

glm::dvec3 NodeChunks::Evaluate(size_t texel, double depth) const
{
  std::int32_t chunk = this->Start[texel];
  if (chunk == NoChunk)
  {
    return glm::dvec3(1.0);
  }
  // `before`: the last node of the chunks walked past, which lies at or before depth.
  const VisibilityNode* before = nullptr;
  for (;;)
  {
    const VisibilityNode* nodes = &this->Entries[static_cast<size_t>(chunk) * this->Nodes];
    const std::int32_t next = this->Next[static_cast<size_t>(chunk)];
    if (static_cast<double>(nodes[this->Nodes - 1].Depth) <= depth && next > chunk)
    {
      before = &nodes[this->Nodes - 1];
      chunk = next;
      continue;
    }
    // The first node of this chunk beyond depth brackets it with the one before.
    const int first = NodesAtOrBefore(nodes, this->Nodes, depth);
    const VisibilityNode* a = first > 0 ? &nodes[first - 1] : before;
    if (!a)
    {
      return glm::dvec3(1.0);
    }
    if (first == this->Nodes)
    {
      return ValueOf(*a);
    }
    return InterpolateNodes(*a, nodes[first], depth);
  }
}

std::vector<VisibilityNode> NodeChunks::NodesOf(size_t texel) const
{
  std::vector<VisibilityNode> nodes;
  for (std::int32_t chunk = this->Start[texel]; chunk != NoChunk;)
  {
    const auto begin = this->Entries.begin() + static_cast<std::ptrdiff_t>(chunk) * this->Nodes;
    nodes.insert(nodes.end(), begin, begin + this->Nodes);
    const std::int32_t next = this->Next[static_cast<size_t>(chunk)];
    chunk = next > chunk ? next : NoChunk;
  }
  return nodes;
}

long long NodeChunks::Used() const
{
  return std::min(this->Requested(), this->Limit);
}

long long ChunkBytes(int chunkNodes, bool colored)
{
  return (static_cast<long long>(chunkNodes) + 1) * (colored ? 16 : 8);
}

long long ChunkPoolCapacity(size_t texels, int chunkNodes, bool colored, int layers, double megabytes)
{
  const long long chunk = ChunkBytes(chunkNodes, colored);
  const double bytes = megabytes > 0.0 ? megabytes * 1048576.0
                                       : static_cast<double>(texels) * std::max(1, layers) * (colored ? 16 : 8);
  const double chunks = std::floor(bytes / static_cast<double>(chunk));
  return static_cast<long long>(std::clamp(chunks, 1.0, static_cast<double>(MaxPoolChunks)));
}

double ChunkedBuildBound(double bound, long long requested, long long capacity)
{
  if (requested <= capacity || bound >= 1.0)
  {
    return -1.0;
  }
  return std::max(2.0 * bound, 1.0 / 1024.0);
}

}
