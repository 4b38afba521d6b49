#include "vtkDeepShadowVolumeMapper.h"

#include "CoreAdapter.h"
#include "Shadows/OtherVolumeShadows.h"
#include "Shadows/ShadowContext.h"
#include "vtkDeepShadowTechnique.h"
#include "EmptySpace.h"
#include "GL/FloatTexels.h"
#include "GL/FramebufferCopy.h"
#include "LightingUniforms.h"
#include "PassFrame.h"
#include "SurfaceSet.h"
#include "ShaderComposer.h"
#include "Translucency/TranslucentLayers.h"
#include "TransferFunction.h"
#include "vtkDeepShadowVolumeFS.h"
#include "vtkDeepShadowVolumeVS.h"

#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPropCollection.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtk_glew.h"

#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <set>

namespace adapter = deepshadow::adapter;

vtkStandardNewMacro(vtkDeepShadowVolumeMapper);

namespace
{
constexpr int BlockSize = 8;

void SetMatrix(vtkShaderProgram* program, const char* name, const glm::dmat4& matrix)
{
  glm::mat4 m(matrix);
  program->SetUniformMatrix4x4(name, glm::value_ptr(m));
}

void SetMatrix(vtkShaderProgram* program, const char* name, const glm::dmat3& matrix)
{
  glm::mat3 m(matrix);
  program->SetUniformMatrix3x3(name, glm::value_ptr(m));
}

void SetVector(vtkShaderProgram* program, const char* name, const glm::dvec3& v)
{
  const float f[3] = { static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z) };
  program->SetUniform3f(name, f);
}

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
      diagonal, technique->GetStepFactor() * context.ViewStep, "the shadow step (sample distance x StepFactor)");
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

vtkSmartPointer<vtkTextureObject> NewTexture(vtkOpenGLRenderWindow* window)
{
  auto texture = vtkSmartPointer<vtkTextureObject>::New();
  texture->SetContext(window);
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  texture->SetWrapR(vtkTextureObject::ClampToEdge);
  return texture;
}
}

class vtkDeepShadowVolumeMapper::Internals
{
public:
  // The uploaded volume and what it was made from.
  vtkSmartPointer<vtkTextureObject> Volume;
  vtkImageData* VolumeSource = nullptr;
  vtkMTimeType VolumeTime = 0;
  bool VolumeReplaceNonFinite = false;
  glm::ivec3 Dims{ 0 };
  glm::dvec2 Range{ 0.0 };
  glm::dvec2 ScalarMap{ 1.0, 0.0 };    // texel value -> the shaders' scalar
  glm::dvec2 ShaderScalar{ 1.0, 0.0 }; // data scalar -> the shaders' scalar (ShadowContext)
  double EffectiveStep = 0.0; // world sample distance of the last frame
  deepshadow::BlockRanges Blocks;
  std::string DataError;

  // Transfer-function table and what it depends on.
  vtkSmartPointer<vtkTextureObject> Transfer;
  std::array<double, 3> TransferKey{ { -1.0, -1.0, -1.0 } }; // colour, opacity times; unit distance
  int TransferUploadCount = -1;
  double TransferStep = 0.0;
  int TransferSize = 0;
  deepshadow::TransferTable Table;

  // Empty-space block map.
  vtkSmartPointer<vtkTextureObject> Occupancy;
  vtkMTimeType OccupancyOpacityTime = 0;
  int OccupancyUploadCount = -1;
  bool AnyEmptyBlock = false;
  double EmptyBlockFraction = 0.0;

  // Depth of the opaque geometry, copied from the framebuffer each frame that needs it.
  deepshadow::FramebufferCopy Opaque;

  // Proxy geometry.
  vtkSmartPointer<vtkOpenGLVertexArrayObject> VertexArray;
  vtkSmartPointer<vtkOpenGLBufferObject> Corners;
  vtkSmartPointer<vtkOpenGLBufferObject> Triangles;
  vtkShaderProgram* VertexArrayProgram = nullptr;

  // The polyhedral bound (feature Bound) and what it was built from.
  std::vector<vtkSmartPointer<vtkPolyData>> Bounds;
  std::shared_ptr<const deepshadow::BoundRegion> Region;
  deepshadow::BoundTextures BoundGPU;
  vtkSmartPointer<vtkTextureObject> BoundNodes;
  vtkSmartPointer<vtkTextureObject> BoundTriangles;
  std::vector<vtkMTimeType> BoundTimes; // each bound's MTime when built
  std::string BoundBuiltExpression;
  glm::dmat4 BoundDataToIndex{ 0.0 };
  bool BoundEnclosesNothing = false;
  std::string BoundError;
  long long BoundBytes = 0;

