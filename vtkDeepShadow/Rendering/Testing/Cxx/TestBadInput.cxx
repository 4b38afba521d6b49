// Bad input gets one clear error (once, not every frame), no crash, and no garbage: the
// volume (or mesh) is not drawn and the picture shows only the background.
//   Data: no input, an empty image, zero extent (N x N x 1), flat cell scalars, no scalars, a
//   named array that is not there, five components (2-4 are drawn: TestComponents), three
//   dependent ones, unsupported scalar types (int, double),
//   NaN and Inf samples (an error, or with ReplaceNonFiniteScalars a warning and a defined
//   picture), a volume beyond the GL's 3D texture limit.
//   Placement and settings (silent before issue 17): NaN spacing and origin, a zero or NaN
//   direction matrix, spacings of 1e-30 and 1e30 and an origin far away for its size, a NaN
//   opacity point, an opacity unit distance of 0 or NaN, a NaN light position, a positional
//   light at 1e300; SetSampleDistance(NaN or -1) and SetTerminationOpacity(NaN) (an error at
//   the call, the old value kept, the picture unchanged).
//   Meshes: vtkDeepShadowPolyDataMapper with point ids past its points or NaN points; a
//   volume bound with point ids past its points.
//   And a light at 1e308 along a diagonal still lights (directions are normalised in double).
#include "DeepShadowTestUtilities.h"
#include "vtkDeepShadowPass.h"
#include "vtkDeepShadowPolyDataMapper.h"
#include "vtkDeepShadowRayTechnique.h"
#include "vtkDeepShadowRenderWindow.h"
#include "vtkDeepShadowVolumeMapper.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkColorTransferFunction.h"
#include "vtkFloatArray.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPoints.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <functional>
#include <limits>

using deepshadow::testing::MessageCapture;

namespace
{
struct Outcome
{
  std::vector<std::string> Errors;
  std::vector<std::string> Warnings;
  double Covered = 0.0;
  deepshadow::Image Picture;
};

// What a case changes before rendering.
struct Scene
{
  vtkDeepShadowVolumeMapper* Mapper;
  vtkVolumeProperty* Property;
  vtkPiecewiseFunction* Opacity;
  vtkRenderer* Renderer;
  vtkLight* Light;
};

// Renders `data` (null: no input) three times; returns what the mapper said and drew.
// Three frames (a failure is said once, not every frame), then what was said and drawn.
Outcome Draw(vtkRenderWindow* window, MessageCapture* capture)
{
  for (int frame = 0; frame < 3; ++frame)
  {
    window->Render();
  }
  Outcome outcome;
  outcome.Errors = capture->Errors;
  outcome.Warnings = capture->Warnings;
  outcome.Picture = deepshadow::testing::Grab(window);
  outcome.Covered = deepshadow::testing::CoveredFraction(outcome.Picture, { 0.2, 0.3, 0.4 });
  return outcome;
}

Outcome RenderBad(vtkImageData* data, bool replaceNonFinite = false,
  const std::function<void(Scene&)>& change = nullptr)
{
  vtkNew<vtkDeepShadowRenderWindow> window;
  window->SetSize(64, 64);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.2, 0.3, 0.4);
  window->AddRenderer(renderer);
  vtkNew<vtkDeepShadowVolumeMapper> mapper;
  mapper->SetReplaceNonFiniteScalars(replaceNonFinite);
  vtkNew<MessageCapture> capture;
  capture->Watch(mapper);
  if (data)
  {
    mapper->SetInputData(data);
  }
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(-10.0, 1.0);
  opacity->AddPoint(10.0, 1.0);
  vtkNew<vtkVolumeProperty> property;
  property->SetScalarOpacity(opacity);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  renderer->AddVolume(volume);
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPosition(0.0, 0.0, 1.0);
  light->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->AddLight(light);
  renderer->GetActiveCamera()->SetPosition(0.0, 0.0, 10.0);
  renderer->GetActiveCamera()->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->ResetCameraClippingRange();
  if (change)
  {
    Scene scene{ mapper, property, opacity, renderer, light };
    change(scene);
  }
  return Draw(window, capture);
}

