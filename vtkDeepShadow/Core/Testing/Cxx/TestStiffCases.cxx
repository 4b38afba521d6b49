// Stiff and extreme cases (issue 7), CPU side: the double-precision twins at the edges, for
// every shadow technique, with the defined behaviour in each test's name and comment. The GPU
// side, each technique against its twin, is Rendering's TestStiffCasesGPU.cxx ("GPU n" is its
// part n). The index of every stiff case, here and elsewhere:
// - opacity -> 1: OpacityNearOneSaturatesToAmbientOnlyWithoutNaN; GPU 2; view rays alone:
//   ReferenceRenderer.OpacityOneEverywhereSaturatesWithoutNaN.
// - opacity -> 0: OpacityZeroDrawsTheBackgroundAndCastsNoShadow; GPU 2 (rays-opaque, shadowmap,
//   caches); TestShadowEdgeCases (rays) and TestDeepShadowEdgeCases (dsm, dsm-color, dsm3, cssm).
// - opacity unit distance 1e-4 .. 1e4: OpacityUnitDistancesFrom...; GPU 3.
// - visibility monotone along a light ray: VisibilityNeverIncreasesAwayFromTheLight.
// - one-voxel slab, face-on and edge-on: OneVoxelSlabShadowsFaceOnAndEdgeOn; GPU 1.
// - sample distance 1e-3 .. 10 voxels: SampleDistancesFrom...; GPU 3 (with llvmpipe's loop
//   limit); view rays at 1 .. 0.01: ReferenceRenderer.HomogeneousSlabFollowsBeerLambert;
//   feelers at 1 .. 0.25: Shadows.TranslucentFeelerFollowsBeerLambertThroughASlab.
// - 1x1x1, 1x1xN, NxNx1: FlatGridsDrawNothingAndShadowNothing (cached and uncached); GPU 4
//   (1x1x1 and 1x1xN refused, 2x2x2 drawn); N x N x 1 refused: TestBadInput.
// - spacing 1:1000: SpacingRatiosOfAThousand...; MapsKeepTheShadowOfANeedleSeenEndOn; GPU 5.
// - lights grazing a face, inside, at the camera, exactly behind, 1e6 away: LightsAtThe
//   Extremes...; inside: ALightInsideTheVolume..., Shadows.PositionalLightsStopTheFeelerAtTheLight;
//   at the camera: ALightAtTheCamera..., GPU 6; behind: GPU 2; 1e6 away: GPU 6 (rays, shadow
//   maps, caches); grazing, inside, 1e6 (other maps) on the GPU: TestShadowEdgeCases and
//   TestDeepShadowEdgeCases.
// - several lights of zero intensity: ZeroIntensityLightsGive...; GPU 6.
// - near/far 1e6: ShadowMapsHoldForNearFarRatiosOfAMillion; GPU 6 (shadow map); deep shadow
//   maps: LightSpace.DepthPrecisionHoldsForNearFarRatiosOfAMillion, TestDeepShadowEdgeCases.
// - epsilon 0: DeepShadowMap.EpsilonZeroKeepsEverySampleToFloatPrecision, TestDeepShadow
//   Techniques "dsm, epsilon 0, 64 layers"; one layer: DeepShadowMap.OverflowDoublesTheBound
//   UntilTheNodesFit, TestDeepShadowTechniques "dsm, 1 layer"; negative nodes:
//   DeepShadowMapNodesAreNeverNegative, GPU 2.
// - map sizes: MapSizeOneShadowsALaterallyUniformLayer; GPU 7 (1, the GL's largest, one more);
//   0 clamped to 1, 100000 refused: TestShadowEdgeCases; 3072 layers: TestDeepShadowEdgeCases.
// - NaN / +-Inf: VolumeGrid.RangeIgnoresNonFiniteValues, VolumeGrid.ReplacingAnAllNonFinite
//   ArrayGivesZeros, TestBadInput (refused, or replaced); replaced and shadowed: GPU 8.
// - denormals, full-range float and short: DenormalAndFullRangeSamplesAreTheirValues; GPU 8;
//   unsigned short over its full range: TestScalarTypes.
// - determinism: JitterAndStochasticSeedsGiveBitIdenticalPictures; GPU 9; ReferenceRenderer.
//   ImagesAreIdenticalForAnyThreadCount; StochasticShadowMap.SeedsMakeMapsReproducible.
#include "Core/Shadows/DeepShadowMap.h"
#include "Core/Shadows/LightSpace.h"
#include "Core/ReferenceRenderer.h"
#include "Core/Shadows.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <string>

using namespace deepshadow;

