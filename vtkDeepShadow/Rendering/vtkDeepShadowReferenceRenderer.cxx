#include "vtkDeepShadowReferenceRenderer.h"

#include "CoreAdapter.h"
#include "Core/ReferenceRenderer.h"
#include "Core/ShadowSubsampling.h"
#include "Core/Shadows.h"
#include "Volume/DrawnScalars.h"
#include "vtkDeepShadowImageConversion.h"
#include "vtkDeepShadowPass.h"
#include "vtkDeepShadowTechnique.h"
#include "vtkDeepShadowPolyDataMapper.h"
#include "vtkDeepShadowVolumeMapper.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkActor.h"
#include "vtkActorCollection.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkLightCollection.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeCollection.h"
#include "vtkVolumeMapper.h"
#include "vtkVolumeProperty.h"

#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cstring>
#include <stdexcept>

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

namespace
{
// The renderer's camera, lights, background and lighting model: what the scene takes from
// vtkRenderer itself.
deepshadow::Scene MakeSceneFrame(vtkRenderer* renderer)
{
  deepshadow::Scene scene;
  scene.View = adapter::MakeCamera(renderer);
  scene.Lights = adapter::MakeLights(renderer);
  double background[3], ambient[3];
  renderer->GetBackground(background);
  renderer->GetAmbient(ambient);
  scene.Background = { background[0], background[1], background[2] };
  scene.AmbientLight = { ambient[0], ambient[1], ambient[2] };
  scene.TwoSidedLighting = renderer->GetTwoSidedLighting() != 0;
  return scene;
}

// One visible volume as the reference renders it: its grid, transfer, material, technique
// parameters and bound, as the GPU mapper builds them. False, with `error`, when the data or
// the bound cannot be converted.
// Several components: combined as VTK's mapper combines them, each independent one with its
// own gradient opacity (Core/Components.h).
bool AddComponents(vtkVolumeMapper* mapper, vtkVolume* volume, vtkImageData* image,
  const deepshadow::DrawnScalars& drawn, bool replaceNonFinite, double unitScale, deepshadow::VolumeInstance& instance,
  std::string& error)
{
  vtkVolumeProperty* property = volume->GetProperty();
  const std::shared_ptr<const deepshadow::VolumeGrid>& grid = instance.Grid;
  deepshadow::ComponentSet set;
  error = adapter::MakeComponentSet(property, 1 + static_cast<int>(drawn.GetOtherComponents().size()),
    image->GetPointData()->GetScalars()->GetDataType(), unitScale, set);
  if (!error.empty())
  {
    return false;
  }
  for (const auto& other : drawn.GetOtherComponents())
  {
    auto otherGrid = adapter::MakeVolumeGrid(other, volume->GetMatrix(), replaceNonFinite, error);
    if (!otherGrid)
    {
      return false;
    }
    set.Others.push_back(otherGrid);
  }
  std::vector<glm::dvec2> ranges{ grid->GetRange() };
  for (const auto& other : set.Others)
  {
    ranges.push_back(other->GetRange());
  }
  set.Gradients = adapter::MakeComponentGradients(mapper, property, ranges, glm::make_vec3(image->GetSpacing()));
  instance.Components = std::move(set);
  return true;
}

// What scales or replaces a sample's opacity: a mask or label map, gradient opacity (of one
// component or of dependent ones), a 2D transfer function.
bool AddOpacityFactors(vtkVolumeMapper* mapper, vtkVolume* volume, vtkImageData* image, bool several,
  deepshadow::VolumeInstance& instance, std::string& error)
{
  vtkVolumeProperty* property = volume->GetProperty();
  const std::shared_ptr<const deepshadow::VolumeGrid>& grid = instance.Grid;
  auto* gpuMapper = vtkGPUVolumeRayCastMapper::SafeDownCast(mapper);
  if (vtkImageData* mask = gpuMapper && !several ? adapter::UsableMask(gpuMapper, image) : nullptr)
  {
    instance.Mask = adapter::MakeVolumeGrid(mask, volume->GetMatrix(), false, error);
    if (!instance.Mask)
    {
      error = "the mask: " + error;
      return false;
    }
    if (gpuMapper->GetMaskType() == vtkGPUVolumeRayCastMapper::LabelMapMaskType)
    {
      // A label map without labels (or blended away) changes nothing, as in VTK's mapper.
      instance.Labels = adapter::MakeLabelMap(gpuMapper, property, instance.Mask->GetRange());
      if (!instance.Labels)
      {
        instance.Mask = nullptr;
      }
    }
  }
  if (!several)
  {
    instance.Gradient = adapter::MakeGradientOpacity(mapper, property, grid->GetRange(),
      glm::make_vec3(image->GetSpacing()));
  }
  else if (instance.Components->Mode != deepshadow::ComponentMode::Independent)
  {
    instance.Gradient = adapter::MakeDependentGradientOpacity(mapper, property, grid->GetRange(),
      instance.Components->Others.back()->GetRange(), glm::make_vec3(image->GetSpacing()));
  }
  if (vtkImageData* function = adapter::UsableTransfer2D(mapper, property, several ? 2 : 1, error))
  {
    instance.Function2D = std::make_shared<deepshadow::Transfer2D>(
      adapter::MakeTransfer2D(function, grid->GetRange(), glm::make_vec3(image->GetSpacing()), true));
  }
  else if (!error.empty())
  {
    return false;
  }
  return true;
}

bool MakeVolumeInstance(vtkRenderer* renderer, vtkVolume* volume, vtkVolumeMapper* mapper,
  bool replaceNonFinite, bool groundTruth, bool keyLit, std::vector<deepshadow::Light>& lights,
  deepshadow::VolumeInstance& instance, std::string& error)
{
  // The array the mapper selects, as its point scalars (cell scalars resampled as drawn).
  deepshadow::DrawnScalars drawn;
  vtkImageData* image = drawn.Update(mapper, vtkImageData::SafeDownCast(mapper->GetDataSetInput()), error);
  if (!error.empty())
  {
    return false;
  }
  auto grid = adapter::MakeVolumeGrid(image, volume->GetMatrix(), replaceNonFinite, error);
  if (!grid)
  {
    return false;
  }
  grid->SetGradientReach(drawn.FromCells() ? 2 : 1); // cells are two voxels of the drawn grid
  instance.Grid = grid;
  vtkVolumeProperty* property = volume->GetProperty();
  // Opacity per dataset unit, as the mapper (and VTK's) integrates it.
  const double unitScale = adapter::DatasetLengthScale(volume->GetMatrix());
  instance.Transfer = adapter::MakeTransferFunction(property, unitScale);
  instance.Surface = adapter::MakeMaterial(property);
  instance.Shade = property->GetShade(0) != 0;
  instance.Sampling = property->GetInterpolationType() == VTK_NEAREST_INTERPOLATION
    ? deepshadow::Interpolation::Nearest
    : deepshadow::Interpolation::Linear;
  // Several components: combined as VTK's mapper combines them, composite only (the mapper
  // says so once for isosurfaces or a mask).
  const bool several = !drawn.GetOtherComponents().empty();
  if (several && !AddComponents(mapper, volume, image, drawn, replaceNonFinite, unitScale, instance, error))
  {
    return false;
  }
  auto* ours = vtkDeepShadowVolumeMapper::SafeDownCast(mapper);
  instance.Projection = adapter::MakeProjection(mapper, grid->GetRange());
  const bool projection = instance.Projection.Mode != deepshadow::BlendMode::Composite;
  instance.Shade = instance.Shade && !projection; // projections are unlit and unshadowed
  // Shaded as the mapper shades: VTK's mapper, and ours by default, as the VTK built with.
  // (The path VTK's mapper would reach from the one ours has: VTK 9.1's never goes back.)
  const bool blinnPhong = ours && ours->GetShadingModel() == vtkDeepShadowVolumeMapper::BLINN_PHONG_SHADING;
  const int path = static_cast<int>(adapter::NextVTKLightingPath(
    static_cast<deepshadow::ShadingPath>(ours ? ours->GetVTKLightingComplexity() : 0), renderer));
  instance.Shading = adapter::MakeVolumeShading(renderer, volume, image,
    vtkImageData::SafeDownCast(mapper->GetDataSetInput()), grid->GetIndexToWorld(),
    blinnPhong ? deepshadow::ShadingModel::BlinnPhong : deepshadow::ShadingModel::VTK,
    static_cast<deepshadow::ShadingPath>(path), keyLit, lights);
  instance.IsoValues = several ? std::vector<double>() : adapter::MakeIsoValues(mapper, property);
  bool anisotropic = false;
  instance.DatasetScale = adapter::DatasetLengthScale(volume->GetMatrix(), &anisotropic);
  if (anisotropic && !projection && instance.IsoValues.empty())
  {
    instance.WorldToDataset = glm::inverse(glm::dmat3(adapter::ToGlm(volume->GetMatrix())));
  }
  if (!AddOpacityFactors(mapper, volume, image, several, instance, error))
  {
    return false;
  }
  vtkDeepShadowTechnique* technique = ours && !projection ? ours->GetShadowTechnique() : nullptr;
  if (technique)
  {
    instance.Shadows = technique->GetParameters();
    if (technique->GetShadowProperty())
    {
      instance.ShadowTransfer = adapter::MakeTransferFunction(technique->GetShadowProperty(), unitScale);
    }
  }
  std::vector<vtkPolyData*> bounds;
  std::string expression;
  if (ours)
  {
    ours->GetDrawnRegion(volume, bounds, expression); // bounds, clipping planes, cropping
  }
  if (!bounds.empty())
  {
    // The mapper's bound, built the same way (in the data's coordinates).
    instance.Bound = adapter::MakeBoundRegion(bounds, expression,
      glm::inverse(adapter::IndexToWorld(image, nullptr)), error);
    if (!instance.Bound)
    {
      return false;
    }
  }
  if (groundTruth)
  {
    // Coloured when the technique is: the truth of the model it approximates.
    instance.Shadows = deepshadow::ShadowParameters::GroundTruth(instance.Shadows.IsColored());
  }
  return true;
}

// The GPU mapper's parameters, taken from the first volume that has one (`volumeCount`: the
// volumes in the scene so far, this one included).
void TakeMapperSettings(vtkDeepShadowVolumeMapper* ours, bool gpuTwin, size_t volumeCount,
  double& sampleDistance, deepshadow::MarchSettings& settings)
{
  if (sampleDistance <= 0.0)
  {
    sampleDistance = ours->GetSampleDistance();
  }
  if (gpuTwin && volumeCount == 1)
  {
    settings = deepshadow::MarchSettings::GpuTwin(0.0, ours->GetTransferTableSize(),
      ours->GetJitter(), ours->GetJitterSeed(), ours->GetTerminationOpacity());
  }
  if (ours->GetOutputMode() == vtkDeepShadowVolumeMapper::OutputShadowTerm)
  {
    settings.Output = deepshadow::RenderOutput::ShadowTerm;
  }
}

// Meshes of vtkDeepShadowPolyDataMapper: drawn, and cast when they do (as vtkDeepShadowPass).
// Also takes the first mapper's shadow bias as the scene's receiver bias.
void GatherMeshes(vtkRenderer* renderer, deepshadow::Scene& scene,
  std::vector<deepshadow::SurfaceMesh>& drawn, std::vector<deepshadow::SurfaceMesh>& casting)
{
  vtkCollectionSimpleIterator it;
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
}

// Without volumes there is nothing to march: the picture (and its shadow term) is the
// background.
void FillBackground(const deepshadow::Scene& scene, deepshadow::Image& image, deepshadow::Image* shadowTerm)
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
}
}

