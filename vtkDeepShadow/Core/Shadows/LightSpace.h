// Light-space maps, CPU side: the faces through which a light sees the volume, the rays of
// their texels, and the common part of every technique that stores something per texel
// (shadow maps, deep shadow maps, opacity levels, stochastic shadow maps). The GLSL twins
// are Shaders/Shadows/LightSpace.glsl (lookup) and vtkDeepShadowLightSpaceCS.glsl (build).
//
// Depth precision: a depth is the linear distance along the texel's ray from the face's near
// boundary (the near plane of an orthographic face; for a perspective face, the sphere around
// the light that touches the volume's bounding sphere), stored as a 32-bit float. Stored
// depths therefore lie in [0, about 2.02 bounding radii] however near or far the light is, and
// their error is at most 2^-24 of that: unlike a hyperbolic z-buffer, precision does not depend
// on a near/far ratio (TestLightSpace checks ratios of 1e6 both ways). A positional light
// farther than FarLightRadii bounding radii gets an orthographic face along its direction to
// the volume (directions then differ from its own by at most 1/FarLightRadii rad), because a
// perspective face that narrow cannot be resolved in 32-bit floats on the GPU.
#ifndef deepshadow_LightSpace_h
#define deepshadow_LightSpace_h

#include "Core/Shadows.h"
#include "vtkDeepShadowCoreModule.h"

#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <vector>

namespace deepshadow
{
struct ClusteredFaces;

/** One face of a light-space map: a projection whose texels cast rays into the scene. */
struct VTKDEEPSHADOWCORE_EXPORT ShadowMapFace
{
  bool Perspective = false;
  glm::dvec3 Origin{ 0.0 };  // light position (perspective) or centre of the near plane
  glm::dvec3 Forward{ 0.0, 0.0, -1.0 };
  glm::dvec3 Right{ 1.0, 0.0, 0.0 };
  glm::dvec3 Up{ 0.0, 1.0, 0.0 };
  double Extent = 1.0;       // half-width of the near plane (ortho) or tan(half angle)
  double Near = 0.0;         // perspective: where depth 0 is, in distance from the light

