// Every technique's CPU twin against closed-form answers (Beer-Lambert through homogeneous
// bodies, Testing/Common/ClosedForm.h), not against another renderer of this project: a
// mistake a technique shares with its GPU twin fails here.
//
// Scenes: a homogeneous ball over an opaque ground that casts too (mesh receivers, and a
// second volume's grid behind the ball), a homogeneous slab lit obliquely (the caster's own
// samples), a point light inside a uniform medium (cube faces) and a spot light above it
// (a perspective face); grey and coloured media.
//
// Each comparison's tolerance is the sum of what the technique is allowed, each term with its
// reason (Tolerance below): the march's sampling (a path covers whole samples), feeler
// termination (1/512), the technique's own bound (epsilon for deep shadow maps, the
// representation of three opacity levels, 4 standard errors of CSSM's estimate), and the
// resolution of its lookup: the closed form's own variation over the texels (or cache nodes)
// the lookup reads. Binary techniques are checked where the closed form is clearly on one
// side of the threshold over that footprint.
#include "../Common/ClosedForm.h"

#include "LightSpace.h"
#include "ReferenceRenderer.h"
#include "Shadows.h"
#include "SurfaceSet.h"
#include "ShadowGrid.h"
#include "StochasticShadowMap.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <vector>

using namespace deepshadow;
namespace cf = deepshadow::closedform;

namespace
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
  /** Length of the light ray from p (unit direction d, up to maxS) inside the body. */
  std::function<double(const glm::dvec3& p, const glm::dvec3& d, double maxS)> Path;

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

  double Sigma() const { return cf::Extinction(this->Opacity, 1.0); }

  /** Closed form: what reaches p of `light`, per channel for `colored` techniques. */
  glm::dvec3 Exact(const glm::dvec3& p, const Light& light, bool colored) const
  {
    const double length = this->Path(p, light.At(p).ToLight, DistanceToLight(light, p));
    return cf::ColoredTransmittance(this->Opacity, 1.0, colored ? this->Color : glm::dvec3(0.0), length);
  }
};

// A ball of radius 15 at the origin in a 48^3 grid of unit spacing.
constexpr double BallRadius = 15.0;
std::unique_ptr<Body> Ball(double opacity, const glm::dvec3& color = glm::dvec3(0.0))
{
  auto body = std::make_unique<Body>(glm::ivec3(48), glm::dvec3(-23.5), opacity, color,
    [](const glm::dvec3& p) { return cf::BallField(p, glm::dvec3(0.0), BallRadius); });
  body->Path = [](const glm::dvec3& p, const glm::dvec3& d, double maxS) {
    return cf::SphereChord(glm::dvec3(0.0), BallRadius, p, d, maxS);
  };
  return body;
}

// A slab filling a 40^3 grid (world = index) between z = 7.5 and z = 31.5.
std::unique_ptr<Body> Slab(double opacity)
{
  auto body = std::make_unique<Body>(glm::ivec3(40), glm::dvec3(0.0), opacity, glm::dvec3(0.0),
    [](const glm::dvec3& p) { return (p.z >= 8.0 && p.z <= 31.0) ? 1.0f : 0.0f; });
  body->Path = [](const glm::dvec3& p, const glm::dvec3& d, double maxS) {
    return cf::BoxPath(glm::dvec3(0.0, 0.0, 7.5), glm::dvec3(39.0, 39.0, 31.5), p, d, maxS);
  };
  return body;
}

// A uniform medium filling a 41^3 grid (world = index): the box [0, 40]^3.
std::unique_ptr<Body> Filled(double opacity, const glm::dvec3& color = glm::dvec3(0.0))
{
  auto body = std::make_unique<Body>(glm::ivec3(41), glm::dvec3(0.0), opacity, color, [](const glm::dvec3&) { return 1.0f; });
  body->Path = [](const glm::dvec3& p, const glm::dvec3& d, double maxS) {
    return cf::BoxPath(glm::dvec3(0.0), glm::dvec3(40.0), p, d, maxS);
  };
  return body;
}

Light Directional(const glm::dvec3& toLight)
{
  Light light;
  light.Position = toLight;
  light.FocalPoint = glm::dvec3(0.0);
  return light;
}

Light Positional(const glm::dvec3& position, const glm::dvec3& focal, double coneAngle = 180.0)
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
SurfaceMesh Ground()
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

