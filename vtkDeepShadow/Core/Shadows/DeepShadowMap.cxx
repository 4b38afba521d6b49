#include "Core/Shadows/DeepShadowMap.h"
#include "Core/Shadows/NodeChunks.h"

#include "Core/Geometry/SurfaceSet.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <stdexcept>

namespace deepshadow
{

VisibilitySamples SampleVisibility(const ShadowCaster& caster, const glm::dvec3& origin,
  const glm::dvec3& direction, double step, bool colored, double stopAt)
{
  VisibilitySamples samples;
  glm::dvec3 transmittance(1.0);
  // A sample's interval starts with a point unless the previous sample's end is there.
  bool needStart = true;
  auto point = [&](double depth) {
    samples.Depths.push_back(depth);
    samples.Values.push_back(transmittance);
    if (std::max({ transmittance.r, transmittance.g, transmittance.b }) <= stopAt)
    {
      samples.Truncated = true;
      return false;
    }
    return true;
  };
  MarchTexelRay(
    caster, origin, direction, step, caster.Empty,
    [&](long, double t, const CastSample& scalar, bool skipped) {
      if (needStart)
      {
        samples.Depths.push_back(t - 0.5 * step);
        samples.Values.push_back(transmittance);
        needStart = false;
      }
      if (!skipped)
      {
        const glm::dvec4 sample = caster.Sample(scalar, step);
        transmittance *= colored ? 1.0 - sample.a * (1.0 - glm::dvec3(sample))
                                 : glm::dvec3(1.0 - sample.a);
      }
      return point(t + 0.5 * step);
    },
    [&](double t, int surface) {
      // A step: the value before and after at one depth.
      samples.Depths.push_back(t);
      samples.Values.push_back(transmittance);
      transmittance *= SurfaceTransmission(caster.Surfaces->GetSurface(surface).Material, colored);
      needStart = true;
      return point(t);
    });
  return samples;
}

namespace
{
// The float nearest `preferred` inside [low, high], or nearest it if none is.
float FloatInside(double low, double high, double preferred)
{
  const double target = std::clamp(preferred, low, high);
  float f = static_cast<float>(target);
  if (static_cast<double>(f) < low)
  {
    f = std::nextafter(f, std::numeric_limits<float>::infinity());
  }
  else if (static_cast<double>(f) > high)
  {
    f = std::nextafter(f, -std::numeric_limits<float>::infinity());
  }
  if (static_cast<double>(f) < low || static_cast<double>(f) > high)
  {
    f = static_cast<float>(target);
  }
  return f;
}

// The grid point nearest `preferred` inside [low, high], or nearest it if none is.
double GridInside(double low, double high, double preferred, double step)
{
  const double target = std::clamp(preferred, low, high);
  double stored = std::round(target / step) * step;
  if (stored < low && stored + step <= high)
  {
    stored += step;
  }
  else if (stored > high && stored - step >= low)
  {
    stored -= step;
  }
  return stored;
}
}

VisibilityCompressor::VisibilityCompressor(double epsilon, int channels, NodeGrid grid)
  : Epsilon(epsilon)
  , Channels(channels == 3 ? 3 : 1)
  , Grid(grid)
{
}

float VisibilityCompressor::StoredValue(double low, double high, double preferred) const
{
  return this->Grid.Value > 0.0 ? static_cast<float>(GridInside(low, high, preferred, this->Grid.Value))
                                : FloatInside(low, high, preferred);
}

void VisibilityCompressor::Add(double depth, const glm::dvec3& value)
{
  this->AddBounded(depth, value - this->Epsilon, value + this->Epsilon, value);
}

void VisibilityCompressor::AddBounded(
  double depth, const glm::dvec3& lowBound, const glm::dvec3& highBound, const glm::dvec3& preferred)
{
  // A visibility lies in [0, 1]: so must every node (a negative one would take light away
  // from what it shadows). The band always keeps the sample's own value.
  const glm::dvec3 low = glm::max(lowBound, glm::dvec3(0.0));
  const glm::dvec3 high = glm::min(highBound, glm::dvec3(1.0));
  // Work with the stored depth (a float, or a grid point), strictly increasing.
  if (this->Grid.Depth > 0.0)
  {
    const double stored = std::round(depth / this->Grid.Depth) * this->Grid.Depth;
    depth = this->Started && !(stored > this->LastDepth) ? this->LastDepth + this->Grid.Depth : stored;
  }
  else
  {
    float stored = static_cast<float>(depth);
    if (this->Started && !(static_cast<double>(stored) > this->LastDepth))
    {
      stored = std::nextafter(static_cast<float>(this->LastDepth), std::numeric_limits<float>::infinity());
    }
    depth = stored;
  }
  const float stored = static_cast<float>(depth);
  if (!this->Started)
  {
    VisibilityNode node{ stored, {} };
    for (int c = 0; c < 3; ++c)
    {
      const int channel = c < this->Channels ? c : 0;
      node.Value[c] = this->StoredValue(low[channel], high[channel], preferred[channel]);
      this->StartValue[c] = node.Value[c];
    }
    this->Nodes.push_back(node);
    this->Started = true;
    this->StartDepth = this->LastDepth = depth;
    this->HasSegment = false;
    return;
  }
  const double dz = depth - this->StartDepth;
  glm::dvec3 slopeLow = this->SlopeLow, slopeHigh = this->SlopeHigh;
  bool feasible = true;
  for (int c = 0; c < this->Channels; ++c)
  {
    const double lo = (low[c] - this->StartValue[c]) / dz;
    const double hi = (high[c] - this->StartValue[c]) / dz;
    slopeLow[c] = this->HasSegment ? std::max(slopeLow[c], lo) : lo;
    slopeHigh[c] = this->HasSegment ? std::min(slopeHigh[c], hi) : hi;
    feasible = feasible && slopeLow[c] <= slopeHigh[c];
  }
  if (feasible || !this->HasSegment)
  {
    this->SlopeLow = slopeLow;
    this->SlopeHigh = slopeHigh;
    this->LastDepth = depth;
    this->LastPreferred = preferred;
    this->HasSegment = true;
    return;
  }
  // No line from the start reaches this sample too: end the segment at the previous one and
  // start the next there (one constraint is always feasible).
  this->EndSegment();
  this->AddBounded(depth, low, high, preferred);
}

void VisibilityCompressor::EndSegment()
{
  const double dz = this->LastDepth - this->StartDepth;
  VisibilityNode node{ static_cast<float>(this->LastDepth), {} };
  for (int c = 0; c < 3; ++c)
  {
    const int channel = c < this->Channels ? c : 0;
    node.Value[c] = this->StoredValue(this->StartValue[channel] + this->SlopeLow[channel] * dz,
      this->StartValue[channel] + this->SlopeHigh[channel] * dz, this->LastPreferred[channel]);
  }
  this->Nodes.push_back(node);
  this->StartDepth = this->LastDepth;
  for (int c = 0; c < 3; ++c)
  {
    this->StartValue[c] = node.Value[c];
  }
  this->HasSegment = false;
}

std::vector<VisibilityNode> VisibilityCompressor::Finish()
{
  if (this->HasSegment)
  {
    // V' keeps the last node's value beyond it: a level last segment needs no end node.
    bool level = true;
    for (int c = 0; c < this->Channels; ++c)
    {
      level = level && this->SlopeLow[c] <= 0.0 && 0.0 <= this->SlopeHigh[c];
    }
    if (!level)
    {
      this->EndSegment();
    }
    this->HasSegment = false;
  }
  return this->Nodes;
}

CompressedVisibility CompressVisibility(
  const VisibilitySamples& samples, int channels, double epsilon, int maxNodes)
{
  if (maxNodes < 1 || !(epsilon >= 0.0))
  {
    throw std::invalid_argument("CompressVisibility needs maxNodes >= 1 and epsilon >= 0");
  }
  auto compress = [&](double bound) {
    VisibilityCompressor compressor(bound, channels);
    const size_t count = samples.Depths.size();
    for (size_t i = 0; i < count; ++i)
    {
      const glm::dvec3& value = samples.Values[i];
      if (samples.Truncated && i + 1 == count)
      {
        // Beyond here V is somewhere in [0, value]: V' must be within the bound of all of it.
        if (std::max({ value.r, value.g, value.b }) > bound)
        {
          throw std::invalid_argument("truncated visibility samples end above the bound");
        }
        compressor.AddBounded(samples.Depths[i], value - bound, glm::dvec3(bound), value);
      }
      else
      {
        compressor.Add(samples.Depths[i], value);
      }
    }
    return compressor.Finish();
  };
  CompressedVisibility result;
  result.Nodes = compress(epsilon);
  result.NodesNeeded = static_cast<int>(result.Nodes.size());
  result.Epsilon = epsilon;
  while (static_cast<int>(result.Nodes.size()) > maxNodes)
  {
    result.Epsilon = std::max(2.0 * result.Epsilon, 1.0 / 1024.0);
    result.Nodes = compress(result.Epsilon);
  }
  return result;
}

int NodesAtOrBefore(const VisibilityNode* nodes, int count, double depth)
{
  // A binary search (the GLSL twins search the same way).
  int first = 0, remaining = count;
  while (remaining > 0)
  {
    const int half = remaining / 2;
    if (static_cast<double>(nodes[first + half].Depth) <= depth)
    {
      first += half + 1;
      remaining -= half + 1;
    }
    else
    {
      remaining = half;
    }
  }
  return first;
}

glm::dvec3 InterpolateNodes(const VisibilityNode& a, const VisibilityNode& b, double depth)
{
  const glm::dvec3 va(a.Value[0], a.Value[1], a.Value[2]);
  const glm::dvec3 vb(b.Value[0], b.Value[1], b.Value[2]);
  const double f = (depth - a.Depth) / (static_cast<double>(b.Depth) - a.Depth);
  return va + f * (vb - va);
}

glm::dvec3 EvaluateVisibility(const VisibilityNode* nodes, int count, double depth)
{
  const int first = NodesAtOrBefore(nodes, count, depth);
  if (first == 0)
  {
    return glm::dvec3(1.0);
  }
  const VisibilityNode& a = nodes[first - 1];
  if (first == count)
  {
    return glm::dvec3(a.Value[0], a.Value[1], a.Value[2]);
  }
  return InterpolateNodes(a, nodes[first], depth);
}

DeepShadowMap::DeepShadowMap(const ShadowParameters& parameters, const ShadowCaster& caster,
  const Light& light, double step, int threads)
  : LightSpaceShadow(parameters, caster, light, step)
  , Channels(parameters.Colored ? 3 : 1)
  , Layers(std::max(1, parameters.Layers))
{
  if (parameters.ChunkNodes > 0)
  {
    this->BuildChunked(parameters, step, threads);
    return;
  }
  this->Nodes.assign(this->TexelCount() * this->Layers, VisibilityNode{ NoHit, { 1.0f, 1.0f, 1.0f } });
  std::mutex statisticsMutex;
  long nodesTotal = 0;
  this->ForEachTexel(threads, [&](int f, int x, int y, const glm::dvec3& origin, const glm::dvec3& direction) {
    const VisibilitySamples samples =
      SampleVisibility(this->FaceCaster(f), origin, direction, step, parameters.Colored, parameters.Epsilon);
    if (samples.Depths.empty())
    {
      return; // the ray misses the volume: V' = 1
    }
    const CompressedVisibility compressed =
      CompressVisibility(samples, this->Channels, parameters.Epsilon, this->Layers);
    VisibilityNode* texel = &this->Nodes[this->Texel(f, x, y) * this->Layers];
    std::copy(compressed.Nodes.begin(), compressed.Nodes.end(), texel);
    // Unused nodes repeat the last value far away, as on the GPU.
    for (size_t k = compressed.Nodes.size(); k < static_cast<size_t>(this->Layers); ++k)
    {
      texel[k] = VisibilityNode{ NoHit, compressed.Nodes.back().Value };
    }
    const std::lock_guard<std::mutex> lock(statisticsMutex);
    DeepShadowMapStatistics& s = this->Statistics;
    ++s.TexelsHit;
    nodesTotal += compressed.NodesNeeded;
    s.NodesMax = std::max(s.NodesMax, compressed.NodesNeeded);
    s.TexelsOverflowed += compressed.NodesNeeded > this->Layers ? 1 : 0;
    s.EpsilonMax = std::max(s.EpsilonMax, compressed.Epsilon);
  });
  if (this->Statistics.TexelsHit > 0)
  {
    this->Statistics.NodesAverage = static_cast<double>(nodesTotal) / this->Statistics.TexelsHit;
  }
}

DeepShadowMap::~DeepShadowMap() = default;

void DeepShadowMap::BuildChunked(const ShadowParameters& parameters, double step, int threads)
{
  const size_t texels = this->TexelCount();
  const long long capacity = ChunkPoolCapacity(
    texels, parameters.ChunkNodes, parameters.Colored, this->Layers, parameters.PoolMegabytes);
  for (double bound = parameters.Epsilon; bound >= 0.0;)
  {
    // Compressed first, then stored: the pool's memory is then what the texels ask for,
    // whatever its limit.
    std::vector<std::vector<VisibilityNode>> texelNodes(texels);
    DeepShadowMapStatistics s;
    long nodesTotal = 0;
    std::mutex statisticsMutex;
    this->ForEachTexel(threads, [&](int f, int x, int y, const glm::dvec3& origin, const glm::dvec3& direction) {
      const VisibilitySamples samples =
        SampleVisibility(this->FaceCaster(f), origin, direction, step, parameters.Colored, bound);
      if (samples.Depths.empty())
      {
        return;
      }
      CompressedVisibility compressed =
        CompressVisibility(samples, this->Channels, bound, std::numeric_limits<int>::max());
      const std::lock_guard<std::mutex> lock(statisticsMutex);
      ++s.TexelsHit;
      nodesTotal += compressed.NodesNeeded;
      s.NodesMax = std::max(s.NodesMax, compressed.NodesNeeded);
      s.EpsilonMax = bound;
      texelNodes[this->Texel(f, x, y)] = std::move(compressed.Nodes);
    });
    long long expected = 0;
    for (const auto& nodes : texelNodes)
    {
      expected += NodeChunks::ChunksFor(nodes, parameters.ChunkNodes);
    }
    auto chunks = std::make_unique<NodeChunks>(texels, parameters.ChunkNodes, capacity, expected);
    for (size_t texel = 0; texel < texels; ++texel)
    {
      s.TexelsOverflowed += chunks->Store(texel, texelNodes[texel]) ? 0 : 1;
    }
    s.NodesAverage = s.TexelsHit > 0 ? static_cast<double>(nodesTotal) / s.TexelsHit : 0.0;
    s.ChunksUsed = chunks->Used();
    s.ChunksCapacity = capacity;
    bound = ChunkedBuildBound(bound, chunks->Requested(), capacity);
    this->Chunks = std::move(chunks);
    this->Statistics = s;
  }
}

size_t DeepShadowMap::Bytes() const
{
  if (this->Chunks)
  {
    // The start table and the chunks taken, as the GPU stores them.
    return this->TexelCount() * sizeof(float) +
      static_cast<size_t>(this->Chunks->Used() * ChunkBytes(this->Chunks->ChunkNodes(), this->Channels == 3));
  }
  return this->TexelCount() * this->Layers * sizeof(float) * (this->Channels == 3 ? 4 : 2);
}

glm::dvec3 DeepShadowMap::MapVisibility(const MapPoint& point) const
{
  if (this->Chunks)
  {
    return this->Bilinear(point, [&](size_t texel, double depth) { return this->Chunks->Evaluate(texel, depth); });
  }
  return this->Bilinear(point, [&](size_t texel, double depth) {
    return EvaluateVisibility(&this->Nodes[texel * this->Layers], this->Layers, depth);
  });
}

}
