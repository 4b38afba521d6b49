// Chunked node memory (paper 000, section 5): the pool's allocator and list walk on random
// and adversarial node counts, a pool that runs out, and whole deep shadow maps against
// fixed layers and against Beer-Lambert through a stack of sheets.
#include "Core/Shadows/DeepShadowMap.h"
#include "Core/Shadows/NodeChunks.h"
#include "Core/Shadows.h"

#include "ClosedForm.h"
#include "ClosedFormScenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <thread>

using namespace deepshadow;

namespace
{
// `count` nodes of a decreasing function at increasing depths (values in [0, 1]).
std::vector<VisibilityNode> RandomNodes(std::mt19937& random, int count)
{
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<VisibilityNode> nodes;
  float depth = 5.0f * unit(random), value = 1.0f;
  for (int k = 0; k < count; ++k)
  {
    nodes.push_back(VisibilityNode{ depth, { value, value, value } });
    depth += 0.01f + unit(random);
    value *= unit(random);
  }
  return nodes;
}

// The nodes as fixed layers store them: padded with (NoHit, last value) to `length`.
std::vector<VisibilityNode> Padded(std::vector<VisibilityNode> nodes, size_t length)
{
  const VisibilityNode tail{ NoHit, nodes.empty() ? std::array<float, 3>{ { 1.0f, 1.0f, 1.0f } } : nodes.back().Value };
  nodes.resize(std::max(length, nodes.size()), tail);
  return nodes;
}

// Chunks for texels of RandomNodes: one node (of value 1) takes none.
long long ChunksFor(const std::vector<int>& counts, int chunkNodes)
{
  long long chunks = 0;
  for (int count : counts)
  {
    chunks += count == 1 ? 0 : (count + chunkNodes - 1) / chunkNodes;
  }
  return chunks;
}

// Stores every texel's nodes from two threads in a shuffled order.
std::vector<bool> StoreAll(NodeChunks& chunks, const std::vector<std::vector<VisibilityNode>>& nodes, std::mt19937& random)
{
  std::vector<size_t> order(nodes.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::shuffle(order.begin(), order.end(), random);
  std::vector<char> stored(nodes.size(), 0);
  auto half = [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i)
    {
      stored[order[i]] = chunks.Store(order[i], nodes[order[i]]) ? 1 : 0;
    }
  };
  std::thread other(half, size_t(0), order.size() / 2);
  half(order.size() / 2, order.size());
  other.join();
  return std::vector<bool>(stored.begin(), stored.end());
}

// Every lookup of a texel equals the fixed-layer lookup of `expected` (its nodes, padded).
void ExpectSameLookups(const NodeChunks& chunks, size_t texel, const std::vector<VisibilityNode>& expected)
{
  const std::vector<VisibilityNode> padded = Padded(expected, expected.size() + 1);
  std::vector<double> depths{ -1.0, 1e30 };
  for (const VisibilityNode& node : expected)
  {
    depths.push_back(node.Depth);
    depths.push_back(node.Depth - 0.005);
    depths.push_back(node.Depth + 0.005);
  }
  for (double depth : depths)
  {
    const glm::dvec3 want = EvaluateVisibility(padded.data(), static_cast<int>(padded.size()), depth);
    ASSERT_EQ(chunks.Evaluate(texel, depth), want) << "texel " << texel << " depth " << depth;
  }
}
}

