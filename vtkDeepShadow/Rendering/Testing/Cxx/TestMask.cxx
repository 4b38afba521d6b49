// Binary masks and label maps (vtkGPUVolumeRayCastMapper::SetMaskInput), drawn as VTK's
// mapper draws them and cast into every shadow technique.
//
// 1. The comparison volume with a mask that keeps a ball and the half x < 0 of the slab,
//    shaded, drawn by our mapper and by VTK's in one run, within a tolerance calibrated on VTK
//    against itself (CalibrateOnVTK); ours without the mask must fail it; the GPU picture
//    must match its CPU twin.
//    The same mask under MIP, average and additive blending: VTK skips what a binary mask
//    clears in every blend mode, and so do we (against VTK, the twin; without: must fail).
//    MinIP against a closed relation (VTK draws a ray with nothing kept at the range's top).
// 2. The shadow scene (a dense ball over a plate) with a mask that clears the ball: the
//    plate's shadow term where the ball's shadow was gets the light, since what the mask
//    clears casts nothing, and drops nowhere; every technique's picture matches its CPU twin
//    with a mask that keeps half of the ball.
// 3. Label maps against VTK's mapper in one run (shaded): labels 1 and 2 with their own colour
//    and opacity functions, at mask blend factors 1 and 0.5, and a mask whose range is not
//    [0, N] (VTK maps labels over the mask's range); ours drawing it as a binary mask must
//    fail; the GPU matches its CPU twin. A label map without labels draws the volume
//    unmasked, as VTK's. In the shadow scene, the ball labelled clear casts no shadow, and
//    every technique matches its twin under a label map.
#include "DeepShadowTestUtilities.h"

#include "vtkGPUVolumeRayCastMapper.h"

#include <functional>

using deepshadow::testing::Check;
using deepshadow::testing::Grab;
using deepshadow::testing::Mirrored;
using deepshadow::testing::MirroredFunctions;
using deepshadow::testing::WithinTolerance;

namespace
{
// An unsigned char mask of `image`'s grid: `label` (at normalized coordinates in [-1, 1]^3).
vtkSmartPointer<vtkImageData> MakeLabels(vtkImageData* image, const std::function<int(double, double, double)>& label)
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
        v[i + dims[0] * (j + dims[1] * k)] = static_cast<unsigned char>(label(x, y, z));
      }
  return mask;
}

// A binary mask: 1 where `keep` says so, else 0.
vtkSmartPointer<vtkImageData> MakeMask(vtkImageData* image, const std::function<bool(double, double, double)>& keep)
{
  return MakeLabels(image, [&](double x, double y, double z) { return keep(x, y, z) ? 1 : 0; });
}

using Drawn = deepshadow::testing::ComparisonPicture;

// `labelled`: the property of a label map (else the mask is binary), unless `binary`.
Drawn Draw(vtkRenderWindow* window, vtkImageData* data, vtkImageData* mask, bool vtks, float step = 0.5f,
  bool jitter = false, vtkVolumeProperty* labelled = nullptr, float blend = 1.0f,
  int blendMode = vtkVolumeMapper::COMPOSITE_BLEND, bool binary = false)
{
  deepshadow::testing::ComparisonMappers mappers;
  vtkGPUVolumeRayCastMapper* mapper = mappers.Pick(vtks, step, jitter);
  mapper->SetBlendMode(blendMode);
  mapper->SetMaskInput(mask);
  mapper->SetMaskType(labelled && !binary ? vtkGPUVolumeRayCastMapper::LabelMapMaskType
                                          : vtkGPUVolumeRayCastMapper::BinaryMaskType);
  mapper->SetMaskBlendFactor(blend);
  return deepshadow::testing::DrawForComparison(window, mapper, data,
    labelled ? labelled : deepshadow::testing::MakeComparisonProperty(true).GetPointer(), { 0.1, 0.1, 0.15 }, !vtks);
}

// The comparison property with labels 1 (red, denser) and 2 (its own opacity, the volume's colour).
vtkSmartPointer<vtkVolumeProperty> LabelledProperty()
{
  vtkSmartPointer<vtkVolumeProperty> property = deepshadow::testing::MakeComparisonProperty(true);
  vtkNew<vtkColorTransferFunction> red;
  red->AddRGBPoint(0, 0.3, 0.0, 0.0);
  red->AddRGBPoint(255, 1.0, 0.2, 0.1);
  vtkNew<vtkPiecewiseFunction> dense;
  dense->AddPoint(0, 0.0);
  dense->AddPoint(10, 0.0);
  dense->AddPoint(255, 0.6);
  vtkNew<vtkPiecewiseFunction> faint;
  faint->AddPoint(0, 0.0);
  faint->AddPoint(100, 0.0);
  faint->AddPoint(255, 0.08);
  property->SetLabelColor(1, red);
  property->SetLabelScalarOpacity(1, dense);
  property->SetLabelScalarOpacity(2, faint);
  return property;
}

