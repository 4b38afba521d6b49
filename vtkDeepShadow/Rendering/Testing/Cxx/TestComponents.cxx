// Volumes of several components per voxel, classified and combined as VTK's mapper does
// (Core/Components.h), and cast into every shadow technique.
//
// 1. Against VTK's mapper in one run, with a tolerance calibrated on VTK against itself
//    (TestGradientOpacity's rule): 2 and 4 independent components (per-component functions,
//    and weights), unshaded and shaded (each component lit with its own gradient); 2
//    dependent components (luminance, opacity) and 4 (RGBA), each component over its own
//    range, and the dependent ones with gradient opacity (component 0's gradient, as VTK).
//    Ours drawing component 0 alone must fail each (and without gradient opacity where it
//    is set); the GPU matches its CPU twin.
// 2. Shadows: the shadow scene's volume as two independent components (the ball in one, the
//    plate and pillar in the other): every technique matches its CPU twin, and the ball's
//    shadow darkens the floor, which lies in the other component.
// 3. Projections (MIP, MinIP, average, additive) over independent and dependent components:
//    against VTK where VTK 9.1 projects as it means to, else against closed relations (a
//    mirrored volume's MinIP is the original's MIP; luminance + opacity of one field twice is
//    that field's projection) and the CPU twin.
// 4. Gradient opacity over independent components, each component's own function at its own
//    gradient: against VTK's mapper where VTK 9.1 applies it as documented (the function on
//    component 0, component 1 clear), else against VTK's picture of the component alone (the
//    function on component 1 alone, which VTK's two-component mapper ignores) and the CPU
//    twin; shadows cast with it, and a hollowed ball casts a lighter shadow.
// 5. 3 dependent components are one error, and so are 5; an isosurface over components is
//    drawn composite, said once.
#include "DeepShadowTestUtilities.h"

#include "vtkGPUVolumeRayCastMapper.h"

using deepshadow::Image;
using deepshadow::testing::Check;
using deepshadow::testing::Grab;
using deepshadow::testing::Mirrored;
using deepshadow::testing::MirroredFunctions;
using deepshadow::testing::WithinTolerance;

namespace
{
using Drawn = deepshadow::testing::ComparisonPicture;

// The test volume's field in component 0 (0..255), and in the others fields of their own:
// a slab across y (component 1, 40..190), a ramp along z (2), a ball off centre (3).
vtkSmartPointer<vtkImageData> MakeComponents(int count, int n = 40)
{
  auto base = deepshadow::testing::MakeTestVolume(VTK_UNSIGNED_CHAR, n);
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->CopyStructure(base);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, count);
  vtkDataArray* in = base->GetPointData()->GetScalars();
  vtkDataArray* out = image->GetPointData()->GetScalars();
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        const vtkIdType id = i + n * (j + static_cast<vtkIdType>(n) * k);
        const double x = 2.0 * i / (n - 1) - 1.0, y = 2.0 * j / (n - 1) - 1.0, z = 2.0 * k / (n - 1) - 1.0;
        const double values[4] = { in->GetComponent(id, 0),
          std::abs(y + 0.2) < 0.15 && std::abs(x) < 0.7 ? 190.0 : 40.0, std::round(127.5 * (z + 1.0)),
          std::sqrt((x - 0.3) * (x - 0.3) + (y - 0.3) * (y - 0.3) + z * z) < 0.35 ? 220.0 : 10.0 };
        for (int c = 0; c < count; ++c)
        {
          out->SetComponent(id, c, values[c]);
        }
      }
  return image;
}

// Component c's colour and opacity: orange (0), blue (1), green (2), white (3), each clear
// at its low end; set as the property's component `target` (c unless given).
void SetComponentFunctions(vtkVolumeProperty* property, int c, int target = -1)
{
  target = target < 0 ? c : target;
  const double colors[4][3] = { { 1.0, 0.5, 0.2 }, { 0.2, 0.4, 1.0 }, { 0.3, 1.0, 0.3 }, { 1.0, 1.0, 1.0 } };
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0, 0.1, 0.1, 0.1);
  color->AddRGBPoint(255, colors[c][0], colors[c][1], colors[c][2]);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0, 0.0);
  opacity->AddPoint(c == 2 ? 150 : 30, 0.0);
  opacity->AddPoint(255, c == 0 ? 0.3 : 0.15);
  property->SetColor(target, color);
  property->SetScalarOpacity(target, opacity);
}

