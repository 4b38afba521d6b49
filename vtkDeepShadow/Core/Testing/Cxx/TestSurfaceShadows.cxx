// Surfaces that cast shadows (SurfaceSet) on every CPU technique: the twins of the GPU's
// Features/Surfaces.glsl, and the ground truth of hybrid scenes.
#include "Core/Shadows/LightSpace.h"
#include "Core/Shadows.h"
#include "SlabScene.h"
#include "Core/Geometry/SurfaceSet.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

using namespace deepshadow;

namespace
{
// A square in the plane z = height, [x0, x1] x [y0, y1], facing +z.
SurfaceMesh Square(double height, double opacity, const glm::dvec3& color = glm::dvec3(1.0),
  double x0 = -5.0, double x1 = 25.0, double y0 = -5.0, double y1 = 25.0)
{
  SurfaceMesh mesh;
  mesh.Points = { { x0, y0, height }, { x1, y0, height }, { x1, y1, height }, { x0, y1, height } };
  mesh.Triangles = { { 0, 1, 2 }, { 0, 2, 3 } };
  mesh.Material.Opacity = opacity;
  mesh.Material.Color = color;
  return mesh;
}

// The slab scene (value 1 for z in [8, 12], opacity `slab` per unit) with casting surfaces.
struct HybridScene : deepshadow::testing::SlabScene
{
  SurfaceSet Surfaces;

  HybridScene(double slab, std::vector<SurfaceMesh> meshes)
    : SlabScene(slab)
    , Surfaces(std::move(meshes))
  {
    this->Caster.Surfaces = &this->Surfaces;
  }
};

Light Overhead()
{
  Light light;
  light.Position = { 10.0, 10.0, 100.0 };
  light.FocalPoint = { 10.0, 10.0, 0.0 };
  return light;
}
}

TEST(SurfaceShadows, TransmissionOfOpaqueGreyAndColouredSurfaces)
{
  SurfaceMaterial m;
  m.Opacity = 1.0;
  m.Color = { 1.0, 1.0, 1.0 };
  EXPECT_EQ(SurfaceTransmission(m, false), glm::dvec3(0.0));
  EXPECT_EQ(SurfaceTransmission(m, true), glm::dvec3(0.0)); // opaque stops every channel
  m.Opacity = 0.4;
  m.Color = { 1.0, 0.5, 0.0 };
  EXPECT_EQ(SurfaceTransmission(m, false), glm::dvec3(0.6));
  const glm::dvec3 c = SurfaceTransmission(m, true);
  EXPECT_DOUBLE_EQ(c.r, 1.0);
  EXPECT_DOUBLE_EQ(c.g, 0.8);
  EXPECT_DOUBLE_EQ(c.b, 0.6);
  m.Opacity = 0.0;
  EXPECT_EQ(SurfaceTransmission(m, true), glm::dvec3(1.0));
}

TEST(SurfaceShadows, BadMeshesAreClearErrors)
{
  SurfaceMesh nan = Square(1.0, 1.0);
  nan.Points[2].y = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(SurfaceSet({ nan }), std::invalid_argument);
  SurfaceMesh index = Square(1.0, 1.0);
  index.Triangles.push_back({ 0, 1, 7 });
  EXPECT_THROW(SurfaceSet({ index }), std::invalid_argument);
  EXPECT_THROW(SurfaceSet({ Square(1.0, 1.5) }), std::invalid_argument);
  EXPECT_THROW(SurfaceSet(std::vector<SurfaceMesh>(SurfaceSet::MaxSurfaces + 1, Square(1.0, 1.0))),
    std::invalid_argument);
  // Degenerate triangles are dropped; an empty set casts nothing.
  SurfaceMesh flat = Square(1.0, 1.0);
  flat.Triangles = { { 0, 0, 1 } };
  EXPECT_TRUE(SurfaceSet({ flat }).Empty());
  EXPECT_TRUE(SurfaceSet().Empty());
}

TEST(SurfaceShadows, CrossingsMultiplyAndOccludeAboveTheThreshold)
{
  const SurfaceSet set({ Square(2.0, 0.5), Square(4.0, 0.25, { 0.0, 1.0, 0.0 }) });
  const glm::dvec3 o(10.0, 10.0, 0.0), up(0.0, 0.0, 1.0);
  EXPECT_EQ(set.Transmittance(o, up, 0.0, 1e9, false), glm::dvec3(0.5 * 0.75));
  // Coloured: white lets every channel through; green stops a quarter of red and blue.
  EXPECT_EQ(set.Transmittance(o, up, 0.0, 1e9, true), glm::dvec3(0.75, 1.0, 0.75));
  EXPECT_EQ(set.Transmittance(o, up, 0.0, 3.0, false), glm::dvec3(0.5)); // the light before the second
  EXPECT_EQ(set.Transmittance(o, -up, 0.0, 1e9, false), glm::dvec3(1.0));
  EXPECT_TRUE(set.Occludes(o, up, 0.0, 1e9, 0.4));
  EXPECT_FALSE(set.Occludes(o, up, 0.0, 1e9, 0.5));
  const SurfaceHit hit = set.NextHit(o, up, 0.0);
  ASSERT_TRUE(hit.Found);
  EXPECT_DOUBLE_EQ(hit.T, 2.0);
  EXPECT_EQ(hit.Surface, 0);
  EXPECT_NEAR(glm::dot(set.Normal(hit), up), 1.0, 1e-12);
}

