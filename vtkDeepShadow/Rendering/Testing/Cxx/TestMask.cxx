// Binary masks (vtkGPUVolumeRayCastMapper::SetMaskInput), drawn as VTK's mapper draws them and
// cast into every shadow technique.
//
// 1. The comparison volume with a mask that keeps a ball and the half x < 0 of the slab,
//    shaded, drawn by our mapper and by VTK's in one run, within a tolerance calibrated on VTK
//    against itself (CalibrateOnVTK); ours without the mask must fail it; the GPU picture
//    must match its CPU twin.
// 2. The shadow scene (a dense ball over a plate) with a mask that clears the ball: the
//    plate's shadow term where the ball's shadow was gets the light, since what the mask
//    clears casts nothing, and drops nowhere; every technique's picture matches its CPU twin
//    with a mask that keeps half of the ball.
#include "DeepShadowTestUtilities.h"

#include "vtkGPUVolumeRayCastMapper.h"

#include <functional>

using deepshadow::testing::Check;
using deepshadow::testing::Grab;
using deepshadow::testing::WithinTolerance;

namespace
{
// An unsigned char mask of `image`'s grid: 1 where `keep` (at normalized coordinates in
// [-1, 1]^3) says so, else 0.
vtkSmartPointer<vtkImageData> MakeMask(vtkImageData* image, const std::function<bool(double, double, double)>& keep)
{
  int dims[3];
  image->GetDimensions(dims);
  auto mask = vtkSmartPointer<vtkImageData>::New();
  mask->SetDimensions(dims);
  mask->SetSpacing(image->GetSpacing());
  mask->SetOrigin(image->GetOrigin());
  mask->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  auto* v = static_cast<unsigned char*>(mask->GetScalarPointer());
  for (int k = 0; k < dims[2]; ++k)
    for (int j = 0; j < dims[1]; ++j)
      for (int i = 0; i < dims[0]; ++i)
      {
        const double x = 2.0 * i / (dims[0] - 1) - 1.0, y = 2.0 * j / (dims[1] - 1) - 1.0,
                     z = 2.0 * k / (dims[2] - 1) - 1.0;
        v[i + dims[0] * (j + dims[1] * k)] = keep(x, y, z) ? 1 : 0;
      }
  return mask;
}

using Drawn = deepshadow::testing::ComparisonPicture;

Drawn Draw(vtkRenderWindow* window, vtkImageData* data, vtkImageData* mask, bool vtks, float step = 0.5f,
  bool jitter = false)
{
  deepshadow::testing::ComparisonMappers mappers;
  vtkGPUVolumeRayCastMapper* mapper = mappers.Pick(vtks, step, jitter);
  mapper->SetMaskInput(mask);
  mapper->SetMaskTypeToBinary();
  return deepshadow::testing::DrawForComparison(
    window, mapper, data, deepshadow::testing::MakeComparisonProperty(true), { 0.1, 0.1, 0.15 }, !vtks);
}
}

int TestMask(int, char*[])
{
  bool ok = true;
  {
    vtkNew<vtkDeepShadowRenderWindow> window;
    window->SetSize(200, 200);
    vtkSmartPointer<vtkImageData> data = deepshadow::testing::MakeTestVolume(VTK_UNSIGNED_CHAR);
    vtkSmartPointer<vtkImageData> mask =
      MakeMask(data, [](double x, double y, double z) { return x < 0.0 || x * x + y * y + z * z < 0.3; });
    const std::string what = "binary mask";
    const Drawn ours = Draw(window, data, mask, false);
    const Drawn vtks = Draw(window, data, mask, true);
    const deepshadow::testing::VTKTolerance tolerance = deepshadow::testing::CalibrateOnVTK(
      what, vtks.Picture, [&](float scale, bool jitter) { return Draw(window, data, mask, true, 0.5f * scale, jitter).Picture; });
    ok = WithinTolerance(what.c_str(), ours.Picture, vtks.Picture, tolerance.MaxRMSE, 8.0 / 255.0,
           tolerance.MaxFraction) && ok;
    ok = WithinTolerance((what + " vs CPU twin").c_str(), ours.Picture, ours.Twin, 1.5 / 255.0, 8.0 / 255.0, 0.005) && ok;
    const Drawn without = Draw(window, data, nullptr, false);
    ok = !WithinTolerance((what + ", ours without it (must fail)").c_str(), without.Picture, vtks.Picture,
           tolerance.MaxRMSE, 8.0 / 255.0, tolerance.MaxFraction) && ok;
  }

  // Shadows: the volume's shadow term, where the ball's shadow falls on the plate.
  deepshadow::testing::ShadowScene scene;
  scene.Mapper->SetOutputModeToShadowTerm();
  vtkSmartPointer<vtkDeepShadowTechnique> dsm = vtkDeepShadowTechniqueFactory::New("dsm");
  scene.Mapper->SetShadowTechnique(dsm);
  scene.Window->Render();
  const deepshadow::Image plain = Grab(scene.Window);
  const int builds = dsm->GetBuildCount();
  // The ball (centre (-0.1, 0, 0.2), radius 0.3 in normalized coordinates) cleared.
  auto ball = [](double x, double y, double z) {
    return (x + 0.1) * (x + 0.1) + y * y + (z - 0.2) * (z - 0.2) < 0.35 * 0.35;
  };
  scene.Mapper->SetMaskInput(MakeMask(scene.Data, [&](double x, double y, double z) { return !ball(x, y, z); }));
  scene.Window->Render();
  const deepshadow::Image cleared = Grab(scene.Window);
  ok = Check("a mask set: the deep shadow map rebuilt", dsm->GetBuildCount() == builds + 1) && ok;
  ok = Check("composed with Mask", deepshadow::testing::HasFeature(scene.Mapper, "Mask")) && ok;
  // The plate's darkest point (the ball's shadow; grey: the term, not the background) gets the
  // light once the ball is cleared, and the plate's term nowhere drops.
  int darkest = -1;
  double darkestTerm = 2.0, drop = 0.0;
  for (int y = 0; y < plain.Height; ++y)
    for (int x = 0; x < plain.Width; ++x)
    {
      const glm::dvec3 before = plain.At(x, y), after = cleared.At(x, y);
      if (std::abs(before.x - before.z) < 1.0 / 255.0 && std::abs(after.x - after.z) < 1.0 / 255.0)
      {
        drop = std::max(drop, before.x - after.x);
        if (before.x < darkestTerm)
        {
          darkestTerm = before.x;
          darkest = x + plain.Width * y;
        }
      }
    }
  const double clearedTerm = darkest >= 0 ? cleared.At(darkest % plain.Width, darkest / plain.Width).x : 0.0;
  std::printf("the plate's darkest term without the mask %.3f, with it %.3f; largest drop %.4f\n", darkestTerm,
    clearedTerm, drop);
  if (const char* directory = std::getenv("DEEPSHADOW_TEST_IMAGES"))
  {
    deepshadow::WritePNG(plain, std::string(directory) + "/mask-term-without.png");
    deepshadow::WritePNG(cleared, std::string(directory) + "/mask-term-with.png");
  }
  ok = Check("what the mask clears casts nothing: the ball's shadow gone",
         darkest >= 0 && clearedTerm > darkestTerm + 0.5 && drop <= 2.0 / 255.0) && ok;
  scene.Mapper->SetOutputModeToColor();

  // The twins compared with half of the ball kept (x < -0.1).
  scene.Mapper->SetMaskInput(
    MakeMask(scene.Data, [&](double x, double y, double z) { return !ball(x, y, z) || x < -0.1; }));
  ok = scene.AllMatchTwins("mask") && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
