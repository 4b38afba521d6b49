#include "Core/Shadows/FixedBudgetDeepShadowMap.h"

#include "Core/ShadowTechniques.h"
#include "Core/Shadows/DeepShadowMap.h"

#include <algorithm>
#include <cmath>
#include <mutex>

namespace deepshadow
{

int FixedBudgetBits(const ShadowParameters& parameters)
{
  return static_cast<int>(FindShadowParameter("dsm-bits")->Get(parameters).at(0));
}

double FixedBudgetError(const ShadowParameters& parameters)
{
  return FindShadowParameter("dsm-fixed-error")->Get(parameters).at(0);
}

int FixedNodesForError(const std::vector<long long>& histogram)
{
  long long total = 0;
  for (long long count : histogram)
  {
    total += count;
  }
  int nodes = 0;
  long long below = 0;
  // The smallest n with at least the percentile of the texels at n nodes or fewer.
  while (nodes + 1 < static_cast<int>(histogram.size()) &&
    static_cast<double>(below + histogram[static_cast<size_t>(nodes)]) < FixedNodePercentile * static_cast<double>(total))
  {
    below += histogram[static_cast<size_t>(nodes)];
    ++nodes;
  }
  return std::clamp(nodes + (nodes % 2), 2, MaxFixedNodes);
}

namespace
{
constexpr double UnormMax = 65535.0;

// One attempt at `bound`: the nodes from the first absorbing depth on, or none where the
// ray absorbs nothing (then `hit` is false).
std::vector<VisibilityNode> CompressFromFirstHit(const ShadowCaster& caster, const glm::dvec3& origin,
  const glm::dvec3& direction, double step, double bound, double depthStep, bool& hit)
{
  const VisibilitySamples samples = SampleVisibility(caster, origin, direction, step, false, bound);
  const size_t count = samples.Depths.size();
  size_t first = 0;
  while (first < count && samples.Values[first].r >= 1.0)
  {
    ++first;
  }
  hit = first < count;
  if (!hit)
  {
    return {};
  }
  // The point before the first absorbing one starts its interval (or is a mesh's step).
  VisibilityCompressor compressor(bound, 1, NodeGrid{ depthStep, 1.0 / UnormMax });
  compressor.AddBounded(std::floor(samples.Depths[first - 1] / depthStep) * depthStep, glm::dvec3(1.0),
    glm::dvec3(1.0), glm::dvec3(1.0));
  for (size_t i = first; i < count; ++i)
  {
    const glm::dvec3& value = samples.Values[i];
    if (samples.Truncated && i + 1 == count)
    {
      // Beyond here V lies in [0, value] (as CompressVisibility).
      compressor.AddBounded(samples.Depths[i], value - bound, glm::dvec3(bound), value);
    }
    else
    {
      compressor.Add(samples.Depths[i], value);
    }
  }
  return compressor.Finish();
}

std::uint16_t Unorm(double x)
{
  return static_cast<std::uint16_t>(std::clamp(std::round(x * UnormMax), 0.0, UnormMax));
}
}

int FixedNodesWithin(const ShadowCaster& caster, const glm::dvec3& origin, const glm::dvec3& direction,
  double step, double bound, double depthRange)
{
  bool hit = false;
  const size_t nodes = CompressFromFirstHit(caster, origin, direction, step, bound, depthRange / UnormMax, hit).size();
  return hit ? static_cast<int>(nodes) : 0;
}

FixedBudgetTexel FitFixedBudget(const ShadowCaster& caster, const glm::dvec3& origin,
  const glm::dvec3& direction, double step, int nodes, double depthRange)
{
  const double depthStep = depthRange / UnormMax;
  FixedBudgetTexel texel;
  texel.Nodes.assign(2 * static_cast<size_t>(nodes), static_cast<std::uint16_t>(UnormMax));
  std::vector<VisibilityNode> best;
  double bound = std::ldexp(1.0, FixedBoundLog2Min);
  best = CompressFromFirstHit(caster, origin, direction, step, bound, depthStep, texel.Hit);
  if (!texel.Hit)
  {
    return texel;
  }
  if (static_cast<int>(best.size()) > nodes)
  {
    // Bisection of log2 epsilon: lo never fits, hi always does (one node at a bound of 1).
    double lo = FixedBoundLog2Min, hi = 0.0;
    best.clear();
    for (int i = 0; i < FixedBisectionSteps; ++i)
    {
      const double middle = 0.5 * (lo + hi);
      bool hit = false;
      std::vector<VisibilityNode> attempt =
        CompressFromFirstHit(caster, origin, direction, step, std::exp2(middle), depthStep, hit);
      if (static_cast<int>(attempt.size()) <= nodes)
      {
        hi = middle;
        best = std::move(attempt);
      }
      else
      {
        lo = middle;
      }
    }
    bound = std::exp2(hi);
    if (best.empty())
    {
      bool hit = false;
      best = CompressFromFirstHit(caster, origin, direction, step, bound, depthStep, hit);
    }
  }
  texel.Epsilon = bound;
  const std::uint16_t last = Unorm(best.back().Value[0]);
  for (int i = 0; i < nodes; ++i)
  {
    const bool used = i < static_cast<int>(best.size());
    texel.Nodes[2 * i] = used ? Unorm(best[i].Depth / depthRange) : static_cast<std::uint16_t>(UnormMax);
    texel.Nodes[2 * i + 1] = used ? Unorm(best[i].Value[0]) : last;
  }
  return texel;
}

double EvaluateFixedNodes(const std::uint16_t* nodes, int count, double depth)
{
  double visibility = 1.0;
  double previousDepth = nodes[0] / UnormMax, previousValue = nodes[1] / UnormMax;
  for (int i = 1; i < count; ++i)
  {
    const double nodeDepth = nodes[2 * i] / UnormMax, nodeValue = nodes[2 * i + 1] / UnormMax;
    visibility += (nodeValue - previousValue) *
      std::clamp((depth - previousDepth) / std::max(nodeDepth - previousDepth, 1e-9), 0.0, 1.0);
    previousDepth = nodeDepth;
    previousValue = nodeValue;
  }
  return visibility;
}

FixedBudgetDeepShadowMap::FixedBudgetDeepShadowMap(const ShadowParameters& parameters,
  const ShadowCaster& caster, const Light& light, double step, int threads)
  : LightSpaceShadow(parameters, caster, light, step)
  , Count(FixedBudgetNodes(parameters))
  , DepthRange(LightDepthRange(
      CasterBoundsOf(caster.Grid->GetIndexToWorld(), caster.Grid->GetDims(), caster.Surfaces).Radius))
{
  const double error = FixedBudgetError(parameters);
  std::vector<long long> needed(MaxFixedNodes + 2, 0); // texels by the nodes they need (last: more)
  if (error > 0.0)
  {
    // An error instead of a budget: the nodes each texel needs within it, their percentile.
    std::mutex countMutex;
    this->ForEachTexel(threads, [&](int f, int, int, const glm::dvec3& origin, const glm::dvec3& direction) {
      const int nodes = FixedNodesWithin(this->FaceCaster(f), origin, direction, step, error, this->DepthRange);
      if (nodes > 0)
      {
        const std::lock_guard<std::mutex> lock(countMutex);
        ++needed[static_cast<size_t>(std::min(nodes, MaxFixedNodes + 1))];
      }
    });
    this->Count = FixedNodesForError(needed);
  }
  this->Statistics.Nodes = this->Count;
  this->Nodes.assign(this->TexelCount() * 2 * this->Count, static_cast<std::uint16_t>(UnormMax));
  std::mutex statisticsMutex;
  double epsilonTotal = 0.0;
  this->ForEachTexel(threads, [&](int f, int x, int y, const glm::dvec3& origin, const glm::dvec3& direction) {
    const FixedBudgetTexel texel =
      FitFixedBudget(this->FaceCaster(f), origin, direction, step, this->Count, this->DepthRange);
    std::copy(texel.Nodes.begin(), texel.Nodes.end(), this->Nodes.begin() + this->Texel(f, x, y) * 2 * this->Count);
    if (texel.Hit)
    {
      const std::lock_guard<std::mutex> lock(statisticsMutex);
      ++this->Statistics.TexelsHit;
      epsilonTotal += texel.Epsilon;
      this->Statistics.EpsilonMax = std::max(this->Statistics.EpsilonMax, texel.Epsilon);
    }
  });
  if (this->Statistics.TexelsHit > 0)
  {
    this->Statistics.EpsilonMean = epsilonTotal / this->Statistics.TexelsHit;
    long long beyond = 0;
    for (size_t n = static_cast<size_t>(this->Count) + 1; n < needed.size(); ++n)
    {
      beyond += needed[n];
    }
    this->Statistics.BeyondError = static_cast<double>(beyond) / static_cast<double>(this->Statistics.TexelsHit);
  }
}

glm::dvec3 FixedBudgetDeepShadowMap::MapVisibility(const MapPoint& point) const
{
  return this->Bilinear(point, [&](size_t texel, double depth) {
    return glm::dvec3(EvaluateFixedNodes(&this->Nodes[texel * 2 * this->Count], this->Count, depth / this->DepthRange));
  });
}

}
