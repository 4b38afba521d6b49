#include "vtkDeepShadowVolumeMapper.h"
#include "vtkDeepShadowVolumeMapperInternals.h"

#include "CoreAdapter.h"
#include "PassFrame.h"
#include "ShaderComposer.h"
#include "Shadows/OtherVolumeShadows.h"
#include "Translucency/TranslucentLayers.h"
#include "RayCast/RayCastFrame.h"
#include "GL/UniformSink.h"
#include "Sampling/ShadowContext.h"
#include "RayCast/UnsupportedSettings.h"
#include "RayCast/VolumeFeatures.h"
#include "vtkDeepShadowTechniqueInternals.h"
#include "vtkDeepShadowVolumeFS.h"
#include "vtkDeepShadowVolumeVS.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLShaderProperty.h"
#include "vtkOpenGLUniforms.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkPolyData.h"
#include "vtkPropCollection.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtk_glew.h"

#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>

namespace adapter = deepshadow::adapter;

vtkStandardNewMacro(vtkDeepShadowVolumeMapper);

namespace
{
// deepshadow::CheckRaySamples for this frame: any view ray and feeler on every GL (the box's
// diagonal, whatever the camera); on llvmpipe, whose loop limit counts the iterations of every
// loop a ray's invocation runs, also this frame's view rays with what each sample's lighting
// loop and fixed-size shadow lookups add.
std::string CheckRaySamples(
  const deepshadow::ShadowContext& context, vtkDeepShadowTechnique* technique, const deepshadow::Camera& camera)
{
  const double diagonal = deepshadow::LongestPath(context.IndexToWorld, context.Dims);
  std::string problem = deepshadow::CheckRaySamples(diagonal, context.ViewStep, "the sample distance");
  if (problem.empty() && technique)
  {
    problem = deepshadow::CheckRaySamples(
      diagonal, technique->GetStepFactor() * context.ShadowStep, "the shadow step (sample distance x StepFactor)");
  }
  const char* gl = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  if (!problem.empty() || !gl || !std::strstr(gl, "llvmpipe"))
  {
    return problem;
  }
  double shadowed = 0.0;
  for (const deepshadow::Light& light : context.Lights)
  {
    shadowed += light.ShadowAttenuation > 0.0 ? 1.0 : 0.0;
  }
  const double lookups = technique ? technique->GetLookupLoopIterations() : 0.0;
  const double perSample = 1.0 + static_cast<double>(context.Lights.size()) + shadowed * lookups;
  // The longest view path: along the camera's direction (parallel), or towards the box's
  // corners and centre (perspective); the diagonal if none is in front of the camera.
  const glm::dvec3 extent = glm::dvec3(context.Dims - 1);
  double longest = 0.0;
  bool seen = false;
  for (int c = 0; c < 9; ++c)
  {
    const glm::dvec3 index = c < 8 ? glm::dvec3((c & 1) * extent.x, ((c >> 1) & 1) * extent.y, ((c >> 2) & 1) * extent.z)
                                   : 0.5 * extent;
    double x = 0.0, y = 0.0;
    if (camera.Project(glm::dvec3(context.IndexToWorld * glm::dvec4(index, 1.0)), x, y))
    {
      const glm::dvec3 direction = camera.RayThrough(x, y).Direction;
      longest = std::max(longest, deepshadow::LongestPathAlong(context.IndexToWorld, context.Dims, direction));
      seen = true;
    }
  }
  longest = seen ? longest : diagonal;
  return deepshadow::CheckRaySamples(longest, context.ViewStep, "on llvmpipe, the sample distance", perSample);
}

// AutoAdjustSampleDistances: a window that asks for this many frames a second or more is being
// interacted with (vtkSmartVolumeMapper's InteractiveUpdateRate); its view rays step this much
// coarser.
constexpr double InteractiveUpdateRate = 1.0;
constexpr double InteractiveStepFactor = 2.0;

// Visible props other than volumes that draw opaque geometry into the depth buffer.
bool HasOpaqueGeometry(vtkRenderer* renderer)
{
  vtkPropCollection* props = renderer->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    if (prop->GetVisibility() && !vtkVolume::SafeDownCast(prop) && prop->HasOpaqueGeometry())
    {
      return true;
    }
  }
  return false;
}
}

