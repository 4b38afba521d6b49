// 2D transfer functions (vtkVolumeProperty TF_2D; Core/Transfer2D.h), drawn as VTK's mapper
// draws them and cast into every shadow technique.
//
// 1. The comparison volume under a 2D function (colour along the scalar, opacity along the
//    scalar times a ramp along the gradient magnitude, so that edges show), unshaded and
//    shaded, drawn by our mapper and by VTK's in one run, within a tolerance calibrated on
//    VTK against itself; ours drawing the 1D functions must fail; the GPU matches its CPU
//    twin. A function given as a 64 x 8 image (VTK resizes it to 1024 x 1024) too.
// 2. The shadow scene under a 2D function: every technique matches its CPU twin; a function
//    that leaves the ball (scalar 200) clear while the 1D one does not removes the ball's
//    shadow from the floor.
// 3. What cannot be read is one error: TF_2D without an image, a 3D image.
#include "DeepShadowTestUtilities.h"

#include "vtkFloatArray.h"
#include "vtkGPUVolumeRayCastMapper.h"

#include <functional>

using deepshadow::testing::Check;
using deepshadow::testing::Grab;
using deepshadow::testing::WithinTolerance;

namespace
{
// A `width` x `height` RGBA float image: `rgba(s, g)` at normalized scalar s and magnitude g.
vtkSmartPointer<vtkImageData> MakeFunction2D(
  int width, int height, const std::function<glm::dvec4(double, double)>& rgba)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_FLOAT, 4);
  auto* texels = static_cast<float*>(image->GetScalarPointer());
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i)
    {
      const glm::dvec4 c = rgba(i / (width - 1.0), height > 1 ? j / (height - 1.0) : 0.0);
      for (int k = 0; k < 4; ++k)
      {
        texels[4 * (i + width * j) + k] = static_cast<float>(c[k]);
      }
    }
  return image;
}

// Orange to white along the scalar; opacity from 0.08 up to 0.35, times 0.3 + 0.7 g (edges).
glm::dvec4 EdgeFunction(double s, double g)
{
  const double opacity = s < 0.08 ? 0.0 : 0.35 * (s - 0.08) / 0.92;
  return { 1.0, 0.5 + 0.5 * s, 0.2 + 0.8 * s, opacity * (0.3 + 0.7 * g) };
}

using Drawn = deepshadow::testing::ComparisonPicture;

Drawn Draw(vtkRenderWindow* window, vtkImageData* data, vtkVolumeProperty* property, bool vtks, float step = 0.5f,
  bool jitter = false)
{
  deepshadow::testing::ComparisonMappers mappers;
  return deepshadow::testing::DrawForComparison(
    window, mappers.Pick(vtks, step, jitter), data, property, { 0.1, 0.1, 0.15 }, !vtks);
}

bool MatchesVTK(vtkRenderWindow* window, vtkImageData* function, bool shade, const std::string& what)
{
  bool ok = true;
  vtkSmartPointer<vtkImageData> data = deepshadow::testing::MakeTestVolume(VTK_UNSIGNED_CHAR);
  vtkSmartPointer<vtkVolumeProperty> property = deepshadow::testing::MakeComparisonProperty(shade);
  property->SetTransferFunction2D(function);
  property->SetTransferFunctionMode(vtkVolumeProperty::TF_2D);
  const Drawn ours = Draw(window, data, property, false);
  const Drawn vtks = Draw(window, data, property, true);
  const deepshadow::testing::VTKTolerance tolerance = deepshadow::testing::CalibrateOnVTK(what, vtks.Picture,
    [&](float scale, bool jitter) { return Draw(window, data, property, true, 0.5f * scale, jitter).Picture; });
  ok = WithinTolerance(what.c_str(), ours.Picture, vtks.Picture, tolerance.MaxRMSE, 8.0 / 255.0, tolerance.MaxFraction) && ok;
  ok = WithinTolerance((what + " vs CPU twin").c_str(), ours.Picture, ours.Twin, 1.5 / 255.0, 8.0 / 255.0, 0.005) && ok;
  property->SetTransferFunctionMode(vtkVolumeProperty::TF_1D);
  ok = !WithinTolerance((what + ", ours with the 1D functions (must fail)").c_str(),
         Draw(window, data, property, false).Picture, vtks.Picture, tolerance.MaxRMSE, 8.0 / 255.0,
         tolerance.MaxFraction) && ok;
  return ok;
}
}