TEST(NodeChunks, RandomCountsReadBackAsStoredAndLookUpAsFixedLayers)
{
  std::mt19937 random(7);
  for (int chunkNodes : { 1, 2, 3, 4, 8 })
  {
    std::vector<std::vector<VisibilityNode>> nodes;
    std::vector<int> counts;
    std::uniform_int_distribution<int> count(0, 40);
    for (int texel = 0; texel < 400; ++texel)
    {
      // Chunk boundaries (a multiple, one less, one more) as often as anything else.
      const int kind = texel % 4;
      const int n = kind == 0 ? count(random) : std::max(0, chunkNodes * (1 + texel % 5) + kind - 2);
      counts.push_back(n);
      nodes.push_back(RandomNodes(random, n));
    }
    const long long needed = ChunksFor(counts, chunkNodes);
    NodeChunks chunks(nodes.size(), chunkNodes, needed);
    const std::vector<bool> stored = StoreAll(chunks, nodes, random);
    EXPECT_EQ(chunks.Requested(), needed);
    EXPECT_EQ(chunks.Used(), needed);
    for (size_t texel = 0; texel < nodes.size(); ++texel)
    {
      EXPECT_TRUE(stored[texel]);
      const size_t length = nodes[texel].size() == 1 ? 0 : ((nodes[texel].size() + chunkNodes - 1) / chunkNodes) * chunkNodes;
      const std::vector<VisibilityNode> read = chunks.NodesOf(texel);
      ASSERT_EQ(read.size(), length) << "chunk nodes " << chunkNodes << " texel " << texel;
      const std::vector<VisibilityNode> padded = Padded(nodes[texel], length);
      for (size_t k = 0; k < length; ++k)
      {
        ASSERT_EQ(read[k].Depth, padded[k].Depth);
        ASSERT_EQ(read[k].Value, padded[k].Value);
      }
      ExpectSameLookups(chunks, texel, nodes[texel]);
    }
  }
}

TEST(NodeChunks, AdversarialCounts)
{
  std::mt19937 random(11);
  // One node: of value 1 (a ray through empty space) no chunk, below 1 a chunk.
  {
    NodeChunks chunks(2, 4, 10);
    EXPECT_TRUE(chunks.Store(0, { VisibilityNode{ 3.0f, { 1.0f, 1.0f, 1.0f } } }));
    EXPECT_EQ(chunks.Requested(), 0);
    EXPECT_TRUE(chunks.Store(1, { VisibilityNode{ 3.0f, { 1.0f, 0.5f, 1.0f } } }));
    EXPECT_EQ(chunks.Requested(), 1);
    EXPECT_EQ(chunks.Evaluate(1, 4.0), glm::dvec3(1.0, 0.5, 1.0));
    EXPECT_EQ(chunks.Evaluate(1, 2.0), glm::dvec3(1.0));
  }
  // One texel with thousands of nodes among empty ones: its chain is long, theirs absent.
  {
    std::vector<std::vector<VisibilityNode>> nodes(64);
    nodes[37] = RandomNodes(random, 5000);
    NodeChunks chunks(nodes.size(), 4, 1250);
    StoreAll(chunks, nodes, random);
    EXPECT_EQ(chunks.Requested(), 1250);
    EXPECT_EQ(chunks.NodesOf(37).size(), 5000u);
    ExpectSameLookups(chunks, 37, nodes[37]);
    EXPECT_EQ(chunks.Evaluate(36, 3.0), glm::dvec3(1.0));
  }
  // Every texel exactly at a chunk's end, and a pool with no chunk to spare.
  {
    std::vector<std::vector<VisibilityNode>> nodes;
    for (int texel = 0; texel < 100; ++texel)
    {
      nodes.push_back(RandomNodes(random, 8));
    }
    NodeChunks chunks(nodes.size(), 4, 200);
    const std::vector<bool> stored = StoreAll(chunks, nodes, random);
    EXPECT_TRUE(std::all_of(stored.begin(), stored.end(), [](bool s) { return s; }));
    EXPECT_EQ(chunks.Used(), 200);
  }
}