TEST(SurfaceShadows, FeelerMeetsSurfacesInsideAndOutsideTheVolume)
{
  // A translucent sheet inside the slab's box and one above the box: Beer-Lambert through the
  // slab times each sheet's transmission.
  const HybridScene scene(0.3, { Square(15.0, 0.5), Square(30.0, 0.2) });
  const ShadowParameters p = ShadowParameters::GroundTruth(false, 1.0);
  const double v = FeelerVisibility(scene.Caster, { 10, 10, 2 }, { 0, 0, 1 }, 1e300, 0.5, p).r;
  EXPECT_NEAR(v, std::pow(0.7, 5.0) * 0.5 * 0.8, 1e-12);
  // A light between the sheets: the upper one is beyond it.
  EXPECT_NEAR(FeelerVisibility(scene.Caster, { 10, 10, 2 }, { 0, 0, 1 }, 20.0, 0.5, p).r,
    std::pow(0.7, 5.0) * 0.5, 1e-12);
  // From below the box: the samples start at its entry, not at the point.
  EXPECT_NEAR(FeelerVisibility(scene.Caster, { 10, 10, -7 }, { 0, 0, 1 }, 1e300, 0.5, p).r,
    std::pow(0.7, 5.0) * 0.5 * 0.8, 1e-12);
  // Opaque rays, by default on the accumulated opacity (sheets included): 1 - 0.0672.
  ShadowParameters opaque;
  opaque.Kind = ShadowKind::Rays;
  opaque.Opaque = true;
  opaque.Threshold = 0.9;
  EXPECT_EQ(FeelerVisibility(scene.Caster, { 10, 10, 2 }, { 0, 0, 1 }, 1e300, 0.5, opaque), glm::dvec3(0.0));
  opaque.Threshold = 0.95;
  EXPECT_EQ(FeelerVisibility(scene.Caster, { 10, 10, 2 }, { 0, 0, 1 }, 1e300, 0.5, opaque), glm::dvec3(1.0));
  // Per sample: a sheet whose opacity exceeds the threshold is a full occluder.
  opaque.Mode = ThresholdMode::Opacity;
  opaque.Threshold = 0.4; // above the slab's 0.3
  EXPECT_EQ(FeelerVisibility(scene.Caster, { 10, 10, 2 }, { 0, 0, 1 }, 1e300, 0.5, opaque), glm::dvec3(0.0));
  opaque.Threshold = 0.6;
  EXPECT_EQ(FeelerVisibility(scene.Caster, { 10, 10, 2 }, { 0, 0, 1 }, 1e300, 0.5, opaque), glm::dvec3(1.0));
}

TEST(SurfaceShadows, FacesCoverSurfacesOutsideTheVolume)
{
  const SurfaceSet set({ Square(60.0, 1.0, glm::dvec3(1.0), 40.0, 50.0, 40.0, 50.0) });
  glm::dvec3 centre;
  double radius = 0.0;
  CasterBoundingSphere(glm::dmat4(1.0), glm::ivec3(21), &set, centre, radius);
  for (const glm::dvec3& p : { glm::dvec3(0.0), glm::dvec3(20.0), glm::dvec3(40, 40, 60), glm::dvec3(50, 50, 60) })
  {
    EXPECT_LE(glm::length(p - centre), radius * (1.0 + 1e-12));
  }
}

// Every technique sees the surface steps: an opaque square above the volume's box blacks out
// what lies under it, a translucent coloured one tints it by its transmission.
TEST(SurfaceShadows, EveryTechniqueSeesOpaqueAndTranslucentSurfaces)
{
  const HybridScene opaque(0.0, { Square(40.0, 1.0, glm::dvec3(1.0), 0.0, 10.0, 0.0, 20.0) });
  const HybridScene glass(0.0, { Square(40.0, 0.5, { 1.0, 0.2, 0.2 }) });
  const Light light = Overhead();
  for (ShadowKind kind : { ShadowKind::Rays, ShadowKind::ShadowMap, ShadowKind::DeepShadowMap,
         ShadowKind::OpacityLevels, ShadowKind::Stochastic })
  {
    ShadowParameters p;
    p.Kind = kind;
    p.MapSize = 64;
    p.Epsilon = 0.01;
    p.Offsets = 7;
    p.Photons = 64;
    p.Filter = ShadowFilter::None;
    const auto dark = MakeLightShadow(p, opaque.Caster, light, 0.5, 2);
    EXPECT_LT(dark->Visibility({ 5.0, 10.0, 10.0 }).r, 0.01) << p.Name() << " under the square";
    EXPECT_GT(dark->Visibility({ 15.0, 10.0, 10.0 }).r, 0.99) << p.Name() << " beside it";
    EXPECT_GT(dark->Visibility({ 5.0, 10.0, 50.0 }).r, 0.99) << p.Name() << " above it";
    if (kind == ShadowKind::ShadowMap)
    {
      continue; // binary: a translucent sheet below the threshold casts nothing
    }
    p.Colored = kind != ShadowKind::OpacityLevels;
    const auto tinted = MakeLightShadow(p, glass.Caster, light, 0.5, 2);
    const glm::dvec3 expected =
      p.IsColored() ? glm::dvec3(1.0, 0.6, 0.6) : glm::dvec3(0.5);
    // CSSM estimates from 64 photons x 7 offsets; the others are exact within their epsilon.
    const double tolerance = kind == ShadowKind::Stochastic ? 0.08 : 0.02;
    const glm::dvec3 v = tinted->Visibility({ 10.0, 10.0, 10.0 });
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(v[c], p.IsColored() ? expected[c] : expected[0], tolerance)
        << p.Name() << " channel " << c;
    }
    EXPECT_GT(tinted->Visibility({ 10.0, 10.0, 45.0 }).r, 0.99) << p.Name() << " above the glass";
  }
}