  /** Texel ray through face coordinates (u, v) in [-1, 1], starting at depth 0. */
  void TexelRay(double u, double v, glm::dvec3& origin, glm::dvec3& direction) const;
  /** Face coordinates and depth of world point p; false if p is behind the face. */
  bool Project(const glm::dvec3& p, double& u, double& v, double& depth) const;
};

/**
 * The light's depth range: 2.1 radii of the casters' bounding sphere. Every face's depths lie
 * within about 2.06 of them (a clustered face's sphere is no larger than the whole one), so
 * techniques that store depths as fractions (dsm-fixed's 16-bit nodes, opacity slices) use
 * this; the GPU's light-space build and lookup get it as u_lightDepthRange.
 */
inline double LightDepthRange(double casterRadius)
{
  return 2.1 * casterRadius;
}

/** Beyond this many bounding radii a positional light's face is orthographic. */
constexpr double FarLightRadii = 1000.0;

/** The depth stored where a texel's ray finds nothing (the largest float). */
constexpr float NoHit = std::numeric_limits<float>::max();

/** Bounding sphere (world) of the box [0, dims - 1] of index space mapped by indexToWorld. */
VTKDEEPSHADOWCORE_EXPORT void VolumeBoundingSphere(
  const glm::dmat4& indexToWorld, const glm::ivec3& dims, glm::dvec3& centre, double& radius);

/**
 * What a light's faces must see: the casters' bounding sphere (where depths start and which
 * faces a light needs) and the corners of their boxes in world space (how wide a face is).
 */
struct VTKDEEPSHADOWCORE_EXPORT CasterBounds
{
  glm::dvec3 Centre{ 0.0 };
  double Radius = 0.0;
  std::vector<glm::dvec3> Corners; // empty: the sphere alone
};

/**
 * The faces a light needs to see the casters: one orthographic face for a directional light
 * or a positional one beyond FarLightRadii, one perspective face for a positional light
 * outside the bounding sphere, six (a cube: +x, -x, +y, -y, +z, -z) inside it. A face is
 * fitted to the corners as the light sees them, 1 % wider (an orthographic face centred on
 * their projection, a perspective one as wide as their widest angle from its axis), so that
 * texels are not spent beside a long thin volume (a 1:1000 needle seen end-on covers its
 * face instead of a thousandth of it); without corners, to the sphere.
 */
VTKDEEPSHADOWCORE_EXPORT std::vector<ShadowMapFace> ShadowMapFaces(const Light& light, const CasterBounds& bounds);
/** The same for a bounding sphere (centre, radius) alone. */
VTKDEEPSHADOWCORE_EXPORT std::vector<ShadowMapFace> ShadowMapFaces(
  const Light& light, const glm::dvec3& centre, double radius);

/** For a cube of faces, the face that sees direction `fromLight` (major axis); 0 otherwise. */
VTKDEEPSHADOWCORE_EXPORT int ShadowMapFaceFor(
  const std::vector<ShadowMapFace>& faces, const glm::dvec3& fromLight);

/**
 * The sphere a light's faces must see: the volume's box (VolumeBoundingSphere) grown to hold
 * the casting surfaces, if any.
 */
VTKDEEPSHADOWCORE_EXPORT void CasterBoundingSphere(const glm::dmat4& indexToWorld,
  const glm::ivec3& dims, const SurfaceSet* surfaces, glm::dvec3& centre, double& radius);

/** CasterBoundingSphere, and the corners of the volume's box and of the surfaces' box. */
VTKDEEPSHADOWCORE_EXPORT CasterBounds CasterBoundsOf(
  const glm::dmat4& indexToWorld, const glm::ivec3& dims, const SurfaceSet* surfaces);

/**
 * The span of a texel's ray that MarchTexelRay marches: from t0 (its entry into the
 * volume's box, or its cluster's, clamped to 0) to tExit; false where it misses the box.
 */
VTKDEEPSHADOWCORE_EXPORT bool TexelRaySpan(const ShadowCaster& caster, const glm::dvec3& origin,
  const glm::dvec3& direction, double& t0, double& tExit);

/**
 * Visits the samples of a texel's ray through the volume's box: sample j at depth
 * t = entry + (j + 0.5) * step (entry clamped to 0), with what the light reads there
 * (ShadowCaster::Read). The visitor returns false to stop. With `empty`, a run of samples in
 * empty blocks is visited once, at its last sample inside the box, with skipped = true (they
 * have opacity 0: this is exact).
 * With `visitSurface` and casting surfaces, their crossings at depths t > 0 are visited in
 * depth order between them: a crossing at or before a sample's depth (or a skipped run's
 * last) comes before it, and crossings beyond the box after the last sample.
 */
VTKDEEPSHADOWCORE_EXPORT void MarchTexelRay(const ShadowCaster& caster, const glm::dvec3& origin,
  const glm::dvec3& direction, double step, const EmptySpaceMap* empty,
  const std::function<bool(long j, double t, const CastSample& sample, bool skipped)>& visit,
  const std::function<bool(double t, int surface)>& visitSurface = nullptr);

/**
 * Where a lookup falls on a light's faces: the face, the continuous texel position (texel
 * centres at integers), the point's depth, and for a point on a receiving surface the depth
 * change of its plane per texel along x and y (zero for a volume sample).
 */
struct MapPoint
{
  int Face = 0;
  double X = 0.0, Y = 0.0;
  double Depth = 0.0;
  glm::dvec2 Slope{ 0.0 };

