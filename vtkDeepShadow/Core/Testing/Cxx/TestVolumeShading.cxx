// VolumeShading in closed form: each of VTK 9.1's and 9.2's lighting paths and Blinn-Phong on a
// sample whose normal, lights and viewer are chosen so that every term can be written down.
#include "Core/VolumeShading.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>

using namespace deepshadow;

namespace
{
const glm::dvec3 Colour{ 0.8, 0.5, 0.2 };
const glm::dvec3 Up{ 0.0, 0.0, 1.0 }; // the sample's outward normal
const glm::dvec3 At{ 0.0, 0.0, 0.0 };

Material MakeMaterial()
{
  Material m;
  m.Ambient = 0.2;
  m.Diffuse = 0.7;
  m.Specular = 0.4;
  m.SpecularPower = 8.0;
  return m;
}

Light Directional(const glm::dvec3& towards, double intensity = 1.0)
{
  Light light;
  light.Position = towards;
  light.FocalPoint = glm::dvec3(0.0);
  light.Diffuse = light.Specular = glm::dvec3(intensity);
  return light;
}

// A point light 5 units from the sample, along (0.6, 0, 0.8), unattenuated.
Light PointLight()
{
  Light point;
  point.Positional = true;
  point.Position = { 3.0, 0.0, 4.0 };
  point.FocalPoint = glm::dvec3(0.0);
  return point;
}

// VTK's lone headlight: shaded from the eye, 10 units above the sample.
Light HeadlightAbove()
{
  Light head = Directional({ 0.0, 0.0, 1.0 });
  head.ShadedFromEye = true;
  head.Eye = { 0.0, 0.0, 10.0 };
  return head;
}

glm::dvec3 Shade(const VolumeShading& shading, const std::vector<Light>& lights, const glm::dvec3& toViewer,
  bool twoSided = true, const glm::dvec3& normal = Up)
{
  return ShadeVolumeSample(shading, Colour, normal, At, toViewer, lights, MakeMaterial(), twoSided,
    [](size_t) { return glm::dvec3(1.0); });
}

void ExpectNear(const glm::dvec3& a, const glm::dvec3& b)
{
  EXPECT_NEAR(a.x, b.x, 1e-12);
  EXPECT_NEAR(a.y, b.y, 1e-12);
  EXPECT_NEAR(a.z, b.z, 1e-12);
}
}

TEST(VolumeShading, BlinnPhongIsAmbientTimesColourPlusDiffuseAndTheHalfVectorsSpecular)
{
  VolumeShading shading; // Blinn-Phong, the renderer's ambient light 1
  const double s = std::sqrt(0.5);
  const glm::dvec3 toLight(s, 0.0, s), toViewer(0.0, 0.0, 1.0);
  const glm::dvec3 halfway = glm::normalize(toLight + toViewer);
  const Material m = MakeMaterial();
  const glm::dvec3 expected = m.Ambient * Colour + m.Diffuse * s * Colour +
    glm::dvec3(m.Specular * std::pow(halfway.z, m.SpecularPower));
  ExpectNear(Shade(shading, { Directional(toLight) }, toViewer), glm::clamp(expected, 0.0, 1.0));
}

TEST(VolumeShading, VTKsDirectionalPathHasNoAmbientUnlessTheLightsGiveIt)
{
  VolumeShading shading;
  shading.Path = ShadingPath::VTKDirectional;
  shading.Ambient = glm::dvec3(0.0); // default lights: black ambient colours
  shading.Eye = { 0.0, 0.0, 1e6 };   // the mirrored point's direction is the view's
  const glm::dvec3 toViewer(0.0, 0.0, 1.0);
  const Material m = MakeMaterial();
  // A light overhead: N.L = 1 diffuse, N.H = 1.
  const glm::dvec3 lit = Shade(shading, { Directional({ 0.0, 0.0, 1.0 }) }, toViewer);
  ExpectNear(lit, glm::clamp(m.Diffuse * Colour + glm::dvec3(m.Specular), 0.0, 1.0));
  // The lights' ambient colours, summed, times Ka: not times the sample's colour.
  shading.Ambient = glm::dvec3(0.5, 0.4, 0.3);
  const glm::dvec3 grazing = Shade(shading, { Directional({ 1.0, 0.0, 0.0 }) }, toViewer, false);
  const double halfwayZ = glm::normalize(glm::dvec3(1.0, 0.0, 0.0) + toViewer).z;
  ExpectNear(grazing, m.Ambient * shading.Ambient + glm::dvec3(m.Specular * std::pow(halfwayZ, m.SpecularPower)));
}