bool vtkDeepShadowReferenceRenderer::Render(
  vtkRenderer* renderer, deepshadow::Image& image, deepshadow::Image* shadowTerm, deepshadow::Image* surfaceTerm)
{
  this->LastError.clear();
  deepshadow::Scene scene = MakeSceneFrame(renderer);

  double sampleDistance = this->SampleDistance;
  deepshadow::MarchSettings settings;
  vtkVolumeCollection* volumes = renderer->GetVolumes();
  vtkCollectionSimpleIterator it;
  // Lit as the GPU mapper lights it: a lone headlight becomes a key and a fill.
  bool keyLit = false;
  volumes->InitTraversal(it);
  while (vtkVolume* volume = volumes->GetNextVolume(it))
  {
    auto* ours = vtkDeepShadowVolumeMapper::SafeDownCast(volume->GetMapper());
    if (volume->GetVisibility() && ours && ours->GetShadowTechnique() && ours->GetHeadlightKeyLight())
    {
      scene.Lights = adapter::KeyForLoneHeadlight(renderer, scene.Lights, adapter::KeyLight(), &keyLit);
      break;
    }
  }
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
    deepshadow::VolumeInstance instance;
    if (!MakeVolumeInstance(renderer, volume, mapper, this->ReplaceNonFiniteScalars,
          this->Shadows == GroundTruthShadows, keyLit, scene.Lights, instance, error))
    {
      this->LastError = error;
      vtkErrorMacro(<< error);
      return false;
    }
    scene.Volumes.push_back(instance);
    if (auto* ours = vtkDeepShadowVolumeMapper::SafeDownCast(mapper))
    {
      TakeMapperSettings(ours, this->GpuTwin, scene.Volumes.size(), sampleDistance, settings);
    }
  }
  std::vector<deepshadow::SurfaceMesh> drawn, casting;
  GatherMeshes(renderer, scene, drawn, casting);
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
    FillBackground(scene, image, shadowTerm);
    if (surfaceTerm)
    {
      // No receiver anywhere.
      *surfaceTerm = deepshadow::Image(image.Width, image.Height);
      for (int y = 0; y < image.Height; ++y)
      {
        for (int x = 0; x < image.Width; ++x)
        {
          surfaceTerm->Set(x, y, glm::dvec3(-1.0));
        }
      }
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
    if (this->ShadowSubsampling > 1)
    {
      if (shadowTerm || surfaceTerm || settings.Output != deepshadow::RenderOutput::Color)
      {
        throw std::invalid_argument("subsampled shadows are drawn as the colour only");
      }
      image = deepshadow::RenderShadowSubsampled(scene, settings, this->ShadowSubsampling, this->Threads);
    }
    else
    {
      image = deepshadow::ReferenceRenderer::Render(scene, settings, this->Threads, shadowTerm, surfaceTerm);
    }
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
  os << indent << "ShadowSubsampling: " << this->ShadowSubsampling << "\n";
}