TEST(NodeChunks, APoolThatRunsOutKeepsWholeChunksAndCountsWhatWasAsked)
{
  std::mt19937 random(3);
  std::vector<std::vector<VisibilityNode>> nodes;
  std::vector<int> counts;
  for (int texel = 0; texel < 300; ++texel)
  {
    counts.push_back(texel % 13);
    nodes.push_back(RandomNodes(random, counts.back()));
  }
  const long long needed = ChunksFor(counts, 3);
  for (long long capacity : { needed - 1, needed / 2, 0LL })
  {
    NodeChunks chunks(nodes.size(), 3, capacity);
    const std::vector<bool> stored = StoreAll(chunks, nodes, random);
    EXPECT_EQ(chunks.Requested(), needed) << "capacity " << capacity;
    EXPECT_EQ(chunks.Used(), capacity);
    long long cut = 0;
    for (size_t texel = 0; texel < nodes.size(); ++texel)
    {
      const std::vector<VisibilityNode> read = chunks.NodesOf(texel);
      if (stored[texel])
      {
        ExpectSameLookups(chunks, texel, nodes[texel]);
        continue;
      }
      ++cut;
      // A cut texel keeps a prefix of whole chunks (none: lit), never another texel's nodes.
      ASSERT_LT(read.size(), nodes[texel].size());
      ASSERT_EQ(read.size() % 3, 0u);
      for (size_t k = 0; k < read.size(); ++k)
      {
        ASSERT_EQ(read[k].Depth, nodes[texel][k].Depth);
      }
      if (read.empty())
      {
        EXPECT_EQ(chunks.Evaluate(texel, 1e30), glm::dvec3(1.0));
      }
      else
      {
        ExpectSameLookups(chunks, texel, read);
      }
    }
    EXPECT_GT(cut, 0);
  }
  // The rule after such a build: double the bound until one node per texel did not fit.
  EXPECT_EQ(ChunkedBuildBound(0.02, 10, 10), -1.0);
  EXPECT_EQ(ChunkedBuildBound(0.02, 11, 10), 0.04);
  EXPECT_EQ(ChunkedBuildBound(0.0, 11, 10), 1.0 / 1024.0);
  EXPECT_EQ(ChunkedBuildBound(1.28, 11, 10), -1.0);
}

TEST(NodeChunks, PoolCapacity)
{
  // Automatic: the bytes of the fixed layers, in chunks of (nodes + link) entries.
  EXPECT_EQ(ChunkBytes(4, false), 40);
  EXPECT_EQ(ChunkBytes(4, true), 80);
  EXPECT_EQ(ChunkPoolCapacity(1000, 4, false, 8, 0.0), 1000 * 64 / 40);
  EXPECT_EQ(ChunkPoolCapacity(1000, 4, true, 8, 0.0), 1000 * 128 / 80);
  EXPECT_EQ(ChunkPoolCapacity(1000, 4, false, 8, 1.0), 1048576 / 40);
  EXPECT_EQ(ChunkPoolCapacity(1, 64, false, 1, 0.0), 1);
  EXPECT_EQ(ChunkPoolCapacity(1, 4, false, 1, 65536.0), MaxPoolChunks);
}

namespace
{
// Ten sheets of opacity 0.2 per unit, two units thick, across a 40^3 grid (world = index):
// z in [4k + 1.5, 4k + 3.5]. Under a light from +z, V steps down ten times, more nodes than
// 8 layers hold at epsilon 0.02.
std::unique_ptr<closedform::Body> Sheets()
{
  auto inSheet = [](double z) { return z >= 2.0 && z <= 39.5 && std::fmod(z, 4.0) >= 2.0; };
  auto body = std::make_unique<closedform::Body>(glm::ivec3(40, 40, 44), glm::dvec3(0.0), 0.2, glm::dvec3(0.0),
    [inSheet](const glm::dvec3& p) { return inSheet(p.z) ? 1.0f : 0.0f; });
  body->Path = [](const glm::dvec3& p, const glm::dvec3& d, double maxS, double grow) {
    double length = 0.0;
    for (int k = 0; k < 10; ++k)
    {
      length += closedform::BoxPath(glm::dvec3(-1.0, -1.0, 4 * k + 1.5 - grow),
        glm::dvec3(40.0, 40.0, 4 * k + 3.5 + grow), p, d, maxS);
    }
    return length;
  };
  return body;
}

// Between the sheets under a light from +z: how far a map's V' strays from Beer-Lambert
// beyond `bound` and the sampling's error (at most 0 when it holds).
double WorstBeyondBeerLambert(const LightShadow& map, const closedform::Body& sheets, const Light& light, double bound)
{
  double worst = -1.0;
  for (int k = 0; k < 10; ++k)
  {
    const glm::dvec3 p(20.2, 19.7, 4.0 * k + 0.5);
    const double exact = sheets.Exact(p, light, false).r;
    const double allowed = bound + closedform::SamplingError(exact, sheets.Sigma(), 0.25) + 1e-6;
    worst = std::max(worst, std::abs(map.Visibility(p).r - exact) - allowed);
  }
  return worst;
}
}