  // Surfaces that cast shadows onto the volume, in world space, and the same in index space
  // on the GPU (rebuilt when the set or the volume's placement changes).
  std::shared_ptr<const deepshadow::SurfaceSet> Surfaces;
  // Held, not a raw pointer: a new set allocated where a freed one was is still new.
  std::shared_ptr<const deepshadow::SurfaceSet> SurfacesBuiltFrom;
  glm::dmat4 SurfacesWorldToIndex{ 0.0 };
  deepshadow::SurfaceTextures SurfacesGPU;
  vtkSmartPointer<vtkTextureObject> SurfaceNodes;
  vtkSmartPointer<vtkTextureObject> SurfaceTriangles;
  long long SurfaceBytes = 0;

  std::string LastSource;

  // vtkDeepShadowPass's early call: prepare only (what mesh receivers read goes to its frame).
  bool PrepareOnly = false;
  bool KeepPasses = false;

  void Release(vtkWindow* window)
  {
    for (vtkTextureObject* texture : { this->Volume.Get(), this->Transfer.Get(),
           this->Occupancy.Get() })
    {
      if (texture)
      {
        texture->ReleaseGraphicsResources(window);
      }
    }
    this->Opaque.Release(window);
    if (this->VertexArray)
    {
      this->VertexArray->ReleaseGraphicsResources();
    }
    if (this->Corners)
    {
      this->Corners->ReleaseGraphicsResources();
    }
    if (this->Triangles)
    {
      this->Triangles->ReleaseGraphicsResources();
    }
    for (vtkTextureObject* texture : { this->BoundNodes.Get(), this->BoundTriangles.Get(),
           this->SurfaceNodes.Get(), this->SurfaceTriangles.Get() })
    {
      if (texture)
      {
        texture->ReleaseGraphicsResources(window);
      }
    }
    // What was composed, and the bounds and surfaces set, are independent of GL resources.
    const std::string lastSource = this->LastSource;
    auto bounds = std::move(this->Bounds);
    auto surfaces = std::move(this->Surfaces);
    // What the pass set for this frame survives a data change inside it.
    const bool prepareOnly = this->PrepareOnly;
    *this = Internals();
    this->LastSource = lastSource;
    this->Bounds = std::move(bounds);
    this->Surfaces = std::move(surfaces);
    this->PrepareOnly = prepareOnly;
  }
};

vtkDeepShadowVolumeMapper::vtkDeepShadowVolumeMapper()
  : TerminationOpacity(deepshadow::DefaultTerminationOpacity)
  , Impl(new Internals)
{
}

vtkDeepShadowVolumeMapper::~vtkDeepShadowVolumeMapper()
{
  this->SetShadowTechnique(nullptr);
}