TEST(VolumeShading, VTKsDirectionalPathKeepsOnlyTheLastLightsSpecular)
{
  VolumeShading shading;
  shading.Path = ShadingPath::VTKDirectional;
  shading.Ambient = glm::dvec3(0.0);
  shading.Eye = { 0.0, 0.0, 1e6 };
  const glm::dvec3 toViewer(0.0, 0.0, 1.0);
  const Material m = MakeMaterial();
  const double s = std::sqrt(0.5);
  const Light overhead = Directional({ 0.0, 0.0, 1.0 }); // N.H = 1
  const Light slanted = Directional({ s, 0.0, s });      // N.H = cos(22.5 degrees)
  const double slantedSpecular = m.Specular * std::pow(std::cos(M_PI / 8.0), m.SpecularPower);
  const glm::dvec3 diffuse = m.Diffuse * (1.0 + s) * Colour;
  ExpectNear(Shade(shading, { overhead, slanted }, toViewer), glm::clamp(diffuse + glm::dvec3(slantedSpecular), 0.0, 1.0));
  ExpectNear(Shade(shading, { slanted, overhead }, toViewer), glm::clamp(diffuse + glm::dvec3(m.Specular), 0.0, 1.0));
  // Blinn-Phong sums both.
  shading.Path = ShadingPath::BlinnPhong;
  shading.Ambient = glm::dvec3(1.0);
  ExpectNear(Shade(shading, { slanted, overhead }, toViewer),
    glm::clamp(m.Ambient * Colour + diffuse + glm::dvec3(m.Specular + slantedSpecular), 0.0, 1.0));
}

TEST(VolumeShading, VTKsDirectionalPathLooksAtThePointMirroredThroughTheFirstVoxel)
{
  VolumeShading shading;
  shading.Path = ShadingPath::VTKDirectional;
  shading.Ambient = glm::dvec3(0.0);
  shading.Eye = { 0.0, 0.0, 10.0 };
  shading.MirrorCentre = { 2.0 * -10.0, 0.0, 0.0 }; // first voxel at x = -10
  // The point seen is 2 P0 - p = (-20, 0, 0): from the eye, direction (-20, 0, -10).
  glm::dvec3 toLight(0.0, 0.0, 1.0);
  const glm::dvec3 halfway = shading.Halfway(toLight, { 0.0, 0.0, 1.0 }, At);
  const glm::dvec3 expected = glm::normalize(glm::dvec3(0.0, 0.0, 1.0) + glm::normalize(glm::dvec3(20.0, 0.0, 10.0)));
  ExpectNear(halfway, expected);
}

TEST(VolumeShading, VTKsPositionalPathTakesLMinusVAndLightsWhereTheTransformSays)
{
  VolumeShading shading;
  shading.Path = ShadingPath::VTKPositional;
  shading.Ambient = glm::dvec3(0.0);
  shading.Eye = { 0.0, 0.0, 10.0 };
  Light point = PointLight();
  point.Attenuation = { 0.5, 0.1, 0.0 };
  const Material m = MakeMaterial();
  // From the origin: the light 5 away along (0.6, 0, 0.8), the eye along +z.
  const glm::dvec3 toLight(0.6, 0.0, 0.8), toEye(0.0, 0.0, 1.0);
  const double attenuation = 1.0 / (0.5 + 0.1 * 5.0);
  const double nDotH = glm::normalize(toLight - toEye).z; // negative: abs under two-sided lighting
  const glm::dvec3 expected = attenuation *
    (m.Diffuse * 0.8 * Colour + glm::dvec3(m.Specular * std::pow(std::abs(nDotH), m.SpecularPower)));
  ExpectNear(Shade(shading, { point }, toEye), glm::clamp(expected, 0.0, 1.0));
  // One-sided, that N.H < 0 gives no specular light.
  ExpectNear(Shade(shading, { point }, toEye, false), attenuation * m.Diffuse * 0.8 * Colour);
  // Lit from where LightingTransform moves the sample: one unit up, the light straight above.
  shading.LightingTransform[3] = glm::dvec4(3.0, 0.0, 1.0, 1.0);
  const double attenuationThere = 1.0 / (0.5 + 0.1 * 3.0);
  const double nDotHThere = glm::normalize(glm::dvec3(0.0, 0.0, 1.0) - glm::normalize(glm::dvec3(-3.0, 0.0, 9.0))).z;
  ExpectNear(Shade(shading, { point }, toEye, false),
    attenuationThere * (m.Diffuse * Colour + glm::dvec3(m.Specular * std::pow(nDotHThere, m.SpecularPower))));
}