namespace
{
constexpr int Threads = 2;

std::shared_ptr<VolumeGrid> Grid(const glm::ivec3& dims, const glm::dvec3& spacing,
  const std::function<float(int, int, int)>& value)
{
  std::vector<float> values;
  values.reserve(static_cast<size_t>(dims.x) * dims.y * dims.z);
  for (int k = 0; k < dims.z; ++k)
    for (int j = 0; j < dims.y; ++j)
      for (int i = 0; i < dims.x; ++i)
        values.push_back(value(i, j, k));
  return std::make_shared<VolumeGrid>(dims, std::move(values), glm::scale(glm::dmat4(1.0), spacing));
}

std::shared_ptr<VolumeGrid> Uniform(int n, float value = 1.0f)
{
  return Grid(glm::ivec3(n), glm::dvec3(1.0), [=](int, int, int) { return value; });
}

// Scalars in [0, 1]: opacity 0 at 0 and `alpha` from `from` up; grey colour `grey` (< 1, so
// that a coloured technique's medium lets through only part of the light).
TransferFunction Medium(double alpha, double from = 0.5, double grey = 0.5)
{
  TransferFunction tf = TransferFunction::Grey({ { 0.0, 0.0 }, { from, alpha }, { 1.0, alpha } });
  tf.Red = tf.Green = tf.Blue = PiecewiseLinear({ { 0.0, grey } });
  return tf;
}

Light Directional(const glm::dvec3& toLight)
{
  Light light;
  light.Position = toLight;
  return light;
}

Light Positional(const glm::dvec3& position)
{
  Light light;
  light.Positional = true;
  light.Position = position;
  return light;
}

ShadowParameters Technique(ShadowKind kind, bool colored = false, bool cached = false, bool opaque = false)
{
  ShadowParameters p;
  p.Kind = kind;
  p.Colored = colored;
  p.Cached = cached;
  p.Opaque = opaque;
  p.MapSize = 32;
  p.VolumeSize = 128; // as many nodes as voxels: cache nodes sit on the voxels
  p.Seed = 3;
  return p;
}

// Every technique the mapper offers, at small maps; the ground truth (no early termination) first.
std::vector<ShadowParameters> EveryTechnique()
{
  return { ShadowParameters::GroundTruth(false, 1.0), Technique(ShadowKind::Rays),
    Technique(ShadowKind::Rays, false, false, true), Technique(ShadowKind::Rays, true),
    Technique(ShadowKind::ShadowMap), Technique(ShadowKind::DeepShadowMap),
    Technique(ShadowKind::DeepShadowMap, true), Technique(ShadowKind::OpacityLevels),
    Technique(ShadowKind::Stochastic), Technique(ShadowKind::Rays, false, true),
    Technique(ShadowKind::ShadowMap, false, true), Technique(ShadowKind::DeepShadowMap, false, true),
    Technique(ShadowKind::Stochastic, false, true) };
}

std::string NameOf(const ShadowParameters& p)
{
  return p.Kind == ShadowKind::Rays && !p.EarlyTermination ? "ground truth" : p.Name();
}

// What a technique may leave of the light where the true visibility is (nearly) 0: binary
// and stochastic ones nothing, translucent feelers and opacity levels the transmittance at
// which they stop, deep shadow maps their bound.
double DarkTolerance(const ShadowParameters& p)
{
  if (p.Kind == ShadowKind::DeepShadowMap)
  {
    return p.Epsilon;
  }
  const bool binary = p.Kind == ShadowKind::ShadowMap || p.Kind == ShadowKind::Stochastic || p.Opaque;
  return binary || !p.EarlyTermination ? 0.0 : ShadowTerminationTransmittance;
}

// No technique takes light below the ambient-only value: every visibility is in [0, 1]
// (deep shadow map nodes included, see DeepShadowMapNodesAreNeverNegative).
double NegativeAllowance(const ShadowParameters&)
{
  return 0.0;
}

// A volume that casts, kept alive with its transfer function.
struct Caster
{
  std::shared_ptr<VolumeGrid> G;
  TransferFunction Transfer;
  Interpolation Sampling = Interpolation::Linear;
  ShadowCaster Get() const
  {
    ShadowCaster c;
    c.Grid = this->G.get();
    c.Transfer = &this->Transfer;
    c.Sampling = this->Sampling;
    return c;
  }
  std::unique_ptr<LightShadow> Shadow(const ShadowParameters& p, const Light& light, double step = 0.5) const
  {
    return MakeLightShadow(p, this->Get(), light, step, Threads);
  }
};

// A size x size orthographic view of the box [0, extent]^2 x [0, depth] from below (-z),
// unshaded (lit isotropically because it receives shadows).
Scene ViewFromBelow(std::shared_ptr<VolumeGrid> grid, const TransferFunction& tf, const ShadowParameters& p,
  const std::vector<Light>& lights, int size = 24)
{
  const glm::dvec3 top = glm::dvec3(grid->GetIndexToWorld() * glm::dvec4(glm::dvec3(grid->GetDims() - 1), 1.0));
  const glm::dvec3 centre = 0.5 * top;
  const double half = 0.6 * std::max({ top.x, top.y, 1.0 });
  Scene scene;
  const glm::dmat4 view = glm::lookAt(glm::dvec3(centre.x, centre.y, -40.0 - top.z), centre, glm::dvec3(0, 1, 0));
  scene.View = Camera(glm::ortho(-half, half, -half, half, 1.0, 100.0 + 2.0 * top.z) * view, size, size);
  scene.Lights = lights;
  scene.Background = { 0.2, 0.3, 0.4 };
  VolumeInstance volume;
  volume.Grid = std::move(grid);
  volume.Transfer = tf;
  volume.Shadows = p;
  scene.Volumes.push_back(volume);
  return scene;
}

MarchSettings Exact(double sampleDistance = 0.5)
{
  MarchSettings settings;
  settings.SampleDistance = sampleDistance;
  return settings;
}

// Every channel finite, and ambient-only <= shadowed <= unshadowed: shadows never add light
// and never take away more than the direct light. Returns the shadowed image.
Image ExpectLightBounded(const Scene& scene, const MarchSettings& settings, const std::string& what)
{
  const double allowance = NegativeAllowance(scene.Volumes[0].Shadows);
  Scene unshadowed = scene, ambient = scene;
  for (Light& light : unshadowed.Lights)
  {
    light.ShadowAttenuation = 0.0;
  }
  for (Light& light : ambient.Lights)
  {
    light.Diffuse = light.Specular = glm::dvec3(0.0);
  }
  const Image shadowed = ReferenceRenderer::Render(scene, settings, Threads);
  const Image upper = ReferenceRenderer::Render(unshadowed, settings, Threads);
  const Image lower = ReferenceRenderer::Render(ambient, settings, Threads);
  size_t nonFinite = 0, outside = 0;
  for (size_t i = 0; i < shadowed.RGB.size(); ++i)
  {
    nonFinite += std::isfinite(shadowed.RGB[i]) ? 0 : 1;
    const double floor = lower.RGB[i] - allowance * (upper.RGB[i] - lower.RGB[i]) - 1e-12;
    outside += (shadowed.RGB[i] >= floor && shadowed.RGB[i] <= upper.RGB[i] + 1e-12) ? 0 : 1;
  }
  EXPECT_EQ(nonFinite, 0u) << what;
  EXPECT_EQ(outside, 0u) << what << ": channels outside [ambient only, unshadowed]";
  return shadowed;
}

void ExpectVisibilityInUnitRange(const glm::dvec3& v, const std::string& what, double allowance = 0.0)
{
  for (int c = 0; c < 3; ++c)
  {
    ASSERT_TRUE(std::isfinite(v[c]) && v[c] >= -allowance && v[c] <= 1.0) << what << ": " << v[c];
  }
}
}