bool LabelMapMatchesVTK(vtkRenderWindow* window, vtkImageData* data, vtkImageData* labels, float blend,
  const std::string& what)
{
  bool ok = true;
  const auto property = LabelledProperty();
  const Drawn ours = Draw(window, data, labels, false, 0.5f, false, property, blend);
  const Drawn vtks = Draw(window, data, labels, true, 0.5f, false, property, blend);
  const deepshadow::testing::VTKTolerance tolerance = deepshadow::testing::CalibrateOnVTK(what, vtks.Picture,
    [&](float scale, bool jitter) { return Draw(window, data, labels, true, 0.5f * scale, jitter, property, blend).Picture; });
  ok = WithinTolerance(what.c_str(), ours.Picture, vtks.Picture, tolerance.MaxRMSE, 8.0 / 255.0, tolerance.MaxFraction) && ok;
  ok = WithinTolerance((what + " vs CPU twin").c_str(), ours.Picture, ours.Twin, 1.5 / 255.0, 8.0 / 255.0, 0.005) && ok;
  ok = !WithinTolerance((what + ", ours as a binary mask (must fail)").c_str(),
         Draw(window, data, labels, false).Picture, vtks.Picture, tolerance.MaxRMSE, 8.0 / 255.0, tolerance.MaxFraction) &&
    ok;
  return ok;
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

    // Projections skip what the mask clears, as VTK's mapper does in every blend mode.
    for (const auto& [mode, name] : { std::make_pair(vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND, "MIP"),
           std::make_pair(vtkVolumeMapper::AVERAGE_INTENSITY_BLEND, "average"),
           std::make_pair(vtkVolumeMapper::ADDITIVE_BLEND, "additive") })
    {
      const std::string projected = what + ", " + name;
      const int blend = mode;
      const Drawn oursProjected = Draw(window, data, mask, false, 0.5f, false, nullptr, 1.0f, blend);
      const Drawn vtksProjected = Draw(window, data, mask, true, 0.5f, false, nullptr, 1.0f, blend);
      const deepshadow::testing::VTKTolerance projectedTolerance =
        deepshadow::testing::CalibrateOnVTK(projected, vtksProjected.Picture, [&](float scale, bool jitter) {
          return Draw(window, data, mask, true, 0.5f * scale, jitter, nullptr, 1.0f, blend).Picture;
        });
      ok = WithinTolerance(projected.c_str(), oursProjected.Picture, vtksProjected.Picture,
             projectedTolerance.MaxRMSE, 8.0 / 255.0, projectedTolerance.MaxFraction) && ok;
      ok = WithinTolerance((projected + " vs CPU twin").c_str(), oursProjected.Picture, oursProjected.Twin,
             1.5 / 255.0, 8.0 / 255.0, 0.005) && ok;
      ok = !WithinTolerance((projected + ", ours without it (must fail)").c_str(),
             Draw(window, data, nullptr, false, 0.5f, false, nullptr, 1.0f, blend).Picture, vtksProjected.Picture,
             projectedTolerance.MaxRMSE, 8.0 / 255.0, projectedTolerance.MaxFraction) && ok;
    }
    // The minimum: VTK's mapper draws a ray whose every sample is masked with the colour and
    // opacity of the range's top (its minimum starts there), where ours draws nothing. So:
    // the mirrored volume's (v -> 255 - v, functions mirrored) minimum under the mask is the
    // original's maximum under it, which matches VTK's above.
    {
      const std::string projected = what + ", MinIP of the mirror";
      const auto mirrored = Mirrored(data);
      const auto mirroredFunctions =
        MirroredFunctions(deepshadow::testing::MakeComparisonProperty(false), 1);
      const Drawn minimum = Draw(window, mirrored, mask, false, 0.5f, false, mirroredFunctions, 1.0f,
        vtkVolumeMapper::MINIMUM_INTENSITY_BLEND, true);
      const Drawn maximum =
        Draw(window, data, mask, false, 0.5f, false, nullptr, 1.0f, vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND);
      ok = WithinTolerance((projected + " vs the original's MIP").c_str(), minimum.Picture, maximum.Picture, 0.004,
             8.0 / 255.0, 0.002) && ok;
      ok = WithinTolerance((projected + " vs CPU twin").c_str(), minimum.Picture, minimum.Twin, 1.5 / 255.0,
             8.0 / 255.0, 0.005) && ok;
      ok = !WithinTolerance((projected + ", without the mask (must fail)").c_str(),
             Draw(window, mirrored, nullptr, false, 0.5f, false, mirroredFunctions, 1.0f,
               vtkVolumeMapper::MINIMUM_INTENSITY_BLEND, true).Picture,
             maximum.Picture, 0.004, 8.0 / 255.0, 0.002) && ok;
    }
  }

  {
    vtkNew<vtkDeepShadowRenderWindow> window;
    window->SetSize(200, 200);
    vtkSmartPointer<vtkImageData> data = deepshadow::testing::MakeTestVolume(VTK_UNSIGNED_CHAR);
    // Label 1: a ball; label 2: the half x < 0 outside it; 0 elsewhere (the mask's range [0, 2]).
    const auto labels = MakeLabels(data, [](double x, double y, double z) {
      return x * x + y * y + z * z < 0.3 ? 1 : x < 0.0 ? 2 : 0;
    });
    ok = LabelMapMatchesVTK(window, data, labels, 1.0f, "label map") && ok;
    ok = LabelMapMatchesVTK(window, data, labels, 0.5f, "label map, blend factor 0.5") && ok;
    // Labels 0, 1 and 3 with functions for 1 and 2: VTK 9.1 maps the mask's range [0, 3] onto
    // the labels 0..2 (1 -> 0, 3 -> 2), VTK 9.2 onwards [0, 2] (1 -> 1, 3 -> 2), and so do we.
    const auto spread = MakeLabels(data, [](double x, double y, double z) {
      return x * x + y * y + z * z < 0.3 ? 3 : x < 0.0 ? 1 : 0;
    });
    ok = LabelMapMatchesVTK(window, data, spread, 1.0f, "label map over a mask of range [0, 3]") && ok;
    // No label functions: the volume as if unmasked, as VTK's.
    const Drawn plain = Draw(window, data, nullptr, false);
    const auto noLabels = deepshadow::testing::MakeComparisonProperty(true);
    ok = WithinTolerance("a label map without labels vs no mask", Draw(window, data, labels, false, 0.5f, false,
                           noLabels).Picture, plain.Picture, 0.0005, 8.0 / 255.0, 0.0) && ok;
  }

  // Shadows: the volume's shadow term, where the ball's shadow falls on the plate.
  deepshadow::testing::ShadowScene scene;
  scene.Mapper->SetMaskTypeToBinary();
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

  // A label map in the shadow scene: the ball labelled clear (label 1, opacity 0) casts no
  // shadow onto the plate (label 0, the volume's functions).
  scene.Mapper->SetMaskTypeToLabelMap();
  vtkNew<vtkPiecewiseFunction> clear;
  clear->AddPoint(0.0, 0.0);
  clear->AddPoint(255.0, 0.0);
  scene.Property->SetLabelScalarOpacity(1, clear);
  scene.Mapper->SetMaskInput(MakeLabels(scene.Data, [&](double x, double y, double z) { return ball(x, y, z) ? 1 : 0; }));
  scene.Mapper->SetOutputModeToShadowTerm();
  scene.Mapper->SetShadowTechnique(dsm);
  scene.Window->Render();
  const deepshadow::Image labelledClear = Grab(scene.Window);
  ok = Check("composed with LabelMap", deepshadow::testing::HasFeature(scene.Mapper, "LabelMap")) && ok;
  const double labelledTerm = darkest >= 0 ? labelledClear.At(darkest % plain.Width, darkest / plain.Width).x : 0.0;
  std::printf("the plate's darkest term with the ball labelled clear %.3f\n", labelledTerm);
  ok = Check("a label's opacity casts: the ball labelled clear casts no shadow", labelledTerm > darkestTerm + 0.5) && ok;
  scene.Mapper->SetOutputModeToColor();
  // The ball half dense (label 1 at the volume's opacity x 2), the twins compared.
  vtkNew<vtkPiecewiseFunction> dense;
  dense->AddPoint(0.0, 0.0);
  dense->AddPoint(255.0, 0.9);
  scene.Property->SetLabelScalarOpacity(1, dense);
  scene.Mapper->SetMaskInput(
    MakeLabels(scene.Data, [&](double x, double y, double z) { return ball(x, y, z) && x < -0.1 ? 1 : 0; }));
  ok = scene.AllMatchTwins("label map") && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
