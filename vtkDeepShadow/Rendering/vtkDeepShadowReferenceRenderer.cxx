#include "vtkDeepShadowReferenceRenderer.h"

#include "CoreAdapter.h"
#include "Core/ReferenceRenderer.h"
#include "Core/Shadows.h"
#include "vtkDeepShadowImageConversion.h"
#include "vtkDeepShadowPass.h"
#include "vtkDeepShadowTechnique.h"
#include "vtkDeepShadowPolyDataMapper.h"
#include "vtkDeepShadowVolumeMapper.h"
#include "vtkActor.h"
#include "vtkActorCollection.h"

#include "vtkImageData.h"
#include "vtkLightCollection.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeCollection.h"
#include "vtkVolumeMapper.h"
#include "vtkVolumeProperty.h"

#include <stdexcept>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cstring>

namespace adapter = deepshadow::adapter;

vtkStandardNewMacro(vtkDeepShadowReferenceRenderer);

void vtkDeepShadowReferenceRenderer::PrepareRenderer(vtkRenderer* renderer)
{
  if (renderer->GetLights()->GetNumberOfItems() == 0 && renderer->GetAutomaticLightCreation())
  {
    renderer->CreateLight();
  }
  renderer->ResetCameraClippingRange();
  renderer->UpdateLightsGeometryToFollowCamera();
}

