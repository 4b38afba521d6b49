// Closed-form scenes shared by the CPU (Core: TestClosedFormShadows.cxx) and GPU
// (Rendering: TestClosedFormShadowsGPU.cxx) tests: homogeneous bodies in volume grids with
// their Beer-Lambert answers (ClosedForm.h), the techniques by name, and Judge(), which holds
// one answer against the closed form within what the technique is allowed, each term with its
// reason: the march's sampling (a path covers whole samples), where the grid puts the body's
// surface (trilinear interpolation of its field), feeler termination (1/512), the
// technique's own bound (the registry's StatedError: epsilon for deep shadow maps, three opacity
// levels, 4 standard errors of CSSM's estimate), and the resolution of its lookup (the closed
// form's own variation over the texels or cache nodes the lookup reads). Binary techniques are
// judged where the closed form is clearly on one side of their threshold.
#ifndef deepshadow_testing_ClosedFormScenes_h
#define deepshadow_testing_ClosedFormScenes_h

#include "ClosedForm.h"

#include "Core/Shadows/LightSpace.h"
#include "Core/Shadows/ResolutionMatched.h"
#include "Core/Shadows.h"
#include "Core/Shadows/StochasticShadowMap.h"
#include "Core/ShadowTechniques.h"
#include "Core/Geometry/SurfaceSet.h"
#include "Core/TransferFunction.h"
#include "Core/VolumeGrid.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace deepshadow
{
namespace closedform
{

constexpr double Pi = 3.14159265358979323846;
constexpr double ViewStep = 0.5; // the default sample distance of a unit-spaced volume

// A homogeneous body in a volume grid: a scalar field that is 1 inside and 0 outside, a
// transfer function that steps from 0 to `Opacity` at 0.5, and the body's closed form. Its
// colour is what it transmits of the light it stops (coloured techniques): a black body casts
// the same shadow on grey and coloured techniques.
struct Body
{
  std::shared_ptr<VolumeGrid> Grid;
  TransferFunction Transfer;
  ShadowCaster Caster;
  double Opacity = 0.0;
  glm::dvec3 Color{ 0.0 };
  /**
   * Length of the light ray from p (unit direction d, up to maxS) inside the body, with its
   * surface moved outwards by `grow`.
   */
  std::function<double(const glm::dvec3& p, const glm::dvec3& d, double maxS, double grow)> Path;
  /** How far from its closed-form surface the grid may put the body's (trilinear sampling). */
  double SurfaceSlack = 0.0;

  Body(const glm::ivec3& dims, const glm::dvec3& origin, double opacity, const glm::dvec3& color,
    const std::function<float(const glm::dvec3&)>& field)
    : Opacity(opacity)
    , Color(color)
  {
    std::vector<float> values(static_cast<size_t>(dims.x) * dims.y * dims.z);
    for (int k = 0; k < dims.z; ++k)
      for (int j = 0; j < dims.y; ++j)
        for (int i = 0; i < dims.x; ++i)
          values[i + dims.x * (j + static_cast<size_t>(dims.y) * k)] = field(origin + glm::dvec3(i, j, k));
    this->Grid = std::make_shared<VolumeGrid>(dims, values, glm::translate(glm::dmat4(1.0), origin));
    this->Transfer.Opacity = PiecewiseLinear({ { 0.0, 0.0 }, { 0.499, 0.0 }, { 0.5, opacity }, { 1.0, opacity } });
    this->Transfer.Red = PiecewiseLinear({ { 0.0, color.r } });
    this->Transfer.Green = PiecewiseLinear({ { 0.0, color.g } });
    this->Transfer.Blue = PiecewiseLinear({ { 0.0, color.b } });
    this->Transfer.OpacityUnitDistance = 1.0;
    this->Caster.Grid = this->Grid.get();
    this->Caster.Transfer = &this->Transfer;
  }
  // The caster points into the body: no copies.
  Body(const Body&) = delete;
  Body& operator=(const Body&) = delete;

  double Sigma() const { return Extinction(this->Opacity, 1.0); }

  /** Closed form: what reaches p of `light`, per channel for `colored` techniques. */
  glm::dvec3 Exact(const glm::dvec3& p, const Light& light, bool colored, double grow = 0.0) const
  {
    const double length = this->Path(p, light.At(p).ToLight, DistanceToLight(light, p), grow);
    return ColoredTransmittance(this->Opacity, 1.0, colored ? this->Color : glm::dvec3(0.0), length);
  }
};

// A ball of radius 15 at the origin in a 48^3 grid of unit spacing.
constexpr double BallRadius = 15.0;
inline std::unique_ptr<Body> Ball(double opacity, const glm::dvec3& color = glm::dvec3(0.0))
{
  auto body = std::make_unique<Body>(glm::ivec3(48), glm::dvec3(-23.5), opacity, color,
    [](const glm::dvec3& p) { return BallField(p, glm::dvec3(0.0), BallRadius); });
  body->Path = [](const glm::dvec3& p, const glm::dvec3& d, double maxS, double grow) {
    return SphereChord(glm::dvec3(0.0), BallRadius + grow, p, d, maxS);
  };
  // BallField's ramp of 4 units: trilinear interpolation bends the surface in by at most
  // (1/8)(2/R) of it, plus the transfer function's step of 0.001 over the ramp's slope.
  body->SurfaceSlack = 1.0 / (4.0 * BallRadius) + 0.004;
  return body;
}

// A slab filling a 40^3 grid (world = index) between z = 7.5 and z = 31.5.
inline std::unique_ptr<Body> Slab(double opacity)
{
  auto body = std::make_unique<Body>(glm::ivec3(40), glm::dvec3(0.0), opacity, glm::dvec3(0.0),
    [](const glm::dvec3& p) { return (p.z >= 8.0 && p.z <= 31.0) ? 1.0f : 0.0f; });
  body->Path = [](const glm::dvec3& p, const glm::dvec3& d, double maxS, double grow) {
    return BoxPath(glm::dvec3(0.0, 0.0, 7.5 - grow), glm::dvec3(39.0, 39.0, 31.5 + grow), p, d, maxS);
  };
  body->SurfaceSlack = 0.001; // linear across z: the transfer function's step alone
  return body;
}

// A uniform medium filling a 41^3 grid (world = index): the box [0, 40]^3.
inline std::unique_ptr<Body> Filled(double opacity, const glm::dvec3& color = glm::dvec3(0.0))
{
  auto body = std::make_unique<Body>(glm::ivec3(41), glm::dvec3(0.0), opacity, color, [](const glm::dvec3&) { return 1.0f; });
  body->Path = [](const glm::dvec3& p, const glm::dvec3& d, double maxS, double) {
    return BoxPath(glm::dvec3(0.0), glm::dvec3(40.0), p, d, maxS); // the box's own faces
  };
  return body;
}

inline Light Directional(const glm::dvec3& toLight)
{
  Light light;
  light.Position = toLight;
  light.FocalPoint = glm::dvec3(0.0);
  return light;
}

inline Light Positional(const glm::dvec3& position, const glm::dvec3& focal, double coneAngle = 180.0)
{
  Light light;
  light.Positional = true;
  light.Position = position;
  light.FocalPoint = focal;
  light.ConeAngle = coneAngle;
  return light;
}

// The ground under the ball on the far side of a light at 45 degrees in the x-z plane: an
// opaque box [-58, -2] x [-28, 28] x [-31, -30] that casts shadows too (as
// vtkDeepShadowPolyDataMapper's meshes do by default), with one smooth normal per corner
// (what the mapper computes for a box that has none: the shading normal of its top face
// tilts towards its edges, its plane does not).
constexpr double GroundTop = -30.0;
inline SurfaceMesh Ground()
{
  SurfaceMesh mesh;
  for (int c = 0; c < 8; ++c)
  {
    const glm::dvec3 corner((c & 1) ? 1.0 : -1.0, (c & 2) ? 1.0 : -1.0, (c & 4) ? 1.0 : -1.0);
    mesh.Points.emplace_back(corner.x > 0.0 ? -2.0 : -58.0, corner.y > 0.0 ? 28.0 : -28.0,
      corner.z > 0.0 ? GroundTop : GroundTop - 1.0);
    mesh.Normals.push_back(glm::normalize(corner));
  }
  // Outward, counter-clockwise seen from outside: -z, +z, -y, +y, -x, +x.
  const int faces[6][4] = { { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 }, { 2, 6, 7, 3 }, { 0, 4, 6, 2 },
    { 1, 3, 7, 5 } };
  for (const auto& q : faces)
  {
    mesh.Triangles.push_back({ q[0], q[1], q[2] });
    mesh.Triangles.push_back({ q[0], q[2], q[3] });
  }
  mesh.Material.Opacity = 1.0;
  return mesh;
}

/**
 * A technique by its short name (deepshadow --technique), at its defaults, or as a spec with
 * parameters after it (dsm:chunk-nodes=4, as the report's sweep writes them).
 */
inline ShadowParameters Technique(std::string name)
{
  std::vector<std::pair<std::string, std::string>> settings;
  for (size_t colon = name.rfind(':'); colon != std::string::npos; colon = name.rfind(':'))
  {
    const std::string setting = name.substr(colon + 1);
    const size_t equals = setting.find('=');
    settings.emplace_back(setting.substr(0, equals), setting.substr(equals + 1));
    name.resize(colon);
  }
  // The registry's defaults for NAME or NAME-cached, as the tool and the GPU classes take them.
  bool cached = false;
  const ShadowTechniqueInfo* technique = FindShadowTechnique(name, &cached);
  if (!technique)
  {
    throw std::invalid_argument("no technique " + name);
  }
  ShadowParameters p = technique->DefaultParameters(cached);
  for (const auto& setting : settings)
  {
    const ShadowParameterInfo* info = FindShadowParameter(setting.first);
    info->Set(p, info->Parse(setting.second));
  }
  return p;
}

/** Every technique of the registry, cached or not ("none" left out): the suites' list. */
inline std::vector<std::string> RegistryTechniques()
{
  std::vector<std::string> names = ShadowTechniqueNames();
  names.erase(std::remove(names.begin(), names.end(), "none"), names.end());
  return names;
}

/** A hard shadow (lit or not, by the threshold): the registry's flag (ShadowTechniqueInfo::Binary). */
inline bool IsBinary(const ShadowParameters& p)
{
  return ShadowTechniqueOf(p).Binary;
}

/**
 * What a technique may leave of the light where the true visibility is (nearly) 0: binary
 * and stochastic ones nothing, deep shadow maps their bound, the other translucent ones the
 * transmittance at which they stop and what they state behind a medium (opacity levels
 * nothing, the maximum is exact; a truncated series its ringing) (the stiff suites, CPU and
 * GPU).
 */
inline double DarkTolerance(const ShadowParameters& p)
{
  if (p.Kind == ShadowKind::DeepShadowMap)
  {
    return p.Epsilon;
  }
  if (IsBinary(p) || p.Kind == ShadowKind::Stochastic)
  {
    return 0.0;
  }
  return (p.EarlyTermination ? ShadowTerminationTransmittance : 0.0) +
    ShadowTechniqueOf(p).StatedError(p, StatedErrorCase{ 0.0, false });
}

/**
 * World radius of what a lookup at p reads around it, perpendicular to the light: the
 * texels a light-space technique filters (bilinear, PCF, CSSM's offsets), or nothing.
 */
inline double LookupRadius(const ShadowParameters& parameters, const std::vector<ShadowMapFace>& faces,
  const glm::dvec3& p)
{
  const double texels = ShadowTechniqueOf(parameters).LookupTexels;
  if (texels == 0.0)
  {
    return 0.0;
  }
  // Resolution-matched maps without a camera hold their base level alone (4 x 4 pages).
  const PageLayout layout = PageLayout::Of(parameters);
  const int resolution = parameters.Kind == ShadowKind::ResolutionMatched ? layout.LevelSize(layout.BaseLevel())
                                                                         : parameters.MapSize;
  const ShadowMapFace& face = faces[ShadowMapFaceFor(faces, p - faces[0].Origin)];
  const double z = face.Perspective ? glm::dot(p - face.Origin, face.Forward) : 1.0;
  return texels * 2.0 * z * face.Extent / resolution;
}

/** The faces the technique's light-space map gets for this caster and light (LightSpace.h). */
inline std::vector<ShadowMapFace> FacesFor(const ShadowCaster& caster, const Light& light)
{
  return ShadowMapFaces(light, CasterBoundsOf(caster.Grid->GetIndexToWorld(), caster.Grid->GetDims(), caster.Surfaces));
}

/**
 * The closed form's spread around p: its largest difference from p's value over the points
 * within `radius` perpendicular to the light, and within `cell` in every direction (a cache
 * node's neighbourhood). What a lookup that blends those points may differ by.
 */
inline glm::dvec3 Spread(const Body& body, const Light& light, bool colored, const glm::dvec3& p, double radius,
  double cell)
{
  const glm::dvec3 centre = body.Exact(p, light, colored);
  glm::dvec3 spread(0.0);
  auto visit = [&](const glm::dvec3& q) {
    spread = glm::max(spread, glm::abs(body.Exact(q, light, colored) - centre));
  };
  if (radius > 0.0)
  {
    const glm::dvec3 l = light.At(p).ToLight;
    const glm::dvec3 e1 = glm::normalize(glm::cross(l, std::abs(l.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0)));
    const glm::dvec3 e2 = glm::cross(l, e1);
    for (double r : { 0.5 * radius, radius })
      for (int k = 0; k < 16; ++k)
        visit(p + r * (std::cos(k * Pi / 8.0) * e1 + std::sin(k * Pi / 8.0) * e2));
  }
  if (cell > 0.0)
  {
    for (int k = 0; k < 27; ++k)
      visit(p + cell * glm::dvec3(k % 3 - 1, (k / 3) % 3 - 1, k / 9 - 1));
  }
  return spread;
}


/** One answer held against the closed form, per channel. */
struct Verdict
{
  std::array<bool, 3> Checked{ { true, true, true } }; // false: binary, too near the threshold
  glm::dvec3 Expected{ 1.0 };
  glm::dvec3 Error{ 0.0 };
  glm::dvec3 Tolerance{ 0.0 };
  bool Good(int c) const { return !this->Checked[c] || this->Error[c] <= this->Tolerance[c]; }
};

/**
 * Holds `got`, a technique's answer for `light` at world point `at` (where the technique was
 * asked: a volume sample, or a mesh point moved towards the light by its lookup offset),
 * against the body's closed form. `cell`: node spacing of a grid the answer was
 * interpolated from (a cache, another volume's grid), else 0; `extra`: what the renderer adds
 * besides (the GPU: float arithmetic and 8-bit pixels).
 */
inline Verdict Judge(const Body& body, const ShadowParameters& parameters, const Light& light,
  const glm::dvec3& at, double cell, const glm::dvec3& got, double extra = 0.0)
{
  Verdict verdict;
  const double step = parameters.StepFactor * ViewStep;
  const std::vector<ShadowMapFace> faces = FacesFor(body.Caster, light);
  const double sigma = body.Sigma();
  const glm::dvec3 toLight = light.At(at).ToLight;
  const bool colored = parameters.IsColored();
  const glm::dvec3 exact = body.Exact(at, light, colored);
  const double length = body.Path(at, toLight, DistanceToLight(light, at), 0.0);
  // Where the grid puts the surface: the closed form for the body grown or shrunk that much.
  const glm::dvec3 surface = glm::max(glm::abs(body.Exact(at, light, colored, body.SurfaceSlack) - exact),
    glm::abs(body.Exact(at, light, colored, -body.SurfaceSlack) - exact));
  const glm::dvec3 spread = Spread(body, light, colored, at, LookupRadius(parameters, faces, at), cell);
  for (int c = 0; c < 3; ++c)
  {
    // Sampling: whole samples cover a path; a coloured medium's discrete model lies above
    // the continuous one by the concavity of exp (ColoredStepError); feelers and light rays
    // stop below 1/512.
    const double color = colored ? body.Color[c] : 0.0;
    double tolerance = SamplingError(exact[c], sigma * (1.0 - color), step) +
      ColoredStepError(sigma, step, color, length) + ShadowTerminationTransmittance + surface[c] + 1e-9;
    // The technique's own representation (the registry's StatedError).
    const bool mediumBehind = body.Path(at, -toLight, std::numeric_limits<double>::infinity(), 0.0) > 0.0;
    tolerance += ShadowTechniqueOf(parameters).StatedError(parameters, StatedErrorCase{ exact[c], mediumBehind });
    if (IsBinary(parameters))
    {
      // 0 where the accumulated opacity exceeds the threshold, 1 where it does not; only
      // where the closed form is on one side over the whole footprint. A shadow map compares
      // the point's depth less its bias: the closed form that far towards the light differs
      // by as much as one more stretch of medium lets through.
      const double bias =
        parameters.Kind == ShadowKind::ShadowMap || parameters.Kind == ShadowKind::ResolutionMatched
        ? exact[c] * (std::exp(sigma * parameters.Bias * step) - 1.0)
        : 0.0;
      const double opacity = 1.0 - exact[c];
      verdict.Checked[c] = std::abs(opacity - parameters.Threshold) > tolerance + spread[c] + bias;
      verdict.Expected[c] = opacity > parameters.Threshold ? 0.0 : 1.0;
      verdict.Tolerance[c] = 1e-9 + extra;
    }
    else
    {
      verdict.Expected[c] = exact[c];
      verdict.Tolerance[c] = tolerance + spread[c] + extra;
    }
    verdict.Error[c] = std::abs(got[c] - verdict.Expected[c]);
  }
  return verdict;
}

}
}
#endif
