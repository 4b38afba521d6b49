#include "Core/Shadows/AdaptiveVolumetricShadowMap.h"

#include "Core/Geometry/SurfaceSet.h"
#include "Core/ShadowTechniques.h"

#include <algorithm>
#include <cmath>

namespace deepshadow
{

int AdaptiveNodes(const ShadowParameters& parameters)
{
  return static_cast<int>(FindShadowParameter("avsm-nodes")->Get(parameters).at(0));
}

AdaptiveNodesBuilder::AdaptiveNodesBuilder(int nodes)
  : Nodes(nodes)
{
  this->Depth.reserve(nodes + 1);
  this->Value.reserve(nodes + 1);
}

void AdaptiveNodesBuilder::Add(double from, double to, double transmission)
{
  if (transmission >= 1.0)
  {
    this->AddClear();
    return;
  }
  // Where the samples before absorbed nothing, the curve is flat up to this one's start.
  if (!this->Absorbing)
  {
    this->Append(from, this->Transmittance);
  }
  this->Absorbing = true;
  this->Transmittance *= transmission;
  this->Append(to, this->Transmittance);
}

void AdaptiveNodesBuilder::Append(double depth, double transmittance)
{
  this->Depth.push_back(static_cast<float>(depth));
  this->Value.push_back(static_cast<float>(transmittance));
  const int count = static_cast<int>(this->Depth.size());
  if (count <= this->Nodes)
  {
    return;
  }
  // AVSM's compression: drop the interior node whose triangle with its neighbours has the
  // smallest area (in float arithmetic, as the GLSL twin computes it).
  int drop = 1;
  float smallest = 0.0f;
  for (int i = 1; i + 1 < count; ++i)
  {
    const float area = std::abs((this->Depth[i] - this->Depth[i - 1]) * (this->Value[i + 1] - this->Value[i - 1]) -
      (this->Depth[i + 1] - this->Depth[i - 1]) * (this->Value[i] - this->Value[i - 1]));
    if (i == 1 || area < smallest)
    {
      smallest = area;
      drop = i;
    }
  }
  this->Depth.erase(this->Depth.begin() + drop);
  this->Value.erase(this->Value.begin() + drop);
}

std::vector<float> AdaptiveNodesBuilder::Finish() const
{
  std::vector<float> nodes(2 * static_cast<size_t>(this->Nodes));
  const float last = this->Value.empty() ? 1.0f : this->Value.back();
  for (int i = 0; i < this->Nodes; ++i)
  {
    const bool used = i < static_cast<int>(this->Depth.size());
    nodes[2 * i] = used ? this->Depth[i] : NoHit;
    nodes[2 * i + 1] = used ? this->Value[i] : last;
  }
  return nodes;
}

double EvaluateAdaptiveNodes(const float* nodes, int count, double depth)
{
  if (depth < nodes[0])
  {
    return 1.0;
  }
  for (int i = 0; i + 1 < count; ++i)
  {
    const double d0 = nodes[2 * i], d1 = nodes[2 * i + 2];
    if (depth < d1)
    {
      return nodes[2 * i + 1] + (depth - d0) / (d1 - d0) * (nodes[2 * i + 3] - nodes[2 * i + 1]);
    }
  }
  return nodes[2 * count - 1];
}

AdaptiveVolumetricShadowMap::AdaptiveVolumetricShadowMap(const ShadowParameters& parameters,
  const ShadowCaster& caster, const Light& light, double step, int threads)
  : LightSpaceShadow(parameters, caster, light, step)
  , Count(AdaptiveNodes(parameters))
{
  const bool meshes = caster.Surfaces && !caster.Surfaces->Empty();
  this->Nodes.assign(this->TexelCount() * 2 * this->Count, 0.0f);
  if (meshes)
  {
    this->Steps.assign(this->TexelCount(), SurfaceSteps());
  }
  this->ForEachTexel(threads, [&](int f, int x, int y, const glm::dvec3& origin, const glm::dvec3& direction) {
    AdaptiveNodesBuilder nodes(this->Count);
    SurfaceStepsBuilder steps;
    MarchBesideSurfaceSteps(this->FaceCaster(f), caster, origin, direction, step, steps,
      [&](double t, double opacity, bool skipped, double) {
        if (skipped)
        {
          nodes.AddClear();
        }
        else
        {
          nodes.Add(t - 0.5 * step, t + 0.5 * step, 1.0 - opacity);
        }
      });
    const size_t texel = this->Texel(f, x, y);
    const std::vector<float> stored = nodes.Finish();
    std::copy(stored.begin(), stored.end(), this->Nodes.begin() + texel * 2 * this->Count);
    if (meshes)
    {
      this->Steps[texel] = steps.Finish();
    }
  });
}

glm::dvec3 AdaptiveVolumetricShadowMap::MapVisibility(const MapPoint& point) const
{
  return this->Bilinear(point, [&](size_t texel, double depth) {
    const double volume = EvaluateAdaptiveNodes(&this->Nodes[texel * 2 * this->Count], this->Count, depth);
    return glm::dvec3(this->Steps.empty() ? volume : volume * EvaluateSurfaceSteps(this->Steps[texel], depth));
  });
}

}