TEST(NodeChunks, ChunkedMapsHoldTheNodesFixedLayersCutAndFollowBeerLambert)
{
  const auto sheets = Sheets();
  const Light light = closedform::Directional({ 0.0, 0.0, 1.0 });
  ShadowParameters fixed;
  fixed.Kind = ShadowKind::DeepShadowMap;
  fixed.MapSize = 16;
  ShadowParameters chunked = fixed;
  chunked.ChunkNodes = 4;
  // Every texel needs about 18 nodes here: more than the automatic pool (the 8 layers' bytes).
  chunked.PoolMegabytes = 1.0;
  const auto fixedMap = MakeLightShadow(fixed, sheets->Caster, light, 0.25, 2);
  const auto chunkedMap = MakeLightShadow(chunked, sheets->Caster, light, 0.25, 2);
  const auto& fixedStats = dynamic_cast<const DeepShadowMap&>(*fixedMap).GetStatistics();
  const auto& chunkedStats = dynamic_cast<const DeepShadowMap&>(*chunkedMap).GetStatistics();
  EXPECT_GT(fixedStats.TexelsOverflowed, 0);
  EXPECT_GT(fixedStats.EpsilonMax, fixed.Epsilon);
  EXPECT_EQ(chunkedStats.TexelsOverflowed, 0);
  EXPECT_EQ(chunkedStats.EpsilonMax, chunked.Epsilon);
  EXPECT_GT(chunkedStats.NodesMax, 8);
  EXPECT_LE(chunkedStats.ChunksUsed, chunkedStats.ChunksCapacity);
  EXPECT_GT(chunkedMap->Bytes(), fixedMap->Bytes()); // what holding every node costs here
  // Between the sheets: Beer-Lambert within the bound and the sampling's error; the same
  // check fails on the fixed layers' doubled bound.
  EXPECT_LE(WorstBeyondBeerLambert(*chunkedMap, *sheets, light, chunked.Epsilon), 0.0);
  EXPECT_GT(WorstBeyondBeerLambert(*fixedMap, *sheets, light, fixed.Epsilon), 0.0);
}

TEST(NodeChunks, ChunkedMapsEqualFixedLayersThatDoNotOverflow)
{
  const auto ball = closedform::Ball(0.1);
  const Light light = closedform::Directional({ 0.3, 0.2, 1.0 });
  ShadowParameters fixed;
  fixed.Kind = ShadowKind::DeepShadowMap;
  fixed.MapSize = 24;
  fixed.Layers = 64;
  ShadowParameters chunked = fixed;
  chunked.ChunkNodes = 3;
  chunked.Layers = 8;
  const auto fixedMap = MakeLightShadow(fixed, ball->Caster, light, 0.5, 2);
  const auto chunkedMap = MakeLightShadow(chunked, ball->Caster, light, 0.5, 2);
  ASSERT_EQ(dynamic_cast<const DeepShadowMap&>(*fixedMap).GetStatistics().TexelsOverflowed, 0);
  std::mt19937 random(5);
  std::uniform_real_distribution<double> coordinate(-22.0, 22.0);
  for (int i = 0; i < 2000; ++i)
  {
    const glm::dvec3 p(coordinate(random), coordinate(random), coordinate(random));
    ASSERT_EQ(chunkedMap->Visibility(p), fixedMap->Visibility(p)) << p.x << " " << p.y << " " << p.z;
  }
}

TEST(NodeChunks, ASmallPoolDoublesTheBoundOfTheWholeMap)
{
  const auto sheets = Sheets();
  const Light light = closedform::Directional({ 0.0, 0.0, 1.0 });
  ShadowParameters p;
  p.Kind = ShadowKind::DeepShadowMap;
  p.MapSize = 16;
  p.ChunkNodes = 4;
  // 40-byte chunks: 0.01 MB is 262 of them, a node per texel and a bit.
  p.PoolMegabytes = 0.01;
  const auto map = MakeLightShadow(p, sheets->Caster, light, 0.25, 2);
  const auto& stats = dynamic_cast<const DeepShadowMap&>(*map).GetStatistics();
  EXPECT_GT(stats.EpsilonMax, p.Epsilon);
  EXPECT_EQ(stats.TexelsOverflowed, 0);
  EXPECT_LE(stats.ChunksUsed, 262);
  EXPECT_EQ(stats.ChunksCapacity, 262);
  // The doubled bound still holds: V' within it of Beer-Lambert (plus sampling).
  EXPECT_LE(WorstBeyondBeerLambert(*map, *sheets, light, stats.EpsilonMax), 0.0);
}
