// Leave out what the scene does not need, rebuild only what changed, and make it observable:
// - moving the camera re-uploads nothing and rebuilds nothing;
// - an opacity change rebuilds the table and the block map, a colour change only the
//   table, neither the volume; switching shading on rebuilds nothing but the shader;
// - new data re-uploads the volume; a new sample distance rebuilds only the table;
// - the shader holds only the features in use (no shading code unshaded, no jitter code
//   without jitter, no depth code without opaque geometry, no skipping code with nothing to
//   skip) and no shadow code at all (no technique is chosen).
#include "DeepShadowTestUtilities.h"
#include "vtkDeepShadowRenderWindow.h"
#include "vtkDeepShadowVolumeMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPolyDataMapper.h"
#include "vtkSphereSource.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

using deepshadow::testing::HasFeature;

namespace
{
struct Counters
{
  int Uploads, Tables, Blocks, Shaders;
};

Counters Read(vtkDeepShadowVolumeMapper* m)
{
  return { m->GetVolumeUploads(), m->GetTransferTableBuilds(), m->GetOccupancyBuilds(),
    m->GetShaderCompositions() };
}

bool Check(const char* step, vtkDeepShadowVolumeMapper* m, const Counters& expected)
{
  const Counters c = Read(m);
  const bool ok = c.Uploads == expected.Uploads && c.Tables == expected.Tables &&
    c.Blocks == expected.Blocks && c.Shaders == expected.Shaders;
  std::printf("%-40s uploads %d tables %d blocks %d shaders %d %s\n", step, c.Uploads, c.Tables,
    c.Blocks, c.Shaders, ok ? "ok" : "FAILED");
  return ok;
}
}

int TestWorkIsRedoneOnlyWhenNeeded(int, char*[])
{
  bool ok = true;
  auto data = deepshadow::testing::MakeTestVolume(VTK_UNSIGNED_CHAR, 40);
  vtkNew<vtkDeepShadowRenderWindow> window;
  window->SetSize(96, 96);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkNew<vtkDeepShadowVolumeMapper> mapper;
  mapper->SetInputData(data);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0, 0.0);
  opacity->AddPoint(20, 0.0);
  opacity->AddPoint(255, 0.4);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0, 1, 1, 1);
  vtkNew<vtkVolumeProperty> property;
  property->SetScalarOpacity(opacity);
  property->SetColor(color);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  renderer->AddVolume(volume);
  renderer->ResetCamera();

  window->Render();
  ok = Check("first frame", mapper, { 1, 1, 1, 1 }) && ok;
  const std::string& source = mapper->GetFragmentShaderSource();
  const bool lean =
    mapper->GetShaderFeatures() == std::vector<std::string>{ "EmptySpace", "VolumeSampling" } &&
    source.find("lightSample(") == std::string::npos &&
    source.find("jitterOffset") == std::string::npos &&
    source.find("u_opaqueDepth") == std::string::npos &&
    source.find("u_shadow") == std::string::npos &&
    source.find("feelerVisibility") == std::string::npos &&
    source.find("//DeepShadow::") == std::string::npos;
  std::printf("unshaded shader holds only EmptySpace and VolumeSampling: %s\n", lean ? "ok" : "FAILED");
  ok = lean && ok;

  for (int i = 0; i < 5; ++i)
  {
    renderer->GetActiveCamera()->Azimuth(15.0);
    renderer->GetActiveCamera()->Zoom(1.05);
    window->Render();
  }
  ok = Check("camera moved 5 times", mapper, { 1, 1, 1, 1 }) && ok;

  opacity->AddPoint(128, 0.9);
  window->Render();
  ok = Check("opacity function changed", mapper, { 1, 2, 2, 1 }) && ok;

  color->AddRGBPoint(255, 1, 0, 0);
  window->Render();
  ok = Check("colour function changed", mapper, { 1, 3, 2, 1 }) && ok;

  mapper->SetSampleDistance(0.3);
  window->Render();
  ok = Check("sample distance changed", mapper, { 1, 4, 2, 1 }) && ok;

  data->Modified();
  window->Render();
  ok = Check("data modified", mapper, { 2, 5, 3, 1 }) && ok;

  property->ShadeOn();
  window->Render();
  ok = Check("shading switched on", mapper, { 2, 5, 3, 2 }) && ok;
  ok = HasFeature(mapper, "Lighting") && HasFeature(mapper, "Gradient") && ok;

  mapper->JitterOn();
  window->Render();
  ok = Check("jitter switched on", mapper, { 2, 5, 3, 3 }) && ok;
  ok = HasFeature(mapper, "Jitter") && ok;

  vtkNew<vtkSphereSource> sphere;
  vtkNew<vtkPolyDataMapper> sphereMapper;
  sphereMapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(sphereMapper);
  renderer->AddActor(actor);
  window->Render();
  ok = Check("opaque geometry added", mapper, { 2, 5, 3, 4 }) && ok;
  ok = HasFeature(mapper, "OpaqueDepth") && ok;

  actor->VisibilityOff();
  window->Render();
  ok = !HasFeature(mapper, "OpaqueDepth") && ok;
  ok = Check("geometry hidden again", mapper, { 2, 5, 3, 5 }) && ok;

  // An opacity function with no zero leaves nothing to skip: no skipping code.
  opacity->RemoveAllPoints();
  opacity->AddPoint(0, 0.05);
  opacity->AddPoint(255, 0.5);
  window->Render();
  ok = !HasFeature(mapper, "EmptySpace") && ok;
  std::printf("nothing to skip -> no EmptySpace feature: %s\n", HasFeature(mapper, "EmptySpace") ? "FAILED" : "ok");
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
