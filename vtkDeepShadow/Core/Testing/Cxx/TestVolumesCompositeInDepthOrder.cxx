// Along a view ray, every volume's samples and the meshes' crossings are composited in depth
// order (deepshadow::ReferenceRenderer): overlapping volumes interleave, whatever their order
// in the scene; a translucent mesh inside any volume sits between the samples around it; and
// Scene::VolumeSegments, the twin of the GPU's segments, is exact where the volumes do not
// overlap along a ray and converges where they do. Meshes have a shadow term too.
#include "Core/ReferenceRenderer.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>

using namespace deepshadow;

namespace
{
// An unshaded slab over x, y in [-5, 5], z in [z0, z0 + depth] (unit spacing) that emits
// `color` with `opacity` per unit distance everywhere.
VolumeInstance Slab(double z0, int depth, const glm::dvec3& color, double opacity)
{
  std::vector<float> values(11 * 11 * (depth + 1), 1.0f);
  values[0] = 0.0f; // a finite range; colour and opacity are the same for every value
  VolumeInstance volume;
  volume.Grid = std::make_shared<VolumeGrid>(glm::ivec3(11, 11, depth + 1), values,
    glm::translate(glm::dmat4(1.0), glm::dvec3(-5.0, -5.0, z0)));
  volume.Transfer = TransferFunction::Grey({ { 0.0, opacity }, { 1.0, opacity } });
  volume.Transfer.Red = PiecewiseLinear({ { 0.0, color.r }, { 1.0, color.r } });
  volume.Transfer.Green = PiecewiseLinear({ { 0.0, color.g }, { 1.0, color.g } });
  volume.Transfer.Blue = PiecewiseLinear({ { 0.0, color.b }, { 1.0, color.b } });
  return volume;
}

SurfaceMesh Square(double z, double opacity, const glm::dvec3& color)
{
  SurfaceMesh mesh;
  mesh.Points = { { -5.0, -5.0, z }, { 5.0, -5.0, z }, { 5.0, 5.0, z }, { -5.0, 5.0, z } };
  mesh.Triangles = { { 0, 1, 2 }, { 0, 2, 3 } };
  mesh.Colors = { color, color, color, color };
  mesh.Material.Opacity = opacity;
  mesh.Material.Shading = Material{ 1.0, 0.0, 0.0, 1.0 }; // ambient only: its own colour
  return mesh;
}

// An orthographic camera looking down -z at the slabs, 4 x 4 pixels over x, y in [-2, 2].
Scene Above()
{
  Scene scene;
  const glm::dmat4 view =
    glm::lookAt(glm::dvec3(0.0, 0.0, 50.0), glm::dvec3(0.0), glm::dvec3(0.0, 1.0, 0.0));
  scene.View = Camera(glm::ortho(-2.0, 2.0, -2.0, 2.0, 1.0, 100.0) * view, 4, 4);
  return scene;
}

const glm::dvec3 Red{ 1.0, 0.0, 0.0 };
const glm::dvec3 Blue{ 0.0, 0.0, 1.0 };
const glm::dvec3 Green{ 0.0, 1.0, 0.0 };

double MaxDifference(const Image& a, const Image& b)
{
  return Compare(a, b).MaxAbs;
}
}

TEST(VolumesCompositeInDepthOrder, OverlappingVolumesInterleaveWhateverTheirOrder)
{
  // Blue over z in [5.3, 15.3] reaches into red over [0, 10] (not on the same sample depths).
  Scene scene = Above();
  scene.Volumes = { Slab(0.0, 10, Red, 0.15), Slab(5.3, 10, Blue, 0.15) };
  const Image redFirst = ReferenceRenderer::Render(scene, MarchSettings{}, 2);
  std::swap(scene.Volumes[0], scene.Volumes[1]);
  const Image blueFirst = ReferenceRenderer::Render(scene, MarchSettings{}, 2);
  EXPECT_LT(MaxDifference(redFirst, blueFirst), 1e-12);
  // Blue is nearer, so it shows more than red. Drawing each alone and blending them in
  // the scene order {blue, red} would put red in front: the test tells the two apart.
  const glm::dvec3 pixel = redFirst.At(1, 1);
  EXPECT_GT(pixel.b, pixel.r + 0.1);
  Scene alone = scene;
  alone.Volumes = { scene.Volumes[0] };
  const glm::dvec3 blue = ReferenceRenderer::Render(alone, MarchSettings{}, 2).At(1, 1);
  alone.Volumes = { scene.Volumes[1] };
  const glm::dvec3 red = ReferenceRenderer::Render(alone, MarchSettings{}, 2).At(1, 1);
  const glm::dvec3 redOverBlue = red + (1.0 - red.r) * blue; // red's opacity is its red
  EXPECT_GT(redOverBlue.r, redOverBlue.b + 0.1);
}

