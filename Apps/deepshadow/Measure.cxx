#include "Measure.h"

#include "Json.h"

#include "vtkDeepShadowImageConversion.h"
#include "vtkDeepShadowPass.h"
#include "vtkDeepShadowPolyDataMapper.h"
#include "vtkDeepShadowRayTechnique.h"
#include "vtkDeepShadowReferenceRenderer.h"
#include "vtkDeepShadowRenderWindow.h"
#include "vtkDeepShadowTechnique.h"
#include "vtkDeepShadowVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkRenderer.h"
#include "vtkTransform.h"

#include <chrono>
#include <cmath>
#include <limits>

namespace deepshadow
{
namespace tool
{

void SetStatistics(Json& json, const vtkDeepShadowTechnique::Statistics& statistics)
{
  for (const auto& statistic : statistics)
  {
    const double value = statistic.second;
    // Counts and bytes stay whole numbers in the JSON.
    if (value == std::floor(value) && std::fabs(value) < 9.0e15)
    {
      json.Set(statistic.first, static_cast<long long>(value));
    }
    else
    {
      json.Set(statistic.first, value);
    }
  }
}

SceneBench::SceneBench(const Options& options, const std::string& name)
  : Settings(options)
{
  if (!name.empty())
  {
    this->Settings.Scene = name;
    this->Settings.VolumeFile.clear();
  }
  else if (this->Settings.Lights.empty())
  {
    // A file has no key light of its own (VTK's headlight casts nothing the camera sees):
    // one from the upper right front, as the head scene's.
    LightSpec key;
    key.Vector = { { 1.0, 1.0, 1.0 } };
    this->Settings.Lights.push_back(key);
  }
  this->Settings.Technique = "none";
  this->Scene = SceneSetup::Build(this->Settings);
  this->StartCamera->DeepCopy(this->Scene.Renderer->GetActiveCamera());
  this->Key = vtkLight::SafeDownCast(this->Scene.Renderer->GetLights()->GetItemAsObject(0));
  this->Key->GetPosition(this->StartPosition);
  RenderFrame(this->Scene.Window);
  RequireDrawn(this->Scene);
}

void SceneBench::Restore()
{
  this->Scene.Renderer->GetActiveCamera()->DeepCopy(this->StartCamera);
  this->Key->SetPosition(this->StartPosition);
  this->Scene.Renderer->ResetCameraClippingRange();
}

void SceneBench::Orbit()
{
  this->Scene.Renderer->GetActiveCamera()->Azimuth(3.0);
  this->Scene.Renderer->ResetCameraClippingRange();
}

void SceneBench::TurnLight()
{
  // The key light's direction turns by 3 degrees about the view-up.
  const double* focal = this->Key->GetFocalPoint();
  double* up = this->Scene.Renderer->GetActiveCamera()->GetViewUp();
  vtkNew<vtkTransform> turn;
  turn->Translate(focal[0], focal[1], focal[2]);
  turn->RotateWXYZ(3.0, up);
  turn->Translate(-focal[0], -focal[1], -focal[2]);
  double position[3];
  this->Key->GetPosition(position);
  turn->TransformPoint(position, position);
  this->Key->SetPosition(position);
}

Image SceneBench::Capture(bool shadowTerm)
{
  // Every mapper of the scene shows the same thing (the CPU reference renders one output).
  const auto show = [this](bool term) {
    for (vtkDeepShadowVolumeMapper* mapper : { this->Scene.Mapper.Get(), this->Scene.SecondMapper.Get() })
    {
      if (mapper)
      {
        mapper->SetOutputMode(term ? vtkDeepShadowVolumeMapper::OutputShadowTerm : vtkDeepShadowVolumeMapper::OutputColor);
      }
    }
    for (vtkDeepShadowPolyDataMapper* mesh : this->Scene.Meshes)
    {
      mesh->SetOutputMode(term ? vtkDeepShadowPolyDataMapper::OutputShadowTerm : vtkDeepShadowPolyDataMapper::OutputColor);
    }
  };
  show(shadowTerm);
  this->Scene.Window->SetSize(this->Settings.ErrorWidth, this->Settings.ErrorHeight);
  RenderFrame(this->Scene.Window);
  Image image = CaptureWindow(this->Scene.Window);
  this->Scene.Window->SetSize(this->Settings.Width, this->Settings.Height);
  show(false);
  return image;
}

Measurement SceneBench::Measure(vtkDeepShadowTechnique* technique, bool shadowTerm,
  vtkDeepShadowTechnique* second, bool lightMoves)
{
  Measurement m;
  vtkDeepShadowVolumeMapper* mapper = this->Scene.Mapper;
  vtkDeepShadowVolumeMapper* secondMapper = this->Scene.SecondMapper;
  second = secondMapper ? second : nullptr;
  this->Use(technique, second);
  const auto builds = [&]() { return mapper->GetShadowBuilds() + (secondMapper ? secondMapper->GetShadowBuilds() : 0); };
  this->Restore();
  RenderFrame(this->Scene.Window); // warm-up: builds and compiles
  RequireDrawn(this->Scene);
  const double warmUpBuildMs = technique
    ? technique->GetLastBuildMilliseconds() + (second ? second->GetLastBuildMilliseconds() : 0.0)
    : 0.0;
  const int buildsBefore = builds();
  std::vector<double> times;
  for (int f = 0; f < this->Settings.Frames; ++f)
  {
    this->Orbit();
    times.push_back(RenderFrame(this->Scene.Window));
  }
  // No timed frames (report --frames 0, errors only): not measured.
  const double unmeasured = std::numeric_limits<double>::quiet_NaN();
  m.CameraMs = times.empty() ? unmeasured : Median(times);
  m.CameraPasses = mapper->GetLastPasses();
  m.Features = mapper->GetShaderFeatures();
  m.RebuiltForCamera = builds() != buildsBefore;
  if (technique)
  {
    m.Statistics = technique->GetStatistics();
  }
  this->Restore();
  // Every light-moving frame rebuilds: the build time is the median of theirs.
  times.clear();
  std::vector<double> buildTimes;
  for (int f = 0; lightMoves && f < this->Settings.Frames; ++f)
  {
    this->TurnLight();
    times.push_back(RenderFrame(this->Scene.Window));
    if (technique)
    {
      buildTimes.push_back(technique->GetLastBuildMilliseconds() + (second ? second->GetLastBuildMilliseconds() : 0.0));
    }
  }
  m.LightMs = times.empty() ? unmeasured : Median(times);
  m.BuildMs = buildTimes.empty() ? warmUpBuildMs : Median(buildTimes);
  this->Restore();
  m.Picture = this->Capture(false);
  if (shadowTerm)
  {
    m.ShadowTerm = this->Capture(true);
  }
  if (technique)
  {
    m.ShadowBytes = technique->GetShadowBytes() + (second ? second->GetShadowBytes() : 0) +
      (this->Scene.Pass ? this->Scene.Pass->GetOtherVolumeShadowBytes() : 0);
  }
  this->Use(nullptr, nullptr);
  return m;
}

void SceneBench::Use(vtkDeepShadowTechnique* technique, vtkDeepShadowTechnique* second)
{
  this->Scene.Mapper->SetShadowTechnique(technique);
  if (this->Scene.SecondMapper)
  {
    this->Scene.SecondMapper->SetShadowTechnique(second);
  }
}

Image SceneBench::Picture(vtkDeepShadowTechnique* technique, vtkDeepShadowTechnique* second)
{
  this->Use(technique, second);
  this->Restore();
  RenderFrame(this->Scene.Window);
  RequireDrawn(this->Scene);
  Image picture = CaptureWindow(this->Scene.Window);
  this->Use(nullptr, nullptr);
  return picture;
}

Image SceneBench::TwinSurfaceTerm(vtkDeepShadowTechnique* technique, vtkDeepShadowTechnique* second)
{
  this->Use(technique, second);
  this->Restore();
  this->Scene.Window->SetSize(this->Settings.ErrorWidth, this->Settings.ErrorHeight);
  RenderFrame(this->Scene.Window); // lights and clipping as the ground truth has them
  vtkNew<vtkDeepShadowReferenceRenderer> reference;
  Image picture, surface;
  if (!reference->Render(this->Scene.Renderer, picture, nullptr, &surface))
  {
    throw std::runtime_error("the CPU twin failed: " + reference->GetLastError());
  }
  this->Scene.Window->SetSize(this->Settings.Width, this->Settings.Height);
  this->Use(nullptr, nullptr);
  return surface;
}

const GroundTruth& SceneBench::Truth(bool colored)
{
  GroundTruth& truth = this->Truths[colored ? 1 : 0];
  if (this->HaveTruth[colored ? 1 : 0])
  {
    return truth;
  }
  vtkNew<vtkDeepShadowRayTechnique> model; // says only grey or coloured
  model->SetColored(colored);
  vtkNew<vtkDeepShadowRayTechnique> secondModel; // a second volume casts and receives too
  secondModel->SetColored(colored);
  this->Use(model, secondModel);
  this->Restore();
  this->Scene.Window->SetSize(this->Settings.ErrorWidth, this->Settings.ErrorHeight);
  RenderFrame(this->Scene.Window); // lights and clipping as the GPU frames have them
  vtkNew<vtkDeepShadowReferenceRenderer> reference;
  reference->SetShadows(vtkDeepShadowReferenceRenderer::GroundTruthShadows);
  const auto start = std::chrono::steady_clock::now();
  if (!reference->Render(this->Scene.Renderer, truth.Picture, &truth.ShadowTerm, &truth.SurfaceTerm))
  {
    throw std::runtime_error("the ground truth failed: " + reference->GetLastError());
  }
  truth.Milliseconds =
    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  this->Scene.Window->SetSize(this->Settings.Width, this->Settings.Height);
  this->Use(nullptr, nullptr);
  this->HaveTruth[colored ? 1 : 0] = true;
  return truth;
}

}
}