// Opacity -> 1 in every sample (1 - 1e-16, whose transmittance across the volume underflows to
// a denormal; 1; and 0.9 per 1e-4 units, which corrects to 1 - binary techniques threshold the
// opacity per unit distance, 0.9 > 0.5): no NaN; the light stays between ambient only and
// unshadowed; seen from the side away from the light (the light exactly behind the volume),
// every technique saturates to the ambient-only value, within what it may leave of the light
// (where the whole of its lookup's footprint is in the shadow).
TEST(StiffCases, OpacityNearOneSaturatesToAmbientOnlyWithoutNaN)
{
  const struct
  {
    double Alpha, UnitDistance;
  } media[] = { { 1.0 - 1e-16, 1.0 }, { 1.0, 1.0 }, { 0.9, 1e-4 } };
  for (const auto& medium : media)
  {
    TransferFunction tf = Medium(medium.Alpha);
    tf.OpacityUnitDistance = medium.UnitDistance;
    for (ShadowParameters p : EveryTechnique())
    {
      p.MapSize = 128; // CSSM's offsets reach 7 texels: keep them inside the shadow
      const std::string what = NameOf(p) + ", alpha " + std::to_string(medium.Alpha) + " per " +
        std::to_string(medium.UnitDistance);
      const Scene scene = ViewFromBelow(Uniform(21), tf, p, { Directional({ 0.0, 0.0, 1.0 }) });
      const Image image = ExpectLightBounded(scene, Exact(), what);
      // Ambient 0.1 x grey 0.5; the direct light diffuse 0.7 x 0.5 times what is left of it.
      const double ambientOnly = 0.05, slack = 0.35 * DarkTolerance(p) + 1e-6;
      for (int y = 6; y < 18; ++y)
        for (int x = 6; x < 18; ++x)
          for (int c = 0; c < 3; ++c)
            ASSERT_NEAR(image.At(x, y)[c], ambientOnly, slack) << what << " at " << x << ", " << y;
    }
  }
}

// Opacity -> 0: exactly 0 draws exactly the background and every visibility is 1 (to the
// rounding of the maps' bilinear weights, 1e-15); 1e-12 per unit leaves the picture within
// 1e-9 of the background and every visibility within 1e-9 of 1 (no noise: not one stochastic
// photon stopped).
TEST(StiffCases, OpacityZeroDrawsTheBackgroundAndCastsNoShadow)
{
  for (double alpha : { 0.0, 1e-12 })
  {
    const Caster caster{ Uniform(17), Medium(alpha) };
    for (const ShadowParameters& p : EveryTechnique())
    {
      const std::string what = NameOf(p) + ", alpha " + std::to_string(alpha);
      const Scene scene = ViewFromBelow(caster.G, caster.Transfer, p, { Directional({ 0.3, 0.2, 1.0 }) }, 12);
      const Image image = ReferenceRenderer::Render(scene, Exact(), Threads);
      for (int y = 0; y < image.Height; ++y)
        for (int x = 0; x < image.Width; ++x)
          for (int c = 0; c < 3; ++c)
            ASSERT_NEAR(image.At(x, y)[c], scene.Background[c], alpha == 0.0 ? 0.0 : 1e-9) << what;
      const auto shadow = caster.Shadow(p, scene.Lights[0]);
      for (int k = 0; k <= 16; k += 4)
        for (int i = 0; i <= 16; i += 4)
        {
          const glm::dvec3 v = shadow->Visibility({ i, 8.0, k });
          for (int c = 0; c < 3; ++c)
          {
            ASSERT_NEAR(v[c], 1.0, alpha == 0.0 ? 1e-15 : 1e-9) << what; // 1e-15: bilinear weights' rounding
          }
        }
    }
  }
}

// Opacity unit distances from 1e-4 to 1e4 on a homogeneous medium: the ground-truth feeler is
// Beer-Lambert, (1 - alpha)^(n step / unit) for its n samples, to 1e-12 (0 exactly when that
// underflows); the GPU twin's float table within 1e-6 (its alpha is a float); every technique
// within its tolerance of the truth; the light between ambient only and unshadowed.
TEST(StiffCases, OpacityUnitDistancesFromTenThousandthToTenThousandFollowBeerLambert)
{
  for (double unit : { 1e-4, 1e-2, 1.0, 1e2, 1e4 })
  {
    Caster caster{ Uniform(17), Medium(0.5) };
    caster.Transfer.OpacityUnitDistance = unit;
    const Light light = Directional({ 0.0, 0.0, 1.0 });
    const auto truth = caster.Shadow(ShadowParameters::GroundTruth(false, 1.0), light);
    const TransferTable table = TransferTable::Sample(caster.Transfer, 0.0, 1.0, 4096, 0.5);
    ShadowCaster twin = caster.Get();
    twin.FeelerTable = &table;
    const glm::dvec3 points[] = { { 8.0, 8.0, 0.0 }, { 8.0, 8.0, 3.3 }, { 8.0, 8.0, 8.0 }, { 8.0, 8.0, 15.9 } };
    for (const glm::dvec3& p : points)
    {
      const long n = std::lround(std::floor((16.0 - p.z) / 0.5 + 0.5));
      const double expected = std::pow(0.5, n * 0.5 / unit);
      EXPECT_NEAR(truth->Visibility(p).r, expected, 1e-12 * std::max(expected, 1e-300)) << "unit " << unit << " z " << p.z;
      EXPECT_NEAR(FeelerVisibility(twin, p, { 0, 0, 1 }, 1e300, 0.5, ShadowParameters::GroundTruth()).r,
        expected, 1e-6) << "twin, unit " << unit;
    }
    for (const ShadowParameters& technique : EveryTechnique())
    {
      const std::string what = NameOf(technique) + ", unit " + std::to_string(unit);
      const auto shadow = caster.Shadow(technique, light);
      for (const glm::dvec3& p : points)
      {
        const glm::dvec3 v = shadow->Visibility(p);
        ExpectVisibilityInUnitRange(v, what, NegativeAllowance(technique));
        // Grey feelers follow the truth; binary and stochastic answers are 0 or 1 per test.
        if (technique.Kind == ShadowKind::Rays && !technique.Opaque && !technique.Cached && !technique.Colored)
        {
          EXPECT_NEAR(v.r, truth->Visibility(p).r, DarkTolerance(technique) + 1e-12) << what;
        }
      }
      ExpectLightBounded(ViewFromBelow(caster.G, caster.Transfer, technique, { Directional({ 0.3, 0.2, 1.0 }) }, 12),
        Exact(), what);
    }
  }
}

