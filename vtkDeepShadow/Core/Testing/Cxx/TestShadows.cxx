// CPU shadow techniques (the GPU's twins and the ground truth) against closed forms.
#include "Core/ReferenceRenderer.h"
#include "Core/Shadows/ShadowMap.h"
#include "Core/Shadows.h"
#include "SlabScene.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

using namespace deepshadow;
using deepshadow::testing::SlabScene;

namespace
{
Light DirectionalFrom(const glm::dvec3& toLight)
{
  Light light;
  light.Position = toLight;
  light.FocalPoint = glm::dvec3(0.0);
  return light;
}
}

TEST(Shadows, TranslucentFeelerFollowsBeerLambertThroughASlab)
{
  const SlabScene scene(0.3);
  ShadowParameters p = ShadowParameters::GroundTruth(false, 1.0);
  for (double step : { 1.0, 0.5, 0.25 })
  {
    // From below the slab straight up: nearest sampling sees the slab on z in [7.5, 12.5].
    const double v = FeelerVisibility(scene.Caster, { 10.0, 10.0, 2.0 }, { 0, 0, 1 }, 1e300, step, p).r;
    long inside = 0;
    for (long j = 0; (j + 0.5) * step < 18.0; ++j)
    {
      const double z = 2.0 + (j + 0.5) * step;
      inside += (z >= 7.5 && z < 12.5) ? 1 : 0;
    }
    EXPECT_NEAR(v, std::pow(0.7, inside * step), 1e-12) << "step " << step;
    EXPECT_NEAR(v, std::pow(0.7, 5.0), 1e-12);
  }
  // Above the slab towards +z: nothing in the way.
  EXPECT_EQ(FeelerVisibility(scene.Caster, { 10.0, 10.0, 15.0 }, { 0, 0, 1 }, 1e300, 0.5, p), glm::dvec3(1.0));
}

TEST(Shadows, OpaqueFeelerIsBinaryAtTheThreshold)
{
  const SlabScene scene(0.3);
  ShadowParameters p;
  p.Kind = ShadowKind::Rays;
  p.Opaque = true;
  // By default on the accumulated opacity: the slab lets through 0.7^5 = 0.168 (1 - 0.832).
  p.Threshold = 0.8;
  EXPECT_EQ(FeelerVisibility(scene.Caster, { 10, 10, 2 }, { 0, 0, 1 }, 1e300, 0.5, p), glm::dvec3(0.0));
  p.Threshold = 0.85;
  EXPECT_EQ(FeelerVisibility(scene.Caster, { 10, 10, 2 }, { 0, 0, 1 }, 1e300, 0.5, p), glm::dvec3(1.0));
  // Per sample: each has opacity 0.3 per unit.
  p.Mode = ThresholdMode::Opacity;
  p.Threshold = 0.2;
  EXPECT_EQ(FeelerVisibility(scene.Caster, { 10, 10, 2 }, { 0, 0, 1 }, 1e300, 0.5, p), glm::dvec3(0.0));
  p.Threshold = 0.4; // above the slab's opacity
  EXPECT_EQ(FeelerVisibility(scene.Caster, { 10, 10, 2 }, { 0, 0, 1 }, 1e300, 0.5, p), glm::dvec3(1.0));
  p.Mode = ThresholdMode::Scalar; // normalized scalar of the slab is 1 > 0.4
  EXPECT_EQ(FeelerVisibility(scene.Caster, { 10, 10, 2 }, { 0, 0, 1 }, 1e300, 0.5, p), glm::dvec3(0.0));
}

TEST(Shadows, EarlyTerminationStopsBelowTheTransmittanceFloor)
{
  const SlabScene scene(0.95);
  ShadowParameters exact = ShadowParameters::GroundTruth(false, 1.0), early = exact;
  early.EarlyTermination = true;
  const double a = FeelerVisibility(scene.Caster, { 10, 10, 2 }, { 0, 0, 1 }, 1e300, 0.25, exact).r;
  const double b = FeelerVisibility(scene.Caster, { 10, 10, 2 }, { 0, 0, 1 }, 1e300, 0.25, early).r;
  EXPECT_LT(a, ShadowTerminationTransmittance);
  EXPECT_LT(b, ShadowTerminationTransmittance);
  EXPECT_GE(b, a);
}