/** A technique by its short name (deepshadow --technique), at its defaults. */
ShadowParameters Technique(std::string name)
{
  ShadowParameters p;
  const std::string cached = "-cached";
  if (name.size() > cached.size() && name.compare(name.size() - cached.size(), cached.size(), cached) == 0)
  {
    p.Cached = true;
    name.resize(name.size() - cached.size());
  }
  p.Kind = name.rfind("rays", 0) == 0 ? ShadowKind::Rays
    : name == "shadowmap"             ? ShadowKind::ShadowMap
    : name == "dsm3"                  ? ShadowKind::OpacityLevels
    : name == "cssm"                  ? ShadowKind::Stochastic
                                      : ShadowKind::DeepShadowMap;
  p.Opaque = name == "rays-opaque";
  p.Colored = name == "rays-color" || name == "dsm-color";
  return p;
}

bool IsBinary(const ShadowParameters& p)
{
  return p.Opaque || p.Kind == ShadowKind::ShadowMap;
}

/**
 * World radius of what a lookup at p reads around it, perpendicular to the light: the
 * texels a light-space technique filters (bilinear, PCF, CSSM's offsets), or nothing.
 */
double LookupRadius(const ShadowParameters& parameters, const std::vector<ShadowMapFace>& faces,
  const glm::dvec3& p)
{
  double texels = 0.0;
  switch (parameters.Kind)
  {
    case ShadowKind::DeepShadowMap:
    case ShadowKind::OpacityLevels:
      texels = 1.5; // bilinear
      break;
    case ShadowKind::ShadowMap:
      texels = 2.5; // PCF 3x3 around the nearest texel
      break;
    case ShadowKind::Stochastic:
      texels = 7.5; // the farthest of the 13 offsets, and the nearest texel
      break;
    default:
      return 0.0;
  }
  const ShadowMapFace& face = faces[ShadowMapFaceFor(faces, p - faces[0].Origin)];
  const double z = face.Perspective ? glm::dot(p - face.Origin, face.Forward) : 1.0;
  return texels * 2.0 * z * face.Extent / parameters.MapSize;
}

/** The faces the technique's light-space map gets for this caster and light (LightSpace.h). */
std::vector<ShadowMapFace> FacesFor(const ShadowCaster& caster, const Light& light)
{
  return ShadowMapFaces(light, CasterBoundsOf(caster.Grid->GetIndexToWorld(), caster.Grid->GetDims(), caster.Surfaces));
}

/**
 * The closed form's spread around p: its largest difference from p's value over the points
 * within `radius` perpendicular to the light, and within `cell` in every direction (a cache
 * node's neighbourhood). What a lookup that blends those points may differ by.
 */