vtkDeepShadowVolumeMapper::vtkDeepShadowVolumeMapper()
  : TerminationOpacity(deepshadow::DefaultTerminationOpacity)
  , Impl(new Internals)
{
  // Ours where VTK's defaults differ: the sample distance follows the spacing (0), and it is
  // not re-chosen from the frame-time budget unless asked for.
  this->SampleDistance = 0.0f;
  this->AutoAdjustSampleDistances = 0;
}

vtkDeepShadowVolumeMapper::~vtkDeepShadowVolumeMapper()
{
  this->SetShadowTechnique(nullptr);
}

void vtkDeepShadowVolumeMapper::SetTerminationOpacity(double opacity)
{
  if (std::isnan(opacity))
  {
    vtkErrorMacro("SetTerminationOpacity(nan): the termination opacity must be a number in "
                  "[0, 1]; it stays " << this->TerminationOpacity);
    return;
  }
  opacity = std::clamp(opacity, 0.0, 1.0);
  if (opacity != this->TerminationOpacity)
  {
    this->TerminationOpacity = opacity;
    this->Modified();
  }
}

double* vtkDeepShadowVolumeMapper::GetBounds()
{
  double* bounds = this->Superclass::GetBounds();
  vtkImageData* input = this->GetImageInput();
  if (!input)
  {
    return bounds;
  }
  // VTK's renderer culls a volume whose bounds are NaN, or too small for its camera (1e-30),
  // before Render() could say why: said here (once; Render() says the same).
  vtkDataArray* scalars = nullptr;
  std::string problem = adapter::CheckVolumeInput(input, scalars);
  if (problem.empty())
  {
    const int* dims = input->GetDimensions();
    problem = adapter::CheckVolumePlacement(
      adapter::IndexToWorld(input, nullptr), glm::ivec3(dims[0], dims[1], dims[2]));
  }
  if (!problem.empty())
  {
    this->ReportError(problem);
  }
  return bounds;
}

void vtkDeepShadowVolumeMapper::SetShadowTechnique(vtkDeepShadowTechnique* technique)
{
  if (technique == this->ShadowTechnique)
  {
    return;
  }
  if (this->ShadowTechnique)
  {
    // Its maps and caches would otherwise stay on the GPU (about 18 MB each time here).
    if (vtkOpenGLRenderWindow* window = this->Impl->Window)
    {
      window->MakeCurrent();
      this->ShadowTechnique->ReleaseGraphicsResources(window);
    }
    this->ShadowTechnique->UnRegister(this);
  }
  this->ShadowTechnique = technique;
  if (technique)
  {
    technique->Register(this);
  }
  this->Modified();
}

void vtkDeepShadowVolumeMapper::AddBound(vtkPolyData* bound)
{
  this->Impl->Bounds.emplace_back(bound);
  this->Modified();
}

void vtkDeepShadowVolumeMapper::RemoveAllBounds()
{
  if (!this->Impl->Bounds.empty())
  {
    this->Impl->Bounds.clear();
    this->Modified();
  }
}

int vtkDeepShadowVolumeMapper::GetNumberOfBounds() const
{
  return static_cast<int>(this->Impl->Bounds.size());
}

vtkPolyData* vtkDeepShadowVolumeMapper::GetBound(int index) const
{
  return index >= 0 && index < this->GetNumberOfBounds() ? this->Impl->Bounds[static_cast<size_t>(index)].Get()
                                                          : nullptr;
}

void vtkDeepShadowVolumeMapper::SetBoundExpression(const std::string& expression)
{
  if (expression != this->BoundExpression)
  {
    this->BoundExpression = expression;
    this->Modified();
  }
}

int vtkDeepShadowVolumeMapper::GetShadowBuilds()
{
  return this->ShadowTechnique ? this->ShadowTechnique->GetBuildCount() : 0;
}

