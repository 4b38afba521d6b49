// Stiff and extreme cases (issue 7), CPU side: the double-precision twins at the edges, for
// every shadow technique of the registry, cached or not (StiffCases.h's EveryTechnique), with the defined behaviour in each test's name and comment. The GPU
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
// Lights, near/far ratios, map sizes, sample values and determinism are in
// TestStiffCasesLights.cxx.

#include "StiffCases.h"

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
      // Ambient 0.1 x grey 0.5; the light (unshaded: isotropic, Light.h) (1 - 0.1) x 0.5 times
      // what is left of it.
      const double ambientOnly = 0.05, slack = 0.45 * DarkTolerance(p) + 1e-6;
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
// plus one), for every map (their lookups are monotone in depth along a texel; a truncated
// Fourier series ripples within its stated error: the registry's Monotone), and for caches
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
            // A technique that ripples (the registry's Monotone) within its stated error.
            const ShadowTechniqueInfo& info = ShadowTechniqueOf(p);
            const double ripple = info.Monotone ? 0.0 : info.StatedError(p, StatedErrorCase{ v[c], true });
            ASSERT_LE(v[c], std::max(previous[c], floor) + ripple + 1e-12) << NameOf(p) << " step " << k;
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
      // The pancake's layer is 1/4000 of the light's depth range: thinner than a slice.
      if (ShadowTechniqueOf(p).ResolvesThinLayers)
      {
        EXPECT_LE(v, DarkTolerance(p) + 1e-9) << NameOf(p) << ", " << what;
      }
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
