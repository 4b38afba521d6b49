// The optical model: opacity correction, compositing and shading, checked against closed forms.
#include "Core/Light.h"
#include "Core/OpticalModel.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>

using namespace deepshadow;

TEST(CorrectOpacity, IsIdentityAtTheUnitDistance)
{
  for (double a : { 0.0, 0.1, 0.5, 0.99, 1.0 })
  {
    EXPECT_NEAR(CorrectOpacity(a, 2.5, 2.5), a, 1e-15);
  }
}

TEST(CorrectOpacity, TwoHalfStepsEqualOneFullStep)
{
  for (double a : { 0.01, 0.3, 0.9 })
  {
    const double half = CorrectOpacity(a, 0.5, 1.0);
    EXPECT_NEAR(1.0 - (1.0 - half) * (1.0 - half), a, 1e-14);
  }
}

TEST(CorrectOpacity, ClampsAndKeepsTheLimits)
{
  EXPECT_EQ(CorrectOpacity(0.0, 1e-4, 1.0), 0.0);
  EXPECT_EQ(CorrectOpacity(1.0, 1e-4, 1.0), 1.0);
  EXPECT_EQ(CorrectOpacity(-0.5, 1.0, 1.0), 0.0);
  EXPECT_EQ(CorrectOpacity(1.5, 1.0, 1.0), 1.0);
  // Extreme ratios stay in [0, 1] and finite.
  for (double ratio : { 1e-8, 1e-4, 1e4, 1e8 })
  {
    const double c = CorrectOpacity(0.5, ratio, 1.0);
    EXPECT_TRUE(std::isfinite(c));
    EXPECT_GE(c, 0.0);
    EXPECT_LE(c, 1.0);
  }
}

TEST(CompositeFrontToBack, MatchesTheTransmittanceProduct)
{
  glm::dvec4 accumulated(0.0);
  double transmittance = 1.0;
  glm::dvec3 expected(0.0);
  const double alphas[] = { 0.2, 0.5, 0.1, 0.7 };
  const glm::dvec3 colors[] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 1, 1, 1 } };
  for (int i = 0; i < 4; ++i)
  {
    CompositeFrontToBack(accumulated, colors[i], alphas[i]);
    expected += transmittance * alphas[i] * colors[i];
    transmittance *= 1.0 - alphas[i];
  }
  EXPECT_NEAR(accumulated.a, 1.0 - transmittance, 1e-15);
  EXPECT_NEAR(glm::length(glm::dvec3(accumulated) - expected), 0.0, 1e-15);
}

TEST(SurfaceLight, FollowsVTKsClosedForm)
{
  Material m;
  m.Diffuse = 0.6;
  m.Specular = 0.3;
  m.SpecularPower = 8.0;
  LightSample light;
  light.ToLight = glm::normalize(glm::dvec3(0.0, 1.0, 1.0));
  const glm::dvec3 normal(0.0, 0.0, 1.0), color(0.5, 0.25, 1.0);
  const glm::dvec3 toViewer = glm::normalize(glm::dvec3(0.0, -0.5, 1.0));
  const glm::dvec3 lit = SurfaceLight(color, normal, toViewer, light, m, false, glm::dvec3(1.0));
  // VTK's polygon mapper: the reflection of the light's direction, (0, -1, 1)/sqrt(2) here.
  const double nDotL = std::sqrt(0.5);
  const double rDotV = glm::dot(glm::normalize(glm::dvec3(0.0, -1.0, 1.0)), toViewer);
  const glm::dvec3 expected = 0.6 * nDotL * color + 0.3 * std::pow(rDotV, 8.0) * glm::dvec3(1.0);
  EXPECT_NEAR(glm::length(lit - expected), 0.0, 1e-14);
  // A lone headlight: VTK's simplest path, (N.L)^p.
  const glm::dvec3 headlit = SurfaceLight(color, normal, toViewer, light, m, true, glm::dvec3(1.0));
  EXPECT_NEAR(glm::length(headlit - (0.6 * nDotL * color + 0.3 * std::pow(nDotL, 8.0) * glm::dvec3(1.0))), 0.0, 1e-14);
}

TEST(SurfaceLight, IsOneSided)
{
  Material m;
  m.Specular = 1.0;
  LightSample light;
  light.ToLight = glm::dvec3(0.0, 0.0, 1.0);
  const glm::dvec3 up(0, 0, 1), down(0, 0, -1), viewer(0, 0, 1), color(1.0);
  EXPECT_GT(SurfaceLight(color, up, viewer, light, m, false, glm::dvec3(1.0)).x, 0.0);
  // Lit from behind: neither diffuse nor specular light (|N.L| would light a sphere's far side).
  EXPECT_EQ(SurfaceLight(color, down, viewer, light, m, false, glm::dvec3(1.0)), glm::dvec3(0.0));
  EXPECT_EQ(SurfaceLight(color, down, -viewer, light, m, false, glm::dvec3(1.0)), glm::dvec3(0.0));
  EXPECT_EQ(SurfaceLight(color, glm::dvec3(0.0), viewer, light, m, false, glm::dvec3(1.0)), glm::dvec3(0.0));
}

TEST(Light, DirectionalLightsPointFromTheFocalPointToThePosition)
{
  Light light;
  light.Position = { 1.0, 2.0, 3.0 };
  light.FocalPoint = { 1.0, 2.0, 0.0 };
  const LightSample s = light.At({ 100.0, -5.0, 7.0 });
  EXPECT_NEAR(glm::length(s.ToLight - glm::dvec3(0.0, 0.0, 1.0)), 0.0, 1e-15);
  EXPECT_EQ(s.Diffuse, light.Diffuse);
}

TEST(Light, PositionalLightsAttenuateAndSpotsCut)
{
  Light light;
  light.Positional = true;
  light.Position = { 0.0, 0.0, 10.0 };
  light.FocalPoint = { 0.0, 0.0, 0.0 };
  light.Attenuation = { 1.0, 0.1, 0.01 };
  const LightSample below = light.At({ 0.0, 0.0, 0.0 });
  EXPECT_NEAR(below.Diffuse.x, 1.0 / (1.0 + 1.0 + 1.0), 1e-15);
  EXPECT_NEAR(glm::length(below.ToLight - glm::dvec3(0, 0, 1)), 0.0, 1e-15);

  light.ConeAngle = 30.0;
  light.Exponent = 2.0;
  const LightSample inside = light.At({ 0.0, 0.0, 0.0 });
  EXPECT_NEAR(inside.Diffuse.x, 1.0 / 3.0, 1e-15); // cos(0)^2 = 1
  const LightSample outside = light.At({ 10.0, 0.0, 0.0 }); // 45 degrees off the axis
  EXPECT_EQ(outside.Diffuse, glm::dvec3(0.0));
}