int vtkDeepShadowVolumeMapper::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  if (port > 0)
  {
    // VTK's mapper takes more volumes on ports 1..9 (vtkMultiVolume); ours draws port 0.
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

void vtkDeepShadowVolumeMapper::ReportError(const std::string& message)
{
  // Said once while it lasts: a failure repeated every frame is not repeated in the log.
  if (message != this->LastError)
  {
    vtkErrorMacro(<< message);
  }
  this->LastError = message;
  this->ErrorThisFrame = true;
}

vtkImageData* vtkDeepShadowVolumeMapper::GetImageInput()
{
  std::string problem;
  vtkImageData* drawn = this->Impl->Drawn.Update(this, vtkImageData::SafeDownCast(this->GetDataSetInput()), problem);
  if (!problem.empty())
  {
    this->ReportError(problem);
  }
  return drawn;
}

double vtkDeepShadowVolumeMapper::GetEffectiveSampleDistance()
{
  return this->Impl->EffectiveStep;
}

void vtkDeepShadowVolumeMapper::Update()
{
  if (this->GetNumberOfInputConnections(0) == 0)
  {
    // vtkVolume updates its mapper every frame, then skips drawing without an input.
    vtkDataArray* none = nullptr;
    this->ReportError(adapter::CheckVolumeInput(nullptr, none));
    return;
  }
  this->Superclass::Update();
}

void vtkDeepShadowVolumeMapper::AdoptWindow(vtkOpenGLRenderWindow* window)
{
  vtkOpenGLRenderWindow* previous = this->Impl->Window;
  if (previous == window)
  {
    return;
  }
  if (previous)
  {
    previous->MakeCurrent();
    this->ReleaseGraphicsResources(previous);
    window->MakeCurrent();
  }
  this->Impl->Window = window;
}

void vtkDeepShadowVolumeMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Impl->Release(window);
  if (this->ShadowTechnique)
  {
    this->ShadowTechnique->ReleaseGraphicsResources(window);
  }
}


void vtkDeepShadowVolumeMapper::GetDrawnRegion(
  vtkVolume* volume, std::vector<vtkPolyData*>& meshes, std::string& expression)
{
  Internals& impl = *this->Impl;
  meshes.clear();
  for (const auto& bound : impl.Bounds)
  {
    meshes.push_back(bound);
  }
  vtkImageData* input = this->GetImageInput();
  const std::vector<vtkPolyData*>& cut =
    input ? impl.Cut.Update(this, input, volume ? volume->GetMatrix() : nullptr) : std::vector<vtkPolyData*>();
  meshes.insert(meshes.end(), cut.begin(), cut.end());
  expression = deepshadow::CutRegion::Combine(
    static_cast<int>(impl.Bounds.size()), this->BoundExpression, static_cast<int>(cut.size()));
}

void vtkDeepShadowVolumeMapper::BeginFrame()
{
  this->ErrorThisFrame = false;
  if (!this->Impl->PreparedByPass)
  {
    this->LastPasses.clear();
  }
  this->Impl->PreparedByPass = false;
}

const deepshadow::ShadowContext* vtkDeepShadowVolumeMapper::PrepareShadows(
  vtkRenderer* renderer, vtkVolume* volume)
{
  Internals& impl = *this->Impl;
  if (!this->Frame)
  {
    return nullptr;
  }
  this->Frame->Prepared.erase(this);
  this->BeginFrame();
  deepshadow::RayCastFrame frame;
  // Receivers drawn before the volume read the structures built now.
  if (this->Prepare(renderer, volume, frame) && frame.Technique)
  {
    this->Frame->Prepared.insert_or_assign(this, frame.Context);
  }
  // The frame's Render() keeps what this found to do in LastPasses.
  impl.PreparedByPass = true;
  const auto prepared = this->Frame->Prepared.find(this);
  return prepared != this->Frame->Prepared.end() ? &prepared->second : nullptr;
}