void vtkDeepShadowVolumeMapper::SetSampleDistance(double distance)
{
  if (!(distance >= 0.0) || !std::isfinite(distance))
  {
    vtkErrorMacro("SetSampleDistance(" << distance << "): the sample distance must be finite "
                  "and >= 0 (0: the default); it stays " << this->SampleDistance);
    return;
  }
  if (distance != this->SampleDistance)
  {
    this->SampleDistance = distance;
    this->Modified();
  }
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

bool vtkDeepShadowVolumeMapper::UpdateBound(vtkOpenGLRenderWindow* window, vtkImageData* input)
{
  Internals& impl = *this->Impl;
  if (impl.Bounds.empty())
  {
    impl.Region.reset();
    impl.BoundTimes.clear();
    impl.BoundBytes = 0;
    return true;
  }
  // The bound lives in the data's coordinates: it follows the image's placement, not the prop's.
  const glm::dmat4 dataToIndex = glm::inverse(adapter::IndexToWorld(input, nullptr));
  std::vector<vtkMTimeType> times;
  std::vector<vtkPolyData*> meshes;
  for (const auto& bound : impl.Bounds)
  {
    times.push_back(bound ? bound->GetMTime() : 0);
    meshes.push_back(bound);
  }
  const bool changed = times != impl.BoundTimes || this->BoundExpression != impl.BoundBuiltExpression ||
    dataToIndex != impl.BoundDataToIndex;
  if (changed)
  {
    impl.BoundTimes = times;
    impl.BoundBuiltExpression = this->BoundExpression;
    impl.BoundDataToIndex = dataToIndex;
    impl.Region = adapter::MakeBoundRegion(meshes, this->BoundExpression, dataToIndex, impl.BoundError);
    if (impl.Region)
    {
      const deepshadow::BoundRegion::GPUData data = impl.Region->PackForGPU();
      const std::string limit =
        deepshadow::FloatTexelsLimit(std::max(data.Triangles.size(), data.Nodes.size()),
          data.Triangles.size() / 3, data.MaxDepth);
      if (!limit.empty())
      {
        impl.BoundError = "the bound cannot be used: " + limit;
        impl.Region.reset();
      }
      else
      {
        impl.BoundBytes = deepshadow::UploadFloatTexels(window, impl.BoundNodes, data.Nodes) +
          deepshadow::UploadFloatTexels(window, impl.BoundTriangles, data.Triangles);
        impl.BoundGPU.Nodes = impl.BoundNodes;
        impl.BoundGPU.Triangles = impl.BoundTriangles;
        impl.BoundGPU.LeafRoots = data.LeafRoots;
        impl.BoundGPU.TruthTable = data.TruthTable;
        // Nothing can be inside when the states the empty bounds allow all evaluate false.
        uint32_t emptyLeaves = 0;
        for (int i = 0; i < impl.Region->GetLeafCount(); ++i)
        {
          emptyLeaves |= impl.Region->GetLeaf(i).Empty() ? (1u << i) : 0u;
        }
        impl.BoundEnclosesNothing = true;
        for (uint32_t state = 0; state < (1u << impl.Region->GetLeafCount()); ++state)
        {
          if (!(state & emptyLeaves) && impl.Region->GetExpression().Evaluate(state))
          {
            impl.BoundEnclosesNothing = false;
            break;
          }
        }
        if (impl.BoundEnclosesNothing)
        {
          vtkWarningMacro("the volume's bound encloses nothing (its meshes are empty): nothing is drawn");
        }
        ++this->BoundBuilds;
        this->LastPasses.emplace_back("bound-upload");
      }
    }
  }
  if (!impl.BoundError.empty())
  {
    this->ReportError(impl.BoundError);
    return false;
  }
  return true;
}

int vtkDeepShadowVolumeMapper::GetShadowBuilds()
{
  return this->ShadowTechnique ? this->ShadowTechnique->GetBuildCount() : 0;
}

int vtkDeepShadowVolumeMapper::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
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
  return vtkImageData::SafeDownCast(this->GetDataSetInput());
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

void vtkDeepShadowVolumeMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Impl->Release(window);
  if (this->ShadowTechnique)
  {
    this->ShadowTechnique->ReleaseGraphicsResources(window);
  }
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
  impl.PrepareOnly = true;
  this->Render(renderer, volume);
  impl.PrepareOnly = false;
  // The frame's Render() keeps what this found to do in LastPasses.
  impl.KeepPasses = true;
  const auto prepared = this->Frame->Prepared.find(this);
  return prepared != this->Frame->Prepared.end() ? &prepared->second : nullptr;
}