// Visibility never increases along a light ray, away from the light: exactly for the ground
// truth when points are a feeler step apart (the farther one's samples are the nearer one's
// plus one), for every map (their lookups are monotone in depth along a texel), and for caches
// along a light parallel to their grid; feelers that stop early may rise only up to the
// transmittance at which they stop.
TEST(StiffCases, VisibilityNeverIncreasesAwayFromTheLight)
{
  // A smooth, lumpy medium: a ball over a floor with a soft gradient.
  Caster caster{ Grid(glm::ivec3(21), glm::dvec3(1.0), [](int i, int j, int k) {
    const double r = glm::length(glm::dvec3(i, j, k) - glm::dvec3(9.0, 11.0, 13.0));
    return static_cast<float>(std::max(0.0, 1.0 - r / 6.0) + (k < 4 ? 0.4 : 0.0));
  }), Medium(0.8, 1.0) }; // above the 0.5 threshold in the ball: binary techniques shadow too
  for (const glm::dvec3& toLight : { glm::dvec3(0.0, 0.0, 1.0), glm::normalize(glm::dvec3(0.3, -0.2, 1.0)) })
  {
    const Light light = Directional(toLight);
    for (const ShadowParameters& p : EveryTechnique())
    {
      if (p.Cached && toLight.x != 0.0)
      {
        continue; // trilinear interpolation is monotone only along the grid's axes
      }
      const auto shadow = caster.Shadow(p, light);
      const double floor = p.EarlyTermination && p.Kind == ShadowKind::Rays ? ShadowTerminationTransmittance : 0.0;
      for (const glm::dvec3& start : { glm::dvec3(10.0, 10.0, 20.0), glm::dvec3(4.0, 13.5, 19.0) })
      {
        glm::dvec3 previous(1.0);
        for (int k = 0; k < 40; ++k) // all inside the box
        {
          const glm::dvec3 v = shadow->Visibility(start - (0.5 * k) * toLight);
          ExpectVisibilityInUnitRange(v, NameOf(p));
          for (int c = 0; c < 3; ++c)
          {
            ASSERT_LE(v[c], std::max(previous[c], floor) + 1e-12) << NameOf(p) << " step " << k;
          }
          previous = v;
        }
      }
    }
  }
}

// A one-voxel-thin opaque slab (nearest: exactly one voxel; linear: 1.5 voxels above the
// threshold) shadows what is behind it for every technique, whether the light sees it face-on
// or edge-on (then the light-space texels are finer than a voxel: 64 over 56 units), and
// leaves what is beside it, beyond the lookup's footprint (CSSM: 7 texels), lit.
TEST(StiffCases, OneVoxelSlabShadowsFaceOnAndEdgeOn)
{
  const int n = 33;
  for (Interpolation sampling : { Interpolation::Nearest, Interpolation::Linear })
  {
    // Face-on: the full plane k = 16, light from +z. Edge-on: the plane k = 16 for i >= 20,
    // light from +x: its shadow is the plane's continuation towards -x.
    const Caster face{ Grid(glm::ivec3(n), glm::dvec3(1.0), [](int, int, int k) { return k == 16 ? 1.0f : 0.0f; }),
      Medium(1.0, 0.3, 0.0), sampling };
    const Caster edge{ Grid(glm::ivec3(n), glm::dvec3(1.0), [](int i, int, int k) { return k == 16 && i >= 20 ? 1.0f : 0.0f; }),
      Medium(1.0, 0.3, 0.0), sampling };
    const struct
    {
      const char* Name;
      const Caster& Slab;
      glm::dvec3 ToLight, Behind, Beside;
    } views[] = { { "face-on", face, { 0, 0, 1 }, { 16, 16, 8 }, { 16, 16, 24 } },
      { "edge-on", edge, { 1, 0, 0 }, { 8, 16, 16 }, { 8, 16, 24 } } };
    for (const auto& view : views)
    {
      for (ShadowParameters p : EveryTechnique())
      {
        p.MapSize = 64; // texels of 0.87 voxel over the bounding sphere
        const std::string what = NameOf(p) + ", " + view.Name +
          (sampling == Interpolation::Nearest ? ", nearest" : ", linear");
        const auto shadow = view.Slab.Shadow(p, Directional(view.ToLight));
        const glm::dvec3 behind = shadow->Visibility(view.Behind), beside = shadow->Visibility(view.Beside);
        // Edge-on, a lookup that filters over several texels sees the sheet in some of its
        // taps only: 2 of the 3 rows of a 3x3 PCF, 5 of the 13 CSSM offsets (one row).
        double dark = DarkTolerance(p) + 1e-6; // 1e-6: caches hold floats
        if (view.ToLight.x != 0.0 && p.Kind == ShadowKind::ShadowMap)
        {
          dark = 1.0 / 3.0 + 1e-6;
        }
        if (view.ToLight.x != 0.0 && p.Kind == ShadowKind::Stochastic)
        {
          dark = 8.0 / 13.0 + 1e-6;
        }
        EXPECT_LE(std::max({ behind.r, behind.g, behind.b }), dark) << what << ": no shadow behind";
        EXPECT_GE(std::min({ beside.r, beside.g, beside.b }), 1.0 - 1e-9) << what << ": shadow beside";
      }
    }
  }
}

// Sample distances from 1e-3 to 10 voxels: view rays composite (1 - alpha)^(n dt) over their
// n samples (none when dt exceeds the box: the first sample sits half a step in), feelers
// likewise, to 1e-9; at every distance the light stays bounded for the techniques whose cost
// does not grow with the square of the sample count (feelers per sample are left out at 1e-3).
TEST(StiffCases, SampleDistancesFromAThousandthToTenVoxelsFollowBeerLambert)
{
  Caster caster{ Uniform(5), Medium(0.3) };
  for (double dt : { 1e-3, 1e-2, 0.1, 1.0, 10.0 })
  {
    const std::string what = "dt " + std::to_string(dt);
    const long samples = dt > 4.0 ? 0 : std::lround(std::floor(4.0 / dt - 0.5 + 1e-9)) + 1;
    const double expected = 1.0 - std::pow(0.7, samples * dt);
    Scene scene = ViewFromBelow(caster.G, caster.Transfer, ShadowParameters(), {}, 4);
    const glm::dvec4 rgba = ReferenceRenderer::MarchRay(scene, scene.Volumes[0],
      ReferenceRenderer::Prepare(scene, scene.Volumes[0], Exact(dt)), scene.View.PixelRay(2, 2), 1e300, 0.5, Exact(dt));
    EXPECT_NEAR(rgba.a, expected, 1e-9) << what;
    EXPECT_NEAR(FeelerVisibility(caster.Get(), { 2.0, 2.0, 0.0 }, { 0, 0, 1 }, 1e300, dt, ShadowParameters::GroundTruth()).r,
      1.0 - expected, 1e-9) << what;
    for (const ShadowParameters& p : EveryTechnique())
    {
      if (dt < 0.01 && p.Kind == ShadowKind::Rays && !p.Cached)
      {
        continue;
      }
      ExpectLightBounded(ViewFromBelow(caster.G, caster.Transfer, p, { Directional({ 0.3, 0.2, 1.0 }) }, 4),
        Exact(dt), NameOf(p) + ", " + what);
    }
  }
}