enum class Mode
{
  Independent,
  Weighted, // independent, component 1 at half weight
  LuminanceAlpha,
  RGBA
};

vtkSmartPointer<vtkVolumeProperty> MakeProperty(Mode mode, int count, bool shade)
{
  vtkSmartPointer<vtkVolumeProperty> property = deepshadow::testing::MakeComparisonProperty(shade);
  property->SetIndependentComponents(mode == Mode::Independent || mode == Mode::Weighted);
  if (mode == Mode::Independent || mode == Mode::Weighted)
  {
    for (int c = 0; c < count; ++c)
    {
      SetComponentFunctions(property, c);
      property->SetShade(c, shade);
    }
    if (mode == Mode::Weighted)
    {
      property->SetComponentWeight(1, 0.5);
    }
  }
  return property;
}

Drawn Draw(vtkRenderWindow* window, vtkImageData* data, bool vtks, vtkVolumeProperty* property, float step = 0.5f,
  bool jitter = false, int blend = vtkVolumeMapper::COMPOSITE_BLEND)
{
  deepshadow::testing::ComparisonMappers mappers;
  vtkGPUVolumeRayCastMapper* mapper = mappers.Pick(vtks, step, jitter);
  mapper->SetBlendMode(blend);
  return deepshadow::testing::DrawForComparison(window, mapper, data, property, { 0.1, 0.1, 0.15 }, !vtks);
}

// Component c (0 unless given) alone, as a volume of one component.
vtkSmartPointer<vtkImageData> FirstComponent(vtkImageData* data, int c = 0)
{
  auto first = vtkSmartPointer<vtkImageData>::New();
  first->CopyStructure(data);
  first->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  first->GetPointData()->GetScalars()->CopyComponent(0, data->GetPointData()->GetScalars(), c);
  return first;
}

bool MatchesVTK(vtkRenderWindow* window, int count, Mode mode, bool shade, const std::string& what,
  int blend = vtkVolumeMapper::COMPOSITE_BLEND, bool mirrored = false, bool gradientOpacity = false)
{
  bool ok = true;
  auto data = MakeComponents(count);
  auto property = MakeProperty(mode, count, shade);
  if (gradientOpacity)
  {
    // Faint where component 0 is flat, as VTK applies it to dependent components.
    vtkNew<vtkPiecewiseFunction> gradient;
    gradient->AddPoint(0.0, 0.15);
    gradient->AddPoint(20.0, 1.0);
    property->SetGradientOpacity(0, gradient);
  }
  if (mirrored)
  {
    // Minimum intensity: the fields and functions mirrored, so that the minimum shows.
    data = Mirrored(data);
    property = MirroredFunctions(property, mode == Mode::Independent || mode == Mode::Weighted ? count : 1);
  }
  const Drawn ours = Draw(window, data, false, property, 0.5f, false, blend);
  // Ours reads the property without adding to it: a default gradient opacity made here
  // changed VTK's picture drawn after ours (RMSE 0.044 with 4 weighted components).
  ok = Check((what + ": the property is left as it was").c_str(), property->HasGradientOpacity(0) == gradientOpacity) &&
    ok;
  const Drawn vtks = Draw(window, data, true, property, 0.5f, false, blend);
  const deepshadow::testing::VTKTolerance tolerance = deepshadow::testing::CalibrateOnVTK(what, vtks.Picture,
    [&](float scale, bool jitter) { return Draw(window, data, true, property, 0.5f * scale, jitter, blend).Picture; });
  ok = WithinTolerance(what.c_str(), ours.Picture, vtks.Picture, tolerance.MaxRMSE, 8.0 / 255.0, tolerance.MaxFraction) && ok;
  ok = WithinTolerance((what + " vs CPU twin").c_str(), ours.Picture, ours.Twin, 1.5 / 255.0, 8.0 / 255.0, 0.005) && ok;
  const auto single = MakeProperty(Mode::Independent, 1, shade);
  if (gradientOpacity)
  {
    property->SetDisableGradientOpacity(0, 1);
    ok = !WithinTolerance((what + ", ours without it (must fail)").c_str(),
           Draw(window, data, false, property, 0.5f, false, blend).Picture, vtks.Picture, tolerance.MaxRMSE,
           8.0 / 255.0, tolerance.MaxFraction) && ok;
    property->SetDisableGradientOpacity(0, 0);
  }
  ok = !WithinTolerance((what + ", component 0 alone (must fail)").c_str(),
         Draw(window, FirstComponent(data), false, single, 0.5f, false, blend).Picture, vtks.Picture,
         tolerance.MaxRMSE, 8.0 / 255.0, tolerance.MaxFraction) && ok;
  return ok;
}