glm::dvec3 Spread(const Body& body, const Light& light, bool colored, const glm::dvec3& p, double radius,
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

/** A point where a technique is asked for the light: a volume sample, or a mesh's point. */
struct Receiver
{
  glm::dvec3 Position;
  const SurfaceSet* Mesh = nullptr; // a mesh of it, seen from above, receives at Position
};

/**
 * What the CPU reference shows at a mesh receiver of `light` with only this shadow: its
 * shadow term, as ReferenceRenderer::ShadeSurface computes it (the lookup towards the light,
 * the triangle's plane) for the mesh point seen from straight above.
 */
glm::dvec3 MeshShadowTerm(const SurfaceSet& mesh, const glm::dvec3& position, const LightShadow& shadow,
  const Light& light, double feelerStep)
{
  const Ray ray{ position + glm::dvec3(0.0, 0.0, 5.0), glm::dvec3(0.0, 0.0, -1.0) };
  const SurfaceHit hit = mesh.NextHit(ray.Origin, ray.Direction, 0.0);
  EXPECT_TRUE(hit.Found && std::abs(hit.T - 5.0) < 1e-9);
  Scene scene;
  scene.Lights = { light };
  glm::dvec3 term(1.0);
  ReferenceRenderer::ShadeSurface(scene, mesh, hit, ray, { &shadow }, {}, DefaultReceiverBias(feelerStep), &term);
  return term;
}

struct Outcome
{
  int Checked = 0;
  int Failed = 0;
  double MaxError = 0.0;
};

/**
 * Asks `shadow` (built with `parameters` from `body`) for the light at every receiver and
 * holds the answer against the closed form within the technique's tolerance. `cell`: node
 * spacing of the grid the answers come from (a cache or another volume's grid), else 0.
 */
Outcome CheckAgainstClosedForm(const std::string& what, const Body& body, const ShadowParameters& parameters,
  const LightShadow& shadow, const Light& light, const std::vector<Receiver>& receivers, double cell = 0.0)
{
  Outcome outcome;
  const double step = parameters.StepFactor * ViewStep;
  const std::vector<ShadowMapFace> faces = FacesFor(body.Caster, light);
  const double sigma = body.Sigma();
  for (const Receiver& receiver : receivers)
  {
    const glm::dvec3 at = receiver.Position;
    const glm::dvec3 toLight = light.At(at).ToLight;
    const bool mesh = receiver.Mesh != nullptr;
    const glm::dvec3 got =
      mesh ? MeshShadowTerm(*receiver.Mesh, at, shadow, light, step) : shadow.Visibility(at);
    const bool colored = parameters.IsColored();
    const glm::dvec3 exact = body.Exact(at, light, colored);
    const double length = body.Path(at, toLight, DistanceToLight(light, at));
    const glm::dvec3 spread = Spread(body, light, colored, at, LookupRadius(parameters, faces, at), cell);
    for (int c = 0; c < 3; ++c)
    {
      // Sampling: whole samples cover a path; a coloured medium's discrete model lies above
      // the continuous one by the concavity of exp (ColoredStepError); feelers and light rays
      // stop below 1/512.
      const double color = colored ? body.Color[c] : 0.0;
      double tolerance = cf::SamplingError(exact[c], sigma * (1.0 - color), step) +
        cf::ColoredStepError(sigma, step, color, length) + ShadowTerminationTransmittance + 1e-9;
      switch (parameters.Kind)
      {
        case ShadowKind::DeepShadowMap:
          tolerance += parameters.Epsilon; // |V' - V| <= epsilon at every sample depth
          break;
        case ShadowKind::OpacityLevels:
          // Three levels joined by smoothsteps (paper 001) approximate an exponential
          // opacity inside a medium within 0.1 (before 10 %, and between 50 and 90 %); past
          // the medium the maximum opacity is exact.
          tolerance += mesh ? 0.0 : 0.1;
          break;
        case ShadowKind::Stochastic:
          // Unbiased: 4 standard errors of the mean of offsets x photons Bernoulli tests.
          tolerance += 4.0 * std::sqrt(exact[c] * (1.0 - exact[c]) /
                               (StochasticOffsets(parameters.Offsets).size() * parameters.Photons));
          break;
        default:
          break;
      }
      const double error = std::abs(got[c] - exact[c]);
      if (IsBinary(parameters))
      {
        // 0 where the accumulated opacity exceeds the threshold, 1 where it does not; only
        // where the closed form is on one side over the whole footprint.
        // A shadow map compares the point's depth less its bias: the closed form that far
        // towards the light differs by as much as one more stretch of medium lets through.
        const double bias = parameters.Kind == ShadowKind::ShadowMap
          ? exact[c] * (std::exp(sigma * parameters.Bias * step) - 1.0)
          : 0.0;
        const double opacity = 1.0 - exact[c], margin = tolerance + spread[c] + bias;
        if (std::abs(opacity - parameters.Threshold) <= margin)
        {
          continue;
        }
        const double expected = opacity > parameters.Threshold ? 0.0 : 1.0;
        const double binaryError = std::abs(got[c] - expected);
        outcome.MaxError = std::max(outcome.MaxError, binaryError);
        ++outcome.Checked;
        if (binaryError > 1e-9)
        {
          if (++outcome.Failed <= 3)
            ADD_FAILURE() << what << " at (" << at.x << ", " << at.y << ", " << at.z << ") channel " << c
                          << ": " << got[c] << ", expected " << expected << " (closed form T " << exact[c]
                          << ", threshold " << parameters.Threshold << ")";
        }
        continue;
      }
      tolerance += spread[c];
      outcome.MaxError = std::max(outcome.MaxError, error);
      ++outcome.Checked;
      if (error > tolerance && ++outcome.Failed <= 3)
      {
        ADD_FAILURE() << what << " at (" << at.x << ", " << at.y << ", " << at.z << ") channel " << c << ": "
                      << got[c] << ", closed form " << exact[c] << ", error " << error << " > " << tolerance;
      }
    }
  }
  std::printf("%-44s %4d checked, max error %.4f%s\n", what.c_str(), outcome.Checked, outcome.MaxError,
    outcome.Failed ? " FAILED" : "");
  return outcome;
}

// Receivers on the ground's top face under the ball: a 4-unit lattice.
std::vector<Receiver> GroundReceivers(const SurfaceSet& ground)
{
  std::vector<Receiver> receivers;
  for (double x = -54.0; x <= -6.0; x += 4.0)
    for (double y = -24.0; y <= 24.0; y += 4.0)
      receivers.push_back({ { x, y, GroundTop }, &ground });
  return receivers;
}

const Light BallLight = Directional({ 1.0, 0.0, 1.0 });
constexpr double BallOpacity = 0.04; // a 30-unit chord lets through 0.29, the rim 1

void CheckBallOnGround(const std::string& name, const glm::dvec3& color = glm::dvec3(0.0))
{
  const auto ball = Ball(BallOpacity, color);
  Body& body = *ball;
  SurfaceSet surfaces({ Ground() });
  body.Caster.Surfaces = &surfaces;
  ShadowParameters parameters = Technique(name);
  if (parameters.Kind == ShadowKind::Stochastic)
  {
    // Independent photons per texel: the mean over 32 seeds' maps, at 256^2 to keep the
    // CPU build short (the lookup's footprint, and the tolerance, grow with the texel).
    parameters.Photons = 32;
    parameters.MapSize = 256;
  }
  // Meshes look a cached technique up directly (its grid covers the volume's box only).
  parameters.Cached = false;
  const auto shadow = MakeLightShadow(parameters, body.Caster, BallLight, ViewStep);
  const Outcome outcome =
    CheckAgainstClosedForm(name + " ball on a ground", body, parameters, *shadow, BallLight, GroundReceivers(surfaces));
  EXPECT_EQ(outcome.Failed, 0);
  EXPECT_GT(outcome.Checked, 200);
}

void CheckSlabSelfShadow(const std::string& name)
{
  const auto slab = Slab(0.06);
  const Body& body = *slab;
  const Light light = Directional({ std::sin(Pi / 6.0), 0.0, std::cos(Pi / 6.0) });
  ShadowParameters parameters = Technique(name);
  if (parameters.Kind == ShadowKind::Stochastic)
  {
    parameters.Photons = 32; // the mean over 32 seeds' maps, at 256^2 (see CheckBallOnGround)
    parameters.MapSize = 256;
  }
  const auto shadow = MakeLightShadow(parameters, body.Caster, light, ViewStep);
  // Inside the slab, where the light enters through its top face.
  std::vector<Receiver> receivers;
  for (double z = 9.0; z <= 30.0; z += 3.0)
    for (double x = 6.0; x <= 22.0; x += 4.0)
      receivers.push_back({ { x, 20.0, z } });
  const double cell = parameters.Cached ? 39.0 / (ShadowVolumeDims(body.Grid->GetDims(), parameters.VolumeSize).x - 1) : 0.0;
  const Outcome outcome =
    CheckAgainstClosedForm(name + " slab, its own samples", body, parameters, *shadow, light, receivers, cell);
  EXPECT_EQ(outcome.Failed, 0);
  EXPECT_GT(outcome.Checked, 100);
}


// A second volume's grid behind the ball (what vtkDeepShadowPass stores for a receiving
// volume, GridFrame::OverVolume at the default 64 nodes): the ball's technique evaluated at
// its nodes and interpolated trilinearly, as the GPU's OtherVolumeShadows does.
void CheckBallOnSecondVolume(const std::string& name)
{
  const auto ball = Ball(BallOpacity);
  const Body& body = *ball;
  ShadowParameters parameters = Technique(name);
  parameters.Cached = false; // other volumes read a technique directly
  if (parameters.Kind == ShadowKind::Stochastic)
  {
    parameters.Photons = 32; // the mean over 32 seeds' maps, at 256^2 (see CheckBallOnGround)
    parameters.MapSize = 256;
  }
  const auto shadow = MakeLightShadow(parameters, body.Caster, BallLight, ViewStep);
  // A receiver 48 x 48 x 8 units under the ball's shadow (1-unit voxels).
  const glm::ivec3 dims(49, 49, 9);
  const glm::dmat4 indexToWorld = glm::translate(glm::dmat4(1.0), glm::dvec3(-54.0, -24.0, -34.0));
  const GridFrame frame = GridFrame::OverVolume(dims, indexToWorld, 64);
  const ShadowGrid grid([&](const glm::dvec3& p) { return shadow->Visibility(p); }, frame, parameters.IsColored());
  std::vector<Receiver> receivers;
  for (double x = -50.0; x <= -10.0; x += 5.0)
    for (double y = -20.0; y <= 20.0; y += 5.0)
      for (double z : { -33.0, -30.5, -28.0 })
        receivers.push_back({ { x, y, z } });
  const double cell = 48.0 / (frame.Dims.x - 1);
  const Outcome outcome = CheckAgainstClosedForm(
    name + " ball on a second volume", body, parameters, grid, BallLight, receivers, cell);
  EXPECT_EQ(outcome.Failed, 0);
  EXPECT_GT(outcome.Checked, 200);
}

// A point light at the centre of a uniform medium: exp(-sigma r) at distance r (six cube
// faces for light-space techniques); and a spot light above it, pointing in (a perspective
// face): exp(-sigma * the path from the box's top face).
void CheckMediumWithPositionalLight(const std::string& name, bool spot, const glm::dvec3& color = glm::dvec3(0.0))
{
  const auto filled = Filled(0.05, color);
  const Body& body = *filled;
  const Light light = spot ? Positional({ 20.0, 20.0, 70.0 }, { 20.0, 20.0, 0.0 }, 20.0)
                           : Positional({ 20.0, 20.0, 20.0 }, { 20.0, 20.0, 0.0 });
  ShadowParameters parameters = Technique(name);
  // Six (or one) faces of a medium that fills the volume: 128^2 texels keep the CPU build
  // short; the lookup's footprint grows with the texel and the tolerance with it.
  parameters.MapSize = 128;
  if (parameters.Kind == ShadowKind::Stochastic)
  {
    parameters.Photons = 16;
  }
  const auto shadow = MakeLightShadow(parameters, body.Caster, light, ViewStep);
  std::vector<Receiver> receivers;
  for (int k = 0; k < 200; ++k)
  {
    // Points spread over directions and distances (a fixed low-discrepancy set).
    const double u = std::fmod(0.618033988749895 * k, 1.0), v = std::fmod(0.754877666246693 * k, 1.0);
    const double w = std::fmod(0.569840290998053 * k, 1.0);
    glm::dvec3 p;
    if (spot)
    {
      // Inside the cone (half angle 20 degrees), below the top face by 2 to 38 units.
      const double depth = 2.0 + 36.0 * w, radius = 0.9 * (70.0 - 40.0 + depth) * std::tan(20.0 * Pi / 180.0);
      const double r = std::min(radius * std::sqrt(u), 18.0);
      p = { 20.0 + r * std::cos(2.0 * Pi * v), 20.0 + r * std::sin(2.0 * Pi * v), 40.0 - depth };
    }
    else
    {
      const double z = 2.0 * u - 1.0, phi = 2.0 * Pi * v, r = 3.0 + 15.0 * w;
      p = glm::dvec3(20.0) + r * glm::dvec3(std::sqrt(1.0 - z * z) * std::cos(phi), std::sqrt(1.0 - z * z) * std::sin(phi), z);
    }
    receivers.push_back({ p });
  }
  const double cell = parameters.Cached ? 40.0 / (ShadowVolumeDims(body.Grid->GetDims(), parameters.VolumeSize).x - 1) : 0.0;
  const Outcome outcome = CheckAgainstClosedForm(name + (spot ? " spot light above a medium" : " point light in a medium"),
    body, parameters, *shadow, light, receivers, cell);
  EXPECT_EQ(outcome.Failed, 0);
  EXPECT_GT(outcome.Checked, 150);
}

// A coloured medium (orange: it lets red through, stops most blue).
const glm::dvec3 Orange{ 1.0, 0.6, 0.2 };
}