bool vtkDeepShadowVolumeMapper::Prepare(vtkRenderer* renderer, vtkVolume* volume, deepshadow::RayCastFrame& frame)
{
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  if (!window)
  {
    this->ReportError("vtkDeepShadowVolumeMapper needs an OpenGL render window");
    return false;
  }
  this->AdoptWindow(window);
  this->Update();
  vtkImageData* input = this->GetImageInput();
  vtkVolumeProperty* property = volume->GetProperty();
  Internals& impl = *this->Impl;
  if (!input && !this->ErrorThisFrame && this->GetDataSetInput())
  {
    this->ReportError("the volume mapper's input is not a vtkImageData");
  }
  if (!input || !this->UpdateVolume(window, input))
  {
    return false;
  }
  const glm::dmat4 indexToWorld = adapter::IndexToWorld(input, volume->GetMatrix());
  std::string problem = adapter::CheckVolumePlacement(indexToWorld, impl.Volume.GetDims());
  if (problem.empty())
  {
    problem = adapter::CheckVolumeProperty(property);
  }
  if (!problem.empty())
  {
    this->ReportError(problem);
    return false;
  }
  this->ReadUserCodeAndSayUnsupported(volume, frame);
  // Opacity per dataset unit, as VTK's mapper integrates it under a scaled prop.
  const double unitScale = adapter::DatasetLengthScale(volume->GetMatrix());
  const glm::dmat4 worldToIndex = glm::inverse(indexToWorld);
  // The still step; while the interactor moves (the window asks for 1 frame a second or more,
  // as vtkSmartVolumeMapper decides) with AutoAdjustSampleDistances on, the view rays take
  // samples InteractiveStepFactor times farther apart and the shadows stay as built.
  const double stillStep = this->SampleStep(input, indexToWorld);
  const bool interactive = renderer->GetRenderWindow()->GetDesiredUpdateRate() >= InteractiveUpdateRate;
  const double step = this->AutoAdjustSampleDistances && interactive ? InteractiveStepFactor * stillStep : stillStep;
  impl.EffectiveStep = step;
  if (!this->UpdateSurfaces(window, worldToIndex))
  {
    return false;
  }
  const int filter = property->GetInterpolationType() == VTK_NEAREST_INTERPOLATION
    ? vtkTextureObject::Nearest
    : vtkTextureObject::Linear;
  impl.Volume.GetTexture()->SetMinificationFilter(filter);
  impl.Volume.GetTexture()->SetMagnificationFilter(filter);
  // Several components are projected, or drawn composite (UnsupportedSettings says so for
  // isosurface and slice blending).
  const bool several = !impl.Drawn.GetOtherComponents().empty();
  frame.Projection = adapter::MakeProjection(this, impl.Volume.GetRange());
  const bool projection = frame.Projection.Mode != deepshadow::BlendMode::Composite;
  frame.Context.IsoValues = several ? std::vector<double>() : adapter::MakeIsoValues(this, property);
  const bool isosurface = !frame.Context.IsoValues.empty();
  if (this->BlendMode == vtkVolumeMapper::ISOSURFACE_BLEND && !isosurface && !several)
  {
    ++this->RenderCount;
    return false; // no contour value: nothing to draw, as VTK's mapper (said by UnsupportedSettings)
  }
  if (!several && !this->UpdateOpacityFactors(window, property, input, frame))
  {
    return false;
  }
  // Projections but additive, and isosurfaces, look opacity up uncorrected (as VTK's
  // mapper): a step of one unit distance corrects nothing.
  const bool uncorrected = isosurface || (projection && !frame.Projection.CorrectsOpacity());
  this->UpdateTables(window, property,
    uncorrected ? property->GetScalarOpacityUnitDistance(0) * unitScale : step, unitScale);
  // The polyhedral bound: rebuilt when a bound, the expression or the data's placement changed.
  if (!this->UpdateBound(window, input, volume))
  {
    return false;
  }
  if (impl.Bound.GetTextures() && impl.Bound.EnclosesNothing())
  {
    this->LastError.clear();
    ++this->RenderCount;
    return false; // said when the bound was built
  }

  this->FillFrame(renderer, volume, frame, indexToWorld, stillStep, step, unitScale);
  frame.Context.LightLagDegrees = interactive ? this->InteractiveShadowLag : 0.0;
  frame.Interactive = interactive;
  // What the pass interleaves with this volume (translucent meshes, other volumes).
  frame.Layers = this->Frame ? this->Frame->LayersFor(this) : nullptr;
  frame.Segments = frame.Layers || !this->Frame
    ? nullptr
    : this->Frame->SegmentsFor(frame.Volume, frame.SegmentGuest);
  if (several && !this->UpdateComponents(window, property, step, uncorrected, unitScale, frame))
  {
    return false;
  }
  return this->PrepareLightsAndShadows(frame);
}

