// Stiff and extreme cases, CPU side, second half: lights at the extremes, zero intensities,
// near/far ratios, map sizes, denormal and full-range samples, determinism. The index of
// every stiff case is at the head of TestStiffCases.cxx.

#include "StiffCases.h"

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
    // Ambient 0.1 x 0.5, and the light's isotropic (1 - 0.1) x 0.5 (Light.h) times its visibility.
    bounds += weight * (0.05 + 0.45 * glm::dvec2(std::pow(1.0 - a, k + 1), std::pow(1.0 - a, k)));
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
      // Along the oblique axis the point lies 0.13 behind the wall: closer than a slice.
      if (ShadowTechniqueOf(p).ResolvesThinLayers)
      {
        EXPECT_LE(shadow->Visibility(behind).r, p.Cached ? 0.5 : DarkTolerance(p) + 1e-9) << NameOf(p) << ": dark behind";
      }
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

// An unshaded volume with a technique, every light reaching it (none casting: shadow
// attenuation 0): the picture is the one without a technique, which emits the colour, to
// rounding, whatever the lights (one of intensity 1, a light kit's five of 1.66 in all,
// coloured ones, a positional one) and the material's ambient (Light.h's IsotropicLightScale),
// tinted by the lights' colour: their summed diffuse over its largest channel.
// Then the key light casting: never brighter than that. The former model (Ka + Kd sum Ld)
// fails the first (0.8 of it under one light; 1.26 under the kit).
TEST(StiffCases, UnshadedWithATechniqueKeepsItsColourWhereFullyLit)
{
  const Caster caster{ Grid(glm::ivec3(17), glm::dvec3(1.0), [](int i, int, int k) { return (i + k) % 5 == 0 ? 1.0f : 0.3f; }),
    Medium(0.4, 0.2, 0.6) };
  auto light = [](const glm::dvec3& toLight, double intensity, const glm::dvec3& colour) {
    Light l = Directional(toLight);
    l.Diffuse = l.Specular = intensity * colour;
    return l;
  };
  const std::vector<std::vector<Light>> setups{
    { light({ 0.3, 0.2, 1.0 }, 1.0, glm::dvec3(1.0)) },
    // vtkLightKit's (key, fill, head-on, two back lights; warm and cool colours)
    { light({ 0.3, 0.2, 1.0 }, 0.75, { 1.0, 0.97232, 0.90222 }), light({ -0.5, -0.3, 0.8 }, 0.25, { 0.90824, 0.93314, 1.0 }),
      light({ 0.0, 0.0, -1.0 }, 0.25, glm::dvec3(0.9998)), light({ 1.0, 0.0, 0.2 }, 0.2142857, glm::dvec3(0.9998)),
      light({ -1.0, 0.0, 0.2 }, 0.2142857, glm::dvec3(0.9998)) },
    { light({ 0.3, 0.2, 1.0 }, 0.6, { 1.0, 0.2, 0.2 }), Positional({ 8.0, 8.0, 40.0 }) },
  };
  Scene emitting = ViewFromBelow(caster.G, caster.Transfer, ShadowParameters(), setups[0], 12);
  emitting.Volumes[0].Shadows.Kind = ShadowKind::None;
  emitting.Background = glm::dvec3(0.0);
  const Image expected = ReferenceRenderer::Render(emitting, Exact(), Threads);
  for (const std::vector<Light>& lights : setups)
  {
    glm::dvec3 tint(0.0);
    for (const Light& l : lights)
    {
      tint += l.Diffuse;
    }
    tint /= std::max({ tint.r, tint.g, tint.b });
    for (double ambient : { 0.1, 0.4 })
    {
      Scene scene = ViewFromBelow(caster.G, caster.Transfer, Technique(ShadowKind::DeepShadowMap), lights, 12);
      scene.Volumes[0].Surface.Ambient = ambient;
      scene.Background = glm::dvec3(0.0);
      for (Light& l : scene.Lights)
      {
        l.ShadowAttenuation = 0.0;
      }
      const Image lit = ReferenceRenderer::Render(scene, Exact(), Threads);
      for (size_t i = 0; i < lit.RGB.size(); ++i)
      {
        // (Over a black background every pixel is the drawn colour, tinted.)
        const double tinted = expected.RGB[i] * (ambient + (1.0 - ambient) * tint[static_cast<int>(i % 3)]);
        ASSERT_NEAR(lit.RGB[i], tinted, 1e-9) << lights.size() << " lights, ambient " << ambient;
      }
      scene.Lights[0].ShadowAttenuation = 1.0;
      const Image shadowed = ReferenceRenderer::Render(scene, Exact(), Threads);
      double darker = 0.0;
      for (size_t i = 0; i < lit.RGB.size(); ++i)
      {
        ASSERT_LE(shadowed.RGB[i], lit.RGB[i] + 1e-9);
        darker = std::max(darker, lit.RGB[i] - shadowed.RGB[i]);
      }
      EXPECT_GT(darker, 0.02) << "the key light's shadow darkens";
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
      if (expected == 1.0 || ShadowTechniqueOf(p).Binary)
      {
        EXPECT_EQ(v.r, std::round(expected)) << NameOf(p); // above the layer, or binary (opacity 0.6 > 0.5)
      }
      else if (p.Kind == ShadowKind::Stochastic)
      {
        EXPECT_TRUE(v.r == 0.0 || v.r == 1.0) << NameOf(p) << ": one photon is all or nothing";
      }
      else
      {
        // Within what the technique states (the registry): opacity levels are exact behind
        // the layer (the maximum opacity), dsm within epsilon.
        EXPECT_NEAR(v.r, expected, ShadowTechniqueOf(p).StatedError(p, StatedErrorCase{ expected, false }) + 1e-6)
          << NameOf(p);
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
