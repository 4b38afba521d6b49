// Light-space faces and depth precision: every light-space technique sees the whole volume,
// and depths stay precise whatever the ratio of the nearest to the farthest depth.
#include "Core/Shadows/DeepShadowMap.h"
#include "Core/Shadows/LightSpace.h"
#include "Core/Shadows.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

using namespace deepshadow;

namespace
{
// A unit-sized volume (17^3 voxels, spacing 1/16) at `origin`, with a ball of translucent
// medium in its middle.
struct Ball
{
  std::shared_ptr<VolumeGrid> Grid;
  TransferFunction Transfer;
  ShadowCaster Caster;
  explicit Ball(const glm::dvec3& origin)
  {
    std::vector<float> values(17 * 17 * 17);
    for (int k = 0; k < 17; ++k)
      for (int j = 0; j < 17; ++j)
        for (int i = 0; i < 17; ++i)
          values[i + 17 * (j + 17 * k)] =
            static_cast<float>(std::max(0.0, 1.0 - glm::length(glm::dvec3(i, j, k) - 8.0) / 6.0));
    const glm::dmat4 indexToWorld = glm::scale(glm::translate(glm::dmat4(1.0), origin), glm::dvec3(1.0 / 16));
    this->Grid = std::make_shared<VolumeGrid>(glm::ivec3(17), values, indexToWorld);
    this->Transfer = TransferFunction::Grey({ { 0.0, 0.0 }, { 1.0, 1.0 } });
    this->Transfer.OpacityUnitDistance = 1.0 / 16;
    this->Caster.Grid = this->Grid.get();
    this->Caster.Transfer = &this->Transfer;
  }
};

// Mean |DSM - ground truth| over points on a line through the ball, away from the light.
double MeanError(const Ball& ball, const Light& light, int mapSize)
{
  ShadowParameters p;
  p.Kind = ShadowKind::DeepShadowMap;
  p.MapSize = mapSize;
  p.Epsilon = 0.005;
  p.Layers = 16;
  const double step = 1.0 / 64;
  const auto map = MakeLightShadow(p, ball.Caster, light, step, 2);
  const auto truth = MakeLightShadow(ShadowParameters::GroundTruth(false, 1.0), ball.Caster, light, step);
  const glm::dvec3 centre = glm::dvec3(ball.Grid->GetIndexToWorld() * glm::dvec4(8.0, 8.0, 8.0, 1.0));
  double error = 0.0;
  int count = 0;
  for (int n = -7; n <= 7; ++n)
  {
    const glm::dvec3 p0 = centre + glm::dvec3(0.06 * n, 0.03 * n, 0.05 * n);
    error += std::abs(map->Visibility(p0).r - truth->Visibility(p0).r);
    ++count;
  }
  return error / count;
}
}

TEST(LightSpace, FacesCoverTheBoundingSphereFromEveryKindOfLight)
{
  const glm::dvec3 centre(1.0, 2.0, 3.0);
  const double radius = 5.0;
  Light directional;
  directional.Position = { 1, 1, 1 };
  Light outside;
  outside.Positional = true;
  outside.Position = centre + glm::dvec3(0.0, 30.0, 10.0);
  Light inside = outside;
  inside.Position = centre + glm::dvec3(1.0, 0.0, 0.0);
  Light far = outside;
  far.Position = centre + glm::dvec3(0.0, 0.0, 2.0 * FarLightRadii * radius);
  EXPECT_EQ(ShadowMapFaces(directional, centre, radius).size(), 1u);
  EXPECT_EQ(ShadowMapFaces(outside, centre, radius).size(), 1u);
  EXPECT_EQ(ShadowMapFaces(inside, centre, radius).size(), 6u);
  ASSERT_EQ(ShadowMapFaces(far, centre, radius).size(), 1u);
  EXPECT_FALSE(ShadowMapFaces(far, centre, radius)[0].Perspective);
  EXPECT_TRUE(ShadowMapFaces(outside, centre, radius)[0].Perspective);
  for (const Light& light : { directional, outside, inside, far })
  {
    const auto faces = ShadowMapFaces(light, centre, radius);
    for (int n = 0; n < 500; ++n)
    {
      const double a = 0.1 * n, b = 0.37 * n;
      const glm::dvec3 p = centre + radius * glm::dvec3(std::cos(a) * std::sin(b), std::sin(a) * std::sin(b), std::cos(b));
      const int f = ShadowMapFaceFor(faces, p - faces[0].Origin);
      double u, v, depth;
      ASSERT_TRUE(faces[f].Project(p, u, v, depth));
      EXPECT_LE(std::abs(u), 1.0 + 1e-9);
      EXPECT_LE(std::abs(v), 1.0 + 1e-9);
      // Depths start at the face's near boundary: within [0, 2.02 radii] for one face.
      EXPECT_GE(depth, -1e-9);
      if (faces.size() == 1)
      {
        EXPECT_LE(depth, 2.03 * radius);
      }
      glm::dvec3 origin, direction;
      faces[f].TexelRay(u, v, origin, direction);
      EXPECT_NEAR(glm::length(origin + depth * direction - p), 0.0, 1e-9 * (1.0 + glm::length(p - faces[0].Origin)));
    }
  }
}

TEST(LightSpace, DepthPrecisionHoldsForNearFarRatiosOfAMillion)
{
  // Near/far = 1e-6: a positional light 1e-6 from the volume's face, inside its bounding
  // sphere (a cube of faces), lighting points up to ~1.7 away.
  const Ball near(glm::dvec3(0.0));
  Light touching;
  touching.Positional = true;
  touching.Position = { 0.5, 0.5, -1e-6 };
  // Near/far = 1 - 1e-6: a positional light a million radii away (orthographic), and one
  // just inside the far rule (perspective, depths from its near sphere).
  const Ball far(glm::dvec3(3e5, -2e5, 1e5));
  const glm::dvec3 farCentre = far.Grid->GetIndexToWorld() * glm::dvec4(8.0, 8.0, 8.0, 1.0);
  Light million = touching;
  million.Position = farCentre + glm::dvec3(0.0, 0.0, 1e6);
  Light perspective = touching;
  perspective.Position = farCentre + glm::dvec3(0.0, 0.0, 0.8 * FarLightRadii);
  const Light directional = [] {
    Light l;
    l.Position = { 0.0, 0.0, 1.0 };
    return l;
  }();
  // The same ball lit from the same direction: the errors are those of the technique, not of
  // where the light is.
  const double reference = MeanError(far, directional, 64);
  EXPECT_LT(reference, 0.02);
  EXPECT_LT(MeanError(far, million, 64), reference + 0.005);
  EXPECT_LT(MeanError(far, perspective, 64), reference + 0.005);
  EXPECT_LT(MeanError(near, touching, 64), 0.03);
}