// 1x1x1, 1x1xN and NxNx1 grids bound no volume (the box [0, Dims - 1] is flat): nothing is
// drawn and nothing is shadowed, for every technique. (The VTK adapter refuses them with one
// error; TestStiffCasesGPU and TestBadInput check that.)
TEST(StiffCases, FlatGridsDrawNothingAndShadowNothing)
{
  for (const glm::ivec3& dims : { glm::ivec3(1, 1, 1), glm::ivec3(1, 1, 9), glm::ivec3(9, 9, 1) })
  {
    const Caster caster{ Grid(dims, glm::dvec3(1.0), [](int, int, int) { return 1.0f; }), Medium(0.8) };
    for (const ShadowParameters& p : EveryTechnique())
    {
      const std::string what = NameOf(p) + ", " + std::to_string(dims.x) + "x" +
        std::to_string(dims.y) + "x" + std::to_string(dims.z);
      const Scene scene = ViewFromBelow(caster.G, caster.Transfer, p, { Directional({ 0.3, 0.2, 1.0 }) }, 8);
      const Image image = ReferenceRenderer::Render(scene, Exact(), Threads);
      for (size_t i = 0; i < image.RGB.size(); ++i)
      {
        ASSERT_EQ(image.RGB[i], scene.Background[i % 3]) << what;
      }
      const auto shadow = caster.Shadow(p, scene.Lights[0]);
      for (const glm::dvec3& point : { glm::dvec3(0.0), glm::dvec3(dims - 1) * 0.5, glm::dvec3(dims - 1), glm::dvec3(-1.0, 0.0, -3.0) })
      {
        ASSERT_EQ(shadow->Visibility(point), glm::dvec3(1.0)) << what;
      }
    }
  }
}

// The cached shadow of a grid with a flat axis (once 0 / 0 in CachedShadow::Visibility, a
// NaN node index and an out-of-bounds read): 1 everywhere, as for the uncached techniques.
TEST(StiffCases, CachedShadowsOfFlatGridsAreOne)
{
  for (const glm::ivec3& dims : { glm::ivec3(1, 1, 1), glm::ivec3(1, 1, 9), glm::ivec3(9, 9, 1) })
  {
    const Caster caster{ Grid(dims, glm::dvec3(1.0), [](int, int, int) { return 1.0f; }), Medium(0.8) };
    for (const ShadowParameters& p : EveryTechnique())
    {
      if (p.Cached)
      {
        EXPECT_EQ(caster.Shadow(p, Directional({ 0.3, 0.2, 1.0 }))->Visibility(glm::dvec3(0.0)), glm::dvec3(1.0)) << NameOf(p);
      }
    }
  }
}

// A point that projects more than 2^31 texels off a light-space face (any point off a 1x1x1
// grid, whose face is 2e-12 wide; once an int overflow in LightSpaceShadow::Bilinear and
// values like 1e12): 1, nothing casts.
TEST(StiffCases, DeepShadowMapLookupsOffAPointGridAreOne)
{
  const Caster caster{ Grid(glm::ivec3(1), glm::dvec3(1.0), [](int, int, int) { return 1.0f; }), Medium(0.8) };
  const auto shadow = caster.Shadow(Technique(ShadowKind::DeepShadowMap), Directional({ 0.3, 0.2, 1.0 }));
  EXPECT_EQ(shadow->Visibility({ 4.0, 4.0, -30.0 }), glm::dvec3(1.0));
  EXPECT_EQ(shadow->Visibility({ -1.0, 0.0, -3.0 }), glm::dvec3(1.0));
}

// Deep shadow map nodes lie in [0, 1] even where the truncated end of a geometric fall
// (1, 1/2, ... 1/64, truncated at epsilon 0.02) allows [-epsilon, epsilon]: the compressor
// intersects its band with [0, 1] (it once stored -0.0025 there, light below ambient).
TEST(StiffCases, DeepShadowMapNodesAreNeverNegative)
{
  VisibilitySamples samples;
  for (int k = 0; k < 7; ++k)
  {
    samples.Depths.push_back(k);
    samples.Values.emplace_back(std::ldexp(1.0, -k));
  }
  samples.Truncated = true;
  double lowest = 1.0;
  for (int channels : { 1, 3 })
  {
    for (const VisibilityNode& node : CompressVisibility(samples, channels, 0.02, 8).Nodes)
    {
      lowest = std::min<double>({ lowest, node.Value[0], node.Value[1], node.Value[2] });
    }
  }
  EXPECT_GE(lowest, 0.0);
}

// Spacing ratios of 1:1000 both ways (a needle and a pancake of 9^3 points): feelers
// integrate world distance, (1 - alpha)^(L / unit) along the long and the short axis alike;
// an opaque layer across the volume (one voxel thick) shadows what lies behind it and nothing
// in front, for every technique.
TEST(StiffCases, SpacingRatiosOfAThousandIntegrateWorldDistance)
{
  for (const glm::dvec3& spacing : { glm::dvec3(1.0, 1.0, 1000.0), glm::dvec3(1000.0, 1000.0, 1.0) })
  {
    const std::string what = "spacing " + std::to_string(spacing.x) + ":" + std::to_string(spacing.z);
    const Caster layer{ Grid(glm::ivec3(9), spacing, [](int, int, int k) { return k == 4 ? 1.0f : 0.0f; }),
      Medium(1.0, 0.5, 0.0), Interpolation::Nearest };
    const glm::dvec3 below(4.0 * spacing.x, 4.0 * spacing.y, 1.0 * spacing.z), above(below.x, below.y, 7.0 * spacing.z);
    for (const ShadowParameters& p : EveryTechnique())
    {
      // Light along z: a feeler step of a quarter of the layer's thickness.
      const auto shadow = layer.Shadow(p, Directional({ 0.0, 0.0, 1.0 }), 0.25 * spacing.z);
      const double v = shadow->Visibility(below).r;
      ExpectVisibilityInUnitRange(shadow->Visibility(below), NameOf(p));
      EXPECT_EQ(shadow->Visibility(above), glm::dvec3(1.0)) << NameOf(p) << ", " << what;
      EXPECT_LE(v, DarkTolerance(p) + 1e-9) << NameOf(p) << ", " << what;
    }
    // Beer-Lambert across the whole box along z and along x, on a homogeneous medium.
    Caster uniform{ Grid(glm::ivec3(9), spacing, [](int, int, int) { return 1.0f; }), Medium(0.5) };
    uniform.Transfer.OpacityUnitDistance = 8.0 * std::max(spacing.x, spacing.z);
    for (const glm::dvec3& axis : { glm::dvec3(0, 0, 1), glm::dvec3(1, 0, 0) })
    {
      const glm::dvec3 size = 8.0 * spacing, start = 0.5 * size * (glm::dvec3(1.0) - axis);
      const double length = glm::dot(axis, size);
      const double v = FeelerVisibility(uniform.Get(), start, axis, 1e300, length / 64.0, ShadowParameters::GroundTruth()).r;
      EXPECT_NEAR(v, std::pow(0.5, length / uniform.Transfer.OpacityUnitDistance), 1e-12) << what;
    }
  }
}

