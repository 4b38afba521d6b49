#include "Core/Shadows/StochasticShadowMap.h"

#include "Core/Geometry/SurfaceSet.h"

#include "Core/Jitter.h"

#include <cmath>
#include <stdexcept>

namespace deepshadow
{

const std::vector<glm::ivec2>& StochasticOffsets(int count)
{
  static const std::vector<glm::ivec2> seven{ { 0, 0 }, { 4, 0 }, { -4, 0 }, { 0, 4 }, { 0, -4 },
    { 3, 3 }, { -3, -3 } };
  static const std::vector<glm::ivec2> thirteen{ { 0, 0 }, { 3, 3 }, { -3, 3 }, { 3, -3 },
    { -3, -3 }, { 4, 0 }, { -4, 0 }, { 0, 4 }, { 0, -4 }, { 7, 0 }, { -7, 0 }, { 0, 7 },
    { 0, -7 } };
  static const std::vector<glm::ivec2> twentyOne = [] {
    std::vector<glm::ivec2> offsets = thirteen;
    offsets.insert(offsets.end(), { { 7, 7 }, { -7, 7 }, { 7, -7 }, { -7, -7 }, { 10, 0 },
                                    { -10, 0 }, { 0, 10 }, { 0, -10 } });
    return offsets;
  }();
  switch (count)
  {
    case 7:
      return seven;
    case 13:
      return thirteen;
    case 21:
      return twentyOne;
    default:
      throw std::invalid_argument(
        "CSSM offsets must be 7, 13 or 21, not " + std::to_string(count));
  }
}

double StochasticThreshold(uint32_t x, uint32_t y, uint32_t layer, uint32_t segment, uint32_t seed)
{
  const uint32_t hash = PcgHash(x + PcgHash(y + PcgHash(layer + PcgHash(segment + PcgHash(seed)))));
  return static_cast<double>(hash >> 8u) * (1.0 / 16777216.0);
}

std::array<float, 3> TraceStochasticPhoton(const ShadowCaster& caster, const glm::dvec3& origin,
  const glm::dvec3& direction, double step, uint32_t x, uint32_t y, uint32_t layer, uint32_t seed)
{
  std::array<float, 3> stop{ { NoHit, NoHit, NoHit } };
  // A photon stops in channel c where rho_c exceeds the segment's random threshold.
  auto segment = [&](double t, const glm::dvec3& rho, uint32_t id) {
    const double r = StochasticThreshold(x, y, layer, id, seed);
    bool all = true;
    for (int c = 0; c < 3; ++c)
    {
      if (stop[c] == NoHit && rho[c] > r)
      {
        stop[c] = static_cast<float>(t);
      }
      all = all && stop[c] != NoHit;
    }
    return !all;
  };
  uint32_t crossings = 0;
  MarchTexelRay(
    caster, origin, direction, step, caster.Empty,
    [&](long j, double t, const CastSample& scalar, bool skipped) {
      if (skipped)
      {
        return true; // no photon stops in empty space
      }
      const glm::dvec4 sample = caster.Sample(scalar, step);
      return segment(t, sample.a * (1.0 - glm::dvec3(sample)), static_cast<uint32_t>(j));
    },
    [&](double t, int surface) {
      // A surface is a segment of its own: rho = what it stops of each channel.
      const glm::dvec3 rho =
        1.0 - SurfaceTransmission(caster.Surfaces->GetSurface(surface).Material, true);
      return segment(t, rho, SurfaceSegmentBase + crossings++);
    });
  return stop;
}

StochasticShadowMap::StochasticShadowMap(const ShadowParameters& parameters,
  const ShadowCaster& caster, const Light& light, double step, int threads)
  : LightSpaceShadow(parameters, caster, light, step)
  , Photons(std::max(1, parameters.Photons))
{
  StochasticOffsets(parameters.Offsets); // validates the count before the work
  this->Stops.assign(this->TexelCount() * this->Photons, { { NoHit, NoHit, NoHit } });
  this->ForEachTexel(threads, [&](int f, int x, int y, const glm::dvec3& origin, const glm::dvec3& direction) {
    for (int photon = 0; photon < this->Photons; ++photon)
    {
      this->Stops[this->Texel(f, x, y) * this->Photons + photon] = TraceStochasticPhoton(this->FaceCaster(f),
        origin, direction, step, static_cast<uint32_t>(x), static_cast<uint32_t>(y),
        static_cast<uint32_t>(f * this->Photons + photon), parameters.Seed);
    }
  });
}

glm::dvec3 StochasticShadowMap::MapVisibility(const MapPoint& point) const
{
  const int nx = static_cast<int>(std::floor(point.X + 0.5)), ny = static_cast<int>(std::floor(point.Y + 0.5));
  const auto& offsets = StochasticOffsets(this->Parameters.Offsets);
  glm::dvec3 lit(0.0);
  for (const glm::ivec2& o : offsets)
  {
    const size_t texel = this->Texel(point.Face, nx + o.x, ny + o.y);
    const double depth = point.DepthAt(nx + o.x, ny + o.y);
    for (int photon = 0; photon < this->Photons; ++photon)
    {
      const std::array<float, 3>& stop = this->Stops[texel * this->Photons + photon];
      for (int c = 0; c < 3; ++c)
      {
        lit[c] += static_cast<double>(stop[c]) > depth ? 1.0 : 0.0;
      }
    }
  }
  return lit / static_cast<double>(offsets.size() * this->Photons);
}

}