// A triangle mesh with a point id past its three points (or a NaN point), drawn by
// vtkDeepShadowPolyDataMapper alone or, under vtkDeepShadowPass, beside a shadowing volume
// (which gathers it as a caster): one error, nothing drawn, no crash.
Outcome RenderBadMesh(bool nanPoint, bool withPass)
{
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(-3.0, -3.0, 0.0);
  points->InsertNextPoint(3.0, -3.0, 0.0);
  points->InsertNextPoint(nanPoint ? std::numeric_limits<double>::quiet_NaN() : 0.0, 3.0, 0.0);
  vtkNew<vtkCellArray> triangles;
  const vtkIdType good[3] = { 0, 1, 2 };
  const vtkIdType bad[3] = { 0, 1, 99 };
  triangles->InsertNextCell(3, good);
  if (!nanPoint)
  {
    triangles->InsertNextCell(3, bad);
  }
  vtkNew<vtkPolyData> mesh;
  mesh->SetPoints(points);
  mesh->SetPolys(triangles);

  vtkNew<vtkDeepShadowRenderWindow> window;
  window->SetSize(64, 64);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.2, 0.3, 0.4);
  window->AddRenderer(renderer);
  vtkNew<vtkDeepShadowPolyDataMapper> mapper;
  vtkNew<MessageCapture> capture;
  capture->Watch(mapper);
  mapper->SetInputData(mesh);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  renderer->AddActor(actor);
  vtkNew<vtkDeepShadowPass> pass;
  vtkNew<vtkDeepShadowVolumeMapper> volumeMapper;
  vtkNew<vtkDeepShadowRayTechnique> rays;
  vtkNew<vtkVolume> volume;
  if (withPass)
  {
    // A volume beside the mesh (its picture is not looked at): the pass gathers the mesh as
    // a caster for the volume's technique.
    auto data = deepshadow::testing::MakeShadowVolume(16);
    data->SetOrigin(20.0, 20.0, 20.0);
    volumeMapper->SetInputData(data);
    volumeMapper->SetShadowTechnique(rays);
    volume->SetMapper(volumeMapper);
    renderer->AddVolume(volume);
    renderer->SetPass(pass);
  }
  renderer->GetActiveCamera()->SetPosition(0.0, 0.0, 10.0);
  renderer->GetActiveCamera()->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->ResetCameraClippingRange();
  return Draw(window, capture);
}

vtkSmartPointer<vtkImageData> Image(int nx, int ny, int nz, int type, int components = 1)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(nx, ny, nz);
  image->SetOrigin(-0.5 * (nx - 1), -0.5 * (ny - 1), -0.5 * (nz - 1));
  if (type != VTK_VOID)
  {
    image->AllocateScalars(type, components);
    vtkDataArray* scalars = image->GetPointData()->GetScalars();
    for (vtkIdType i = 0; i < scalars->GetNumberOfTuples(); ++i)
    {
      for (int c = 0; c < components; ++c)
      {
        scalars->SetComponent(i, c, 1.0);
      }
    }
  }
  return image;
}

bool Expect(const char* what, const Outcome& outcome, const std::string& needle, bool drawn)
{
  bool ok = true;
  const bool mentioned = std::any_of(outcome.Errors.begin(), outcome.Errors.end(),
    [&](const std::string& e) { return e.find(needle) != std::string::npos; });
  if (!needle.empty() && (!mentioned || outcome.Errors.size() != 1))
  {
    std::printf("%s: expected exactly one error mentioning '%s', got %zu\n", what,
      needle.c_str(), outcome.Errors.size());
    ok = false;
  }
  if (needle.empty() && !outcome.Errors.empty())
  {
    std::printf("%s: unexpected error: %s\n", what, outcome.Errors.front().c_str());
    ok = false;
  }
  if (drawn != (outcome.Covered > 0.05))
  {
    std::printf("%s: volume %s drawn (%.1f%% covered)\n", what, drawn ? "not" : "wrongly",
      100.0 * outcome.Covered);
    ok = false;
  }
  // Print the message without VTK's "ERROR: In file, line" header (ctest fails on it).
  std::string message;
  if (!outcome.Errors.empty())
  {
    message = outcome.Errors.front();
    const size_t at = message.find("): ");
    message = ": " + (at == std::string::npos ? message : message.substr(at + 3));
  }
  std::printf("%-28s %s%s\n", what, ok ? "ok" : "FAILED", message.c_str());
  return ok;
}
}