void vtkDeepShadowVolumeMapper::ReadUserCodeAndSayUnsupported(vtkVolume* volume, deepshadow::RayCastFrame& frame)
{
  Internals& impl = *this->Impl;
  // What VTK's mapper would draw and this one does not: said once each, never silent.
  this->Unsupported =
    deepshadow::UnsupportedSettings(this, this->GetImageInput(), impl.Drawn.FromCells(),
      1 + static_cast<int>(impl.Drawn.GetOtherComponents().size()), volume->GetProperty(), volume->GetMatrix(),
      this->ShadowTechnique != nullptr);
  // A vtkShaderProperty's fragment code, where our shader has its place (or refused, said).
  impl.UserCode = deepshadow::ReadUserShaderCode(volume);
  if (!impl.UserCode.Refusal.empty())
  {
    this->Unsupported.push_back(impl.UserCode.Refusal);
  }
  frame.UserCode = impl.UserCode.Empty() || !impl.UserCode.Refusal.empty() ? nullptr : &impl.UserCode;
  for (const std::string& setting : this->Unsupported)
  {
    if (std::find(this->UnsupportedSaid.begin(), this->UnsupportedSaid.end(), setting) ==
      this->UnsupportedSaid.end())
    {
      this->UnsupportedSaid.push_back(setting);
      vtkWarningMacro(<< setting);
    }
  }
}

void vtkDeepShadowVolumeMapper::FillFrame(vtkRenderer* renderer, vtkVolume* volume, deepshadow::RayCastFrame& frame,
  const glm::dmat4& indexToWorld, double stillStep, double step, double unitScale)
{
  // Viewport, camera, lights, and the volume as the GPU holds it (the tables, textures and
  // bound already up to date).
  Internals& impl = *this->Impl;
  vtkVolumeProperty* property = volume->GetProperty();
  const bool several = !impl.Drawn.GetOtherComponents().empty();
  const bool projection = frame.Projection.Mode != deepshadow::BlendMode::Composite;
  const bool isosurface = !frame.Context.IsoValues.empty();
  const glm::dmat4 worldToIndex = glm::inverse(indexToWorld);
  const bool nearest = property->GetInterpolationType() == VTK_NEAREST_INTERPOLATION;
  frame.Renderer = renderer;
  frame.Volume = volume;
  frame.Property = property;
  renderer->GetTiledSizeAndOrigin(&frame.Width, &frame.Height, &frame.X0, &frame.Y0);
  frame.View = adapter::MakeCamera(renderer);
  frame.Context.Eye = frame.View.Unproject(0.5 * frame.View.GetWidth(), 0.5 * frame.View.GetHeight(), 0.0);
  frame.Context.View = frame.View;
  frame.Shade = !projection && property->GetShade(0) != 0;
  bool anisotropic = false;
  frame.DatasetScale = adapter::DatasetLengthScale(volume->GetMatrix(), &anisotropic);
  if (anisotropic && !projection && !isosurface)
  {
    frame.WorldToDataset = glm::inverse(glm::dmat3(adapter::ToGlm(volume->GetMatrix())));
  }
  frame.ShadowTerm = !projection && this->OutputMode == OutputShadowTerm;
  frame.Lit = frame.Shade || (!projection && this->ShadowTechnique) || frame.ShadowTerm;
  frame.Transfer = impl.Transfer.GetTexture();
  deepshadow::ShadowContext& context = frame.Context;
  context.Window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  context.Volume = impl.Volume.GetTexture();
  // A projection counts clear samples too: nothing is skipped for being transparent; an
  // isosurface's crossings lie in clear blocks as well.
  // The block map knows component 0's opacity only.
  // (A vtkShaderProperty's code runs at every sample, as in VTK's mapper: nothing skipped.)
  // (The block map knows the volume's 1D opacity only, not a label map's or a 2D function's.)
  context.Occupancy = !projection && !isosurface && !several && !frame.UserCode && !context.LabelTable &&
      !context.Transfer2DImage &&
      this->EmptySpaceSkipping &&
      impl.Occupancy.AnyEmptyBlock()
    ? impl.Occupancy.GetTexture()
    : nullptr;
  context.EmptyBlocks = context.Occupancy ? &impl.Occupancy.GetMap() : nullptr;
  context.BlockSize = static_cast<float>(deepshadow::VolumeTexture::BlockSize);
  context.Dims = impl.Volume.GetDims();
  context.Range = impl.Volume.GetRange();
  context.ScalarMap = impl.Volume.GetScalarMap();
  context.GradientReach = impl.Drawn.FromCells() ? 2 : 1; // cells are two voxels of the drawn grid
  context.ShaderScalar = impl.Volume.GetShaderScalar();
  context.TableMap = impl.Transfer.GetTable().CoordinateMap();
  context.TableSize = this->TransferTableSize;
  context.Sampling = nearest ? deepshadow::Interpolation::Nearest : deepshadow::Interpolation::Linear;
  context.IndexToWorld = indexToWorld;
  context.WorldToIndex = worldToIndex;
  context.ViewStep = step;
  context.ShadowStep = stillStep;
  context.OpacityUnitScale = unitScale;
  context.DataVersion = this->VolumeUploads;
  context.Bound = impl.Bound.GetTextures();
  context.BoundVersion = this->BoundBuilds;
  const bool surfaces = impl.Surfaces && !impl.Surfaces->Empty();
  context.Surfaces = surfaces ? &impl.SurfacesGPU.GetTextures() : nullptr;
  context.CastingSurfaces = surfaces ? impl.Surfaces.get() : nullptr;
  context.SurfacesVersion = this->SurfaceUploads;
}