// A 1:1000 needle seen end-on (8 x 8 units of a box 8000 long) fell between the texels of
// every map when faces covered the bounding sphere (8000 across: a thousandth of a 32^2
// map). Faces are fitted to the box as the light sees it, so every technique shadows it.
TEST(StiffCases, MapsKeepTheShadowOfANeedleSeenEndOn)
{
  const glm::dvec3 spacing(1.0, 1.0, 1000.0);
  const Caster needle{ Grid(glm::ivec3(9), spacing, [](int, int, int k) { return k == 4 ? 1.0f : 0.0f; }),
    Medium(1.0, 0.5, 0.0), Interpolation::Nearest };
  for (ShadowParameters p : EveryTechnique())
  {
    p.MapSize = 32;
    const glm::dvec3 v = needle.Shadow(p, Directional({ 0.0, 0.0, 1.0 }), 250.0)->Visibility({ 4.0, 4.0, 1000.0 });
    ExpectVisibilityInUnitRange(v, NameOf(p));
    EXPECT_LE(v.r, DarkTolerance(p) + 1e-6) << NameOf(p);
  }
}

// A ray may take at most MaxRayIterations samples across a volume (llvmpipe's loop limit;
// elsewhere hours of work): beyond, the reference refuses with one sentence naming the
// smallest sample distance that fits, instead of marching for hours.
TEST(StiffCases, RaysOfMoreSamplesThanARayMayTakeAreRefused)
{
  const glm::dmat4 sheared = glm::dmat4(glm::dvec4(2, 0, 0, 0), glm::dvec4(1, 1, 0, 0), glm::dvec4(0, 0, 3, 0), glm::dvec4(5, 6, 7, 1));
  EXPECT_NEAR(LongestPath(glm::dmat4(1.0), glm::ivec3(11)), std::sqrt(300.0), 1e-12);
  EXPECT_NEAR(LongestPathAlong(glm::dmat4(1.0), glm::ivec3(11), { 1.0, 0.0, 0.0 }), 10.0, 1e-12);
  EXPECT_NEAR(LongestPathAlong(glm::dmat4(1.0), glm::ivec3(11), glm::normalize(glm::dvec3(1.0, 1.0, 0.0))),
    std::sqrt(200.0), 1e-12);
  // Along the sheared box's x edge (2 units a voxel, 10 voxels) and its longest diagonal.
  EXPECT_NEAR(LongestPathAlong(sheared, glm::ivec3(11), { 1.0, 0.0, 0.0 }), 20.0, 1e-12);
  EXPECT_NEAR(LongestPath(sheared, glm::ivec3(11)), glm::length(glm::dvec3(30.0, 10.0, 30.0)), 1e-12);
  EXPECT_TRUE(CheckRaySamples(100.0, 100.0 / MaxRayIterations, "the sample distance").empty());
  const std::string refused = CheckRaySamples(100.0, 1e-6, "the sample distance");
  EXPECT_NE(refused.find("the sample distance 1e-06 takes up to 1e+08 samples"), std::string::npos) << refused;
  EXPECT_NE(refused.find("use at least 0.001525"), std::string::npos) << refused;
  EXPECT_FALSE(CheckRaySamples(100.0, 0.01, "the sample distance", 20.0).empty()); // 10000 x 20

  Scene scene;
  scene.View = Camera(glm::dmat4(1.0), 4, 4);
  VolumeInstance volume;
  volume.Grid = Grid(glm::ivec3(9), glm::dvec3(1.0), [](int, int, int) { return 1.0f; });
  volume.Transfer = Medium(0.5);
  scene.Volumes.push_back(volume);
  MarchSettings settings;
  settings.SampleDistance = 1e-6;
  const auto start = std::chrono::steady_clock::now();
  EXPECT_THROW(ReferenceRenderer::Render(scene, settings, Threads), std::invalid_argument);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
  // A shadow step (StepFactor x sample distance) is bounded alike.
  settings.SampleDistance = 0.01;
  scene.Volumes[0].Shadows = Technique(ShadowKind::Rays);
  scene.Volumes[0].Shadows.StepFactor = 1e-5;
  EXPECT_THROW(ReferenceRenderer::Render(scene, settings, Threads), std::invalid_argument);
}

// Lights at the extremes, every technique: grazing the top face, inside the volume (and a
// sample exactly at the light), at the camera (positional at its eye, and directional along
// its view), exactly behind the volume (directional and positional on the view axis) and 1e6
// units away. The light stays between ambient only and unshadowed, with no NaN.
TEST(StiffCases, LightsAtTheExtremesKeepTheLightBounded)
{
  const Caster caster{ Grid(glm::ivec3(17), glm::dvec3(1.0), [](int i, int j, int k) {
    const double r = glm::length(glm::dvec3(i, j, k) - glm::dvec3(8.0, 9.0, 11.0));
    return static_cast<float>(r < 4.5 ? 1.0 : (k < 3 ? 0.6 : 0.0));
  }), Medium(0.7, 0.5, 0.6) };
  const struct
  {
    const char* Name;
    Light L;
  } lights[] = { { "grazing the top face", Directional({ 1.0, 0.0, 0.0 }) },
    { "inside the volume", Positional({ 8.0, 9.0, 5.0 }) },
    { "at a voxel inside", Positional({ 8.0, 9.0, 11.0 }) },
    { "at the camera's eye", Positional({ 8.0, 8.0, -56.0 }) },
    { "along the view, towards the camera", Directional({ 0.0, 0.0, -1.0 }) },
    { "exactly behind, directional", Directional({ 0.0, 0.0, 1.0 }) },
    { "exactly behind, positional", Positional({ 8.0, 8.0, 40.0 }) },
    { "1e6 away", Positional({ 8.0 + 3e5, 8.0 - 4e5, 8.0 + 8.66e5 }) } };
  for (const auto& light : lights)
  {
    for (const ShadowParameters& p : EveryTechnique())
    {
      const std::string what = NameOf(p) + ", light " + light.Name;
      ExpectLightBounded(ViewFromBelow(caster.G, caster.Transfer, p, { light.L }, 16), Exact(), what);
      // A sample exactly at a positional light: its direction is defined (not NaN).
      ExpectVisibilityInUnitRange(caster.Shadow(p, light.L)->Visibility(light.L.Position), what);
    }
  }
}

