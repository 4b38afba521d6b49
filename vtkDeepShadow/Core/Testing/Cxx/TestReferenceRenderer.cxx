// The CPU reference: closed-form answers on homogeneous media, determinism across threads,
// and the bounded effect of early ray termination.
#include "Core/ReferenceRenderer.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

using namespace deepshadow;

namespace
{
std::shared_ptr<VolumeGrid> ConstantGrid(glm::ivec3 dims, float value, const glm::dmat4& m)
{
  return std::make_shared<VolumeGrid>(
    dims, std::vector<float>(static_cast<size_t>(dims.x) * dims.y * dims.z, value), m);
}

Scene OrthographicScene(int size, std::shared_ptr<VolumeGrid> grid, double alpha)
{
  // Looking down -z at the box [0, 10]^3 through parallel rays.
  const glm::dmat4 view = glm::lookAt(glm::dvec3(5, 5, 30), glm::dvec3(5, 5, 0), glm::dvec3(0, 1, 0));
  const glm::dmat4 projection = glm::ortho(-6.0, 6.0, -6.0, 6.0, 1.0, 100.0);
  Scene scene;
  scene.View = Camera(projection * view, size, size);
  VolumeInstance volume;
  volume.Grid = std::move(grid);
  volume.Transfer = TransferFunction::Grey({ { 0.0, alpha }, { 1.0, alpha } });
  volume.Transfer.Red = volume.Transfer.Green = volume.Transfer.Blue = PiecewiseLinear({ { 0.0, 1.0 } });
  scene.Volumes.push_back(volume);
  return scene;
}
}

TEST(ReferenceRenderer, HomogeneousSlabFollowsBeerLambert)
{
  // 11^3 points spanning [0, 10]: a ray along z crosses 10 world units.
  auto grid = ConstantGrid({ 11, 11, 11 }, 0.5f, glm::dmat4(1.0));
  const Scene scene = OrthographicScene(8, grid, 0.2);
  for (double dt : { 1.0, 0.5, 0.1, 0.01 })
  {
    MarchSettings settings;
    settings.SampleDistance = dt;
    const Ray ray = scene.View.PixelRay(4, 4);
    const glm::dvec4 rgba = ReferenceRenderer::MarchRay(scene, scene.Volumes[0], ReferenceRenderer::Prepare(scene, scene.Volumes[0], settings), ray, 1e300, 0.5, settings);
    const long samples = std::lround(10.0 / dt);
    const double expected = 1.0 - std::pow(1.0 - 0.2, samples * dt);
    EXPECT_NEAR(rgba.a, expected, 1e-12) << "dt " << dt;
    EXPECT_NEAR(rgba.a, 1.0 - std::pow(0.8, 10.0), 1e-12) << "independent of dt when L/dt is whole";
  }
}

TEST(ReferenceRenderer, ScaledVolumesIntegrateOverWorldDistance)
{
  // The same slab scaled by 3 along z is three times as thick in world units.
  auto grid = ConstantGrid({ 11, 11, 11 }, 0.5f, glm::scale(glm::dmat4(1.0), glm::dvec3(1.0, 1.0, 3.0)));
  Scene scene = OrthographicScene(8, grid, 0.05);
  const glm::dmat4 view = glm::lookAt(glm::dvec3(5, 5, 60), glm::dvec3(5, 5, 0), glm::dvec3(0, 1, 0));
  scene.View = Camera(glm::ortho(-6.0, 6.0, -6.0, 6.0, 1.0, 100.0) * view, 8, 8);
  MarchSettings settings;
  settings.SampleDistance = 0.25;
  const glm::dvec4 rgba = ReferenceRenderer::MarchRay(scene, scene.Volumes[0], ReferenceRenderer::Prepare(scene, scene.Volumes[0], settings), scene.View.PixelRay(4, 4), 1e300, 0.5, settings);
  EXPECT_NEAR(rgba.a, 1.0 - std::pow(0.95, 30.0), 1e-12);
}