int TestTransfer2D(int, char*[])
{
  bool ok = true;
  {
    vtkNew<vtkDeepShadowRenderWindow> window;
    window->SetSize(200, 200);
    const auto function = MakeFunction2D(256, 256, EdgeFunction);
    ok = MatchesVTK(window, function, false, "2D transfer function") && ok;
    ok = MatchesVTK(window, function, true, "2D transfer function, shaded") && ok;
    ok = MatchesVTK(window, MakeFunction2D(64, 8, EdgeFunction), false, "2D transfer function of 64 x 8") && ok;
  }

  // Shadows: the shadow scene's 1D functions as a 2D one (the gradient ignored), then with the
  // ball (200) left clear.
  deepshadow::testing::ShadowScene scene;
  auto fromScene = [&](bool ballClear) {
    return MakeFunction2D(256, 4, [&](double s, double) {
      const double scalar = 200.0 * s; // the shadow volume's range is [0, 200]
      double rgb[3];
      scene.Color->GetColor(scalar, rgb);
      const double opacity = ballClear && scalar > 180.0 ? 0.0 : scene.Opacity->GetValue(scalar);
      return glm::dvec4(rgb[0], rgb[1], rgb[2], opacity);
    });
  };
  scene.Property->SetTransferFunction2D(fromScene(false));
  scene.Property->SetTransferFunctionMode(vtkVolumeProperty::TF_2D);
  ok = scene.AllMatchTwins("2D transfer function") && ok;
  ok = Check("composed with Transfer2D", deepshadow::testing::HasFeature(scene.Mapper, "Transfer2D")) && ok;
  ok = scene.DeepShadowDarkensFloor("the 2D function's ball over the floor") && ok;
  const glm::dvec3 shadowed = deepshadow::testing::ShadowScene::FloorUnderBall(Grab(scene.Window));
  scene.Property->SetTransferFunction2D(fromScene(true));
  scene.Window->Render();
  const glm::dvec3 clear = deepshadow::testing::ShadowScene::FloorUnderBall(Grab(scene.Window));
  std::printf("the floor under the ball: %.3f with the ball in the 2D function, %.3f with it clear\n",
    shadowed.x + shadowed.y + shadowed.z, clear.x + clear.y + clear.z);
  ok = Check("the 2D function's opacity casts: a clear ball casts no shadow",
         clear.x + clear.y + clear.z > 1.5 * (shadowed.x + shadowed.y + shadowed.z)) && ok;

  // What cannot be read: one error each, nothing drawn.
  auto says = [&](vtkImageData* function, const std::string& needle) {
    vtkNew<deepshadow::testing::MessageCapture> capture;
    capture->Watch(scene.Mapper);
    // A fresh property: VTK's SetTransferFunction2D(nullptr) crashes in VTK 9.1.
    vtkNew<vtkVolumeProperty> property;
    property->SetTransferFunctionMode(vtkVolumeProperty::TF_2D);
    if (function)
    {
      property->SetTransferFunction2D(function);
    }
    scene.Volume->SetProperty(property);
    scene.Window->Render();
    const bool heard = capture->ErrorContains(needle);
    std::printf("%s: %s\n", needle.c_str(), heard ? "said" : "NOT SAID");
    return heard;
  };
  ok = Check("TF_2D without an image: one error", says(nullptr, "no 2D transfer function")) && ok;
  // (VTK's property refuses images of other types or components itself, but not a 3D one.)
  auto slab = vtkSmartPointer<vtkImageData>::New();
  slab->SetDimensions(16, 16, 2);
  slab->AllocateScalars(VTK_FLOAT, 4);
  ok = Check("a 16 x 16 x 2 image: one error", says(slab, "16x16x2 image")) && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