TEST(VolumeShading, VTKsHeadlightPathComparesTheInwardNormalAndIsBlackWhereItsPowIsUndefined)
{
  VolumeShading shading;
  shading.Path = ShadingPath::VTKHeadlight;
  shading.IndexGradientToNormal = glm::dmat3(1.0);
  // An index gradient pointing down (density grows downwards): VTK's normal is the gradient.
  const glm::dvec3 normal = shading.Normal({ 0.0, 0.0, -2.0 });
  ExpectNear(normal, { 0.0, 0.0, -1.0 });
  const Light head = HeadlightAbove();
  const Material m = MakeMaterial();
  // Two-sided: |N.L| = |N.H| = 1, ambient Ka x colour.
  ExpectNear(Shade(shading, { head }, { 0.0, 0.0, 1.0 }, true, normal),
    glm::clamp(m.Ambient * Colour + m.Diffuse * Colour + glm::dvec3(m.Specular), 0.0, 1.0));
  // One-sided: N.H = -1, VTK's pow(-1, 8) in GLSL: black, ambient included.
  ExpectNear(Shade(shading, { head }, { 0.0, 0.0, 1.0 }, false, normal), glm::dvec3(0.0));
}

TEST(VolumeShading, SpotsOfNinetyDegreesAreSpots)
{
  Light spot;
  spot.Positional = true;
  spot.Position = { 0.0, 0.0, 1.0 };
  spot.FocalPoint = glm::dvec3(0.0);
  spot.ConeAngle = 90.0;
  EXPECT_GT(spot.At({ 0.0, 0.0, 0.0 }).Reach, 0.0);
  EXPECT_EQ(spot.At({ 0.0, 0.0, 2.0 }).Reach, 0.0); // behind the light: outside the half-space
  spot.ConeAngle = 90.5;
  EXPECT_GT(spot.At({ 0.0, 0.0, 2.0 }).Reach, 0.0);
}

// VTK 9.2 onwards (VTKShadingRevision::Reflection): Phong's R.V, only where N.L > 0.
TEST(VolumeShading, VTK92sDirectionalPathReflectsTheLightAndSumsEveryLightsSpecular)
{
  VolumeShading shading;
  shading.Path = ShadingPath::VTKDirectional;
  shading.Revision = VTKShadingRevision::Reflection;
  shading.Ambient = glm::dvec3(0.0);
  shading.Eye = { 0.0, 0.0, 1e9 }; // the viewer straight above, wherever the first voxel is
  shading.MirrorCentre = { -20.0, 0.0, 0.0 }; // VTK 9.1's mirror: not looked at any more
  const Material m = MakeMaterial();
  const double s = std::sqrt(0.5);
  // Light at 45 degrees: R = (-s, 0, s), R.V = s; and overhead: R.V = 1. Both speculars count.
  const glm::dvec3 both = Shade(shading, { Directional({ s, 0.0, s }), Directional({ 0.0, 0.0, 1.0 }) },
    { 0.0, 0.0, 1.0 }, false);
  const glm::dvec3 expected = m.Diffuse * (s + 1.0) * Colour +
    glm::dvec3(m.Specular * (std::pow(s, m.SpecularPower) + 1.0));
  ExpectNear(both, glm::clamp(expected, 0.0, 1.0));
  // A grazing light (N.L = 0) gives no specular light, though its R.V is 0 < x: VTK 9.1's
  // half vector would have given some.
  ExpectNear(Shade(shading, { Directional({ 1.0, 0.0, 0.0 }) }, { 0.0, 0.0, 1.0 }, false), glm::dvec3(0.0));
  // From below, two-sided: N.L flipped to s, R reflected with it: R = l - 2 s n = (s, 0, -3s)
  // normalized, R.V = -(-3s)/|R|... R.V = -V.r with r that vector: 3s / sqrt(10 s^2) = 3/sqrt(10).
  const glm::dvec3 below = Shade(shading, { Directional({ s, 0.0, -s }) }, { 0.0, 0.0, 1.0 }, true);
  ExpectNear(below, glm::clamp(m.Diffuse * s * Colour + glm::dvec3(m.Specular * std::pow(3.0 / std::sqrt(10.0), m.SpecularPower)), 0.0, 1.0));
}