// Projections of several components: against VTK's mapper where VTK 9.1 projects them as it
// means to; where its shader slips (minimum over independent components, extremes over
// luminance + opacity), against closed relations to pictures VTK draws right.
bool ProjectionsMatch(vtkRenderWindow* window)
{
  bool ok = true;
  ok = MatchesVTK(window, 2, Mode::Independent, false, "2 independent components, MIP",
         vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND) && ok;
  ok = MatchesVTK(window, 4, Mode::Weighted, false, "4 independent components, weighted, MIP",
         vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND) && ok;
  ok = MatchesVTK(window, 2, Mode::Independent, false, "2 independent components, average",
         vtkVolumeMapper::AVERAGE_INTENSITY_BLEND) && ok;
  ok = MatchesVTK(window, 4, Mode::Weighted, false, "4 independent components, weighted, additive",
         vtkVolumeMapper::ADDITIVE_BLEND) && ok;
  ok = MatchesVTK(window, 4, Mode::RGBA, false, "4 dependent components (RGBA), MIP",
         vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND) && ok;
  ok = MatchesVTK(window, 4, Mode::RGBA, false, "4 dependent components (RGBA), MinIP of the mirror",
         vtkVolumeMapper::MINIMUM_INTENSITY_BLEND, true) && ok;

  // Minimum over independent components: the mirror's minimum is the original's maximum.
  for (const int count : { 2, 4 })
  {
    const std::string what = std::to_string(count) + " independent components, MinIP of the mirror";
    const auto data = MakeComponents(count);
    const auto property = MakeProperty(Mode::Weighted, count, false);
    const Drawn maximum = Draw(window, data, false, property, 0.5f, false, vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND);
    const auto mirroredProperty = MirroredFunctions(property, count);
    const Drawn minimum = Draw(
      window, Mirrored(data), false, mirroredProperty, 0.5f, false, vtkVolumeMapper::MINIMUM_INTENSITY_BLEND);
    ok = WithinTolerance((what + " vs the original's MIP").c_str(), minimum.Picture, maximum.Picture, 0.004,
           8.0 / 255.0, 0.002) && ok;
    ok = WithinTolerance((what + " vs CPU twin").c_str(), minimum.Picture, minimum.Twin, 1.5 / 255.0, 8.0 / 255.0,
           0.005) && ok;
    ok = !WithinTolerance((what + ", its MIP (must fail)").c_str(),
           Draw(window, Mirrored(data), false, mirroredProperty, 0.5f, false,
             vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND).Picture, maximum.Picture, 0.004, 8.0 / 255.0, 0.002) && ok;
  }

  // Luminance + opacity of one field twice: its extremes are that field's, as VTK draws one
  // component (colour and opacity from the volume's functions).
  for (const int blend : { vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND, vtkVolumeMapper::MINIMUM_INTENSITY_BLEND })
  {
    const std::string what = std::string("luminance + opacity of one field, ") +
      (blend == vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND ? "MIP" : "MinIP");
    const bool minimum = blend == vtkVolumeMapper::MINIMUM_INTENSITY_BLEND;
    auto single = FirstComponent(MakeComponents(1));
    auto property = MakeProperty(Mode::LuminanceAlpha, 2, false);
    if (minimum)
    {
      single = Mirrored(single);
      property = MirroredFunctions(property, 1);
    }
    auto twice = vtkSmartPointer<vtkImageData>::New();
    twice->CopyStructure(single);
    twice->AllocateScalars(VTK_UNSIGNED_CHAR, 2);
    twice->GetPointData()->GetScalars()->CopyComponent(0, single->GetPointData()->GetScalars(), 0);
    twice->GetPointData()->GetScalars()->CopyComponent(1, single->GetPointData()->GetScalars(), 0);
    const Drawn ours = Draw(window, twice, false, property, 0.5f, false, blend);
    auto oneComponent = vtkSmartPointer<vtkVolumeProperty>::New();
    oneComponent->DeepCopy(property);
    oneComponent->SetIndependentComponents(true);
    const Drawn vtks = Draw(window, single, true, oneComponent, 0.5f, false, blend);
    ok = WithinTolerance((what + " vs VTK's one component").c_str(), ours.Picture, vtks.Picture, 0.01, 8.0 / 255.0,
           0.01) && ok;
    ok = WithinTolerance((what + " vs CPU twin").c_str(), ours.Picture, ours.Twin, 1.5 / 255.0, 8.0 / 255.0, 0.005) &&
      ok;
  }
  return ok;
}