// Grey techniques on a mesh receiver: the ground under a translucent ball.
TEST(ClosedFormShadows, RaysOnAGroundUnderABall) { CheckBallOnGround("rays"); }
TEST(ClosedFormShadows, DeepShadowMapOnAGroundUnderABall) { CheckBallOnGround("dsm"); }
// CSSM's offsets reach 7 texels: on a receiver that slopes away from the light, they must
// compare the receiver plane's depth there, not the point's (else the ground's own crossing
// in the texels towards the light shadows it: 30 % darker, and the ball's shadow lost).
TEST(ClosedFormShadows, StochasticShadowMapOnAGroundUnderABall) { CheckBallOnGround("cssm"); }
// Three opacity levels interpolate smoothly between their depths: a mesh's step must not be
// one of them (the ground's own step made the levels run from the ball to the ground, and
// the ground under the ball read 1 - 0.9 instead of the ball's transmittance).
TEST(ClosedFormShadows, OpacityLevelsOnAGroundUnderABall) { CheckBallOnGround("dsm3"); }
TEST(ClosedFormShadows, ShadowMapOnAGroundUnderABall) { CheckBallOnGround("shadowmap"); }
TEST(ClosedFormShadows, OpaqueRaysOnAGroundUnderABall) { CheckBallOnGround("rays-opaque"); }