TEST(ReferenceRenderer, ImagesAreIdenticalForAnyThreadCount)
{
  std::vector<float> values(16 * 16 * 16);
  for (size_t i = 0; i < values.size(); ++i)
  {
    values[i] = static_cast<float>((i * 2654435761u) % 256);
  }
  auto grid = std::make_shared<VolumeGrid>(glm::ivec3(16), values, glm::dmat4(1.0));
  Scene scene = OrthographicScene(32, grid, 0.1);
  scene.Volumes[0].Transfer = TransferFunction::Grey({ { 0.0, 0.0 }, { 255.0, 0.3 } });
  scene.Volumes[0].Shade = true;
  Light light;
  scene.Lights.push_back(light);
  MarchSettings settings;
  settings.SampleDistance = 0.3;
  settings.Jitter = true;
  settings.JitterSeed = 9;
  const Image one = ReferenceRenderer::Render(scene, settings, 1);
  const Image many = ReferenceRenderer::Render(scene, settings, 7);
  EXPECT_EQ(one.RGB, many.RGB);
}

TEST(ReferenceRenderer, EarlyTerminationChangesAtMostTheRemainingTransmittance)
{
  auto grid = ConstantGrid({ 11, 11, 11 }, 0.5f, glm::dmat4(1.0));
  const Scene scene = OrthographicScene(8, grid, 0.9);
  MarchSettings exact, early;
  exact.SampleDistance = early.SampleDistance = 0.05;
  early.TerminationOpacity = DefaultTerminationOpacity;
  const Ray ray = scene.View.PixelRay(4, 4);
  const glm::dvec4 a = ReferenceRenderer::MarchRay(scene, scene.Volumes[0], ReferenceRenderer::Prepare(scene, scene.Volumes[0], exact), ray, 1e300, 0.5, exact);
  const glm::dvec4 b = ReferenceRenderer::MarchRay(scene, scene.Volumes[0], ReferenceRenderer::Prepare(scene, scene.Volumes[0], early), ray, 1e300, 0.5, early);
  EXPECT_GT(b.a, DefaultTerminationOpacity);
  EXPECT_LE(std::abs(a.a - b.a), 1.0 - DefaultTerminationOpacity);
  EXPECT_LE(std::abs(a.r - b.r), 1.0 - DefaultTerminationOpacity);
}

TEST(ReferenceRenderer, RaysMissingTheVolumeShowTheBackground)
{
  auto grid = ConstantGrid({ 11, 11, 11 }, 0.5f, glm::translate(glm::dmat4(1.0), glm::dvec3(100.0)));
  Scene scene = OrthographicScene(8, grid, 0.5);
  scene.Background = { 0.25, 0.5, 0.75 };
  MarchSettings settings;
  const Image image = ReferenceRenderer::Render(scene, settings, 2);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x)
      EXPECT_EQ(image.At(x, y), scene.Background);
}

TEST(ReferenceRenderer, OpacityOneEverywhereSaturatesWithoutNaN)
{
  auto grid = ConstantGrid({ 11, 11, 11 }, 0.5f, glm::dmat4(1.0));
  Scene scene = OrthographicScene(8, grid, 1.0);
  for (double unit : { 1e-4, 1.0, 1e4 })
  {
    scene.Volumes[0].Transfer.OpacityUnitDistance = unit;
    MarchSettings settings;
    settings.SampleDistance = 0.5;
    const glm::dvec4 rgba = ReferenceRenderer::MarchRay(scene, scene.Volumes[0], ReferenceRenderer::Prepare(scene, scene.Volumes[0], settings), scene.View.PixelRay(4, 4), 1e300, 0.5, settings);
    EXPECT_EQ(rgba.a, 1.0);
    EXPECT_TRUE(std::isfinite(rgba.r));
  }
}