// A light at the camera (directional along the view, towards it) on a homogeneous medium:
// each view sample's feeler retraces the view ray, so its visibility is (1 - alpha)^k or
// (1 - alpha)^(k + 1) for the k-th sample (its first feeler sample falls on the entry face,
// on either side of it by rounding). The picture lies between those two closed forms.
TEST(StiffCases, ALightAtTheCameraLightsWhatTheCameraSees)
{
  const TransferFunction tf = Medium(0.3);
  const Scene scene = ViewFromBelow(Uniform(21), tf, ShadowParameters::GroundTruth(false, 1.0),
    { Directional({ 0.0, 0.0, -1.0 }) }, 8);
  const Image image = ReferenceRenderer::Render(scene, Exact(), Threads);
  const double a = CorrectOpacity(0.3, 0.5, 1.0);
  glm::dvec2 bounds(0.0);
  for (int k = 0; k < 40; ++k)
  {
    const double weight = a * std::pow(1.0 - a, k);
    bounds += weight * (0.05 + 0.35 * glm::dvec2(std::pow(1.0 - a, k + 1), std::pow(1.0 - a, k)));
  }
  bounds += std::pow(1.0 - a, 40) * scene.Background.r;
  for (int y = 2; y < 6; ++y)
    for (int x = 2; x < 6; ++x)
    {
      EXPECT_GE(image.At(x, y).r, bounds.x - 1e-12);
      EXPECT_LE(image.At(x, y).r, bounds.y + 1e-12);
    }
}

// A light inside the volume (a cube of six faces for the maps): a point between the light and
// an opaque wall is lit, points behind the wall on every side of the cube are dark.
TEST(StiffCases, ALightInsideTheVolumeShadowsBehindAWallOnEveryFace)
{
  // A hollow opaque box of walls at distance 5 around the light at the centre.
  const Caster caster{ Grid(glm::ivec3(25), glm::dvec3(1.0), [](int i, int j, int k) {
    const int d = std::max({ std::abs(i - 12), std::abs(j - 12), std::abs(k - 12) });
    return d == 5 ? 1.0f : 0.0f;
  }), Medium(1.0, 0.3, 0.0), Interpolation::Nearest };
  const Light light = Positional({ 12.0, 12.0, 12.0 });
  for (ShadowParameters p : EveryTechnique())
  {
    p.MapSize = 64;
    const auto shadow = caster.Shadow(p, light);
    for (const glm::dvec3& axis : { glm::dvec3(1, 0, 0), glm::dvec3(-1, 0, 0), glm::dvec3(0, 1, 0),
           glm::dvec3(0, -1, 0), glm::dvec3(0, 0, 1), glm::dvec3(0, 0, -1), glm::dvec3(0.6, 0.5, -0.62) })
    {
      const glm::dvec3 inside = light.Position + 3.0 * axis, behind = light.Position + 9.0 * axis;
      EXPECT_GE(shadow->Visibility(inside).r, p.Cached ? 0.5 : 1.0 - 1e-9) << NameOf(p) << ": lit inside";
      EXPECT_LE(shadow->Visibility(behind).r, p.Cached ? 0.5 : DarkTolerance(p) + 1e-9) << NameOf(p) << ": dark behind";
    }
  }
}

// Several lights of zero intensity: the picture is the ambient-only picture, bit for bit,
// whatever the technique (a shadow of no light is no shadow).
TEST(StiffCases, ZeroIntensityLightsGiveTheAmbientOnlyPictureExactly)
{
  const Caster caster{ Grid(glm::ivec3(17), glm::dvec3(1.0), [](int i, int, int k) { return (i + k) % 5 == 0 ? 1.0f : 0.3f; }),
    Medium(0.4, 1.0) };
  std::vector<Light> lights{ Directional({ 0.3, 0.2, 1.0 }), Positional({ 8.0, 8.0, 8.0 }), Positional({ 40.0, 0.0, 9.0 }) };
  for (Light& light : lights)
  {
    light.Diffuse = light.Specular = glm::dvec3(0.0);
  }
  Scene ambient = ViewFromBelow(caster.G, caster.Transfer, Technique(ShadowKind::Rays), lights, 12);
  for (Light& light : ambient.Lights)
  {
    light.ShadowAttenuation = 0.0;
  }
  const Image expected = ReferenceRenderer::Render(ambient, Exact(), Threads);
  for (const ShadowParameters& p : EveryTechnique())
  {
    for (bool shade : { false, true })
    {
      Scene scene = ViewFromBelow(caster.G, caster.Transfer, p, lights, 12);
      scene.Volumes[0].Shade = shade;
      Scene reference = ambient;
      reference.Volumes[0].Shade = shade;
      EXPECT_EQ(ReferenceRenderer::Render(scene, Exact(), Threads).RGB,
        shade ? ReferenceRenderer::Render(reference, Exact(), Threads).RGB : expected.RGB) << NameOf(p);
    }
  }
}

// Shadow maps at near/far ratios of 1e-6 (a light 1e-6 above the volume's face) and about
// 1 - 1e-6 (1e6 radii away): away from the ball's surface (where the bias decides), the same
// binary answers as the opaque feeler with the same threshold, but where a texel straddles the
// shadow's edge. (Deep shadow maps: TestLightSpace.)
TEST(StiffCases, ShadowMapsHoldForNearFarRatiosOfAMillion)
{
  const glm::dvec3 centre(0.5);
  const Caster caster{ Grid(glm::ivec3(17), glm::dvec3(1.0 / 16), [](int i, int j, int k) {
    return glm::length(glm::dvec3(i, j, k) - 8.0) < 5.0 ? 1.0f : 0.0f;
  }), Medium(0.9, 0.5, 0.0) };
  // Depth precision of a hard surface: the ball's first sample is the occluder.
  ShadowParameters map = Technique(ShadowKind::ShadowMap);
  map.MapSize = 128;
  map.Filter = ShadowFilter::None;
  map.Mode = ThresholdMode::Opacity;
  ShadowParameters opaque = Technique(ShadowKind::Rays, false, false, true);
  opaque.Mode = ThresholdMode::Opacity;
  for (const Light& light : { Positional({ 0.5, 0.5, 1.0 + 1e-6 }), Positional({ 0.5, 0.5, 0.5 + 1e6 }) })
  {
    const double step = 1.0 / 64;
    const auto a = caster.Shadow(map, light, step), b = caster.Shadow(opaque, light, step);
    int differ = 0, count = 0, dark = 0;
    for (int i = 0; i <= 32; ++i)
      for (int k = 0; k <= 32; ++k)
      {
        const glm::dvec3 p(i / 32.0, 0.5, k / 32.0);
        if (std::abs(glm::length(p - centre) - 5.0 / 16) < 2.0 / 16)
        {
          continue;
        }
        differ += a->Visibility(p).r != b->Visibility(p).r ? 1 : 0;
        dark += b->Visibility(p).r == 0.0 ? 1 : 0;
        ++count;
      }
    std::printf("light at z %.7g: %d of %d points differ, %d dark\n", light.Position.z, differ, count, dark);
    EXPECT_GT(dark, count / 10) << "light at z " << light.Position.z;
    EXPECT_LE(differ, count / 50) << "light at z " << light.Position.z;
  }
}