// Gradient opacity over independent components (part 4).
bool IndependentGradientOpacity(vtkRenderWindow* window)
{
  bool ok = true;
  vtkNew<vtkPiecewiseFunction> faint; // faint where the component is flat
  faint->AddPoint(0.0, 0.15);
  faint->AddPoint(20.0, 1.0);
  vtkNew<vtkPiecewiseFunction> edges; // only where it changes fast
  edges->AddPoint(0.0, 0.0);
  edges->AddPoint(10.0, 0.0);
  edges->AddPoint(40.0, 1.0);
  vtkNew<vtkPiecewiseFunction> clear;
  clear->AddPoint(0.0, 0.0);
  clear->AddPoint(255.0, 0.0);
  const auto data = MakeComponents(2);
  // Ours within VTK's own noise of `vtks` (drawn by `drawVTK`) and within 1.5/255 of its twin.
  auto matches = [&](const std::string& what, const Drawn& ours, const std::function<Image(float, bool)>& drawVTK) {
    const Image vtks = drawVTK(1.0f, false);
    const deepshadow::testing::VTKTolerance tolerance = deepshadow::testing::CalibrateOnVTK(what, vtks, drawVTK);
    const bool near = WithinTolerance(what.c_str(), ours.Picture, vtks, tolerance.MaxRMSE, 8.0 / 255.0,
      tolerance.MaxFraction);
    return WithinTolerance((what + " vs CPU twin").c_str(), ours.Picture, ours.Twin, 1.5 / 255.0, 8.0 / 255.0,
             0.005) && near;
  };
  auto fails = [&](const std::string& what, const Image& picture, const Image& reference) {
    return !WithinTolerance((what + " (must fail)").c_str(), picture, reference, 0.01, 8.0 / 255.0, 0.01);
  };

  // The function on component 0, component 1 clear: VTK's mapper applies it as we do.
  {
    const std::string what = "2 independent components, gradient opacity on component 0";
    auto property = MakeProperty(Mode::Independent, 2, true);
    property->SetScalarOpacity(1, clear);
    property->SetGradientOpacity(0, edges);
    const Drawn ours = Draw(window, data, false, property);
    ok = matches(what, ours, [&](float scale, bool jitter) {
      return Draw(window, data, true, property, 0.5f * scale, jitter).Picture;
    }) && ok;
    property->SetDisableGradientOpacity(0, 1);
    ok = fails(what + ", ours without it", Draw(window, data, false, property).Picture, ours.Picture) && ok;
  }

  // The function on component 1 alone (component 0 clear): VTK's picture of component 1 as a
  // volume of its own with the function. VTK's two-component mapper draws none.
  {
    const std::string what = "2 independent components, gradient opacity on component 1 alone";
    auto property = MakeProperty(Mode::Independent, 2, false);
    property->SetScalarOpacity(0, clear);
    property->SetGradientOpacity(1, edges);
    const Drawn ours = Draw(window, data, false, property);
    auto alone = MakeProperty(Mode::Independent, 1, false);
    SetComponentFunctions(alone, 1, 0);
    alone->SetGradientOpacity(0, edges);
    const auto field = FirstComponent(data, 1);
    ok = matches(what + " vs VTK's component 1 alone", ours, [&](float scale, bool jitter) {
      return Draw(window, field, true, alone, 0.5f * scale, jitter).Picture;
    }) && ok;
    ok = fails(what + ", VTK 9.1's two components", Draw(window, data, true, property).Picture,
           Draw(window, field, true, alone).Picture) && ok;
    property->SetDisableGradientOpacity(1, 1);
    ok = fails(what + ", ours without it", Draw(window, data, false, property).Picture, ours.Picture) && ok;
  }

  // Both components with functions of their own, shaded: ours against its twin, and each
  // function counts.
  {
    const std::string what = "2 independent components, shaded, a gradient opacity each";
    auto property = MakeProperty(Mode::Independent, 2, true);
    property->SetGradientOpacity(0, faint);
    property->SetGradientOpacity(1, edges);
    const Drawn ours = Draw(window, data, false, property);
    ok = WithinTolerance((what + " vs CPU twin").c_str(), ours.Picture, ours.Twin, 1.5 / 255.0, 8.0 / 255.0, 0.005) &&
      ok;
    property->SetDisableGradientOpacity(1, 1);
    ok = fails(what + ", ours without component 1's", Draw(window, data, false, property).Picture, ours.Picture) &&
      ok;
  }
  return ok;
}
}