TEST(Shadows, PositionalLightsStopTheFeelerAtTheLight)
{
  const SlabScene scene(0.5);
  Light inside;
  inside.Positional = true;
  inside.Position = { 10.0, 10.0, 5.0 }; // below the slab, inside the volume
  const auto shadow = MakeLightShadow(ShadowParameters::GroundTruth(false, 1.0), scene.Caster, inside, 0.5);
  EXPECT_EQ(shadow->Visibility({ 10.0, 10.0, 2.0 }), glm::dvec3(1.0));  // between light and floor
  EXPECT_LT(shadow->Visibility({ 10.0, 10.0, 16.0 }).r, 0.1); // behind the slab
}

TEST(Shadows, CachedShadowsMatchTheFeelerAtTheirNodes)
{
  const SlabScene scene(0.3);
  ShadowParameters rays = ShadowParameters::GroundTruth(false, 1.0), cached = rays;
  cached.Cached = true;
  cached.VolumeSize = 21; // nodes on the voxels
  const Light light = DirectionalFrom({ 0.2, 0.1, 1.0 });
  const auto direct = MakeLightShadow(rays, scene.Caster, light, 0.5);
  const auto cache = MakeLightShadow(cached, scene.Caster, light, 0.5, 2);
  for (glm::dvec3 p : { glm::dvec3(3, 4, 5), glm::dvec3(10, 10, 2), glm::dvec3(20, 0, 14) })
  {
    EXPECT_NEAR(cache->Visibility(p).r, direct->Visibility(p).r, 1e-6);
  }
  EXPECT_EQ(cache->Bytes(), 21u * 21 * 21 * 2); // R16F, as on the GPU
  EXPECT_EQ(ShadowVolumeDims({ 256, 256, 128 }, 64), glm::ivec3(64, 64, 32));
}

TEST(Shadows, ShadowMapsShadowWhatIsBehindTheFirstHit)
{
  const SlabScene scene(0.9);
  for (auto filter : { ShadowFilter::None, ShadowFilter::PCF2x2, ShadowFilter::PCF3x3, ShadowFilter::Poisson })
  {
    ShadowParameters p;
    p.Kind = ShadowKind::ShadowMap;
    p.Threshold = 0.5;
    p.MapSize = 64;
    p.Filter = filter;
    const auto map = MakeLightShadow(p, scene.Caster, DirectionalFrom({ 0, 0, 1 }), 0.5, 2);
    EXPECT_EQ(map->Visibility({ 10, 10, 3 }), glm::dvec3(0.0));  // below the slab
    EXPECT_EQ(map->Visibility({ 10, 10, 17 }), glm::dvec3(1.0)); // above it
    EXPECT_EQ(map->Bytes(), 64u * 64 * sizeof(float));
  }
}

TEST(Shadows, PercentageCloserFilteringAveragesComparisons)
{
  // A 4x4 map: left half occluder at depth 1, right half empty.
  std::vector<float> depths(16);
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i)
      depths[j * 4 + i] = i < 2 ? 1.0f : 100.0f;
  EXPECT_EQ(FilterShadowMap(depths.data(), 4, 0.0, 1.0, 5.0, ShadowFilter::None), 0.0);
  EXPECT_EQ(FilterShadowMap(depths.data(), 4, 3.0, 1.0, 5.0, ShadowFilter::None), 1.0);
  EXPECT_NEAR(FilterShadowMap(depths.data(), 4, 1.25, 1.0, 5.0, ShadowFilter::PCF2x2), 0.25, 1e-12);
  EXPECT_NEAR(FilterShadowMap(depths.data(), 4, 1.6, 1.0, 5.0, ShadowFilter::PCF3x3), 2.0 / 3.0, 1e-12);
  const double poisson = FilterShadowMap(depths.data(), 4, 1.5, 1.5, 5.0, ShadowFilter::Poisson);
  EXPECT_GT(poisson, 0.0);
  EXPECT_LT(poisson, 1.0);
  EXPECT_EQ(FilterShadowMap(depths.data(), 4, 1.5, 1.5, 0.5, ShadowFilter::Poisson), 1.0); // in front of all
}

