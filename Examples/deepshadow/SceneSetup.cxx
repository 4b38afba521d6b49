#include "SceneSetup.h"

#include "vtkDeepShadowImageConversion.h"
#include "vtkDeepShadowRenderWindow.h"
#include "vtkDeepShadowStandardScene.h"
#include "vtkDeepShadowVolumeMapper.h"
#include "vtkDeepShadowVolumeReader.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkDataArray.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <chrono>
#include <cmath>

namespace deepshadow
{
namespace tool
{
namespace
{
// A neutral look for files that come with none: grey, transparent low values, shaded.
vtkSmartPointer<vtkVolumeProperty> DefaultProperty(vtkImageData* data)
{
  double range[2] = { 0.0, 1.0 };
  if (vtkDataArray* scalars = data->GetPointData()->GetScalars())
  {
    scalars->GetRange(range);
  }
  const double width = range[1] > range[0] ? range[1] - range[0] : 1.0;
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(range[0], 0.2, 0.2, 0.2);
  color->AddRGBPoint(range[0] + width, 1.0, 1.0, 1.0);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(range[0], 0.0);
  opacity->AddPoint(range[0] + 0.2 * width, 0.0);
  opacity->AddPoint(range[0] + width, 0.6);
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetInterpolationTypeToLinear();
  property->ShadeOn();
  const double* spacing = data->GetSpacing();
  property->SetScalarOpacityUnitDistance(
    std::min({ std::abs(spacing[0]), std::abs(spacing[1]), std::abs(spacing[2]) }));
  return property;
}
}

SceneSetup SceneSetup::Build(const Options& options)
{
  SceneSetup setup;
  setup.Window = vtkSmartPointer<vtkDeepShadowRenderWindow>::New();
  if (!options.Backend.empty())
  {
    setup.Window->SetBackend(vtkDeepShadowRenderWindow::BackendFromString(options.Backend.c_str()));
  }
  setup.Window->SetSize(options.Width, options.Height);
  setup.Renderer = vtkSmartPointer<vtkRenderer>::New();
  setup.Renderer->SetBackground(0.08, 0.09, 0.12);
  setup.Window->AddRenderer(setup.Renderer);

  vtkSmartPointer<vtkVolumeProperty> property;
  double lightDirection[3] = { options.LightDirection[0], options.LightDirection[1],
    options.LightDirection[2] };
  bool keyLight = options.HasLightDirection;
  vtkNew<vtkDeepShadowStandardScene> scene;
  if (!options.VolumeFile.empty())
  {
    vtkNew<vtkDeepShadowVolumeReader> reader;
    reader->SetFileName(options.VolumeFile.c_str());
    reader->Update();
    if (!reader->GetLastError().empty())
    {
      throw UsageError(reader->GetLastError());
    }
    setup.Data = reader->GetOutput();
    setup.Name = options.VolumeFile;
    property = DefaultProperty(setup.Data);
  }
  else
  {
    if (!vtkDeepShadowStandardScene::IsSceneName(options.Scene))
    {
      std::string names;
      for (const auto& name : vtkDeepShadowStandardScene::GetSceneNames())
      {
        names += (names.empty() ? "" : ", ") + name;
      }
      throw UsageError("unknown scene '" + options.Scene + "' (scenes: " + names + ")");
    }
    scene->SetScene(options.Scene);
    scene->SetResolutionScale(options.SceneScale);
    setup.Data = scene->GetVolume();
    setup.GenerationSeconds = scene->GetLastGenerationTime();
    setup.Name = options.Scene;
    property = scene->GetVolumeProperty();
    if (!keyLight)
    {
      scene->GetLightDirection(lightDirection);
      keyLight = true;
    }
  }
  property->SetShade(options.Shade ? 1 : 0);

  setup.Mapper = vtkSmartPointer<vtkDeepShadowVolumeMapper>::New();
  setup.Mapper->SetInputData(setup.Data);
  setup.Mapper->SetSampleDistance(options.SampleDistance);
  setup.Mapper->SetJitter(options.Jitter);
  setup.Mapper->SetJitterSeed(options.JitterSeed);
  setup.Mapper->SetEmptySpaceSkipping(options.EmptySpaceSkipping);
  setup.Mapper->SetReplaceNonFiniteScalars(options.ReplaceNonFinite);
  setup.Volume = vtkSmartPointer<vtkVolume>::New();
  setup.Volume->SetMapper(setup.Mapper);
  setup.Volume->SetProperty(property);
  setup.Renderer->AddVolume(setup.Volume);

  vtkCamera* camera = setup.Renderer->GetActiveCamera();
  if (options.VolumeFile.empty())
  {
    scene->ApplyCamera(camera);
  }
  else
  {
    setup.Renderer->ResetCamera();
    camera->Azimuth(30.0);
    camera->Elevation(20.0);
    camera->OrthogonalizeViewUp();
    setup.Renderer->ResetCamera();
  }
  setup.Renderer->ResetCameraClippingRange();

  if (keyLight)
  {
    // One directional key light; the renderer's ambient keeps shadowed parts readable.
    const double* center = setup.Volume->GetCenter();
    vtkNew<vtkLight> light;
    light->SetLightTypeToSceneLight();
    light->SetPositional(false);
    light->SetFocalPoint(center);
    light->SetPosition(center[0] + lightDirection[0], center[1] + lightDirection[1],
      center[2] + lightDirection[2]);
    setup.Renderer->AddLight(light);
  }
  return setup;
}

double RenderFrame(vtkDeepShadowRenderWindow* window)
{
  const auto start = std::chrono::steady_clock::now();
  window->Render();
  window->WaitForCompletion();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void RequireDrawn(const SceneSetup& setup)
{
  if (!setup.Window->HasContext())
  {
    throw std::runtime_error("no headless OpenGL context: " + setup.Window->GetLastError());
  }
  if (!setup.Mapper->GetLastError().empty())
  {
    throw UsageError("cannot render " + setup.Name + ": " + setup.Mapper->GetLastError());
  }
}

void WritePNG(vtkImageData* image, const std::string& path)
{
  if (!deepshadow::WritePNG(image, path))
  {
    throw UsageError("cannot write " + path);
  }
}

void WritePNG(vtkDeepShadowRenderWindow* window, const std::string& path)
{
  WritePNG(ToImageData(CaptureWindow(window)), path);
}

}
}