TEST(VolumeShading, VTK92sHeadlightComparesTheOutwardNormalAndIsNeverBlack)
{
  VolumeShading shading;
  shading.Path = ShadingPath::VTKHeadlight;
  shading.Revision = VTKShadingRevision::Reflection;
  const glm::dvec3 normal = shading.Normal({ 0.0, 0.0, -2.0 }); // density grows downwards
  ExpectNear(normal, { 0.0, 0.0, 1.0 });
  const Light head = HeadlightAbove();
  const Material m = MakeMaterial();
  // Facing the eye, one-sided: N.L = 1, R.V = 1.
  ExpectNear(Shade(shading, { head }, { 0.0, 0.0, 1.0 }, false, normal),
    glm::clamp(m.Ambient * Colour + m.Diffuse * Colour + glm::dvec3(m.Specular), 0.0, 1.0));
  // Its back, one-sided: ambient alone (VTK 9.1 drew it black).
  ExpectNear(Shade(shading, { head }, { 0.0, 0.0, 1.0 }, false, -normal), m.Ambient * Colour);
  // At 60 degrees: N.L = 1/2, R.V = 2 (N.L)^2 - 1 < 0: no specular light.
  const glm::dvec3 tilted(std::sqrt(0.75), 0.0, 0.5);
  ExpectNear(Shade(shading, { head }, { 0.0, 0.0, 1.0 }, false, tilted),
    glm::clamp(m.Ambient * Colour + m.Diffuse * 0.5 * Colour, 0.0, 1.0));
}

TEST(VolumeShading, VTK92sPositionalLightsFlipRDotVUnderTwoSidedLighting)
{
  VolumeShading shading;
  shading.Path = ShadingPath::VTKPositional;
  shading.Revision = VTKShadingRevision::Reflection;
  shading.Ambient = glm::dvec3(0.0);
  shading.Eye = { 0.0, 0.0, 10.0 };
  const Light point = PointLight();
  const Material m = MakeMaterial();
  // The light along (0.6, 0, 0.8): R = (-0.6, 0, 0.8), the eye along +z: R.V = 0.8.
  ExpectNear(Shade(shading, { point }, { 0.0, 0.0, 1.0 }, false),
    glm::clamp(m.Diffuse * 0.8 * Colour + glm::dvec3(m.Specular * std::pow(0.8, m.SpecularPower)), 0.0, 1.0));
  // The eye below the surface, the light above: R.V = -0.8; two-sided flips it for a
  // positional light, not for a directional one.
  shading.Eye = { 0.0, 0.0, -10.0 };
  ExpectNear(Shade(shading, { point }, { 0.0, 0.0, -1.0 }, true),
    glm::clamp(m.Diffuse * 0.8 * Colour + glm::dvec3(m.Specular * std::pow(0.8, m.SpecularPower)), 0.0, 1.0));
  ExpectNear(Shade(shading, { Directional({ 0.6, 0.0, 0.8 }) }, { 0.0, 0.0, -1.0 }, true), m.Diffuse * 0.8 * Colour);
}
