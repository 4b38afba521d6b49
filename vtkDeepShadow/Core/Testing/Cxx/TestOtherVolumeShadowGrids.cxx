// Several volumes in one scene (deepshadow::ReferenceRenderer): every volume with a technique
// casts shadows onto the other volumes and onto the meshes, a light's visibility is the
// product of every caster's (Beer-Lambert: optical depths add along the light ray), and the
// casting meshes count once however many volumes there are.
#include "Core/ReferenceRenderer.h"
#include "Core/Shadows/ShadowGrid.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>

using namespace deepshadow;

namespace
{
constexpr double OpacityA = 0.1; // per unit distance: (1 - 0.1)^10 through 10 units
constexpr double OpacityB = 0.2;

// 11^3 points spanning [x0, x0 + 10] x [-5, 5] x [z0, z0 + 10]; invisible (drawn opacity 0),
// casting `opacity` per unit distance with ground-truth rays.
VolumeInstance Caster(double x0, double z0, double opacity)
{
  std::vector<float> values(11 * 11 * 11, 1.0f);
  values[0] = 0.0f; // a finite range; the opacity is the same for every value
  VolumeInstance volume;
  volume.Grid = std::make_shared<VolumeGrid>(glm::ivec3(11), values,
    glm::translate(glm::dmat4(1.0), glm::dvec3(x0, -5.0, z0)));
  volume.Transfer = TransferFunction::Grey({ { 0.0, 0.0 }, { 1.0, 0.0 } });
  volume.ShadowTransfer = TransferFunction::Grey({ { 0.0, opacity }, { 1.0, opacity } });
  volume.Shadows = ShadowParameters::GroundTruth();
  return volume;
}

// A thin opaque white slab at z in [0, 1] over x in [-5, 27]: it receives (lit isotropically:
// its pixel seen from above is the visibility at its top) and casts nothing.
VolumeInstance Receiver()
{
  std::vector<float> values(33 * 11 * 2, 1.0f);
  VolumeInstance volume;
  volume.Grid = std::make_shared<VolumeGrid>(glm::ivec3(33, 11, 2), values,
    glm::translate(glm::dmat4(1.0), glm::dvec3(-5.0, -5.0, 0.0)));
  volume.Transfer = TransferFunction::Grey({ { 0.0, 1.0 }, { 1.0, 1.0 } });
  volume.Transfer.Red = volume.Transfer.Green = volume.Transfer.Blue = volume.Transfer.Opacity; // white
  volume.ShadowTransfer = TransferFunction::Grey({ { 0.0, 0.0 }, { 1.0, 0.0 } });
  volume.Shadows = ShadowParameters::GroundTruth();
  volume.Surface.Ambient = 0.0;
  volume.Surface.Diffuse = 1.0;
  return volume;
}

SurfaceMesh Square(double z, double opacity)
{
  SurfaceMesh mesh;
  mesh.Points = { { -5.0, -5.0, z }, { 27.0, -5.0, z }, { 27.0, 5.0, z }, { -5.0, 5.0, z } };
  mesh.Triangles = { { 0, 1, 2 }, { 0, 2, 3 } };
  mesh.Material.Opacity = opacity;
  mesh.Material.Shading = Material{ 0.0, 1.0, 0.0, 1.0 };
  return mesh;
}

// Casters A over x in [0, 10] and B over x in [12, 22], both at z in [4, 14]; light from above;
// an orthographic camera from above, 32 pixels a unit apart over x in [-5, 27].
Scene TwoCasters()
{
  Scene scene;
  Light light;
  light.Position = { 0.0, 0.0, 100.0 };
  light.FocalPoint = { 0.0, 0.0, 0.0 };
  light.Specular = glm::dvec3(0.0);
  scene.Lights = { light };
  const glm::dmat4 view = glm::lookAt(glm::dvec3(11.0, 0.0, 50.0), glm::dvec3(11.0, 0.0, 0.0), glm::dvec3(0.0, 1.0, 0.0));
  scene.View = Camera(glm::ortho(-16.0, 16.0, -2.0, 2.0, 1.0, 100.0) * view, 32, 4);
  scene.Volumes = { Caster(0.0, 4.0, OpacityA), Caster(12.0, 4.0, OpacityB) };
  return scene;
}

// Pixel columns over x = 5 (under A), 17 (under B) and 11 (between them).
double At(const Image& image, double x)
{
  return image.At(static_cast<int>(x + 16.0 - 11.0), 2).r;
}

const double UnderA = std::pow(1.0 - OpacityA, 10.0);
const double UnderB = std::pow(1.0 - OpacityB, 10.0);
}

TEST(VolumesShadowEachOther, AVolumeReceivesFromEveryOtherVolume)
{
  Scene scene = TwoCasters();
  scene.Volumes.push_back(Receiver());
  const Image image = ReferenceRenderer::Render(scene, MarchSettings{}, 2);
  EXPECT_NEAR(At(image, 5.0), UnderA, 1e-6);
  EXPECT_NEAR(At(image, 17.0), UnderB, 1e-6);
  EXPECT_NEAR(At(image, 11.0), 1.0, 1e-6);
}

