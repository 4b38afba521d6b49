#include "Shadows.h"

#include "Camera.h"
#include "OpticalModel.h"
#include "Parallel.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace deepshadow
{

ShadowParameters ShadowParameters::GroundTruth(double stepFactor)
{
  ShadowParameters p;
  p.Kind = ShadowKind::Rays;
  p.StepFactor = stepFactor;
  p.EarlyTermination = false;
  return p;
}

std::string ShadowParameters::Name() const
{
  switch (this->Kind)
  {
    case ShadowKind::None:
      return "none";
    case ShadowKind::ShadowMap:
      return "shadowmap";
    case ShadowKind::Rays:
      break;
  }
  return std::string("rays") + (this->Opaque ? "-opaque" : "") + (this->Cached ? "-cached" : "");
}

const std::vector<glm::dvec2>& PoissonDisc()
{
  // A 12-point Poisson disc in the unit circle, scaled to a radius of 2 texels.
  static const std::vector<glm::dvec2> disc = [] {
    const double unit[12][2] = { { -0.326212, -0.405805 }, { -0.840144, -0.073580 },
      { -0.695914, 0.457137 }, { -0.203345, 0.620716 }, { 0.962340, -0.194983 },
      { 0.473434, -0.480026 }, { 0.519456, 0.767022 }, { 0.185461, -0.893124 },
      { 0.507431, 0.064425 }, { 0.896420, 0.412458 }, { -0.321940, -0.932615 },
      { -0.791559, -0.597705 } };
    std::vector<glm::dvec2> points;
    for (const auto& p : unit)
    {
      points.emplace_back(2.0 * p[0], 2.0 * p[1]);
    }
    return points;
  }();
  return disc;
}

glm::ivec3 ShadowVolumeDims(const glm::ivec3& dataDims, int size)
{
  // Never finer than the data: a feeler per voxel is all the data can tell.
  const int longest = std::max({ dataDims.x, dataDims.y, dataDims.z });
  size = std::min(size, longest);
  glm::ivec3 dims;
  for (int axis = 0; axis < 3; ++axis)
  {
    dims[axis] = std::max(2, static_cast<int>(std::lround(
                               static_cast<double>(dataDims[axis]) * size / longest)));
  }
  return dims;
}

namespace
{
// Corrected opacity of a feeler sample and whether it exceeds the threshold.
struct FeelerSampler
{
  const ShadowCaster& Caster;
  const ShadowParameters& Parameters;
  double Step;
  double CorrectedThreshold;

  FeelerSampler(const ShadowCaster& caster, const ShadowParameters& parameters, double step)
    : Caster(caster)
    , Parameters(parameters)
    , Step(step)
    , CorrectedThreshold(CorrectOpacity(
        parameters.Threshold, step, caster.Transfer->OpacityUnitDistance))
  {
  }

  double Alpha(double scalar) const
  {
    return this->Caster.FeelerTable
      ? this->Caster.FeelerTable->Lookup(scalar).a
      : CorrectOpacity(this->Caster.Transfer->Opacity.Evaluate(scalar), this->Step,
          this->Caster.Transfer->OpacityUnitDistance);
  }

  bool AboveThreshold(double scalar) const
  {
    if (this->Parameters.Mode == ThresholdMode::Scalar)
    {
      const glm::dvec2 range = this->Caster.Grid->GetRange();
      const double width = range.y > range.x ? range.y - range.x : 1.0;
      return (scalar - range.x) / width > this->Parameters.Threshold;
    }
    if (this->Caster.FeelerTable)
    {
      return this->Caster.FeelerTable->Lookup(scalar).a > this->CorrectedThreshold;
    }
    return this->Caster.Transfer->Opacity.Evaluate(scalar) > this->Parameters.Threshold;
  }
};

double DistanceToLight(const Light& light, const glm::dvec3& p)
{
  return light.Positional ? glm::length(light.Position - p) : std::numeric_limits<double>::infinity();
}

glm::dvec3 DirectionToLight(const Light& light, const glm::dvec3& p)
{
  return light.At(p).ToLight;
}

class RayShadow : public LightShadow
{
public:
  RayShadow(const ShadowParameters& parameters, const ShadowCaster& caster, const Light& light,
    double step)
    : Parameters(parameters)
    , Caster(caster)
    , TheLight(light)
    , Step(step)
  {
  }
  double Visibility(const glm::dvec3& p) const override
  {
    return FeelerVisibility(this->Caster, p, DirectionToLight(this->TheLight, p),
      DistanceToLight(this->TheLight, p), this->Step, this->Parameters);
  }

private:
  ShadowParameters Parameters;
  ShadowCaster Caster;
  Light TheLight;
  double Step;
};

// The feeler evaluated once per node of a grid spanning the volume's box, then trilinear.
class CachedShadow : public LightShadow
{
public:
  CachedShadow(const ShadowParameters& parameters, const ShadowCaster& caster, const Light& light,
    double step, int threads)
    : Grid(*caster.Grid)
    , Dims(ShadowVolumeDims(caster.Grid->GetDims(), parameters.VolumeSize))
    , Values(static_cast<size_t>(Dims.x) * Dims.y * Dims.z)
  {
    RayShadow rays(parameters, caster, light, step);
    const glm::dvec3 nodeToIndex = glm::dvec3(this->Grid.GetDims() - 1) / glm::dvec3(this->Dims - 1);
    ParallelFor(
      this->Dims.z,
      [&](int k) {
        for (int j = 0; j < this->Dims.y; ++j)
        {
          for (int i = 0; i < this->Dims.x; ++i)
          {
            const glm::dvec3 index = glm::dvec3(i, j, k) * nodeToIndex;
            const glm::dvec3 world = glm::dvec3(this->Grid.GetIndexToWorld() * glm::dvec4(index, 1.0));
            this->Values[i + static_cast<size_t>(this->Dims.x) * (j + static_cast<size_t>(this->Dims.y) * k)] =
              static_cast<float>(rays.Visibility(world));
          }
        }
      },
      threads);
  }

  double Visibility(const glm::dvec3& p) const override
  {
    const glm::dvec3 index = glm::dvec3(this->Grid.GetWorldToIndex() * glm::dvec4(p, 1.0));
    const glm::dvec3 node = glm::clamp(index * glm::dvec3(this->Dims - 1) / glm::dvec3(this->Grid.GetDims() - 1),
      glm::dvec3(0.0), glm::dvec3(this->Dims - 1));
    const glm::ivec3 n0 = glm::min(glm::ivec3(glm::floor(node)), this->Dims - 2);
    const glm::dvec3 t = node - glm::dvec3(n0);
    auto at = [&](int i, int j, int k) {
      return static_cast<double>(this->Values[i + static_cast<size_t>(this->Dims.x) *
          (j + static_cast<size_t>(this->Dims.y) * k)]);
    };
    double result = 0.0;
    for (int c = 0; c < 8; ++c)
    {
      const glm::ivec3 o((c & 1), (c >> 1) & 1, (c >> 2) & 1);
      const double w = (o.x ? t.x : 1.0 - t.x) * (o.y ? t.y : 1.0 - t.y) * (o.z ? t.z : 1.0 - t.z);
      result += w * at(n0.x + o.x, n0.y + o.y, n0.z + o.z);
    }
    return result;
  }
  size_t Bytes() const override { return this->Values.size() * sizeof(float); }

private:
  const VolumeGrid& Grid;
  glm::ivec3 Dims;
  std::vector<float> Values;
};

class MapShadow : public LightShadow
{
public:
  MapShadow(const ShadowParameters& parameters, const ShadowCaster& caster, const Light& light,
    double step, int threads)
    : Size(std::max(1, parameters.MapSize))
    , Bias(parameters.Bias * step)
    , Filter(parameters.Filter)
  {
    glm::dvec3 centre;
    double radius = 0.0;
    VolumeBoundingSphere(caster.Grid->GetIndexToWorld(), caster.Grid->GetDims(), centre, radius);
    this->Faces = ShadowMapFaces(light, centre, radius);
    this->Depths.assign(this->Faces.size() * this->Size * this->Size, std::numeric_limits<float>::max());
    const FeelerSampler sampler(caster, parameters, step);
    for (size_t f = 0; f < this->Faces.size(); ++f)
    {
      ParallelFor(
        this->Size,
        [&](int y) {
          for (int x = 0; x < this->Size; ++x)
          {
            glm::dvec3 origin, direction;
            this->Faces[f].TexelRay(
              2.0 * (x + 0.5) / this->Size - 1.0, 2.0 * (y + 0.5) / this->Size - 1.0, origin, direction);
            this->Depths[(f * this->Size + y) * this->Size + x] =
              static_cast<float>(FirstHit(sampler, origin, direction, step));
          }
        },
        threads);
    }
  }

  // Depth along the texel ray of the first sample above the threshold (max float if none).
  static double FirstHit(const FeelerSampler& sampler, const glm::dvec3& origin,
    const glm::dvec3& direction, double step)
  {
    const VolumeGrid& grid = *sampler.Caster.Grid;
    double tEnter = 0.0, tExit = 0.0;
    if (!IntersectBox(Ray{ origin, direction }, grid.GetWorldToIndex(), glm::dvec3(0.0),
          glm::dvec3(grid.GetDims() - 1), tEnter, tExit))
    {
      return std::numeric_limits<float>::max();
    }
    const double t0 = std::max(tEnter, 0.0);
    const glm::dvec3 indexOrigin = glm::dvec3(grid.GetWorldToIndex() * glm::dvec4(origin, 1.0));
    const glm::dvec3 indexDirection = glm::dvec3(grid.GetWorldToIndex() * glm::dvec4(direction, 0.0));
    const EmptySpaceMap* empty =
      sampler.Parameters.Mode == ThresholdMode::Scalar ? nullptr : sampler.Caster.Empty;
    for (long j = 0;; ++j)
    {
      const double t = t0 + (static_cast<double>(j) + 0.5) * step;
      if (!(t < tExit))
      {
        return std::numeric_limits<float>::max();
      }
      const glm::dvec3 index = indexOrigin + t * indexDirection;
      if (empty)
      {
        if (const int skip = empty->SkipSteps(index, indexDirection * step))
        {
          j += skip - 1;
          continue;
        }
      }
      if (sampler.AboveThreshold(grid.Sample(index, sampler.Caster.Sampling)))
      {
        return t;
      }
    }
  }

  double Visibility(const glm::dvec3& p) const override
  {
    const int f = ShadowMapFaceFor(this->Faces, p - this->Faces[0].Origin);
    double u = 0.0, v = 0.0, depth = 0.0;
    if (!this->Faces[f].Project(p, u, v, depth))
    {
      return 1.0;
    }
    const double x = 0.5 * (u + 1.0) * this->Size - 0.5;
    const double y = 0.5 * (v + 1.0) * this->Size - 0.5;
    return FilterShadowMap(&this->Depths[static_cast<size_t>(f) * this->Size * this->Size],
      this->Size, x, y, depth - this->Bias, this->Filter);
  }
  size_t Bytes() const override { return this->Depths.size() * sizeof(float); }

private:
  int Size;
  double Bias;
  ShadowFilter Filter;
  std::vector<ShadowMapFace> Faces;
  std::vector<float> Depths;
};

glm::dvec3 AnyPerpendicular(const glm::dvec3& forward)
{
  const glm::dvec3 helper = std::abs(forward.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
  return glm::normalize(glm::cross(forward, helper));
}

ShadowMapFace MakeFace(bool perspective, const glm::dvec3& origin, const glm::dvec3& forward,
  double extent)
{
  ShadowMapFace face;
  face.Perspective = perspective;
  face.Origin = origin;
  face.Forward = glm::normalize(forward);
  face.Right = AnyPerpendicular(face.Forward);
  face.Up = glm::cross(face.Right, face.Forward);
  face.Extent = extent;
  return face;
}
}

double FeelerVisibility(const ShadowCaster& caster, const glm::dvec3& from,
  const glm::dvec3& toLight, double maxDistance, double step, const ShadowParameters& parameters)
{
  const VolumeGrid& grid = *caster.Grid;
  double tEnter = 0.0, tExit = 0.0;
  if (!IntersectBox(Ray{ from, toLight }, grid.GetWorldToIndex(), glm::dvec3(0.0),
        glm::dvec3(grid.GetDims() - 1), tEnter, tExit))
  {
    return 1.0;
  }
  const double tEnd = std::min(tExit, maxDistance);
  const glm::dvec3 indexOrigin = glm::dvec3(grid.GetWorldToIndex() * glm::dvec4(from, 1.0));
  const glm::dvec3 indexDirection = glm::dvec3(grid.GetWorldToIndex() * glm::dvec4(toLight, 0.0));
  const FeelerSampler sampler(caster, parameters, step);
  // Zero-opacity blocks cannot stop a feeler, unless the threshold is on the scalar.
  const EmptySpaceMap* empty =
    parameters.Opaque && parameters.Mode == ThresholdMode::Scalar ? nullptr : caster.Empty;
  const glm::dvec3 indexStep = indexDirection * step;
  double transmittance = 1.0;
  for (long j = 0;; ++j)
  {
    const double t = (static_cast<double>(j) + 0.5) * step;
    if (!(t < tEnd))
    {
      break;
    }
    const glm::dvec3 index = indexOrigin + t * indexDirection;
    if (empty)
    {
      if (const int skip = empty->SkipSteps(index, indexStep))
      {
        j += skip - 1;
        continue;
      }
    }
    const double scalar = grid.Sample(index, caster.Sampling);
    if (parameters.Opaque)
    {
      if (sampler.AboveThreshold(scalar))
      {
        return 0.0;
      }
      continue;
    }
    transmittance *= 1.0 - sampler.Alpha(scalar);
    if (parameters.EarlyTermination && transmittance < ShadowTerminationTransmittance)
    {
      break;
    }
  }
  return transmittance;
}

void ShadowMapFace::TexelRay(double u, double v, glm::dvec3& origin, glm::dvec3& direction) const
{
  if (this->Perspective)
  {
    origin = this->Origin;
    direction = glm::normalize(this->Forward + u * this->Extent * this->Right + v * this->Extent * this->Up);
  }
  else
  {
    origin = this->Origin + u * this->Extent * this->Right + v * this->Extent * this->Up;
    direction = this->Forward;
  }
}

bool ShadowMapFace::Project(const glm::dvec3& p, double& u, double& v, double& depth) const
{
  const glm::dvec3 d = p - this->Origin;
  const double z = glm::dot(d, this->Forward);
  if (this->Perspective)
  {
    if (z <= 0.0)
    {
      return false;
    }
    u = glm::dot(d, this->Right) / (z * this->Extent);
    v = glm::dot(d, this->Up) / (z * this->Extent);
    depth = glm::length(d);
    return true;
  }
  u = glm::dot(d, this->Right) / this->Extent;
  v = glm::dot(d, this->Up) / this->Extent;
  depth = z;
  return z >= 0.0;
}

void VolumeBoundingSphere(
  const glm::dmat4& indexToWorld, const glm::ivec3& dims, glm::dvec3& centre, double& radius)
{
  const glm::dvec3 maxIndex = glm::dvec3(dims - 1);
  centre = glm::dvec3(indexToWorld * glm::dvec4(0.5 * maxIndex, 1.0));
  radius = 0.0;
  for (int c = 0; c < 8; ++c)
  {
    const glm::dvec3 corner((c & 1) * maxIndex.x, ((c >> 1) & 1) * maxIndex.y, ((c >> 2) & 1) * maxIndex.z);
    radius = std::max(radius, glm::length(glm::dvec3(indexToWorld * glm::dvec4(corner, 1.0)) - centre));
  }
}

std::vector<ShadowMapFace> ShadowMapFaces(const Light& light, const glm::dvec3& centre, double radius)
{
  radius = std::max(radius, 1e-12);
  if (!light.Positional)
  {
    const glm::dvec3 toLight = glm::normalize(light.Position - light.FocalPoint);
    return { MakeFace(false, centre + 1.01 * radius * toLight, -toLight, 1.01 * radius) };
  }
  const glm::dvec3 toCentre = centre - light.Position;
  const double distance = glm::length(toCentre);
  if (distance > 1.05 * radius)
  {
    const double halfAngle = std::asin(std::min(1.0, 1.01 * radius / distance));
    return { MakeFace(true, light.Position, toCentre, std::tan(halfAngle)) };
  }
  // The light is inside (or at) the bounding sphere: a cube of six 90-degree faces.
  std::vector<ShadowMapFace> cube;
  const glm::dvec3 axes[6] = { { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 },
    { 0, 0, -1 } };
  for (const glm::dvec3& axis : axes)
  {
    cube.push_back(MakeFace(true, light.Position, axis, 1.0));
  }
  return cube;
}

int ShadowMapFaceFor(const std::vector<ShadowMapFace>& faces, const glm::dvec3& fromLight)
{
  if (faces.size() != 6)
  {
    return 0;
  }
  const glm::dvec3 a = glm::abs(fromLight);
  if (a.x >= a.y && a.x >= a.z)
  {
    return fromLight.x >= 0.0 ? 0 : 1;
  }
  if (a.y >= a.z)
  {
    return fromLight.y >= 0.0 ? 2 : 3;
  }
  return fromLight.z >= 0.0 ? 4 : 5;
}

double FilterShadowMap(
  const float* depths, int size, double x, double y, double depth, ShadowFilter filter)
{
  auto lit = [&](int i, int j) {
    i = std::clamp(i, 0, size - 1);
    j = std::clamp(j, 0, size - 1);
    return depth <= static_cast<double>(depths[static_cast<size_t>(j) * size + i]) ? 1.0 : 0.0;
  };
  const int nx = static_cast<int>(std::floor(x + 0.5));
  const int ny = static_cast<int>(std::floor(y + 0.5));
  switch (filter)
  {
    case ShadowFilter::None:
      return lit(nx, ny);
    case ShadowFilter::PCF2x2:
    {
      const int i = static_cast<int>(std::floor(x)), j = static_cast<int>(std::floor(y));
      const double fx = x - i, fy = y - j;
      return (1 - fx) * (1 - fy) * lit(i, j) + fx * (1 - fy) * lit(i + 1, j) +
        (1 - fx) * fy * lit(i, j + 1) + fx * fy * lit(i + 1, j + 1);
    }
    case ShadowFilter::PCF3x3:
    {
      double sum = 0.0;
      for (int dj = -1; dj <= 1; ++dj)
      {
        for (int di = -1; di <= 1; ++di)
        {
          sum += lit(nx + di, ny + dj);
        }
      }
      return sum / 9.0;
    }
    case ShadowFilter::Poisson:
    {
      double sum = 0.0;
      for (const glm::dvec2& o : PoissonDisc())
      {
        sum += lit(static_cast<int>(std::floor(x + o.x + 0.5)), static_cast<int>(std::floor(y + o.y + 0.5)));
      }
      return sum / static_cast<double>(PoissonDisc().size());
    }
  }
  return 1.0;
}

std::unique_ptr<LightShadow> MakeLightShadow(const ShadowParameters& parameters,
  const ShadowCaster& caster, const Light& light, double viewStep, int threads)
{
  const double step = parameters.StepFactor * viewStep;
  switch (parameters.Kind)
  {
    case ShadowKind::None:
      return nullptr;
    case ShadowKind::ShadowMap:
      return std::make_unique<MapShadow>(parameters, caster, light, step, threads);
    case ShadowKind::Rays:
      break;
  }
  if (parameters.Cached)
  {
    return std::make_unique<CachedShadow>(parameters, caster, light, step, threads);
  }
  return std::make_unique<RayShadow>(parameters, caster, light, step);
}

}
