// Every technique's CPU twin against closed-form answers (Beer-Lambert through homogeneous
// bodies, Testing/Common/ClosedForm.h), not against another renderer of this project: a
// mistake a technique shares with its GPU twin fails here.
//
// Scenes: a homogeneous ball over an opaque ground that casts too (mesh receivers, and a
// second volume's grid behind the ball), a homogeneous slab lit obliquely (the caster's own
// samples), a point light inside a uniform medium (cube faces) and a spot light above it
// (a perspective face); grey and coloured media.
//
// Each answer is judged by closedform::Judge (Testing/Common/ClosedFormScenes.h, shared with
// the GPU test): a tolerance summed from what the technique is allowed, each term with its
// reason. Mesh receivers go through ReferenceRenderer::ShadeSurface, as the CPU reference
// draws them.
#include "ClosedFormScenes.h"

#include "Core/Shadows/LightSpace.h"
#include "Core/ReferenceRenderer.h"
#include "Core/Shadows.h"
#include "Core/Geometry/SurfaceSet.h"
#include "Core/Shadows/ShadowGrid.h"
#include "Core/Shadows/StochasticShadowMap.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <vector>

using namespace deepshadow;
namespace cf = deepshadow::closedform;
using namespace deepshadow::closedform;

namespace
{
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
  for (const Receiver& receiver : receivers)
  {
    const glm::dvec3& at = receiver.Position;
    const bool mesh = receiver.Mesh != nullptr;
    const glm::dvec3 got = mesh
      ? MeshShadowTerm(*receiver.Mesh, at, shadow, light, parameters.StepFactor * cf::ViewStep)
      : shadow.Visibility(at);
    const cf::Verdict verdict = cf::Judge(body, parameters, light, at, cell, got);
    for (int c = 0; c < 3; ++c)
    {
      if (!verdict.Checked[c])
      {
        continue;
      }
      ++outcome.Checked;
      outcome.MaxError = std::max(outcome.MaxError, verdict.Error[c]);
      if (!verdict.Good(c) && ++outcome.Failed <= 3)
      {
        ADD_FAILURE() << what << " at (" << at.x << ", " << at.y << ", " << at.z << ") channel " << c << ": "
                      << got[c] << ", expected " << verdict.Expected[c] << ", error " << verdict.Error[c]
                      << " > " << verdict.Tolerance[c];
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
  // At least half the 40 receivers' channels: a binary technique skips those within its
  // tolerance of the threshold (a cached one's grid widens that: 90 of 120).
  EXPECT_GE(outcome.Checked, 60);
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
// Every technique of the registry, cached or not, on the scenes every kind serves: the
// ball's shadow on the ground and the slab's own samples. A new technique is here without
// an edit; the tests below keep the variants (chunked nodes, coloured media, other lights).
TEST(ClosedFormShadows, EveryRegistryTechnique)
{
  for (const std::string& name : RegistryTechniques())
  {
    CheckBallOnGround(name);
    CheckSlabSelfShadow(name);
  }
}

TEST(ClosedFormShadows, RaysOnAGroundUnderABall) { CheckBallOnGround("rays"); }
TEST(ClosedFormShadows, DeepShadowMapOnAGroundUnderABall) { CheckBallOnGround("dsm"); }
TEST(ClosedFormShadows, ChunkedDeepShadowMapOnAGroundUnderABall) { CheckBallOnGround("dsm:chunk-nodes=4"); }
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
TEST(ClosedFormShadows, ChunkedDeepShadowMapInsideASlab) { CheckSlabSelfShadow("dsm:chunk-nodes=2"); }
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
TEST(ClosedFormShadows, ChunkedDeepShadowMapOnASecondVolume) { CheckBallOnSecondVolume("dsm:chunk-nodes=4"); }
TEST(ClosedFormShadows, OpacityLevelsOnASecondVolume) { CheckBallOnSecondVolume("dsm3"); }
TEST(ClosedFormShadows, StochasticShadowMapOnASecondVolume) { CheckBallOnSecondVolume("cssm"); }
TEST(ClosedFormShadows, ShadowMapOnASecondVolume) { CheckBallOnSecondVolume("shadowmap"); }

// Positional lights: inside the medium (cube faces), and a spot above it.
TEST(ClosedFormShadows, PointLightInAMedium)
{
  for (const char* name : { "rays", "rays-cached", "dsm", "dsm:chunk-nodes=4", "dsm-cached", "dsm3", "cssm", "shadowmap", "rays-opaque" })
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
  for (const char* name : { "rays-color", "dsm-color", "dsm-color:chunk-nodes=4", "cssm" })
  {
    CheckMediumWithPositionalLight(name, false, Orange);
  }
}
