#include "Core/Shadows/LightSpace.h"
#include "Core/Shadows/Clusters.h"

#include "Core/Bound/BoundRegion.h"
#include "Core/Camera.h"
#include "Core/Isosurface.h"
#include "Core/Parallel.h"
#include "Core/Geometry/SurfaceSet.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

namespace deepshadow
{

void ShadowMapFace::TexelRay(double u, double v, glm::dvec3& origin, glm::dvec3& direction) const
{
  if (this->Perspective)
  {
    direction = glm::normalize(this->Forward + u * this->Extent * this->Right + v * this->Extent * this->Up);
    origin = this->Origin + this->Near * direction;
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
    depth = glm::length(d) - this->Near;
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

void CasterBoundingSphere(const glm::dmat4& indexToWorld, const glm::ivec3& dims,
  const SurfaceSet* surfaces, glm::dvec3& centre, double& radius)
{
  VolumeBoundingSphere(indexToWorld, dims, centre, radius);
  if (!surfaces || surfaces->Empty())
  {
    return;
  }
  glm::dvec3 other;
  double otherRadius = 0.0;
  surfaces->BoundingSphere(other, otherRadius);
  const double distance = glm::length(other - centre);
  if (distance + otherRadius <= radius)
  {
    return;
  }
  if (distance + radius <= otherRadius)
  {
    centre = other;
    radius = otherRadius;
    return;
  }
  // The smallest sphere around both.
  const double merged = 0.5 * (distance + radius + otherRadius);
  centre += (merged - radius) / distance * (other - centre);
  radius = merged;
}

CasterBounds CasterBoundsOf(const glm::dmat4& indexToWorld, const glm::ivec3& dims, const SurfaceSet* surfaces)
{
  CasterBounds bounds;
  CasterBoundingSphere(indexToWorld, dims, surfaces, bounds.Centre, bounds.Radius);
  const glm::dvec3 maxIndex = glm::dvec3(dims - 1);
  for (int c = 0; c < 8; ++c)
  {
    const glm::dvec3 corner((c & 1) * maxIndex.x, ((c >> 1) & 1) * maxIndex.y, ((c >> 2) & 1) * maxIndex.z);
    bounds.Corners.emplace_back(indexToWorld * glm::dvec4(corner, 1.0));
  }
  if (surfaces && !surfaces->Empty())
  {
    const TriangleBVH::Node& root = surfaces->GetHierarchy().GetNodes().front();
    for (int c = 0; c < 8; ++c)
    {
      bounds.Corners.emplace_back((c & 1) ? root.Max.x : root.Min.x, (c & 2) ? root.Max.y : root.Min.y,
        (c & 4) ? root.Max.z : root.Min.z);
    }
  }
  return bounds;
}

namespace
{
ShadowMapFace MakeFace(bool perspective, const glm::dvec3& origin, const glm::dvec3& forward,
  double extent, double near)
{
  ShadowMapFace face;
  face.Perspective = perspective;
  face.Origin = origin;
  face.Forward = glm::normalize(forward);
  // Any perpendicular will do; the GLSL cube lookup rebuilds it the same way.
  const glm::dvec3 helper = std::abs(face.Forward.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
  face.Right = glm::normalize(glm::cross(face.Forward, helper));
  face.Up = glm::cross(face.Right, face.Forward);
  face.Extent = extent;
  face.Near = near;
  return face;
}
}

std::vector<ShadowMapFace> ShadowMapFaces(const Light& light, const glm::dvec3& centre, double radius)
{
  return ShadowMapFaces(light, CasterBounds{ centre, radius, {} });
}

std::vector<ShadowMapFace> ShadowMapFaces(const Light& light, const CasterBounds& bounds)
{
  const glm::dvec3& centre = bounds.Centre;
  const double radius = std::max(bounds.Radius, 1e-12);
  // 1% margins keep the volume's silhouette off the faces' edges.
  const double margin = 1.01 * radius;
  const glm::dvec3 toCentre = centre - light.Position;
  const double distance = glm::length(toCentre);
  if (!light.Positional || distance > FarLightRadii * radius)
  {
    const glm::dvec3 toLight = light.Positional ? -toCentre / distance
                                                : glm::normalize(light.Position - light.FocalPoint);
    ShadowMapFace face = MakeFace(false, centre + margin * toLight, -toLight, margin, 0.0);
    if (!bounds.Corners.empty())
    {
      // Centred on the corners' projection, as wide as its wider side (never wider than the
      // sphere's face): depths still start at the sphere's near plane.
      glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
      for (const glm::dvec3& corner : bounds.Corners)
      {
        const glm::dvec2 uv(glm::dot(corner - centre, face.Right), glm::dot(corner - centre, face.Up));
        lo = glm::min(lo, uv);
        hi = glm::max(hi, uv);
      }
      const glm::dvec2 middle = 0.5 * (lo + hi);
      face.Origin += middle.x * face.Right + middle.y * face.Up;
      face.Extent = std::clamp(1.01 * 0.5 * std::max(hi.x - lo.x, hi.y - lo.y), 1e-9 * radius, margin);
    }
    return { face };
  }
  if (distance > 1.05 * radius)
  {
    const double halfAngle = std::asin(std::min(1.0, margin / distance));
    ShadowMapFace face =
      MakeFace(true, light.Position, toCentre, std::tan(halfAngle), std::max(0.0, distance - margin));
    if (!bounds.Corners.empty())
    {
      // As wide as the corners' widest angle from the axis (all lie in front of the light,
      // which is outside the sphere), never wider than the sphere's.
      double widest = 0.0;
      for (const glm::dvec3& corner : bounds.Corners)
      {
        const glm::dvec3 d = corner - light.Position;
        const double z = glm::dot(d, face.Forward);
        widest = std::max({ widest, std::abs(glm::dot(d, face.Right)) / z, std::abs(glm::dot(d, face.Up)) / z });
      }
      face.Extent = std::clamp(1.01 * widest, 1e-9, face.Extent);
    }
    return { face };
  }
  // The light is inside (or at) the bounding sphere: a cube of six 90-degree faces.
  std::vector<ShadowMapFace> cube;
  const glm::dvec3 axes[6] = { { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 },
    { 0, 0, -1 } };
  for (const glm::dvec3& axis : axes)
  {
    cube.push_back(MakeFace(true, light.Position, axis, 1.0, 0.0));
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

bool TexelRaySpan(const ShadowCaster& caster, const glm::dvec3& origin, const glm::dvec3& direction,
  double& t0, double& tExit)
{
  const VolumeGrid& grid = *caster.Grid;
  glm::dvec3 lo(0.0), hi(grid.GetDims() - 1);
  if (caster.Clip)
  {
    lo = glm::max(lo, caster.Clip->Lo);
    hi = glm::min(hi, caster.Clip->Hi);
  }
  double tEnter = 0.0;
  if (glm::any(glm::greaterThan(lo, hi)) ||
    !IntersectBox(Ray{ origin, direction }, grid.GetWorldToIndex(), lo, hi, tEnter, tExit))
  {
    return false;
  }
  t0 = std::max(tEnter, 0.0);
  return true;
}

void MarchTexelRay(const ShadowCaster& caster, const glm::dvec3& origin, const glm::dvec3& direction,
  double step, const EmptySpaceMap* empty,
  const std::function<bool(long j, double t, const CastSample& sample, bool skipped)>& visit,
  const std::function<bool(double t, int surface)>& visitSurface)
{
  // Surface crossings come in depth order between the samples: those at or before a sample's
  // depth first, those beyond the box after it.
  const SurfaceSet* surfaces = visitSurface && caster.Surfaces && !caster.Surfaces->Empty()
    ? caster.Surfaces
    : nullptr;
  SurfaceHit surface;
  if (surfaces)
  {
    surface = surfaces->NextHit(origin, direction, 0.0);
  }
  auto surfacesUpTo = [&](double t) {
    for (; surface.Found && surface.T <= t; surface = surfaces->NextHit(origin, direction, surface.T))
    {
      if (!visitSurface(surface.T, surface.Surface))
      {
        return false;
      }
    }
    return true;
  };
  const VolumeGrid& grid = *caster.Grid;
  double t0 = 0.0, tExit = 0.0;
  if (!TexelRaySpan(caster, origin, direction, t0, tExit))
  {
    surfacesUpTo(std::numeric_limits<double>::infinity());
    return;
  }
  auto depthOf = [&](long j) { return t0 + (static_cast<double>(j) + 0.5) * step; };
  const glm::dvec3 indexOrigin = glm::dvec3(grid.GetWorldToIndex() * glm::dvec4(origin, 1.0));
  const glm::dvec3 indexDirection = glm::dvec3(grid.GetWorldToIndex() * glm::dvec4(direction, 0.0));
  const glm::dvec3 indexStep = indexDirection * step;
  std::optional<BoundRegion::Walker> bound;
  if (caster.Bound)
  {
    bound.emplace(*caster.Bound, indexOrigin, indexDirection);
  }
  // The last sample inside the box (a skipped run is visited there at the latest).
  long lastInBox = static_cast<long>(std::floor((tExit - t0) / step - 0.5));
  while (lastInBox >= 0 && !(depthOf(lastInBox) < tExit))
  {
    --lastInBox;
  }
  while (depthOf(lastInBox + 1) < tExit)
  {
    ++lastInBox;
  }
  IsoCrossings crossings(caster.IsoValues);
  for (long j = 0; j <= lastInBox; ++j)
  {
    const glm::dvec3 index = indexOrigin + depthOf(j) * indexDirection;
    // Samples outside the bound, or in empty blocks, are one skipped run, visited at its end.
    long skip = bound ? bound->SkipSteps(depthOf(j), step) : 0;
    if (!skip && empty)
    {
      skip = empty->SkipSteps(index, indexStep);
    }
    if (skip)
    {
      const long last = std::min(j + skip - 1, lastInBox);
      if (!surfacesUpTo(depthOf(last)) || !visit(last, depthOf(last), 0.0, true))
      {
        return;
      }
      j = last;
      continue;
    }
    if (!surfacesUpTo(depthOf(j)) || !visit(j, depthOf(j), caster.Read(index, crossings), false))
    {
      return;
    }
  }
  surfacesUpTo(std::numeric_limits<double>::infinity());
}

LightSpaceShadow::LightSpaceShadow(
  const ShadowParameters& parameters, const ShadowCaster& caster, const Light& light, double step)
  : Parameters(parameters)
  , Caster(caster)
  , Size(std::max(1, parameters.MapSize))
  , Step(step)
{
  // Clusters need empty blocks to find objects in (as the GPU, whose block map exists then).
  const EmptySpaceMap* empty = caster.Empty;
  if (parameters.Clusters > 0 && empty &&
    std::find(empty->Occupied.begin(), empty->Occupied.end(), uint8_t(0)) != empty->Occupied.end())
  {
    auto clustered = std::make_unique<ClusteredFaces>(ClusterFaces(light, caster.Grid->GetIndexToWorld(),
      caster.Grid->GetDims(), *empty, caster.Surfaces, parameters.Clusters, parameters.ClusterDistance,
      caster.Eye ? &*caster.Eye : nullptr));
    if (!clustered->Faces.empty())
    {
      this->Faces = clustered->Faces;
      this->Clustered = std::move(clustered);
    }
  }
  if (this->Faces.empty())
  {
    this->Faces = ShadowMapFaces(
      light, CasterBoundsOf(caster.Grid->GetIndexToWorld(), caster.Grid->GetDims(), caster.Surfaces));
  }
  // A clustered face marches its box, and of it only its own blocks and crossings.
  for (size_t f = 0; this->Clustered && f < this->Faces.size(); ++f)
  {
    ShadowCaster own = caster;
    own.Clip = &this->Clustered->Clips[f];
    own.Empty = &this->Clustered->Occupied[f];
    own.Surfaces = this->Clustered->CastsSurfaces[f] ? caster.Surfaces : nullptr;
    this->FaceCasters.push_back(own);
  }
}

LightSpaceShadow::~LightSpaceShadow() = default;

const ShadowCaster& LightSpaceShadow::FaceCaster(int face) const
{
  return this->Clustered ? this->FaceCasters[static_cast<size_t>(face)] : this->Caster;
}

void LightSpaceShadow::ForEachTexel(int threads,
  const std::function<void(int, int, int, const glm::dvec3&, const glm::dvec3&)>& build) const
{
  for (int f = 0; f < static_cast<int>(this->Faces.size()); ++f)
  {
    ParallelFor(
      this->Size,
      [&](int y) {
        for (int x = 0; x < this->Size; ++x)
        {
          glm::dvec3 origin, direction;
          this->Faces[f].TexelRay(2.0 * (x + 0.5) / this->Size - 1.0,
            2.0 * (y + 0.5) / this->Size - 1.0, origin, direction);
          build(f, x, y, origin, direction);
        }
      },
      threads);
  }
}

bool LightSpaceShadow::Locate(int face, const glm::dvec3& p, MapPoint& point) const
{
  double u = 0.0, v = 0.0;
  point.Face = face;
  if (!this->Faces[face].Project(p, u, v, point.Depth))
  {
    return false;
  }
  point.X = ClampTexelPosition(0.5 * (u + 1.0) * this->Size - 0.5, this->Size);
  point.Y = ClampTexelPosition(0.5 * (v + 1.0) * this->Size - 0.5, this->Size);
  return true;
}

glm::dvec3 LightSpaceShadow::Visibility(const glm::dvec3& p) const
{
  if (this->IsClustered())
  {
    // What every cluster casts along the light's ray: a cluster whose face does not see p,
    // or that lies beyond p, casts nothing there.
    glm::dvec3 visibility(1.0);
    for (int face = 0; face < static_cast<int>(this->Faces.size()); ++face)
    {
      MapPoint point;
      if (this->Locate(face, p, point) && InsideFace(point, this->Size) && point.Depth >= this->Clustered->Starts[face])
      {
        visibility *= this->MapVisibility(point);
      }
    }
    return visibility;
  }
  MapPoint point;
  if (!this->Locate(ShadowMapFaceFor(this->Faces, p - this->Faces[0].Origin), p, point))
  {
    return glm::dvec3(1.0);
  }
  return this->MapVisibility(point);
}

glm::dvec3 LightSpaceShadow::SurfaceVisibility(const glm::dvec3& p, const glm::dvec3& normal) const
{
  if (this->IsClustered())
  {
    glm::dvec3 visibility(1.0);
    for (int face = 0; face < static_cast<int>(this->Faces.size()); ++face)
    {
      MapPoint point;
      if (this->LocateSurface(face, p, normal, point) && InsideFace(point, this->Size))
      {
        visibility *= this->MapVisibility(point);
      }
    }
    return visibility;
  }
  MapPoint point;
  if (!this->LocateSurface(ShadowMapFaceFor(this->Faces, p - this->Faces[0].Origin), p, normal, point))
  {
    return glm::dvec3(1.0);
  }
  return this->MapVisibility(point);
}

bool LightSpaceShadow::LocateSurface(int faceIndex, const glm::dvec3& p, const glm::dvec3& normal, MapPoint& point) const
{
  if (!this->Locate(faceIndex, p, point))
  {
    return false;
  }
  // Two steps of a texel's width along the receiver's plane, located on the same face: the
  // plane's depth changes linearly across the map (locally, for a perspective face).
  const ShadowMapFace& face = this->Faces[point.Face];
  const double z = face.Perspective ? glm::dot(p - face.Origin, face.Forward) : 1.0;
  const double texel = 2.0 * z * face.Extent / this->Size;
  const glm::dvec3 n = glm::normalize(normal);
  const glm::dvec3 e1 =
    glm::normalize(glm::cross(n, std::abs(n.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0)));
  const glm::dvec3 e2 = glm::cross(n, e1);
  MapPoint a, b;
  if (this->Locate(point.Face, p + texel * e1, a) && this->Locate(point.Face, p + texel * e2, b))
  {
    const glm::dvec3 d1(a.X - point.X, a.Y - point.Y, a.Depth - point.Depth);
    const glm::dvec3 d2(b.X - point.X, b.Y - point.Y, b.Depth - point.Depth);
    const double det = d1.x * d2.y - d1.y * d2.x;
    if (std::abs(det) > 1e-12)
    {
      // depth = Slope . (x, y) along both steps.
      point.Slope = glm::dvec2(d1.z * d2.y - d2.z * d1.y, d1.x * d2.z - d2.x * d1.z) / det;
      const double steepest = MaxReceiverSlope * texel, length = glm::length(point.Slope);
      if (length > steepest)
      {
        point.Slope *= steepest / length;
      }
    }
  }
  return true;
}

glm::dvec3 LightSpaceShadow::Bilinear(
  const MapPoint& point, const std::function<glm::dvec3(size_t texel, double depth)>& value) const
{
  // Texels clamp to the edge, so coordinates beyond [-1, Size] change nothing; clamped, far
  // (or NaN, from a degenerate face) coordinates cannot overflow the int conversion.
  const double x = std::isnan(point.X) ? 0.0 : std::clamp(point.X, -1.0, static_cast<double>(this->Size));
  const double y = std::isnan(point.Y) ? 0.0 : std::clamp(point.Y, -1.0, static_cast<double>(this->Size));
  const int i = static_cast<int>(std::floor(x)), j = static_cast<int>(std::floor(y));
  const double fx = x - i, fy = y - j;
  auto at = [&](int ti, int tj) { return value(this->Texel(point.Face, ti, tj), point.DepthAt(ti, tj)); };
  return (1.0 - fx) * (1.0 - fy) * at(i, j) + fx * (1.0 - fy) * at(i + 1, j) + (1.0 - fx) * fy * at(i, j + 1) +
    fx * fy * at(i + 1, j + 1);
}

size_t LightSpaceShadow::Texel(int face, int x, int y) const
{
  x = std::clamp(x, 0, this->Size - 1);
  y = std::clamp(y, 0, this->Size - 1);
  return (static_cast<size_t>(face) * this->Size + y) * this->Size + x;
}

size_t LightSpaceShadow::TexelCount() const
{
  return this->Faces.size() * this->Size * this->Size;
}

}