int TestBadInput(int, char*[])
{
  bool ok = true;
  ok = Expect("no input", RenderBad(nullptr), "no input volume", false) && ok;
  ok = Expect("empty image", RenderBad(Image(0, 0, 0, VTK_VOID)), "empty", false) && ok;
  ok = Expect("zero extent (N x N x 1)", RenderBad(Image(8, 8, 1, VTK_UNSIGNED_CHAR)),
         "zero extent along z", false) && ok;
  {
    // Cell scalars are drawn (TestCellScalars); a flat image has no cells to draw.
    auto cells = Image(8, 8, 1, VTK_VOID);
    vtkNew<vtkFloatArray> values;
    values->SetNumberOfTuples(cells->GetNumberOfCells());
    values->FillValue(1.0f);
    cells->GetCellData()->SetScalars(values);
    ok = Expect("cell scalars, zero extent", RenderBad(cells), "cell scalars need at least one cell", false) && ok;
    ok = Expect("no scalars at all", RenderBad(Image(8, 8, 8, VTK_VOID)), "no point or cell scalars", false) && ok;
    ok = Expect("a named array that is not there", RenderBad(Image(8, 8, 8, VTK_UNSIGNED_CHAR), false, [](Scene& s) {
      s.Mapper->SetScalarModeToUsePointFieldData();
      s.Mapper->SelectScalarArray("density");
    }), "no point array 'density'", false) && ok;
  }
  ok = Expect("five components", RenderBad(Image(8, 8, 8, VTK_UNSIGNED_CHAR, 5)),
         "5 components; at most 4", false) && ok;
  ok = Expect("three dependent components", RenderBad(Image(8, 8, 8, VTK_UNSIGNED_CHAR, 3), false,
                [](Scene& s) { s.Property->SetIndependentComponents(0); }),
         "3 dependent components", false) && ok;
  ok = Expect("bit scalars", RenderBad(Image(8, 8, 8, VTK_BIT)), "scalar type bit", false) && ok;
  {
    auto huge = Image(8, 8, 8, VTK_DOUBLE);
    static_cast<double*>(huge->GetScalarPointer())[5] = 1.0e300;
    ok = Expect("double beyond float's range", RenderBad(huge), "beyond single precision", false) && ok;
  }
  ok = Expect("beyond 3D texture limit", RenderBad(Image(20000, 2, 2, VTK_UNSIGNED_CHAR)),
         "3D texture limit", false) && ok;

  auto nonFinite = Image(8, 8, 8, VTK_FLOAT);
  auto* values = static_cast<float*>(nonFinite->GetScalarPointer());
  values[0] = std::numeric_limits<float>::quiet_NaN();
  values[1] = std::numeric_limits<float>::infinity();
  values[2] = -std::numeric_limits<float>::infinity();
  ok = Expect("NaN and Inf samples", RenderBad(nonFinite), "1 NaN, 1 +Inf and 1 -Inf", false) && ok;
  const Outcome replaced = RenderBad(nonFinite, true);
  ok = Expect("NaN and Inf, replaced", replaced, "", true) && ok;
  if (replaced.Warnings.size() != 1 || replaced.Warnings[0].find("3 non-finite") == std::string::npos)
  {
    std::printf("NaN and Inf, replaced: expected one warning about 3 non-finite samples\n");
    ok = false;
  }
  // Placement: the renderer culls a volume with NaN bounds before drawing; said anyway.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto placed = [](std::function<void(vtkImageData*)> place) {
    auto image = Image(8, 8, 8, VTK_UNSIGNED_CHAR);
    place(image);
    return image;
  };
  ok = Expect("NaN spacing", RenderBad(placed([&](vtkImageData* i) { i->SetSpacing(1.0, nan, 1.0); })),
         "spacing", false) && ok;
  ok = Expect("NaN origin", RenderBad(placed([&](vtkImageData* i) { i->SetOrigin(nan, 0.0, 0.0); })),
         "origin", false) && ok;
  ok = Expect("zero direction matrix", RenderBad(placed([](vtkImageData* i) {
    const double zero[9] = { 0.0 };
    i->SetDirectionMatrix(zero);
  })), "singular", false) && ok;
  ok = Expect("NaN direction matrix", RenderBad(placed([&](vtkImageData* i) {
    const double d[9] = { 1.0, 0.0, 0.0, 0.0, nan, 0.0, 0.0, 0.0, 1.0 };
    i->SetDirectionMatrix(d);
  })), "not finite", false) && ok;
  ok = Expect("spacing 1e-30", RenderBad(placed([](vtkImageData* i) {
    i->SetSpacing(1e-30, 1e-30, 1e-30);
    i->SetOrigin(0.0, 0.0, 0.0);
  })), "voxel edge", false) && ok;
  ok = Expect("spacing 1e30", RenderBad(placed([](vtkImageData* i) {
    i->SetSpacing(1e30, 1e30, 1e30);
    i->SetOrigin(0.0, 0.0, 0.0);
  })), "voxel edge", false) && ok;
  ok = Expect("origin 1e9 voxels away",
         RenderBad(placed([](vtkImageData* i) { i->SetOrigin(1e9, 0.0, 0.0); }), false,
           [](Scene& s) { s.Renderer->ResetCamera(); }), "from the origin", false) && ok;

  // Settings.
  auto valid = [] { return Image(8, 8, 8, VTK_UNSIGNED_CHAR); };
  ok = Expect("NaN opacity point", RenderBad(valid(), false,
         [&](Scene& s) { s.Opacity->AddPoint(nan, 0.5); }), "opacity function", false) && ok;
  ok = Expect("NaN colour point", RenderBad(valid(), false,
         [&](Scene& s) {
           vtkNew<vtkColorTransferFunction> color;
           color->AddRGBPoint(0.0, 1.0, 1.0, 1.0);
           color->AddRGBPoint(nan, 0.5, 0.5, 0.5);
           s.Property->SetColor(color);
         }), "colour transfer function", false) && ok;
  ok = Expect("NaN grey point", RenderBad(valid(), false,
         [&](Scene& s) {
           vtkNew<vtkPiecewiseFunction> gray;
           gray->AddPoint(0.0, 1.0);
           gray->AddPoint(nan, 0.5);
           s.Property->SetColor(gray);
         }), "grey transfer function", false) && ok;
  ok = Expect("opacity unit distance 0", RenderBad(valid(), false,
         [](Scene& s) { s.Property->SetScalarOpacityUnitDistance(0.0); }), "unit distance", false) && ok;
  ok = Expect("opacity unit distance NaN", RenderBad(valid(), false,
         [&](Scene& s) { s.Property->SetScalarOpacityUnitDistance(nan); }), "unit distance", false) && ok;
  // Lights matter to a shaded volume (an unshaded one without shadows ignores them).
  ok = Expect("NaN light position", RenderBad(valid(), false, [&](Scene& s) {
    s.Property->ShadeOn();
    s.Light->SetPosition(nan, 0.0, 1.0);
  }), "light 0", false) && ok;
  ok = Expect("positional light at 1e300", RenderBad(valid(), false, [](Scene& s) {
    s.Property->ShadeOn();
    s.Light->SetPositional(true);
    s.Light->SetPosition(1e300, 0.0, 0.0);
  }), "positional at 1e+300", false) && ok;
  // Setters: an error at the call, the old value kept, the volume drawn as before.
  bool kept = true;
  ok = Expect("SetSampleDistance(NaN)", RenderBad(valid(), false, [&](Scene& s) {
    s.Mapper->SetSampleDistance(nan);
    kept = kept && s.Mapper->GetSampleDistance() == 0.0;
  }), "SetSampleDistance(nan)", true) && ok;
  ok = Expect("SetSampleDistance(-1)", RenderBad(valid(), false, [&](Scene& s) {
    s.Mapper->SetSampleDistance(-1.0);
    kept = kept && s.Mapper->GetSampleDistance() == 0.0;
  }), "SetSampleDistance(-1)", true) && ok;
  ok = Expect("SetTerminationOpacity(NaN)", RenderBad(valid(), false, [&](Scene& s) {
    const double before = s.Mapper->GetTerminationOpacity();
    s.Mapper->SetTerminationOpacity(nan);
    kept = kept && s.Mapper->GetTerminationOpacity() == before;
  }), "SetTerminationOpacity(nan)", true) && ok;
  ok = deepshadow::testing::Check("rejected settings keep their old values", kept) && ok;
  // A sample distance that would take more samples than a ray may (deepshadow::
  // MaxRayIterations): one error naming the smallest that fits, nothing drawn.
  ok = Expect("SetSampleDistance(1e-9)", RenderBad(valid(), false,
         [](Scene& s) { s.Mapper->SetSampleDistance(1e-9); }), "use at least", false) && ok;
  // A directional light at 1e308 along the diagonal lights exactly as one at (1, 1, 1).
  auto diagonal = [&](double d) {
    return RenderBad(valid(), false, [d](Scene& s) {
      s.Property->ShadeOn();
      s.Light->SetPosition(d, d, d);
    });
  };
  const Outcome far = diagonal(1e308);
  ok = Expect("light direction 1e308", far, "", true) && ok;
  ok = deepshadow::testing::Check("light direction 1e308 lights as (1, 1, 1)",
         deepshadow::Compare(far.Picture, diagonal(1.0).Picture, 0.0).MaxAbs == 0.0) && ok;

  // Meshes with point ids past their points, or NaN points: one error, nothing drawn.
  ok = Expect("mesh ids out of range", RenderBadMesh(false, false), "point id 99", false) && ok;
  ok = Expect("mesh ids out of range, pass", RenderBadMesh(false, true), "point id 99", false) && ok;
  ok = Expect("mesh with a NaN point", RenderBadMesh(true, false), "not finite", false) && ok;
  ok = Expect("bound ids out of range", RenderBad(valid(), false, [](Scene& s) {
    vtkNew<vtkPoints> points;
    points->InsertNextPoint(0.0, 0.0, 0.0);
    vtkNew<vtkCellArray> triangles;
    const vtkIdType bad[3] = { 0, 7, 99 };
    triangles->InsertNextCell(3, bad);
    vtkNew<vtkPolyData> bound;
    bound->SetPoints(points);
    bound->SetPolys(triangles);
    s.Mapper->AddBound(bound);
  }), "bound A: a polygon of the mesh has the point id 99", false) && ok;

  // A good volume after all that still renders (the control).
  ok = Expect("valid volume (control)", RenderBad(Image(8, 8, 8, VTK_UNSIGNED_CHAR)), "", true) && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