// Map size 1: one texel for the whole light's view. Every light-space technique then still
// shadows a laterally uniform layer exactly as the ground truth does (every texel's ray would
// see the same), within its tolerance, and stays within [0, 1].
TEST(StiffCases, MapSizeOneShadowsALaterallyUniformLayer)
{
  const Caster caster{ Grid(glm::ivec3(17), glm::dvec3(1.0), [](int, int, int k) { return k >= 8 && k <= 10 ? 1.0f : 0.0f; }),
    Medium(0.6, 0.5, 0.0) };
  const Light light = Directional({ 0.0, 0.0, 1.0 });
  const auto truth = caster.Shadow(ShadowParameters::GroundTruth(false, 1.0), light);
  for (ShadowParameters p : EveryTechnique())
  {
    if (p.Kind == ShadowKind::Rays)
    {
      continue;
    }
    p.MapSize = 1;
    const auto shadow = caster.Shadow(p, light);
    for (const glm::dvec3& point : { glm::dvec3(8, 8, 2), glm::dvec3(1, 15, 4), glm::dvec3(12, 3, 14) })
    {
      const glm::dvec3 v = shadow->Visibility(point);
      ExpectVisibilityInUnitRange(v, NameOf(p));
      const double expected = truth->Visibility(point).r;
      if (expected == 1.0 || p.Kind == ShadowKind::ShadowMap)
      {
        EXPECT_EQ(v.r, std::round(expected)) << NameOf(p); // above the layer, or binary (opacity 0.6 > 0.5)
      }
      else if (p.Kind == ShadowKind::Stochastic)
      {
        EXPECT_TRUE(v.r == 0.0 || v.r == 1.0) << NameOf(p) << ": one photon is all or nothing";
      }
      else
      {
        // Opacity levels are exact behind the layer (the maximum opacity); dsm within epsilon.
        EXPECT_NEAR(v.r, expected, p.Kind == ShadowKind::DeepShadowMap ? p.Epsilon + 1e-6 : 1e-6) << NameOf(p);
      }
    }
  }
}

// Denormal samples are their value: a volume of values in [0, 1e-39] (all but 0 denormal)
// with its transfer function scaled alike draws the picture of the same volume in [0, 1],
// to 1e-9; denormals among normal values act as the tiny values they are. Floats over their
// full range (+-FLT_MAX) stay finite and bounded.
TEST(StiffCases, DenormalAndFullRangeSamplesAreTheirValues)
{
  const auto pattern = [](int i, int j, int k) { return static_cast<float>(((i * 7 + j * 3 + k * 5) % 11) / 10.0); };
  const struct
  {
    const char* Name;
    float Scale;
  } ranges[] = { { "denormal", 1e-39f }, { "full float range", std::numeric_limits<float>::max() } };
  const Caster unit{ Grid(glm::ivec3(13), glm::dvec3(1.0), pattern), Medium(0.5, 1.0) };
  const ShadowParameters p = Technique(ShadowKind::DeepShadowMap);
  const Light light = Directional({ 0.3, 0.2, 1.0 });
  const Image expected = ReferenceRenderer::Render(ViewFromBelow(unit.G, unit.Transfer, p, { light }, 12), Exact(), Threads);
  for (const auto& range : ranges)
  {
    // Full range: values spread over [-FLT_MAX, FLT_MAX], the function over the same.
    const bool full = range.Scale > 1.0f;
    auto grid = Grid(glm::ivec3(13), glm::dvec3(1.0), [&](int i, int j, int k) {
      return full ? static_cast<float>((2.0 * pattern(i, j, k) - 1.0) * range.Scale) : pattern(i, j, k) * range.Scale;
    });
    if (!full)
    {
      EXPECT_EQ(std::fpclassify(grid->At(1, 0, 0)), FP_SUBNORMAL);
    }
    TransferFunction tf = Medium(0.5, 1.0);
    const double scale = full ? 2.0 * range.Scale : range.Scale, offset = full ? -range.Scale : 0.0;
    tf.Opacity = PiecewiseLinear({ { offset, 0.0 }, { offset + scale, 0.5 } });
    tf.Red = tf.Green = tf.Blue = PiecewiseLinear({ { offset, 0.5 } });
    const Scene scene = ViewFromBelow(grid, tf, p, { light }, 12);
    const Image image = ExpectLightBounded(scene, Exact(), range.Name);
    EXPECT_LE(Compare(image, expected).MaxAbs, 1e-6) << range.Name;
    // The GPU twin: the table over the full range (scale and offset computed in double).
    const Image twin = ReferenceRenderer::Render(scene, MarchSettings::GpuTwin(0.5, 4096), Threads);
    EXPECT_LE(Compare(twin, expected).MaxAbs, 2.0 / 255.0) << range.Name << ", GPU twin";
  }
}

// Determinism: the same jitter seed and CSSM seed give bit-identical pictures run to run and
// for any thread count; another CSSM seed gives another picture.
TEST(StiffCases, JitterAndStochasticSeedsGiveBitIdenticalPictures)
{
  const Caster caster{ Grid(glm::ivec3(17), glm::dvec3(1.0), [](int i, int j, int k) {
    return static_cast<float>(glm::length(glm::dvec3(i, j, k) - glm::dvec3(8.0, 8.0, 11.0)) < 4.0 ? 1.0 : (k < 4 ? 0.5 : 0.0));
  }), Medium(0.6, 0.5, 0.7) };
  ShadowParameters p = Technique(ShadowKind::Stochastic);
  p.Seed = 11;
  const Scene scene = ViewFromBelow(caster.G, caster.Transfer, p, { Directional({ 0.3, 0.2, 1.0 }) }, 16);
  MarchSettings settings = Exact();
  settings.Jitter = true;
  settings.JitterSeed = 5;
  const Image first = ReferenceRenderer::Render(scene, settings, Threads);
  EXPECT_EQ(ReferenceRenderer::Render(scene, settings, Threads).RGB, first.RGB);
  EXPECT_EQ(ReferenceRenderer::Render(scene, settings, 1).RGB, first.RGB);
  Scene reseeded = scene;
  reseeded.Volumes[0].Shadows.Seed = 12;
  EXPECT_NE(ReferenceRenderer::Render(reseeded, settings, Threads).RGB, first.RGB);
}