// The caster's own samples: a slab lit at 30 degrees, T = (1 - a)^(depth / cos 30).
TEST(ClosedFormShadows, RaysInsideASlab) { CheckSlabSelfShadow("rays"); }
TEST(ClosedFormShadows, CachedRaysInsideASlab) { CheckSlabSelfShadow("rays-cached"); }
TEST(ClosedFormShadows, DeepShadowMapInsideASlab) { CheckSlabSelfShadow("dsm"); }
TEST(ClosedFormShadows, CachedDeepShadowMapInsideASlab) { CheckSlabSelfShadow("dsm-cached"); }
TEST(ClosedFormShadows, OpacityLevelsInsideASlab) { CheckSlabSelfShadow("dsm3"); }
TEST(ClosedFormShadows, StochasticShadowMapInsideASlab) { CheckSlabSelfShadow("cssm"); }
// Binary techniques: the hard shadow of a thick translucent body (every sample's opacity is
// 0.06, far below the threshold 0.5; the accumulated opacity is not).
TEST(ClosedFormShadows, ShadowMapInsideASlab) { CheckSlabSelfShadow("shadowmap"); }
TEST(ClosedFormShadows, OpaqueRaysInsideASlab) { CheckSlabSelfShadow("rays-opaque"); }

// What one volume casts onto another, through the receiver's grid.
TEST(ClosedFormShadows, RaysOnASecondVolume) { CheckBallOnSecondVolume("rays"); }
TEST(ClosedFormShadows, DeepShadowMapOnASecondVolume) { CheckBallOnSecondVolume("dsm"); }
TEST(ClosedFormShadows, OpacityLevelsOnASecondVolume) { CheckBallOnSecondVolume("dsm3"); }
TEST(ClosedFormShadows, StochasticShadowMapOnASecondVolume) { CheckBallOnSecondVolume("cssm"); }
TEST(ClosedFormShadows, ShadowMapOnASecondVolume) { CheckBallOnSecondVolume("shadowmap"); }