bool vtkDeepShadowVolumeMapper::PrepareLightsAndShadows(deepshadow::RayCastFrame& frame)
{
  deepshadow::ShadowContext& context = frame.Context;
  bool truncated = false;
  context.Lights = frame.Lit ? adapter::MakeLights(frame.Renderer, &truncated) : std::vector<deepshadow::Light>();
  bool keyLit = false;
  if (this->ShadowTechnique && this->HeadlightKeyLight)
  {
    context.Lights = adapter::KeyForLoneHeadlight(frame.Renderer, context.Lights, adapter::KeyLight(), &keyLit);
  }
  // As VTK's mapper picks it (9.1 never lowers it).
  if (frame.Shade)
  {
    this->VTKLightingComplexity = static_cast<int>(adapter::NextVTKLightingPath(
      static_cast<deepshadow::ShadingPath>(this->VTKLightingComplexity), frame.Renderer));
  }
  context.Shading = adapter::MakeVolumeShading(frame.Renderer, frame.Volume, this->GetImageInput(),
    this->GetImageInput(), context.IndexToWorld,
    this->ShadingModel == VTK_SHADING ? deepshadow::ShadingModel::VTK : deepshadow::ShadingModel::BlinnPhong,
    static_cast<deepshadow::ShadingPath>(this->VTKLightingComplexity), keyLit, context.Lights);
  if (truncated)
  {
    vtkWarningMacro("Only the first " << adapter::MaxLights << " lights are used");
  }
  std::string problem = adapter::CheckLights(context.Lights);
  if (!problem.empty())
  {
    this->ReportError(problem);
    return false;
  }
  // Projections are drawn exactly, without shadows (said once by UnsupportedSettings).
  vtkDeepShadowTechnique* technique =
    frame.Projection.Mode == deepshadow::BlendMode::Composite ? this->ShadowTechnique : nullptr;
  // A ray of more samples than a ray may take would be cut short (llvmpipe) or take hours.
  problem = CheckRaySamples(context, technique, frame.View);
  if (!problem.empty())
  {
    this->ReportError(problem);
    return false;
  }
  if (technique)
  {
    context.Transfer = adapter::MakeTransferFunction(frame.Property, context.OpacityUnitScale);
    // Shadows from the coarse grid while interacting (drawn so by Draw): structures rebuilt as
    // coarse.
    context.RebuildCoarsening = deepshadow::ShadowSubsampling(frame, this->InteractiveShadowSubsampling);
    const bool prepared = vtkDeepShadowTechnique::Internals::Prepare(technique, context);
    const std::vector<std::string>& passes = technique->GetLastPasses();
    this->LastPasses.insert(this->LastPasses.end(), passes.begin(), passes.end());
    if (!prepared)
    {
      // A defined picture: the volume without shadows, and the reason said once.
      this->ReportError("shadows are off: " + technique->GetLastError());
      technique = nullptr;
    }
  }
  frame.Technique = technique;
  return true;
}