void vtkDeepShadowVolumeMapper::Render(vtkRenderer* renderer, vtkVolume* volume)
{
  this->ErrorThisFrame = false;
  if (!this->Impl->KeepPasses)
  {
    this->LastPasses.clear();
  }
  this->Impl->KeepPasses = false;
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  if (!window)
  {
    this->ReportError("vtkDeepShadowVolumeMapper needs an OpenGL render window");
    return;
  }
  this->Update();
  vtkImageData* input = this->GetImageInput();
  vtkVolumeProperty* property = volume->GetProperty();
  Internals& impl = *this->Impl;

  // 1. The volume texture: re-uploaded only when the data changed.
  const bool dataChanged = input != impl.VolumeSource || !input ||
    input->GetMTime() != impl.VolumeTime || !impl.Volume ||
    impl.VolumeReplaceNonFinite != this->ReplaceNonFiniteScalars;
  if (dataChanged)
  {
    impl.Release(window);
    impl.VolumeSource = input;
    impl.VolumeTime = input ? input->GetMTime() : 0;
    impl.VolumeReplaceNonFinite = this->ReplaceNonFiniteScalars;

    std::string error;
    auto grid = adapter::MakeVolumeGrid(input, nullptr, this->ReplaceNonFiniteScalars, error);
    if (grid)
    {
      GLint max3D = 0;
      glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &max3D);
      const glm::ivec3 dims = grid->GetDims();
      if (std::max({ dims.x, dims.y, dims.z }) > max3D)
      {
        error = "the volume (" + std::to_string(dims.x) + "x" + std::to_string(dims.y) + "x" +
          std::to_string(dims.z) + ") exceeds this GL's 3D texture limit of " +
          std::to_string(max3D) + " per axis";
        grid.reset();
      }
    }
    if (!grid)
    {
      impl.DataError = error;
    }
    else
    {
      if (this->ReplaceNonFiniteScalars)
      {
        vtkDataArray* scalars = input->GetPointData()->GetScalars();
        if (scalars->GetDataType() == VTK_FLOAT)
        {
          const auto bad = deepshadow::CountNonFinite(
            static_cast<const float*>(scalars->GetVoidPointer(0)), scalars->GetNumberOfTuples());
          if (bad.Total() > 0)
          {
            vtkWarningMacro(<< bad.Total() << " non-finite samples replaced (NaN by the smallest "
                                              "finite value, +-Inf by the largest/smallest)");
          }
        }
      }
      impl.DataError.clear();
      impl.Dims = grid->GetDims();
      impl.Range = grid->GetRange();
      impl.Blocks = deepshadow::BlockRanges::Compute(*grid, BlockSize);

      // Native formats where exact (8/16 bit normalized), float otherwise.
      vtkDataArray* scalars = input->GetPointData()->GetScalars();
      impl.Volume = NewTexture(window);
      std::vector<uint16_t> shifted;
      std::vector<float> normalized;
      const void* texels = scalars->GetVoidPointer(0);
      int vtkType = scalars->GetDataType();
      impl.ShaderScalar = { 1.0, 0.0 };
      switch (vtkType)
      {
        case VTK_UNSIGNED_CHAR:
          impl.Volume->SetInternalFormat(GL_R8);
          impl.ScalarMap = { 255.0, 0.0 };
          break;
        case VTK_UNSIGNED_SHORT:
          impl.Volume->SetInternalFormat(GL_R16);
          impl.ScalarMap = { 65535.0, 0.0 };
          break;
        case VTK_SHORT:
        {
          // Shifted into unsigned range so every value is exact in a 16-bit unorm texture.
          const auto* values = static_cast<const int16_t*>(texels);
          shifted.resize(grid->GetScalars().size());
          for (size_t i = 0; i < shifted.size(); ++i)
          {
            shifted[i] = static_cast<uint16_t>(static_cast<int>(values[i]) + 32768);
          }
          texels = shifted.data();
          vtkType = VTK_UNSIGNED_SHORT;
          impl.Volume->SetInternalFormat(GL_R16);
          impl.ScalarMap = { 65535.0, -32768.0 };
          break;
        }
        default:
        {
          // Float: the checked (and, if asked, repaired) copy, normalized to [0, 1] in double,
          // so that a denormal range or one spanning +-FLT_MAX is mapped without overflow or
          // flushing (the shaders' scalar is the normalized one: ShadowContext::ShaderScalar).
          const double low = impl.Range.x, width = impl.Range.y > impl.Range.x ? impl.Range.y - impl.Range.x : 1.0;
          const std::vector<float>& values = grid->GetScalars();
          normalized.resize(values.size());
          for (size_t i = 0; i < values.size(); ++i)
          {
            normalized[i] = static_cast<float>((static_cast<double>(values[i]) - low) / width);
          }
          texels = normalized.data();
          impl.Volume->SetInternalFormat(GL_R32F);
          impl.ScalarMap = { 1.0, 0.0 };
          impl.ShaderScalar = { 1.0 / width, -low / width };
          break;
        }
      }
      impl.Volume->Create3DFromRaw(static_cast<unsigned int>(impl.Dims.x), static_cast<unsigned int>(impl.Dims.y),
        static_cast<unsigned int>(impl.Dims.z), 1, vtkType, const_cast<void*>(texels));
      ++this->VolumeUploads;
      this->LastPasses.emplace_back("volume-upload");
    }
  }
  if (!impl.DataError.empty())
  {
    this->ReportError(impl.DataError);
    return;
  }

  const glm::dmat4 indexToWorld = adapter::IndexToWorld(input, volume->GetMatrix());
  std::string problem = adapter::CheckVolumePlacement(indexToWorld, impl.Dims);
  if (problem.empty())
  {
    problem = adapter::CheckVolumeProperty(property);
  }
  if (!problem.empty())
  {
    this->ReportError(problem);
    return;
  }
  const glm::dmat4 worldToIndex = glm::inverse(indexToWorld);
  const double step = this->SampleDistance > 0.0 ? this->SampleDistance
                                                 : deepshadow::DefaultSampleDistance(indexToWorld);
  impl.EffectiveStep = step;
  if (!this->UpdateSurfaces(window, worldToIndex))
  {
    return;
  }
  const bool surfaces = impl.Surfaces && !impl.Surfaces->Empty();
  // What the table and the block map depend on: the functions themselves, not the property.
  vtkObject* colorFunction = property->GetColorChannels(0) == 1
    ? static_cast<vtkObject*>(property->GetGrayTransferFunction(0))
    : static_cast<vtkObject*>(property->GetRGBTransferFunction(0));
  const vtkMTimeType opacityTime = property->GetScalarOpacity(0)->GetMTime();
  const std::array<double, 3> transferKey{ { static_cast<double>(colorFunction->GetMTime()),
    static_cast<double>(opacityTime), property->GetScalarOpacityUnitDistance(0) } };
  const bool shade = property->GetShade(0) != 0;
  const int filter =
    property->GetInterpolationType() == VTK_NEAREST_INTERPOLATION ? vtkTextureObject::Nearest
                                                                   : vtkTextureObject::Linear;
  impl.Volume->SetMinificationFilter(filter);
  impl.Volume->SetMagnificationFilter(filter);

  // 2. Transfer table: colour and step-corrected opacity (deepshadow::TransferTable).
  if (!impl.Transfer || impl.TransferKey != transferKey ||
    impl.TransferUploadCount != this->VolumeUploads || impl.TransferStep != step ||
    impl.TransferSize != this->TransferTableSize)
  {
    impl.Table = deepshadow::TransferTable::Sample(adapter::MakeTransferFunction(property),
      impl.Range.x, impl.Range.y, this->TransferTableSize, step);
    impl.Transfer = NewTexture(window);
    impl.Transfer->SetMinificationFilter(vtkTextureObject::Linear);
    impl.Transfer->SetMagnificationFilter(vtkTextureObject::Linear);
    impl.Transfer->Create2DFromRaw(
      impl.Table.Size, 1, 4, VTK_FLOAT, static_cast<void*>(impl.Table.RGBA.data()));
    impl.TransferKey = transferKey;
    impl.TransferUploadCount = this->VolumeUploads;
    impl.TransferStep = step;
    impl.TransferSize = this->TransferTableSize;
    ++this->TransferTableBuilds;
    this->LastPasses.emplace_back("transfer-table");
  }

  // 3. Empty-space block map: depends on the data and the opacity function only.
  if (this->EmptySpaceSkipping &&
    (!impl.Occupancy || impl.OccupancyOpacityTime != opacityTime ||
      impl.OccupancyUploadCount != this->VolumeUploads))
  {
    const auto opacity = adapter::MakeTransferFunction(property).Opacity;
    std::vector<uint8_t> occupancy = impl.Blocks.Occupancy(opacity);
    const auto empty = std::count(occupancy.begin(), occupancy.end(), uint8_t(0));
    impl.AnyEmptyBlock = empty > 0;
    impl.EmptyBlockFraction = occupancy.empty() ? 0.0 : double(empty) / occupancy.size();
    for (uint8_t& v : occupancy)
    {
      v = v ? 255 : 0;
    }
    impl.Occupancy = NewTexture(window);
    impl.Occupancy->SetMinificationFilter(vtkTextureObject::Nearest);
    impl.Occupancy->SetMagnificationFilter(vtkTextureObject::Nearest);
    impl.Occupancy->Create3DFromRaw(static_cast<unsigned int>(impl.Blocks.BlockCount.x),
      static_cast<unsigned int>(impl.Blocks.BlockCount.y), static_cast<unsigned int>(impl.Blocks.BlockCount.z), 1,
      VTK_UNSIGNED_CHAR, occupancy.data());
    impl.OccupancyOpacityTime = opacityTime;
    impl.OccupancyUploadCount = this->VolumeUploads;
    ++this->OccupancyBuilds;
    this->LastPasses.emplace_back("occupancy");
  }
  const bool skipEmpty = this->EmptySpaceSkipping && impl.AnyEmptyBlock;
  this->EmptyBlockFraction = this->EmptySpaceSkipping ? impl.EmptyBlockFraction : 0.0;

  // 3b. The polyhedral bound: rebuilt when a bound, the expression or the data's placement changed.
  if (!this->UpdateBound(window, input))
  {
    return;
  }
  const bool bounded = impl.Region != nullptr;
  if (bounded && impl.BoundEnclosesNothing)
  {
    this->LastError.clear();
    ++this->RenderCount;
    return; // said when the bound was built
  }

  // 4. Viewport, matrices, lights, and the shadow technique's structures.
  int width = 0, height = 0, x0 = 0, y0 = 0;
  renderer->GetTiledSizeAndOrigin(&width, &height, &x0, &y0);
  const deepshadow::Camera camera = adapter::MakeCamera(renderer);
  vtkDeepShadowTechnique* technique = this->ShadowTechnique;
  const bool shadowTerm = this->OutputMode == OutputShadowTerm;
  const bool lit = shade || technique || shadowTerm;
  bool truncated = false;
  deepshadow::ShadowContext context;
  context.Window = window;
  context.Volume = impl.Volume;
  context.Occupancy = skipEmpty ? impl.Occupancy.Get() : nullptr;
  context.BlockSize = static_cast<float>(BlockSize);
  context.Dims = impl.Dims;
  context.Range = impl.Range;
  context.ScalarMap = impl.ScalarMap;
  context.ShaderScalar = impl.ShaderScalar;
  context.TableMap = impl.Table.CoordinateMap();
  context.TableSize = this->TransferTableSize;
  context.Sampling = filter == vtkTextureObject::Nearest ? deepshadow::Interpolation::Nearest
                                                        : deepshadow::Interpolation::Linear;
  context.IndexToWorld = indexToWorld;
  context.WorldToIndex = worldToIndex;
  context.ViewStep = step;
  context.DataVersion = this->VolumeUploads;
  context.Bound = bounded ? &impl.BoundGPU : nullptr;
  context.BoundVersion = this->BoundBuilds;
  context.Surfaces = surfaces ? &impl.SurfacesGPU : nullptr;
  context.CastingSurfaces = surfaces ? impl.Surfaces.get() : nullptr;
  context.SurfacesVersion = this->SurfaceUploads;
  context.Lights = lit ? adapter::MakeLights(renderer, &truncated) : std::vector<deepshadow::Light>();
  if (truncated)
  {
    vtkWarningMacro("Only the first " << adapter::MaxLights << " lights are used");
  }
  problem = adapter::CheckLights(context.Lights);
  if (!problem.empty())
  {
    this->ReportError(problem);
    return;
  }
  // A ray of more samples than a ray may take would be cut short (llvmpipe) or take hours.
  problem = CheckRaySamples(context, technique, camera);
  if (!problem.empty())
  {
    this->ReportError(problem);
    return;
  }
  if (technique)
  {
    context.Transfer = adapter::MakeTransferFunction(property);
    const bool prepared = technique->Prepare(context);
    const std::vector<std::string>& passes = technique->GetLastPasses();
    this->LastPasses.insert(this->LastPasses.end(), passes.begin(), passes.end());
    if (!prepared)
    {
      // A defined picture: the volume without shadows, and the reason said once.
      this->ReportError("shadows are off: " + technique->GetLastError());
      technique = nullptr;
    }
  }
  if (impl.PrepareOnly)
  {
    // vtkDeepShadowPass: receivers drawn before the volume read the structures built now.
    if (technique && this->Frame)
    {
      this->Frame->Prepared.insert_or_assign(this, context);
    }
    return;
  }
  const bool needDepth = HasOpaqueGeometry(renderer);

  // 5. Shader for the features in use.
  std::set<std::string> features;
  std::map<std::string, deepshadow::ShaderFeature> runtime;
  // Surfaces are met by the feelers of lookups only; light-space builds have their own.
  context.AddVolumeFeatures(features, runtime, technique && technique->NeedsFeeler());
  if (lit)
  {
    features.insert("Lighting");
    // The shadow term needs no normal.
    if (shade && !shadowTerm)
    {
      features.insert({ "Gradient", "Phong" });
    }
    else
    {
      features.insert("Isotropic");
    }
  }
  if (shadowTerm)
  {
    features.insert("ShadowTerm");
  }
  if (technique)
  {
    runtime["Shadow"] = deepshadow::ShaderFeature("Shadow", technique->GetShaderFeatureSource());
    if (technique->NeedsFeeler())
    {
      features.insert("Feeler");
    }
    for (const std::string& feature : technique->GetLookupFeatures())
    {
      features.insert(feature);
    }
  }
  // Shadows of the other volumes, when they cast any (a volume receives with a technique).
  const deepshadow::OtherVolumeShadows* passOthers =
    this->Frame ? this->Frame->OthersOnto(this) : nullptr;
  const deepshadow::OtherVolumeShadows* others =
    technique && passOthers && passOthers->Any() ? passOthers : nullptr;
  if (others)
  {
    features.insert({ "OtherVolumeShadows", "ShadowGrid" });
  }
  if (this->Jitter)
  {
    features.insert("Jitter");
    features.insert("Hash");
  }
  if (needDepth)
  {
    features.insert("OpaqueDepth");
  }
  const deepshadow::TranslucentLayers* layers =
    this->Frame ? this->Frame->LayersFor(this) : nullptr;
  if (layers)
  {
    features.insert("TranslucentLayers");
    runtime["TranslucentLayers"] = layers->GetShaderFeature();
  }
  int segmentGuest = 0;
  deepshadow::VolumeSegments* segments =
    layers || !this->Frame ? nullptr : this->Frame->SegmentsFor(volume, segmentGuest);
  if (segments)
  {
    features.insert("VolumeSegments");
    runtime["VolumeSegments"] = deepshadow::VolumeSegmentsShaderFeature(segments->GetSegments());
  }
  const std::string source = deepshadow::ComposeShader(vtkDeepShadowVolumeFS, features, runtime);
  if (source != impl.LastSource)
  {
    impl.LastSource = source;
    this->FragmentShaderSource = source;
    this->ShaderFeatures.assign(features.begin(), features.end());
    if (bounded)
    {
      this->ShaderFeatures.emplace_back("Bound");
    }
    if (technique)
    {
      this->ShaderFeatures.push_back("Shadow:" + technique->GetName());
    }
    ++this->ShaderCompositions;
  }
  vtkShaderProgram* program =
    window->GetShaderCache()->ReadyShaderProgram(vtkDeepShadowVolumeVS, source.c_str(), "");
  if (!program)
  {
    this->ReportError("the volume shader failed to compile (see the messages above)");
    return;
  }

  vtkOpenGLState* state = window->GetState();
  if (needDepth)
  {
    impl.Opaque.Capture(window, x0, y0, width, height, false);
  }

  // 6. Uniforms.
  deepshadow::UniformSink sink(program);
  context.ActivateVolumeTextures();
  impl.Transfer->Activate();
  context.SetVolumeUniforms(sink);
  sink.Set("u_transfer", impl.Transfer->GetTextureUnit());
  sink.Set("u_boxMax", glm::vec3(impl.Dims - 1));
  sink.Set("u_clipToWorld", glm::mat4(camera.GetInverseViewProjection()));
  sink.Set("u_indexToClip", glm::mat4(camera.GetViewProjection() * indexToWorld));
  // Segments are drawn into their own target, its viewport at (0, 0).
  const float viewport[4] = { segments ? 0.0f : static_cast<float>(x0),
    segments ? 0.0f : static_cast<float>(y0), static_cast<float>(width), static_cast<float>(height) };
  program->SetUniform4f("u_viewport", viewport);
  if (segments)
  {
    sink.Set("u_worldToClip", glm::mat4(camera.GetViewProjection()));
  }
  sink.Set("u_step", static_cast<float>(step));
  sink.Set("u_terminationOpacity", static_cast<float>(this->TerminationOpacity));
  if (this->Jitter)
  {
    sink.Set("u_jitterSeed", static_cast<int>(this->JitterSeed));
  }
  if (needDepth)
  {
    impl.Opaque.GetDepth()->Activate();
    sink.Set("u_opaqueDepth", impl.Opaque.GetDepth()->GetTextureUnit());
  }
  if (lit)
  {
    deepshadow::SetLightingUniforms(sink, context.Lights, renderer, adapter::MakeMaterial(property));
    sink.Set("u_indexGradientToWorld", glm::mat3(glm::transpose(glm::dmat3(worldToIndex))));
  }
  if (technique)
  {
    technique->Bind(sink, context);
  }
  if (others)
  {
    others->Activate(sink, static_cast<int>(context.Lights.size()));
  }
  if (layers)
  {
    layers->Activate(sink);
  }

  // 7. Draw the back faces of the box.
  if (!impl.VertexArray)
  {
    impl.VertexArray = vtkSmartPointer<vtkOpenGLVertexArrayObject>::New();
    impl.Corners = vtkSmartPointer<vtkOpenGLBufferObject>::New();
    impl.Triangles = vtkSmartPointer<vtkOpenGLBufferObject>::New();
    std::vector<float> corners;
    for (int i = 0; i < 8; ++i)
    {
      corners.insert(corners.end(),
        { float(i & 1), float((i >> 1) & 1), float((i >> 2) & 1) });
    }
    // Counter-clockwise seen from outside (outward normals).
    const std::vector<unsigned int> triangles = { 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5, 0, 1, 5,
      0, 5, 4, 2, 6, 7, 2, 7, 3, 0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6 };
    impl.Corners->Upload(corners, vtkOpenGLBufferObject::ArrayBuffer);
    impl.Triangles->Upload(triangles, vtkOpenGLBufferObject::ElementArrayBuffer);
  }
  const bool programChanged = impl.VertexArrayProgram != program;
  if (programChanged)
  {
    impl.VertexArray->ShaderProgramChanged(); // drops the VAO: rebind before adding arrays
  }
  impl.VertexArray->Bind();
  if (programChanged)
  {
    impl.VertexArray->AddAttributeArray(
      program, impl.Corners, "a_corner", 0, 3 * sizeof(float), VTK_FLOAT, 3, false);
    impl.VertexArrayProgram = program;
  }
  impl.Triangles->Bind();

  {
    vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable depthTest(state, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglEnableDisable cull(state, GL_CULL_FACE);
    vtkOpenGLState::ScopedglDepthMask depthMask(state);
    vtkOpenGLState::ScopedglBlendFuncSeparate blendFunc(state);
    if (layers || segments)
    {
      // The shader composited the opaque image itself, or writes segments, not colours.
      state->vtkglDisable(GL_BLEND);
    }
    else
    {
      state->vtkglEnable(GL_BLEND);
      state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    }
    state->vtkglDisable(GL_DEPTH_TEST);
    state->vtkglDepthMask(GL_FALSE);
    state->vtkglEnable(GL_CULL_FACE);
    state->vtkglCullFace(GL_FRONT);
    // A mirroring index-to-world transform turns the box inside out.
    const bool mirrored = glm::determinant(glm::dmat3(indexToWorld)) < 0.0;
    glFrontFace(mirrored ? GL_CW : GL_CCW);
    glEnable(GL_DEPTH_CLAMP);
    if (segments)
    {
      segments->Begin(window, segmentGuest);
    }
    glDrawElements(GL_TRIANGLES, 36, GL_UNSIGNED_INT, nullptr);
    if (segments)
    {
      segments->End(window);
    }
    this->LastPasses.emplace_back(segments ? "ray-cast-segments" : "ray-cast");
    glDisable(GL_DEPTH_CLAMP);
    glFrontFace(GL_CCW);
    state->vtkglCullFace(GL_BACK);
  }

  impl.Triangles->Release();
  impl.VertexArray->Release();
  if (technique)
  {
    technique->Unbind();
  }
  if (others)
  {
    others->Deactivate();
  }
  if (layers)
  {
    layers->Deactivate();
  }
  context.DeactivateVolumeTextures();
  impl.Transfer->Deactivate();
  if (needDepth)
  {
    impl.Opaque.GetDepth()->Deactivate();
  }
  this->GPUMemoryBytes = static_cast<long long>(impl.Dims.x) * impl.Dims.y * impl.Dims.z *
      (impl.ScalarMap.x == 255.0 ? 1 : impl.ScalarMap.x == 1.0 ? 4 : 2) +
    static_cast<long long>(impl.Table.Size) * 16 +
    (this->EmptySpaceSkipping ? static_cast<long long>(impl.Blocks.Min.size()) : 0) +
    (bounded ? impl.BoundBytes : 0) + (surfaces ? impl.SurfaceBytes : 0);
  if (!this->ErrorThisFrame)
  {
    this->LastError.clear();
  }
  ++this->RenderCount;
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

bool vtkDeepShadowVolumeMapper::UpdateSurfaces(vtkOpenGLRenderWindow* window, const glm::dmat4& worldToIndex)
{
  Internals& impl = *this->Impl;
  if (!impl.Surfaces || impl.Surfaces->Empty())
  {
    impl.SurfacesBuiltFrom.reset();
    return true;
  }
  if (impl.SurfacesBuiltFrom == impl.Surfaces && impl.SurfacesWorldToIndex == worldToIndex)
  {
    return true;
  }
  const deepshadow::SurfaceSet::GPUData data = impl.Surfaces->PackForGPU(worldToIndex);
  const std::string limit = deepshadow::FloatTexelsLimit(
    std::max(data.Triangles.size(), data.Nodes.size()), data.Triangles.size() / 3, data.MaxDepth);
  if (!limit.empty())
  {
    this->ReportError("the surfaces that cast shadows cannot be used: " + limit);
    return false;
  }
  impl.SurfaceBytes = deepshadow::UploadFloatTexels(window, impl.SurfaceNodes, data.Nodes) +
    deepshadow::UploadFloatTexels(window, impl.SurfaceTriangles, data.Triangles);
  impl.SurfacesGPU.Nodes = impl.SurfaceNodes;
  impl.SurfacesGPU.Triangles = impl.SurfaceTriangles;
  impl.SurfacesGPU.Root = data.Root;
  impl.SurfacesGPU.Transmission = data.Transmission;
  impl.SurfacesGPU.Transmission.resize(deepshadow::SurfaceSet::MaxSurfaces, glm::vec4(1.0f));
  impl.SurfacesBuiltFrom = impl.Surfaces;
  impl.SurfacesWorldToIndex = worldToIndex;
  ++this->SurfaceUploads;
  this->LastPasses.emplace_back("surface-upload");
  return true;
}

void vtkDeepShadowVolumeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SampleDistance: " << this->SampleDistance << " (0 = half the smallest spacing)\n";
  os << indent << "Jitter: " << this->Jitter << " (seed " << this->JitterSeed << ")\n";
  os << indent << "TerminationOpacity: " << this->TerminationOpacity << "\n";
  os << indent << "EmptySpaceSkipping: " << this->EmptySpaceSkipping << "\n";
  os << indent << "TransferTableSize: " << this->TransferTableSize << "\n";
  os << indent << "ReplaceNonFiniteScalars: " << this->ReplaceNonFiniteScalars << "\n";
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