TEST(VolumesCompositeInDepthOrder, AGlassInsideTheSecondVolumeSitsBetweenItsSamples)
{
  // A green glass at z = 10 halves what the lower half of the blue slab [5, 15] shows,
  // and not its upper half; the red slab [-20, -10] is behind everything.
  Scene scene = Above();
  scene.Volumes = { Slab(-20.0, 10, Red, 0.1), Slab(5.0, 10, Blue, 0.1) };
  scene.Surfaces = std::make_shared<const SurfaceSet>(std::vector<SurfaceMesh>{ Square(10.0, 0.5, Green) });
  const Image image = ReferenceRenderer::Render(scene, MarchSettings{}, 2);
  const double half = 1.0 - std::pow(0.9, 5.0); // opacity of five unit samples
  const double blue = half + (1.0 - half) * 0.5 * half;
  const double green = (1.0 - half) * 0.5;
  const double red = (1.0 - half) * 0.5 * (1.0 - half) * (1.0 - std::pow(0.9, 10.0));
  EXPECT_NEAR(image.At(1, 1).b, blue, 1e-9);
  EXPECT_NEAR(image.At(1, 1).g, green, 1e-9);
  EXPECT_NEAR(image.At(1, 1).r, red, 1e-9);
  std::swap(scene.Volumes[0], scene.Volumes[1]);
  EXPECT_LT(MaxDifference(image, ReferenceRenderer::Render(scene, MarchSettings{}, 2)), 1e-12);
}

TEST(VolumesCompositeInDepthOrder, SegmentsAreExactWhereVolumesDoNotOverlap)
{
  // The second volume (blue, in front) in one segment: it is all before the glass and the
  // first volume, so its place among them is right.
  Scene scene = Above();
  scene.Volumes = { Slab(0.0, 4, Red, 0.2), Slab(6.0, 4, Blue, 0.2) };
  scene.Surfaces = std::make_shared<const SurfaceSet>(std::vector<SurfaceMesh>{ Square(5.0, 0.5, Green) });
  const Image exact = ReferenceRenderer::Render(scene, MarchSettings{}, 2);
  for (int segments : { 1, 3, 8 })
  {
    scene.VolumeSegments = segments;
    EXPECT_LT(MaxDifference(exact, ReferenceRenderer::Render(scene, MarchSettings{}, 2)), 1e-12)
      << segments << " segments";
  }
}

TEST(VolumesCompositeInDepthOrder, SegmentsConvergeWhereVolumesOverlap)
{
  Scene scene = Above();
  scene.Volumes = { Slab(0.0, 10, Red, 0.15), Slab(5.3, 10, Blue, 0.15) };
  const Image exact = ReferenceRenderer::Render(scene, MarchSettings{}, 2);
  double previous = 1.0;
  for (int segments : { 1, 2, 4 })
  {
    scene.VolumeSegments = segments;
    const double error = MaxDifference(exact, ReferenceRenderer::Render(scene, MarchSettings{}, 2));
    EXPECT_LT(error, previous) << segments << " segments";
    previous = error;
  }
  EXPECT_GT(previous, 0.0);
  // Segments no longer than a sample step hold one sample each: exact again.
  scene.VolumeSegments = 16;
  EXPECT_LT(MaxDifference(exact, ReferenceRenderer::Render(scene, MarchSettings{}, 2)), 1e-12);
}

TEST(VolumesCompositeInDepthOrder, MeshesHaveAShadowTerm)
{
  // A caster slab (invisible, casting 0.1 per unit) over the left half of a white ground.
  Scene scene = Above();
  VolumeInstance caster = Slab(4.0, 10, Red, 0.0);
  caster.Grid = std::make_shared<VolumeGrid>(glm::ivec3(6, 11, 11), std::vector<float>(6 * 11 * 11, 1.0f),
    glm::translate(glm::dmat4(1.0), glm::dvec3(-5.0, -5.0, 4.0)));
  caster.ShadowTransfer = TransferFunction::Grey({ { 0.0, 0.1 }, { 1.0, 0.1 } });
  caster.Shadows = ShadowParameters::GroundTruth();
  scene.Volumes = { caster };
  SurfaceMesh ground = Square(0.0, 1.0, glm::dvec3(1.0));
  ground.Material.Shading = Material{ 0.0, 1.0, 0.0, 1.0 };
  scene.Surfaces = std::make_shared<const SurfaceSet>(std::vector<SurfaceMesh>{ ground });
  Light light;
  light.Position = { 0.0, 0.0, 100.0 };
  light.FocalPoint = { 0.0, 0.0, 0.0 };
  light.Specular = glm::dvec3(0.0);
  scene.Lights = { light };
  Image term;
  ReferenceRenderer::Render(scene, MarchSettings{}, 2, &term);
  EXPECT_NEAR(term.At(0, 1).r, std::pow(0.9, 10.0), 1e-6); // x = -1.5: under the caster
  EXPECT_NEAR(term.At(3, 1).r, 1.0, 1e-9);                 // x = 1.5: in the open
  MarchSettings termOnly;
  termOnly.Output = RenderOutput::ShadowTerm;
  EXPECT_LT(MaxDifference(term, ReferenceRenderer::Render(scene, termOnly, 2)), 1e-12);
}