  /** The depth to compare with texel (i, j)'s: the receiver plane's there. */
  double DepthAt(double i, double j) const
  {
    return this->Depth + this->Slope.x * (i - this->X) + this->Slope.y * (j - this->Y);
  }
};

/**
 * A continuous texel position kept finite and within 64 texels of a map of `size` (a NaN,
 * from a degenerate face, becomes 0): texels clamp to the map's edge and no lookup reads
 * farther than 10 texels from its point, so nothing changes but the conversion to int, which
 * stays defined.
 */
inline double ClampTexelPosition(double position, int size)
{
  return std::isnan(position) ? 0.0 : std::clamp(position, -64.0, size + 64.0);
}

/**
 * Whether a point lies within its face's texels (u and v in [-1, 1]): a cluster's face casts
 * nothing outside them.
 */
inline bool InsideFace(const MapPoint& point, int size)
{
  return point.X >= -0.5 && point.X <= size - 0.5 && point.Y >= -0.5 && point.Y <= size - 0.5;
}

/**
 * The steepest receiver plane a lookup follows, in depth per texel width: 80 degrees from
 * the light (beyond, the plane extends too far to stand for the surface, and its diffuse
 * light is below cos 80 = 0.17 anyway).
 */
constexpr double MaxReceiverSlope = 5.67;

/**
 * The common part of light-space techniques: the faces of one light, MapSize^2 texels per
 * face, and where a world point falls. Subclasses fill their texels in their constructor
 * with ForEachTexel and answer Visibility() from them.
 */
class VTKDEEPSHADOWCORE_EXPORT LightSpaceShadow : public LightShadow
{
public:
  /** Locates p on the faces (lit where no face sees it) and asks MapVisibility(). */
  glm::dvec3 Visibility(const glm::dvec3& p) const final;
  /** The same with the receiver plane's slope (MapPoint::Slope). */
  glm::dvec3 SurfaceVisibility(const glm::dvec3& p, const glm::dvec3& normal) const final;
  const std::vector<ShadowMapFace>& GetFaces() const { return this->Faces; }
  int GetSize() const { return this->Size; }
  /** Whether the faces are clusters (ShadowParameters::Clusters; Core/Shadows/Clusters.h). */
  bool IsClustered() const { return this->Clustered != nullptr; }
  ~LightSpaceShadow() override;

protected:
  LightSpaceShadow(const ShadowParameters& parameters, const ShadowCaster& caster,
    const Light& light, double step);

  /**
   * Calls build(face, x, y, origin, direction) for every texel of every face, in parallel. A
   * face's rays march FaceCaster(face): the caster, clipped to the face's cluster.
   */
  void ForEachTexel(int threads,
    const std::function<void(int, int, int, const glm::dvec3&, const glm::dvec3&)>& build) const;

  /** The technique's lookup at a point of the map. */
  virtual glm::dvec3 MapVisibility(const MapPoint& point) const = 0;

  /**
   * value(texel, depth) blended bilinearly over the four texels around the point (texel
   * indices as Texel() gives them; depth: MapPoint::DepthAt their centre).
   */
  glm::dvec3 Bilinear(const MapPoint& point,
    const std::function<glm::dvec3(size_t texel, double depth)>& value) const;

  const ShadowCaster& FaceCaster(int face) const;

  /** Index of texel (x, y) of a face, clamped to the face's edge. */
  size_t Texel(int face, int x, int y) const;
  size_t TexelCount() const;

private:
  /** p on face `face`: its texel position and depth; false if it is behind the face. */
  bool Locate(int face, const glm::dvec3& p, MapPoint& point) const;
  /** The same for a point of a receiving surface of that normal, with its plane's slope. */
  bool LocateSurface(int face, const glm::dvec3& p, const glm::dvec3& normal, MapPoint& point) const;

protected:
  ShadowParameters Parameters;
  ShadowCaster Caster;
  int Size;
  double Step;
  std::vector<ShadowMapFace> Faces;
  // Clustered (Core/Shadows/Clusters.h): what each face marches, and Caster clipped to it.
  std::unique_ptr<ClusteredFaces> Clustered;
  std::vector<ShadowCaster> FaceCasters;
};

}
#endif