void vtkDeepShadowVolumeMapper::Render(vtkRenderer* renderer, vtkVolume* volume)
{
  this->BeginFrame();
  deepshadow::RayCastFrame frame;
  if (!this->Prepare(renderer, volume, frame) || !this->Draw(frame))
  {
    return;
  }
  this->GPUMemoryBytes = this->GetHolderBytes();
  if (!this->ErrorThisFrame)
  {
    this->LastError.clear();
  }
  ++this->RenderCount;
}

bool vtkDeepShadowVolumeMapper::Draw(deepshadow::RayCastFrame& frame)
{
  Internals& impl = *this->Impl;
  vtkOpenGLRenderWindow* window = frame.Context.Window;
  frame.Jitter = this->UseJittering != 0;
  frame.JitterSeed = static_cast<int>(this->JitterSeed);
  frame.TerminationOpacity = static_cast<float>(this->TerminationOpacity);
  frame.Opaque = HasOpaqueGeometry(frame.Renderer) ? &impl.Opaque : nullptr;
  // Shadows of the other volumes, when they cast any (a volume receives with a technique).
  const deepshadow::OtherVolumeShadows* others =
    this->Frame ? this->Frame->OthersOnto(this) : nullptr;
  frame.Others = frame.Technique && others && others->Any() ? others : nullptr;

  if (frame.Opaque)
  {
    frame.Opaque->Capture(window, frame.X0, frame.Y0, frame.Width, frame.Height, false);
  }
  this->ShaderFeatures.clear();
  std::function<void()> begin, end;
  if (frame.Segments)
  {
    begin = [&] { frame.Segments->Begin(window, frame.SegmentGuest); };
    end = [&] { frame.Segments->End(window); };
  }
  // With layers the shader composited the opaque image itself; segments are not colours.
  const bool blend = !frame.Layers && !frame.Segments;

  // Decided once, before the technique prepared its structures for it.
  const int scale = frame.Technique ? frame.Context.RebuildCoarsening : 1;
  if (scale > 1 && !impl.Ratio.Allocate(window, frame.Width, frame.Height, scale))
  {
    this->ReportError("no room for the coarse grid of shadows while interacting: shadows per sample");
  }
  else if (scale > 1)
  {
    // Shadows from a coarser grid while interacting: its rays into the target, then every
    // pixel without the technique times their ratio.
    if (!this->DrawPass(deepshadow::CoarsePassOf(frame, scale), impl.LastCoarseSource, false,
          [&] { impl.Ratio.Begin(window); }, [&] { impl.Ratio.End(window); }))
    {
      return false;
    }
    this->LastPasses.emplace_back("ray-cast-coarse-shadows");
    if (!this->DrawPass(deepshadow::FullPassOf(frame, scale, impl.Ratio), impl.LastSource, blend, begin, end))
    {
      return false;
    }
    this->LastPasses.emplace_back("ray-cast");
    return true;
  }
  if (!this->DrawPass(frame, impl.LastSource, blend, begin, end))
  {
    return false;
  }
  this->LastPasses.emplace_back(frame.Segments ? "ray-cast-segments" : "ray-cast");
  return true;
}