TEST(VolumesShadowEachOther, OverlappingCastersMultiply)
{
  // B moved under A: light crosses both, whichever order they come in.
  for (bool swapped : { false, true })
  {
    Scene scene = TwoCasters();
    scene.Volumes[1] = Caster(0.0, 15.0, OpacityB);
    if (swapped)
    {
      std::swap(scene.Volumes[0], scene.Volumes[1]);
    }
    scene.Volumes.push_back(Receiver());
    const Image image = ReferenceRenderer::Render(scene, MarchSettings{}, 2);
    EXPECT_NEAR(At(image, 5.0), UnderA * UnderB, 1e-6) << "swapped " << swapped;
    EXPECT_NEAR(At(image, 17.0), 1.0, 1e-6);
  }
}

TEST(VolumesShadowEachOther, MeshesReceiveFromEveryVolumeAndCastOnce)
{
  for (bool swapped : { false, true })
  {
    Scene scene = TwoCasters();
    if (swapped)
    {
      std::swap(scene.Volumes[0], scene.Volumes[1]);
    }
    // A grey glass above both casters lets half the light through, once.
    scene.Surfaces = std::make_shared<const SurfaceSet>(std::vector<SurfaceMesh>{ Square(0.0, 1.0), Square(20.0, 0.5) });
    scene.CastingSurfaces = std::make_shared<const SurfaceSet>(std::vector<SurfaceMesh>{ Square(20.0, 0.5) });
    // Seen from above: the lit glass (white, fully lit: 0.5 of the pixel) over the ground,
    // which the glass lets half the light onto, and each volume what it lets through.
    const Image image = ReferenceRenderer::Render(scene, MarchSettings{}, 2);
    const auto seen = [](double ground) { return 0.5 * 1.0 + 0.5 * (0.5 * ground); };
    EXPECT_NEAR(At(image, 5.0), seen(UnderA), 1e-6) << "swapped " << swapped;
    EXPECT_NEAR(At(image, 17.0), seen(UnderB), 1e-6) << "swapped " << swapped;
    EXPECT_NEAR(At(image, 11.0), seen(1.0), 1e-6) << "swapped " << swapped;
  }
}

TEST(VolumesShadowEachOther, TheGpuTwinsGridsMatchTheExactProduct)
{
  for (bool meshReceives : { false, true })
  {
    Scene scene = TwoCasters();
    if (meshReceives)
    {
      scene.Surfaces = std::make_shared<const SurfaceSet>(std::vector<SurfaceMesh>{ Square(0.0, 1.0) });
    }
    else
    {
      scene.Volumes.push_back(Receiver());
    }
    const Image exact = ReferenceRenderer::Render(scene, MarchSettings{}, 2);
    scene.OtherVolumeShadowSize = 64;
    const Image grids = ReferenceRenderer::Render(scene, MarchSettings{}, 2);
    // Away from the shadows' edges (a node spacing wide) the product is smooth. A mesh
    // receives A directly (the source) and B from the grid.
    for (double x : { 2.0, 5.0, 8.0, 14.0, 17.0, 20.0 })
    {
      EXPECT_NEAR(At(grids, x), At(exact, x), 1e-3) << "x " << x << " mesh " << meshReceives;
    }
    EXPECT_NEAR(At(grids, 17.0), UnderB, 1e-3);
  }
}

TEST(VolumesShadowEachOther, GridFramesSpanTheirBoxes)
{
  const GridFrame volume = GridFrame::OverVolume(glm::ivec3(101, 51, 1),
    glm::translate(glm::dmat4(1.0), glm::dvec3(1.0, 2.0, 3.0)), 32);
  EXPECT_EQ(volume.Dims, glm::ivec3(32, 16, 2));
  EXPECT_EQ(glm::dvec3(volume.NodeToWorld * glm::dvec4(31.0, 15.0, 0.0, 1.0)), glm::dvec3(101.0, 52.0, 3.0));
  const GridFrame flat = GridFrame::OverBox(glm::dvec3(-1.0, 0.0, 2.0), glm::dvec3(3.0, 2.0, 2.0), 64);
  EXPECT_EQ(flat.Dims, glm::ivec3(64, 32, 2));
  const glm::dvec3 node = glm::dvec3(flat.WorldToNode * glm::dvec4(3.0, 2.0, 2.0, 1.0));
  EXPECT_NEAR(node.x, 63.0, 1e-9);
  EXPECT_NEAR(node.y, 31.0, 1e-9);
  EXPECT_NEAR(node.z, 0.5, 1e-9); // the flat side widened around the plane
  const GridFrame empty = GridFrame::OverBox(glm::dvec3(1.0), glm::dvec3(-1.0), 8);
  EXPECT_TRUE(std::isfinite(empty.WorldToNode[0][0]));
}
