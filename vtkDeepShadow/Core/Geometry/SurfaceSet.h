// The surfaces of a hybrid scene (triangle meshes in world coordinates) as rays meet them.
//
// Light rays: a crossing lets through what the surface's material transmits
// (SurfaceTransmission), so a light ray's transmittance is the product over its crossings and
// a translucent surface is a step in the visibility function (two nodes at one depth, before
// and after). Every shadow technique meets the casting surfaces this way, on its light rays
// and feelers (Shadows.h); the GPU twin is Shaders/Features/Surfaces.glsl.
//
// View rays (the CPU reference): the crossing's surface, its interpolated normal and colour.
#ifndef deepshadow_SurfaceSet_h
#define deepshadow_SurfaceSet_h

#include "Core/OpticalModel.h"
#include "Core/Geometry/TriangleBVH.h"
#include "vtkDeepShadowCoreModule.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace deepshadow
{

/** How a surface looks and what it lets through. */
struct SurfaceMaterial
{
  double Opacity = 1.0;
  glm::dvec3 Color{ 1.0 }; // vtkProperty's colour: also what a translucent surface transmits
  Material Shading;        // ambient, diffuse, specular, specular power
  glm::dvec3 SpecularColor{ 1.0 }; // vtkProperty's: its highlights' colour (SetColor sets it too)
};

/**
 * What one crossing of a surface lets through, per channel: nothing if it is opaque
 * (opacity >= 1); else 1 - alpha grey, or 1 - alpha (1 - c) coloured: as for a volume sample,
 * the colour is what it transmits of the light it stops.
 */
VTKDEEPSHADOWCORE_EXPORT glm::dvec3 SurfaceTransmission(const SurfaceMaterial& material, bool colored);

/** One triangle mesh; normals and colours per point are optional. */
struct SurfaceMesh
{
  std::vector<glm::dvec3> Points;
  std::vector<glm::ivec3> Triangles;
  std::vector<glm::dvec3> Normals; // per point, unit; empty: each triangle's own normal
  std::vector<glm::dvec3> Colors;  // per point; empty: Material.Color
  SurfaceMaterial Material;
  /** Whether its points are shadowed when drawn (light rays ignore this). */
  bool ReceivesShadows = true;
};

/** The axis-aligned box of a mesh's points (lo > hi when it has none). */
VTKDEEPSHADOWCORE_EXPORT void MeshBounds(const SurfaceMesh& mesh, glm::dvec3& lo, glm::dvec3& hi);

/** The default world distance a mesh receiver's lookup starts towards the light. */
inline double DefaultReceiverBias(double feelerStep)
{
  return 2.0 * feelerStep;
}

/**
 * How far towards the light a mesh receiver looks its shadow up: `bias` at normal incidence,
 * up to 4 times that at grazing light, where a map's depths vary fastest across a texel
 * (twin of MeshNormal.glsl's ShadowOffset).
 */
inline double ReceiverOffset(double bias, const glm::dvec3& normal, const glm::dvec3& toLight)
{
  return bias / std::max(std::abs(glm::dot(normal, toLight)), 0.25);
}

/** A crossing of a ray with a surface of the set. */
struct SurfaceHit
{
  bool Found = false;
  double T = 0.0;
  int Surface = -1;
  int Triangle = -1;    // in the surface's mesh
  double U = 0.0, V = 0.0; // barycentric weights of its second and third point
};

class VTKDEEPSHADOWCORE_EXPORT SurfaceSet
{
public:
  /** Surfaces a set may hold (the GPU's material table). */
  static constexpr int MaxSurfaces = 64;

  SurfaceSet() = default;
  /**
   * Takes the meshes. Throws std::invalid_argument naming the mesh for non-finite points, a
   * triangle index out of range, more than MaxSurfaces meshes or an opacity outside [0, 1].
   * Triangles with no area are dropped (no ray crosses them).
   */
  explicit SurfaceSet(std::vector<SurfaceMesh> meshes);

  bool Empty() const { return this->Hierarchy.Empty(); }
  int GetSurfaceCount() const { return static_cast<int>(this->Meshes.size()); }
  const SurfaceMesh& GetSurface(int i) const { return this->Meshes[static_cast<size_t>(i)]; }
  const TriangleBVH& GetHierarchy() const { return this->Hierarchy; }

  /** The nearest crossing after tAfter (either side). */
  SurfaceHit NextHit(const glm::dvec3& origin, const glm::dvec3& direction, double tAfter) const;

  /** Product of the transmissions of the crossings with t in (tFrom, tTo). */
  glm::dvec3 Transmittance(const glm::dvec3& origin, const glm::dvec3& direction, double tFrom,
    double tTo, bool colored) const;
  /** Whether a crossing in (tFrom, tTo) has an opacity above `threshold` (binary shadows). */
  bool Occludes(const glm::dvec3& origin, const glm::dvec3& direction, double tFrom, double tTo,
    double threshold) const;

  /** Unit normal at a hit as the mesh orients it (point normals interpolated, else the face's). */
  glm::dvec3 Normal(const SurfaceHit& hit) const;
  /** Unit normal of the hit triangle's plane (zero for a degenerate one). */
  glm::dvec3 FaceNormal(const SurfaceHit& hit) const;
  /** Colour at a hit (per-point colours interpolated, else the material's). */
  glm::dvec3 Color(const SurfaceHit& hit) const;

  /** What the GPU walks (Features/Surfaces.glsl). */
  struct GPUData
  {
    std::vector<glm::vec4> Nodes;     // TriangleBVH::AppendForGPU, triangles tagged with
    std::vector<glm::vec4> Triangles; // their surface
    int Root = -1;
    int MaxDepth = 0;
    /** Per surface: rgb its coloured transmission, a its grey one (SurfaceTransmission). */
    std::vector<glm::vec4> Transmission;
  };
  /**
   * The set's triangles carried into another space by `worldToSpace` (affine: a ray's
   * parameter is the same in both spaces when its direction is carried along).
   */
  GPUData PackForGPU(const glm::dmat4& worldToSpace) const;

  /** A sphere around every point (radius 0 and centre 0 when empty). */
  void BoundingSphere(glm::dvec3& centre, double& radius) const;

private:
  std::vector<SurfaceMesh> Meshes;
  std::vector<glm::ivec2> TriangleOf; // BVH tag -> (surface, triangle)
  TriangleBVH Hierarchy;
};

}
#endif