bool vtkDeepShadowVolumeMapper::DrawPass(const deepshadow::RayCastFrame& frame, std::string& lastSource,
  bool blend, const std::function<void()>& begin, const std::function<void()>& end)
{
  Internals& impl = *this->Impl;
  vtkOpenGLRenderWindow* window = frame.Context.Window;
  // The shader for the features in use.
  const deepshadow::ComposedFeatures features = deepshadow::ComposeVolumeFeatures(frame);
  const std::string source = deepshadow::ComposeShader(vtkDeepShadowVolumeFS, features.Enabled, features.Runtime);
  if (source != lastSource)
  {
    lastSource = source;
    ++this->ShaderCompositions;
  }
  this->FragmentShaderSource = source;
  // What this frame's shaders are made of (both passes' features, once each).
  std::vector<std::string> names(features.Enabled.begin(), features.Enabled.end());
  names.insert(names.end(), features.Labels.begin(), features.Labels.end());
  for (const std::string& name : names)
  {
    if (std::find(this->ShaderFeatures.begin(), this->ShaderFeatures.end(), name) == this->ShaderFeatures.end())
    {
      this->ShaderFeatures.push_back(name);
    }
  }
  vtkShaderProgram* program =
    window->GetShaderCache()->ReadyShaderProgram(vtkDeepShadowVolumeVS, source.c_str(), "");
  if (!program)
  {
    this->ReportError("the volume shader failed to compile (see the messages above)");
    return false;
  }

  // Each feature's uniforms and textures, then the back faces of the box.
  deepshadow::UniformSink sink(program);
  deepshadow::BindVolumeFeatures(frame, sink);
  if (frame.UserCode)
  {
    // The vtkShaderProperty's own uniforms, as VTK's mapper sets them.
    auto* shaderProperty = vtkOpenGLShaderProperty::SafeDownCast(frame.Volume->GetShaderProperty());
    if (auto* uniforms = vtkOpenGLUniforms::SafeDownCast(shaderProperty->GetFragmentCustomUniforms()))
    {
      uniforms->SetUniforms(program);
    }
  }
  const bool mirrored = glm::determinant(glm::dmat3(frame.Context.IndexToWorld)) < 0.0;
  impl.Box.Draw(window, program, blend, mirrored, begin, end);
  deepshadow::UnbindVolumeFeatures(frame);
  return true;
}

void vtkDeepShadowVolumeMapper::SetPassFrame(deepshadow::PassFrame* frame)
{
  this->Frame = frame;
  if (!frame)
  {
    return; // the casting surfaces stay until a frame replaces them
  }
  std::shared_ptr<const deepshadow::SurfaceSet> surfaces = frame->SurfacesFor(this);
  if (surfaces != this->Impl->Surfaces)
  {
    this->Impl->Surfaces = std::move(surfaces);
    this->Modified();
  }
}

std::shared_ptr<const deepshadow::SurfaceSet> vtkDeepShadowVolumeMapper::GetCastingSurfaces() const
{
  return this->Impl->Surfaces;
}

void vtkDeepShadowVolumeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SampleDistance: " << this->SampleDistance << " (0 = half the smallest spacing)\n";
  os << indent << "Jitter: " << this->UseJittering << " (seed " << this->JitterSeed << ")\n";
  os << indent << "InteractiveShadowLag: " << this->InteractiveShadowLag << " degrees\n";
  os << indent << "InteractiveShadowSubsampling: " << this->InteractiveShadowSubsampling << "\n";
  os << indent << "TerminationOpacity: " << this->TerminationOpacity << "\n";
  os << indent << "EmptySpaceSkipping: " << this->EmptySpaceSkipping << "\n";
  os << indent << "TransferTableSize: " << this->TransferTableSize << "\n";
  os << indent << "ReplaceNonFiniteScalars: " << this->ReplaceNonFiniteScalars << "\n";
  os << indent << "HeadlightKeyLight: " << this->HeadlightKeyLight << "\n";
  os << indent << "ShadingModel: " << (this->ShadingModel == VTK_SHADING ? "VTK" : "BlinnPhong") << "\n";
  os << indent << "VTKLightingComplexity: " << this->VTKLightingComplexity << "\n";
  os << indent << "Bounds: " << this->Impl->Bounds.size() << " (expression \"" << this->BoundExpression
     << "\")\n";
  os << indent << "OutputMode: " << (this->OutputMode == OutputShadowTerm ? "ShadowTerm" : "Color") << "\n";
  os << indent << "RenderCount: " << this->RenderCount << "\n";
  os << indent << "VolumeUploads: " << this->VolumeUploads << "\n";
  os << indent << "TransferTableBuilds: " << this->TransferTableBuilds << "\n";
  os << indent << "OccupancyBuilds: " << this->OccupancyBuilds << "\n";
  os << indent << "ShaderCompositions: " << this->ShaderCompositions << "\n";
  os << indent << "BoundBuilds: " << this->BoundBuilds << "\n";
  os << indent << "SurfaceUploads: " << this->SurfaceUploads << "\n";
}