// Positional lights: inside the medium (cube faces), and a spot above it.
TEST(ClosedFormShadows, PointLightInAMedium)
{
  for (const char* name : { "rays", "rays-cached", "dsm", "dsm-cached", "dsm3", "cssm", "shadowmap", "rays-opaque" })
  {
    CheckMediumWithPositionalLight(name, false);
  }
}
TEST(ClosedFormShadows, SpotLightAboveAMedium)
{
  for (const char* name : { "rays", "dsm", "dsm3", "cssm", "shadowmap", "rays-opaque" })
  {
    CheckMediumWithPositionalLight(name, true);
  }
}

// Coloured media: each channel's transmittance exp(-sigma (1 - c) L).
TEST(ClosedFormShadows, ColouredRaysAndDeepShadowMapsOnAGround)
{
  CheckBallOnGround("rays-color", Orange);
  CheckBallOnGround("dsm-color", Orange);
}
TEST(ClosedFormShadows, ColouredStochasticShadowMapOnAGround) { CheckBallOnGround("cssm", Orange); }
TEST(ClosedFormShadows, ColouredPointLightInAMedium)
{
  for (const char* name : { "rays-color", "dsm-color", "cssm" })
  {
    CheckMediumWithPositionalLight(name, false, Orange);
  }
}
