#include "Core/Geometry/SurfaceSet.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace deepshadow
{

void MeshBounds(const SurfaceMesh& mesh, glm::dvec3& lo, glm::dvec3& hi)
{
  lo = glm::dvec3(std::numeric_limits<double>::infinity());
  hi = -lo;
  for (const glm::dvec3& p : mesh.Points)
  {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
}


glm::dvec3 SurfaceTransmission(const SurfaceMaterial& material, bool colored)
{
  const double alpha = std::clamp(material.Opacity, 0.0, 1.0);
  if (alpha >= 1.0)
  {
    return glm::dvec3(0.0);
  }
  return colored ? 1.0 - alpha * (1.0 - glm::clamp(material.Color, 0.0, 1.0)) : glm::dvec3(1.0 - alpha);
}

SurfaceSet::SurfaceSet(std::vector<SurfaceMesh> meshes)
  : Meshes(std::move(meshes))
{
  if (this->Meshes.size() > static_cast<size_t>(MaxSurfaces))
  {
    throw std::invalid_argument("more than " + std::to_string(MaxSurfaces) +
      " surfaces cast shadows; append meshes of one material into one (vtkAppendPolyData)");
  }
  std::vector<Triangle> triangles;
  for (size_t s = 0; s < this->Meshes.size(); ++s)
  {
    const SurfaceMesh& mesh = this->Meshes[s];
    const std::string name = "surface " + std::to_string(s);
    if (!(mesh.Material.Opacity >= 0.0 && mesh.Material.Opacity <= 1.0))
    {
      throw std::invalid_argument(name + ": opacity must lie in [0, 1]");
    }
    for (const glm::dvec3& p : mesh.Points)
    {
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      {
        throw std::invalid_argument(name + " has a point that is not finite (NaN or infinite)");
      }
    }
    if ((!mesh.Normals.empty() && mesh.Normals.size() != mesh.Points.size()) ||
      (!mesh.Colors.empty() && mesh.Colors.size() != mesh.Points.size()))
    {
      throw std::invalid_argument(name + ": normals and colours must be given per point");
    }
    const int count = static_cast<int>(mesh.Points.size());
    for (size_t i = 0; i < mesh.Triangles.size(); ++i)
    {
      const glm::ivec3 tri = mesh.Triangles[i];
      if (glm::any(glm::lessThan(tri, glm::ivec3(0))) || glm::any(glm::greaterThanEqual(tri, glm::ivec3(count))))
      {
        throw std::invalid_argument(name + ": a triangle refers to a point that does not exist");
      }
      Triangle t{ mesh.Points[tri.x], mesh.Points[tri.y], mesh.Points[tri.z] };
      if (glm::length(glm::cross(t.V1 - t.V0, t.V2 - t.V0)) <= 0.0)
      {
        continue;
      }
      t.Tag = static_cast<int>(this->TriangleOf.size());
      this->TriangleOf.emplace_back(static_cast<int>(s), static_cast<int>(i));
      triangles.push_back(t);
    }
  }
  this->Hierarchy = TriangleBVH(std::move(triangles));
}

SurfaceHit SurfaceSet::NextHit(const glm::dvec3& origin, const glm::dvec3& direction, double tAfter) const
{
  SurfaceHit hit;
  const MeshHit mesh = this->Hierarchy.NextHit(origin, direction, tAfter);
  if (!mesh.Found)
  {
    return hit;
  }
  const Triangle& tri = this->Hierarchy.GetTriangles()[static_cast<size_t>(mesh.Triangle)];
  const glm::ivec2 owner = this->TriangleOf[static_cast<size_t>(tri.Tag)];
  hit.Found = true;
  hit.T = mesh.T;
  hit.Surface = owner.x;
  hit.Triangle = owner.y;
  // Barycentric weights of the crossing point (as the rasterizer interpolates).
  const glm::dvec3 p = origin + mesh.T * direction;
  const glm::dvec3 e1 = tri.V1 - tri.V0, e2 = tri.V2 - tri.V0, d = p - tri.V0;
  const double d11 = glm::dot(e1, e1), d12 = glm::dot(e1, e2), d22 = glm::dot(e2, e2);
  const double d1 = glm::dot(d, e1), d2 = glm::dot(d, e2);
  const double denominator = d11 * d22 - d12 * d12;
  if (denominator > 0.0)
  {
    hit.U = std::clamp((d22 * d1 - d12 * d2) / denominator, 0.0, 1.0);
    hit.V = std::clamp((d11 * d2 - d12 * d1) / denominator, 0.0, 1.0 - hit.U);
  }
  return hit;
}

glm::dvec3 SurfaceSet::Transmittance(const glm::dvec3& origin, const glm::dvec3& direction,
  double tFrom, double tTo, bool colored) const
{
  glm::dvec3 transmittance(1.0);
  for (SurfaceHit hit = this->NextHit(origin, direction, tFrom); hit.Found && hit.T < tTo;
       hit = this->NextHit(origin, direction, hit.T))
  {
    transmittance *= SurfaceTransmission(this->Meshes[static_cast<size_t>(hit.Surface)].Material, colored);
    if (transmittance == glm::dvec3(0.0))
    {
      break;
    }
  }
  return transmittance;
}

bool SurfaceSet::Occludes(const glm::dvec3& origin, const glm::dvec3& direction, double tFrom,
  double tTo, double threshold) const
{
  for (SurfaceHit hit = this->NextHit(origin, direction, tFrom); hit.Found && hit.T < tTo;
       hit = this->NextHit(origin, direction, hit.T))
  {
    if (this->Meshes[static_cast<size_t>(hit.Surface)].Material.Opacity > threshold)
    {
      return true;
    }
  }
  return false;
}

glm::dvec3 SurfaceSet::Normal(const SurfaceHit& hit) const
{
  const SurfaceMesh& mesh = this->Meshes[static_cast<size_t>(hit.Surface)];
  if (mesh.Normals.empty())
  {
    return this->FaceNormal(hit);
  }
  const glm::ivec3 tri = mesh.Triangles[static_cast<size_t>(hit.Triangle)];
  const glm::dvec3 n = (1.0 - hit.U - hit.V) * mesh.Normals[static_cast<size_t>(tri.x)] +
    hit.U * mesh.Normals[static_cast<size_t>(tri.y)] + hit.V * mesh.Normals[static_cast<size_t>(tri.z)];
  const double length = glm::length(n);
  return length > 0.0 ? n / length : glm::dvec3(0.0);
}

glm::dvec3 SurfaceSet::FaceNormal(const SurfaceHit& hit) const
{
  const SurfaceMesh& mesh = this->Meshes[static_cast<size_t>(hit.Surface)];
  const glm::ivec3 tri = mesh.Triangles[static_cast<size_t>(hit.Triangle)];
  const glm::dvec3& a = mesh.Points[static_cast<size_t>(tri.x)];
  const glm::dvec3 n =
    glm::cross(mesh.Points[static_cast<size_t>(tri.y)] - a, mesh.Points[static_cast<size_t>(tri.z)] - a);
  const double length = glm::length(n);
  return length > 0.0 ? n / length : glm::dvec3(0.0);
}

glm::dvec3 SurfaceSet::Color(const SurfaceHit& hit) const
{
  const SurfaceMesh& mesh = this->Meshes[static_cast<size_t>(hit.Surface)];
  if (mesh.Colors.empty())
  {
    return mesh.Material.Color;
  }
  const glm::ivec3 tri = mesh.Triangles[static_cast<size_t>(hit.Triangle)];
  return (1.0 - hit.U - hit.V) * mesh.Colors[static_cast<size_t>(tri.x)] +
    hit.U * mesh.Colors[static_cast<size_t>(tri.y)] + hit.V * mesh.Colors[static_cast<size_t>(tri.z)];
}

SurfaceSet::GPUData SurfaceSet::PackForGPU(const glm::dmat4& worldToSpace) const
{
  GPUData data;
  std::vector<Triangle> triangles = this->Hierarchy.GetTriangles();
  auto carry = [&](const glm::dvec3& p) { return glm::dvec3(worldToSpace * glm::dvec4(p, 1.0)); };
  for (Triangle& t : triangles)
  {
    t = Triangle{ carry(t.V0), carry(t.V1), carry(t.V2), this->TriangleOf[static_cast<size_t>(t.Tag)].x };
  }
  const TriangleBVH hierarchy(std::move(triangles));
  data.Root = hierarchy.AppendForGPU(data.Nodes, data.Triangles);
  data.MaxDepth = hierarchy.GetDepth();
  for (const SurfaceMesh& mesh : this->Meshes)
  {
    data.Transmission.emplace_back(glm::vec3(SurfaceTransmission(mesh.Material, true)),
      static_cast<float>(SurfaceTransmission(mesh.Material, false).r));
  }
  return data;
}

void SurfaceSet::BoundingSphere(glm::dvec3& centre, double& radius) const
{
  centre = glm::dvec3(0.0);
  radius = 0.0;
  if (this->Empty())
  {
    return;
  }
  const TriangleBVH::Node& root = this->Hierarchy.GetNodes().front();
  centre = 0.5 * (root.Min + root.Max);
  radius = 0.5 * glm::length(root.Max - root.Min);
}

}