bool vtkDeepShadowReferenceRenderer::Render(
  vtkRenderer* renderer, deepshadow::Image& image, deepshadow::Image* shadowTerm)
{
  this->LastError.clear();
  deepshadow::Scene scene;
  scene.View = adapter::MakeCamera(renderer);
  scene.Lights = adapter::MakeLights(renderer);
  double background[3], ambient[3];
  renderer->GetBackground(background);
  renderer->GetAmbient(ambient);
  scene.Background = { background[0], background[1], background[2] };
  scene.AmbientLight = { ambient[0], ambient[1], ambient[2] };
  scene.TwoSidedLighting = renderer->GetTwoSidedLighting() != 0;

  double sampleDistance = this->SampleDistance;
  deepshadow::MarchSettings settings;
  vtkVolumeCollection* volumes = renderer->GetVolumes();
  vtkCollectionSimpleIterator it;
  volumes->InitTraversal(it);
  while (vtkVolume* volume = volumes->GetNextVolume(it))
  {
    auto* mapper = vtkVolumeMapper::SafeDownCast(volume->GetMapper());
    if (!volume->GetVisibility() || !mapper)
    {
      continue;
    }
    if (mapper->GetNumberOfInputConnections(0) > 0)
    {
      mapper->Update();
    }
    std::string error;
    auto grid = adapter::MakeVolumeGrid(vtkImageData::SafeDownCast(mapper->GetDataSetInput()),
      volume->GetMatrix(), this->ReplaceNonFiniteScalars, error);
    if (!grid)
    {
      this->LastError = error;
      vtkErrorMacro(<< error);
      return false;
    }
    deepshadow::VolumeInstance instance;
    instance.Grid = grid;
    vtkVolumeProperty* property = volume->GetProperty();
    instance.Transfer = adapter::MakeTransferFunction(property);
    instance.Surface = adapter::MakeMaterial(property);
    instance.Shade = property->GetShade(0) != 0;
    instance.Sampling = property->GetInterpolationType() == VTK_NEAREST_INTERPOLATION
      ? deepshadow::Interpolation::Nearest
      : deepshadow::Interpolation::Linear;
    auto* ours = vtkDeepShadowVolumeMapper::SafeDownCast(mapper);
    vtkDeepShadowTechnique* technique = ours ? ours->GetShadowTechnique() : nullptr;
    if (technique)
    {
      instance.Shadows = technique->GetParameters();
      if (technique->GetShadowProperty())
      {
        instance.ShadowTransfer = adapter::MakeTransferFunction(technique->GetShadowProperty());
      }
    }
    if (ours && ours->GetNumberOfBounds() > 0)
    {
      // The mapper's bound, built the same way (in the data's coordinates).
      std::vector<vtkPolyData*> bounds;
      for (int b = 0; b < ours->GetNumberOfBounds(); ++b)
      {
        bounds.push_back(ours->GetBound(b));
      }
      auto* image = vtkImageData::SafeDownCast(mapper->GetDataSetInput());
      instance.Bound = adapter::MakeBoundRegion(bounds, ours->GetBoundExpression(),
        glm::inverse(adapter::IndexToWorld(image, nullptr)), error);
      if (!instance.Bound)
      {
        this->LastError = error;
        vtkErrorMacro(<< error);
        return false;
      }
    }
    if (this->Shadows == GroundTruthShadows)
    {
      // Coloured when the technique is: the truth of the model it approximates.
      instance.Shadows = deepshadow::ShadowParameters::GroundTruth(instance.Shadows.IsColored());
    }
    scene.Volumes.push_back(instance);

    // The GPU mapper's parameters, taken from the first volume that has one.
    if (ours)
    {
      if (sampleDistance <= 0.0)
      {
        sampleDistance = ours->GetSampleDistance();
      }
      if (this->GpuTwin && scene.Volumes.size() == 1)
      {
        settings = deepshadow::MarchSettings::GpuTwin(0.0, ours->GetTransferTableSize(),
          ours->GetJitter(), ours->GetJitterSeed(), ours->GetTerminationOpacity());
      }
      if (ours->GetOutputMode() == vtkDeepShadowVolumeMapper::OutputShadowTerm)
      {
        settings.Output = deepshadow::RenderOutput::ShadowTerm;
      }
    }
  }
  // Meshes of vtkDeepShadowPolyDataMapper: drawn, and cast when they do (as vtkDeepShadowPass).
  std::vector<deepshadow::SurfaceMesh> drawn, casting;
  vtkActorCollection* actors = renderer->GetActors();
  actors->InitTraversal(it);
  while (vtkActor* actor = actors->GetNextActor(it))
  {
    auto* mapper = vtkDeepShadowPolyDataMapper::SafeDownCast(actor->GetMapper());
    deepshadow::SurfaceMesh mesh;
    std::string error;
    if (!actor->GetVisibility() || !mapper || !mapper->GetSurfaceMesh(actor, mesh, error))
    {
      continue;
    }
    if (mapper->GetShadowBias() > 0.0 && !(scene.ReceiverBias > 0.0))
    {
      scene.ReceiverBias = mapper->GetShadowBias();
    }
    if (mapper->GetCastShadows())
    {
      casting.push_back(mesh);
    }
    drawn.push_back(std::move(mesh));
  }
  // The GPU twin peels translucent meshes into as many layers as the scene pass does...
  if (auto* pass = vtkDeepShadowPass::SafeDownCast(renderer->GetPass()))
  {
    scene.TranslucentLayers = this->GpuTwin ? pass->GetTranslucentLayers() : 0;
    // ... and stores what other volumes cast on grids of as many nodes.
    scene.OtherVolumeShadowSize = this->GpuTwin ? pass->GetOtherVolumeShadowSize() : 0;
    scene.VolumeSegments = this->GpuTwin ? pass->GetVolumeSegments() : 0;
  }
  try
  {
    if (!drawn.empty())
    {
      scene.Surfaces = std::make_shared<const deepshadow::SurfaceSet>(std::move(drawn));
    }
    if (!casting.empty())
    {
      scene.CastingSurfaces = std::make_shared<const deepshadow::SurfaceSet>(std::move(casting));
    }
  }
  catch (const std::invalid_argument& e)
  {
    this->LastError = e.what();
    vtkErrorMacro(<< this->LastError);
    return false;
  }
  if (scene.Volumes.empty())
  {
    image = deepshadow::Image(scene.View.GetWidth(), scene.View.GetHeight());
    for (int y = 0; y < image.Height; ++y)
    {
      for (int x = 0; x < image.Width; ++x)
      {
        image.Set(x, y, scene.Background);
      }
    }
    if (shadowTerm)
    {
      *shadowTerm = image;
    }
    return true;
  }
  if (sampleDistance <= 0.0)
  {
    sampleDistance =
      deepshadow::DefaultSampleDistance(scene.Volumes.front().Grid->GetIndexToWorld());
  }
  settings.SampleDistance = sampleDistance;
  try
  {
    image = deepshadow::ReferenceRenderer::Render(scene, settings, this->Threads, shadowTerm);
  }
  catch (const std::invalid_argument& e)
  {
    this->LastError = e.what();
    vtkErrorMacro(<< this->LastError);
    return false;
  }
  return true;
}

bool vtkDeepShadowReferenceRenderer::Render(vtkRenderer* renderer, vtkImageData* output)
{
  deepshadow::Image image;
  if (!this->Render(renderer, image))
  {
    return false;
  }
  output->DeepCopy(deepshadow::ToImageData(image));
  return true;
}

void vtkDeepShadowReferenceRenderer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SampleDistance: " << this->SampleDistance << "\n";
  os << indent << "GpuTwin: " << this->GpuTwin << "\n";
  os << indent << "Shadows: " << (this->Shadows == GroundTruthShadows ? "ground truth" : "technique") << "\n";
  os << indent << "Threads: " << this->Threads << "\n";
}