int TestComponents(int, char*[])
{
  bool ok = true;
  vtkNew<vtkDeepShadowRenderWindow> window;
  window->SetSize(200, 200);
  ok = MatchesVTK(window, 2, Mode::Independent, false, "2 independent components") && ok;
  ok = MatchesVTK(window, 2, Mode::Independent, true, "2 independent components, shaded") && ok;
  ok = MatchesVTK(window, 4, Mode::Weighted, true, "4 independent components, weighted, shaded") && ok;
  ok = MatchesVTK(window, 2, Mode::LuminanceAlpha, true, "2 dependent components (luminance, opacity)") && ok;
  ok = MatchesVTK(window, 4, Mode::RGBA, false, "4 dependent components (RGBA)") && ok;
  ok = MatchesVTK(window, 2, Mode::LuminanceAlpha, true, "2 dependent components, gradient opacity",
         vtkVolumeMapper::COMPOSITE_BLEND, false, true) && ok;
  ok = MatchesVTK(window, 4, Mode::RGBA, false, "4 dependent components (RGBA), gradient opacity",
         vtkVolumeMapper::COMPOSITE_BLEND, false, true) && ok;
  ok = ProjectionsMatch(window) && ok;
  ok = IndependentGradientOpacity(window) && ok;

  // Shadows: the ball (200) in component 0, the plate and pillar in component 1.
  deepshadow::testing::ShadowScene scene;
  {
    vtkDataArray* values = scene.Data->GetPointData()->GetScalars();
    auto split = vtkSmartPointer<vtkImageData>::New();
    split->CopyStructure(scene.Data);
    split->AllocateScalars(VTK_UNSIGNED_CHAR, 2);
    vtkDataArray* out = split->GetPointData()->GetScalars();
    for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
    {
      const double v = values->GetComponent(i, 0);
      out->SetComponent(i, 0, v == 200.0 ? v : 0.0);
      out->SetComponent(i, 1, v == 200.0 ? 0.0 : v);
    }
    scene.Data = split;
    scene.Mapper->SetInputData(scene.Data);
    scene.Property->SetColor(1, scene.Color);
    scene.Property->SetScalarOpacity(1, scene.Opacity);
    scene.Property->SetShade(1, 1);
  }
  ok = scene.AllMatchTwins("2 components") && ok;
  ok = scene.DeepShadowDarkensFloor("the ball (component 0) over the floor (component 1)") && ok;
  ok = Check("composed with Components", deepshadow::testing::HasFeature(scene.Mapper, "Components")) && ok;
  {
    // The ball's own gradient opacity makes it faint, fainter where it is flat: the shadow it
    // casts on the floor, in the other component, lightens; every technique casts what is drawn.
    const auto floorUnderBall = [&] {
      scene.Window->Render();
      const glm::dvec3 floor = deepshadow::testing::ShadowScene::FloorUnderBall(Grab(scene.Window));
      return floor.x + floor.y + floor.z;
    };
    const double solid = floorUnderBall();
    vtkNew<vtkPiecewiseFunction> faintBall;
    faintBall->AddPoint(0.0, 0.03);
    faintBall->AddPoint(50.0, 0.3);
    scene.Property->SetGradientOpacity(0, faintBall);
    const double faded = floorUnderBall();
    std::printf("2 components: floor under the ball %.3f, %.3f with the ball faint by its gradient opacity\n",
      solid, faded);
    ok = Check("2 components: the faint ball's shadow is lighter", faded > 1.3 * solid) && ok;
    ok = scene.AllMatchTwins("2 components, the ball's gradient opacity") && ok;
    // Its table and the shadow are rebuilt when the function changes, and only then.
    const vtkSmartPointer<vtkDeepShadowTechnique> dsm = vtkDeepShadowTechniqueFactory::New("dsm");
    scene.Mapper->SetShadowTechnique(dsm);
    scene.Window->Render();
    const int builds = dsm->GetBuildCount();
    scene.Window->Render();
    const auto& passes = scene.Mapper->GetLastPasses();
    const bool tableKept = std::find(passes.begin(), passes.end(), "component-gradient-table") == passes.end();
    ok = Check("2 components, gradient opacity unchanged: no table, no shadow rebuilt",
           tableKept && dsm->GetBuildCount() == builds) && ok;
    faintBall->AddPoint(25.0, 0.1);
    scene.Window->Render();
    const bool tableRebuilt = std::find(passes.begin(), passes.end(), "component-gradient-table") != passes.end();
    ok = Check("2 components, gradient opacity changed: its table and the shadow rebuilt",
           tableRebuilt && dsm->GetBuildCount() == builds + 1) && ok;
    scene.Property->SetDisableGradientOpacity(0, 1);
  }

  // What is not drawn is said: 3 dependent components, 5 components; an isosurface drawn composite.
  auto says = [&](vtkImageData* data, bool independent, const std::string& needle) {
    vtkNew<deepshadow::testing::MessageCapture> capture;
    capture->Watch(scene.Mapper);
    scene.Mapper->SetInputData(data);
    scene.Property->SetIndependentComponents(independent);
    scene.Window->Render();
    bool heard = capture->ErrorContains(needle);
    for (const std::string& warning : capture->Warnings)
    {
      heard = heard || warning.find(needle) != std::string::npos;
    }
    std::printf("%s: %s\n", needle.c_str(), heard ? "said" : "NOT SAID");
    return heard;
  };
  ok = Check("3 dependent components: one error", says(MakeComponents(3, 16), false, "3 dependent components")) && ok;
  ok = Check("5 components: one error", [&] {
    auto five = vtkSmartPointer<vtkImageData>::New();
    five->SetDimensions(8, 8, 8);
    five->AllocateScalars(VTK_UNSIGNED_CHAR, 5);
    return says(five, true, "5 components; at most 4");
  }()) && ok;
  scene.Mapper->SetBlendModeToIsoSurface();
  ok = Check("isosurface with components: drawn composite, said", says(scene.Data, true, "drawn composite")) && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