TEST(Shadows, ReferenceRendererDarkensWhatTheSlabShadows)
{
  // Camera below looking up at a floor of low density under a dense slab, light from above.
  std::vector<float> values(21 * 21 * 21, 0.0f);
  for (int k = 0; k <= 20; ++k)
    for (int j = 0; j < 21; ++j)
      for (int i = 0; i < 21; ++i)
        values[i + 21 * (j + 21 * k)] = (k >= 14 && i < 10) ? 1.0f : (k < 4 ? 0.5f : 0.0f);
  auto grid = std::make_shared<VolumeGrid>(glm::ivec3(21), values, glm::dmat4(1.0));
  Scene scene;
  const glm::dmat4 view = glm::lookAt(glm::dvec3(10, 10, -40), glm::dvec3(10, 10, 10), glm::dvec3(0, 1, 0));
  scene.View = Camera(glm::ortho(-12.0, 12.0, -12.0, 12.0, 1.0, 100.0) * view, 24, 24);
  scene.Lights.push_back(DirectionalFrom({ 0, 0, 1 }));
  VolumeInstance volume;
  volume.Grid = grid;
  volume.Transfer = TransferFunction::Grey({ { 0.0, 0.0 }, { 0.5, 0.3 }, { 1.0, 1.0 } });
  volume.Transfer.Red = volume.Transfer.Green = volume.Transfer.Blue = PiecewiseLinear({ { 0.0, 1.0 } });
  volume.Shadows = ShadowParameters::GroundTruth(false, 1.0);
  scene.Volumes.push_back(volume);
  MarchSettings settings;
  settings.SampleDistance = 0.5;
  const Image shadowed = ReferenceRenderer::Render(scene, settings, 2);
  // Empty-space skipping (view rays and feelers) changes nothing, bit for bit.
  MarchSettings marching = settings;
  marching.EmptySpaceSkipping = false;
  EXPECT_EQ(ReferenceRenderer::Render(scene, marching, 2).RGB, shadowed.RGB);
  // Camera at -z looking +z with view-up +y: world +x is image left. The slab covers x < 10.
  const double underSlab = shadowed.At(18, 12).x, open = shadowed.At(5, 12).x;
  EXPECT_LT(underSlab, 0.5 * open);
  EXPECT_GT(open, 0.2);

  // The shadow term, asked for alongside the colour, changes the colour not at all and equals
  // the ShadowTerm output; it is grey (a grey technique), in [0, 1], darker under the slab.
  Image term;
  EXPECT_EQ(ReferenceRenderer::Render(scene, settings, 2, &term).RGB, shadowed.RGB);
  MarchSettings termOnly = settings;
  termOnly.Output = RenderOutput::ShadowTerm;
  EXPECT_EQ(ReferenceRenderer::Render(scene, termOnly, 2).RGB, term.RGB);
  for (double v : term.RGB)
  {
    EXPECT_GE(v, 0.0);
    EXPECT_LE(v, 1.0);
  }
  EXPECT_EQ(term.At(18, 12).x, term.At(18, 12).z);
  EXPECT_LT(term.At(18, 12).x, 0.5 * term.At(5, 12).x);

  // The shadow term at the first receivers changes the colour not at all; -1 off the volume.
  // The camera's ray meets the floor (value 0.5, opacity 0.3 a unit) from z = 0 and reaches
  // opacity 1/2 at the sample centred at z = 1.75 (1 - 0.7^2 < 1/2 <= 1 - 0.7^2.5); the light
  // comes from +z through the floor's top (z 1.75 to 3, and its ramp to 0 over z 3 to 4: in
  // all an optical depth of 1.25 (-ln 0.7) + 0.16 = 0.61, V = 0.54), and under the slab
  // through the slab as well (opaque: V below 0.01).
  Image surface;
  EXPECT_EQ(ReferenceRenderer::Render(scene, settings, 2, nullptr, &surface).RGB, shadowed.RGB);
  EXPECT_EQ(surface.At(0, 12), glm::dvec3(-1.0));
  EXPECT_NEAR(surface.At(5, 12).x, 0.54, 0.04);
  EXPECT_LT(surface.At(18, 12).x, 0.01);
}
