#include "vtkDeepShadowPolyDataMapper.h"

#include "CoreAdapter.h"
#include "LightingUniforms.h"
#include "PassFrame.h"
#include "ShaderComposer.h"
#include "Shadows/OtherVolumeShadows.h"
#include "GL/UniformSink.h"
#include "Sampling/SamplingFeatures.h"
#include "Sampling/ShadowContext.h"
#include "Core/Geometry/PolygonTriangulation.h"
#include "Core/Geometry/SurfaceSet.h"
#include "Translucency/TranslucentLayers.h"
#include "vtkDeepShadowSurfaceFS.h"
#include "vtkDeepShadowSurfaceVS.h"
#include "vtkDeepShadowTechniqueInternals.h"
#include "vtkDeepShadowVolumeMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkScalarsToColors.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolume.h"
#include "vtk_glew.h"

#include <glm/matrix.hpp>

#include <cmath>
#include <map>
#include <set>

namespace adapter = deepshadow::adapter;

vtkStandardNewMacro(vtkDeepShadowPolyDataMapper);

class vtkDeepShadowPolyDataMapper::Internals
{
public:
  // The mesh as drawn: triangles, point normals and colours (model coordinates).
  std::vector<glm::vec3> Points;
  std::vector<glm::vec3> Normals;
  std::vector<glm::vec4> Colors;
  std::vector<unsigned int> Indices;
  vtkMTimeType PreparedTime = 0;
  std::string PrepareError;
  bool BadInput = false; // PrepareError is an error (bad input), not only nothing to draw
  // CheckInput's answer for the input at its modification time (asked for every bounds).
  vtkPolyData* CheckedInput = nullptr;
  vtkMTimeType CheckedTime = 0;
  std::string InputProblem;

  const std::string& CheckInput(vtkPolyData* input)
  {
    if (input != this->CheckedInput || !input || input->GetMTime() != this->CheckedTime)
    {
      this->CheckedInput = input;
      this->CheckedTime = input ? input->GetMTime() : 0;
      this->InputProblem = input ? vtkDeepShadowPolyDataMapper::CheckInput(input) : std::string();
    }
    return this->InputProblem;
  }

  vtkSmartPointer<vtkOpenGLVertexArrayObject> VertexArray;
  vtkSmartPointer<vtkOpenGLBufferObject> Vertices;
  vtkSmartPointer<vtkOpenGLBufferObject> Triangles;
  vtkShaderProgram* VertexArrayProgram = nullptr;
  bool Uploaded = false;
  std::string LastSource;

  const deepshadow::PassFrame* Frame = nullptr;
  const deepshadow::PeelStep* Peel = nullptr;

  /**
   * Triangles, normals and colours of the input, rebuilt only when something they depend on
   * changed. False (and PrepareError) when there is nothing to draw.
   */
  bool Prepare(vtkDeepShadowPolyDataMapper* self, vtkActor* actor);

  /** Builds the buffers once, and again when the mesh changed; true when it uploaded. */
  bool UploadGeometry();
  /** Binds the buffers to `program` and draws, blended or peeled as `opacity` and Peel say. */
  void DrawTriangles(vtkOpenGLRenderWindow* window, vtkShaderProgram* program,
    deepshadow::UniformSink& sink, double opacity);
};

vtkDeepShadowPolyDataMapper::vtkDeepShadowPolyDataMapper()
  : Impl(new Internals)
{
  // vtkMapper creates it on first use (GetIsOpaque, in the first frame) and marks itself
  // modified: the casting meshes would be gathered, and the shadows built, twice.
  this->CreateDefaultLookupTable();
}

vtkDeepShadowPolyDataMapper::~vtkDeepShadowPolyDataMapper() = default;

void vtkDeepShadowPolyDataMapper::SetPeelStep(const deepshadow::PeelStep* step)
{
  this->Impl->Peel = step;
}

void vtkDeepShadowPolyDataMapper::SetPassFrame(const deepshadow::PassFrame* frame)
{
  this->Impl->Frame = frame;
}

namespace
{
// What the mesh's look depends on besides its points: the mapper, the colours, the property.
vtkMTimeType MeshTime(vtkDeepShadowPolyDataMapper* mapper, vtkPolyData* input, vtkActor* actor)
{
  vtkMTimeType time = std::max(mapper->GetMTime(), input->GetMTime());
  if (mapper->GetLookupTable())
  {
    time = std::max(time, mapper->GetLookupTable()->GetMTime());
  }
  return std::max(time, actor->GetProperty()->GetMTime());
}
}

bool vtkDeepShadowPolyDataMapper::Internals::Prepare(vtkDeepShadowPolyDataMapper* self, vtkActor* actor)
{
  Internals& impl = *this;
  vtkPolyData* input = self->GetInput();
  if (!input)
  {
    impl.PrepareError = "vtkDeepShadowPolyDataMapper has no input";
    return false;
  }
  const vtkMTimeType time = MeshTime(self, input, actor);
  if (time == impl.PreparedTime)
  {
    return impl.PrepareError.empty();
  }
  impl.PreparedTime = time;
  impl.PrepareError.clear();
  impl.BadInput = false;
  impl.Uploaded = false;
  impl.Points.clear();
  impl.Normals.clear();
  impl.Colors.clear();
  impl.Indices.clear();
  // Before any VTK filter sees it: they trust the point ids.
  const std::string& problem = impl.CheckInput(input);
  if (!problem.empty())
  {
    impl.PrepareError = problem + ": nothing is drawn";
    impl.BadInput = true;
    return false;
  }
  // Where the actor puts it, single precision must still resolve it.
  const std::string placed = adapter::CheckMeshPlacement(input, adapter::ToGlm(actor->GetMatrix()));
  if (!placed.empty())
  {
    impl.PrepareError = placed + ": nothing is drawn";
    impl.BadInput = true;
    return false;
  }
  // Polygons and strips as triangles over the same points; lines and vertices are not surfaces.
  std::vector<std::array<vtkIdType, 3>> triangles;
  std::string why;
  if (!deepshadow::TriangulateCells(input, triangles, why))
  {
    impl.PrepareError = "the mesh has " + why + ": nothing is drawn";
    impl.BadInput = true;
    return false;
  }
  vtkNew<vtkCellArray> cells;
  cells->AllocateExact(static_cast<vtkIdType>(triangles.size()), static_cast<vtkIdType>(3 * triangles.size()));
  for (const auto& triangle : triangles)
  {
    cells->InsertNextCell(3, triangle.data());
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(input->GetPoints());
  mesh->GetPointData()->PassData(input->GetPointData());
  mesh->SetPolys(cells);
  if (mesh->GetNumberOfPolys() == 0)
  {
    impl.PrepareError = "the mesh has no polygons: nothing is drawn";
    return false;
  }
  if (!mesh->GetPointData()->GetNormals())
  {
    vtkNew<vtkPolyDataNormals> normals;
    normals->SetInputData(mesh);
    normals->SplittingOff(); // smooth: one normal per point, as the points are shared
    normals->ConsistencyOn();
    normals->Update();
    mesh = normals->GetOutput();
  }
  vtkDataArray* normals = mesh->GetPointData()->GetNormals();
  // Colours: the mapped scalars when shown, else the property's colour.
  vtkUnsignedCharArray* mapped = nullptr;
  if (self->GetScalarVisibility())
  {
    // Colours per point: VTK's interpolation before mapping (ParaView's default) would map
    // to texture coordinates instead and leave no colours.
    const vtkTypeBool interpolate = self->InterpolateScalarsBeforeMapping;
    self->InterpolateScalarsBeforeMapping = 0;
    mapped = self->MapScalars(mesh, 1.0);
    self->InterpolateScalarsBeforeMapping = interpolate;
  }
  double color[3];
  actor->GetProperty()->GetColor(color);
  const vtkIdType count = mesh->GetNumberOfPoints();
  for (vtkIdType i = 0; i < count; ++i)
  {
    double p[3], n[3];
    mesh->GetPoint(i, p);
    normals->GetTuple(i, n);
    impl.Points.emplace_back(p[0], p[1], p[2]);
    impl.Normals.emplace_back(n[0], n[1], n[2]);
    if (mapped && mapped->GetNumberOfTuples() == count)
    {
      const unsigned char* c = mapped->GetPointer(4 * i);
      impl.Colors.emplace_back(c[0] / 255.0f, c[1] / 255.0f, c[2] / 255.0f, 1.0f);
    }
    else
    {
      impl.Colors.emplace_back(color[0], color[1], color[2], 1.0f);
    }
  }
  vtkCellArray* polys = mesh->GetPolys();
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
  {
    if (n == 3)
    {
      impl.Indices.insert(impl.Indices.end(), { static_cast<unsigned int>(ids[0]),
        static_cast<unsigned int>(ids[1]), static_cast<unsigned int>(ids[2]) });
    }
  }
  return true;
}

double* vtkDeepShadowPolyDataMapper::GetBounds()
{
  // VTK computes a mesh's bounds from its cells, marking their points by id: ids out of range
  // write past its buffer there, before Render could refuse the mesh.
  if (this->GetNumberOfInputConnections(0) > 0 && !this->Static)
  {
    this->Update();
  }
  const std::string& problem = this->Impl->CheckInput(this->GetInput());
  if (!problem.empty())
  {
    this->Report(problem + ": nothing is drawn", true);
    vtkMath::UninitializeBounds(this->Bounds);
    return this->Bounds;
  }
  return this->Superclass::GetBounds();
}

void vtkDeepShadowPolyDataMapper::ReportPrepareError()
{
  this->Report(this->Impl->PrepareError, this->Impl->BadInput);
}

void vtkDeepShadowPolyDataMapper::Report(const std::string& problem, bool error)
{
  // Once per change, whether the bounds, the pass (gathering casters) or Render asked first.
  if (problem != this->LastError)
  {
    this->LastError = problem;
    if (error)
    {
      vtkErrorMacro(<< problem);
    }
    else
    {
      vtkWarningMacro(<< problem);
    }
  }
}

std::string vtkDeepShadowPolyDataMapper::CheckInput(vtkPolyData* mesh)
{
  return adapter::CheckMeshInput(mesh);
}

bool vtkDeepShadowPolyDataMapper::GetSurfaceMesh(vtkActor* actor, deepshadow::SurfaceMesh& mesh, std::string& error)
{
  Internals& impl = *this->Impl;
  if (!impl.Prepare(this, actor))
  {
    this->ReportPrepareError();
    error = impl.PrepareError;
    return false;
  }
  const glm::dmat4 toWorld = adapter::ToGlm(actor->GetMatrix());
  const glm::dmat3 normalToWorld = glm::transpose(glm::inverse(glm::dmat3(toWorld)));
  mesh = deepshadow::SurfaceMesh();
  for (size_t i = 0; i < impl.Points.size(); ++i)
  {
    mesh.Points.emplace_back(toWorld * glm::dvec4(glm::dvec3(impl.Points[i]), 1.0));
    const glm::dvec3 n = normalToWorld * glm::dvec3(impl.Normals[i]);
    mesh.Normals.push_back(glm::length(n) > 0.0 ? glm::normalize(n) : n);
    mesh.Colors.emplace_back(impl.Colors[i]);
  }
  for (size_t t = 0; t + 2 < impl.Indices.size(); t += 3)
  {
    mesh.Triangles.emplace_back(impl.Indices[t], impl.Indices[t + 1], impl.Indices[t + 2]);
  }
  mesh.Material = adapter::MakeSurfaceMaterial(actor->GetProperty());
  mesh.ReceivesShadows = this->ReceiveShadows;
  return true;
}

void vtkDeepShadowPolyDataMapper::Render(vtkRenderer* renderer, vtkActor* actor)
{
  // One piece, and empty inputs reach RenderPiece, which says why nothing is drawn.
  this->RenderPiece(renderer, actor);
}

namespace
{
// The mesh shader's features: lit always; shadowed when the pass gave a source and the mesh
// receives, with what the other volumes cast, a peeled layer, or the shadow term on request.
void ChooseSurfaceFeatures(vtkDeepShadowTechnique* technique, const deepshadow::ShadowContext* context,
  const deepshadow::OtherVolumeShadows* others, const deepshadow::PeelStep* peel, bool shadowTerm,
  deepshadow::ComposedFeatures& features)
{
  if (technique)
  {
    // The technique's own lookup: a cache's grid covers the volume's box only.
    deepshadow::ComposeSamplingFeatures({ *context, technique->NeedsFeeler(true) }, features);
    features.Runtime["Shadow"] = deepshadow::ShaderFeature("Shadow", technique->GetShaderFeatureSource(true));
    if (technique->NeedsFeeler(true))
    {
      features.Enabled.insert("Feeler");
    }
    for (const std::string& feature : technique->GetLookupFeatures(true))
    {
      features.Enabled.insert(feature);
    }
  }
  if (others)
  {
    features.Enabled.insert({ "OtherVolumeShadows", "ShadowGrid" });
  }
  if (peel)
  {
    features.Enabled.insert("Peel");
  }
  if (shadowTerm)
  {
    features.Enabled.insert("ShadowTerm");
  }
}

// Lights, the actor's placement and the camera: what every mesh shader reads.
void SetViewUniforms(deepshadow::UniformSink& sink, vtkRenderer* renderer, vtkActor* actor,
  const std::vector<deepshadow::Light>& lights, const deepshadow::SurfaceMaterial& material)
{
  deepshadow::SetLightingUniforms(sink, lights, renderer, material.Shading, false);
  sink.Set("u_specularColor", glm::vec3(material.SpecularColor));
  const glm::dmat4 modelToWorld = adapter::ToGlm(actor->GetMatrix());
  sink.Set("u_modelToWorld", glm::mat4(modelToWorld));
  sink.Set("u_normalToWorld", glm::mat3(glm::transpose(glm::inverse(glm::dmat3(modelToWorld)))));
  sink.Set("u_worldToClip", glm::mat4(adapter::MakeCamera(renderer).GetViewProjection()));
  vtkCamera* camera = renderer->GetActiveCamera();
  double position[3], direction[3];
  camera->GetPosition(position);
  camera->GetDirectionOfProjection(direction);
  sink.Set("u_cameraPosition", glm::vec3(position[0], position[1], position[2]));
  sink.Set("u_viewDirection", glm::vec3(direction[0], direction[1], direction[2]));
  sink.Set("u_parallel", camera->GetParallelProjection() ? 1 : 0);
}

// The shadow source's textures and uniforms, the other volumes' grids and the previous
// peeled layer, bound for the draw; UnbindShadowInputs undoes it.
void BindShadowInputs(deepshadow::UniformSink& sink, vtkDeepShadowTechnique* technique,
  const deepshadow::ShadowContext* context, const deepshadow::OtherVolumeShadows* others,
  const deepshadow::PeelStep* peel, const std::vector<deepshadow::Light>& lights, double shadowBias)
{
  if (technique)
  {
    deepshadow::BindSamplingFeatures({ *context, technique->NeedsFeeler(true) }, sink);
    vtkDeepShadowTechnique::Internals::Bind(technique, sink, *context, true);
    const double bias = shadowBias > 0.0
      ? shadowBias
      : deepshadow::DefaultReceiverBias(context->ShadowStep * technique->GetStepFactor());
    sink.Set("u_receiverOffset", static_cast<float>(bias));
  }
  if (others)
  {
    others->Activate(sink, static_cast<int>(lights.size()));
  }
  if (peel)
  {
    peel->Previous->Activate();
    sink.Set("u_peelPrevious", peel->Previous->GetTextureUnit());
    sink.Set("u_peelHasPrevious", peel->First ? 0 : 1);
  }
}

void UnbindShadowInputs(vtkDeepShadowTechnique* technique, const deepshadow::ShadowContext* context,
  const deepshadow::OtherVolumeShadows* others, const deepshadow::PeelStep* peel)
{
  if (peel)
  {
    peel->Previous->Deactivate();
  }
  if (technique)
  {
    technique->Unbind(true);
    deepshadow::UnbindSamplingFeatures({ *context, technique->NeedsFeeler(true) });
  }
  if (others)
  {
    others->Deactivate();
  }
}
}

bool vtkDeepShadowPolyDataMapper::Internals::UploadGeometry()
{
  // Buffers: position, normal, colour per point; re-uploaded only when the mesh changed.
  if (!this->VertexArray)
  {
    this->VertexArray = vtkSmartPointer<vtkOpenGLVertexArrayObject>::New();
    this->Vertices = vtkSmartPointer<vtkOpenGLBufferObject>::New();
    this->Triangles = vtkSmartPointer<vtkOpenGLBufferObject>::New();
  }
  if (this->Uploaded)
  {
    return false;
  }
  std::vector<float> vertices;
  vertices.reserve(this->Points.size() * 10);
  for (size_t i = 0; i < this->Points.size(); ++i)
  {
    vertices.insert(vertices.end(), { this->Points[i].x, this->Points[i].y, this->Points[i].z,
      this->Normals[i].x, this->Normals[i].y, this->Normals[i].z, this->Colors[i].r, this->Colors[i].g,
      this->Colors[i].b, this->Colors[i].a });
  }
  this->Vertices->Upload(vertices, vtkOpenGLBufferObject::ArrayBuffer);
  this->Triangles->Upload(this->Indices, vtkOpenGLBufferObject::ElementArrayBuffer);
  this->Uploaded = true;
  this->VertexArrayProgram = nullptr;
  return true;
}

void vtkDeepShadowPolyDataMapper::Internals::DrawTriangles(vtkOpenGLRenderWindow* window,
  vtkShaderProgram* program, deepshadow::UniformSink& sink, double opacity)
{
  // The attributes are bound again only for a new program.
  const bool programChanged = this->VertexArrayProgram != program;
  if (programChanged)
  {
    this->VertexArray->ShaderProgramChanged();
  }
  this->VertexArray->Bind();
  if (programChanged)
  {
    const int stride = 10 * sizeof(float);
    this->VertexArray->AddAttributeArray(program, this->Vertices, "a_position", 0, stride, VTK_FLOAT, 3, false);
    this->VertexArray->AddAttributeArray(
      program, this->Vertices, "a_normal", 3 * sizeof(float), stride, VTK_FLOAT, 3, false);
    this->VertexArray->AddAttributeArray(
      program, this->Vertices, "a_color", 6 * sizeof(float), stride, VTK_FLOAT, 4, false);
    this->VertexArrayProgram = program;
  }
  this->Triangles->Bind();
  {
    vtkOpenGLState* state = window->GetState();
    vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable depthTest(state, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglDepthMask depthMask(state);
    vtkOpenGLState::ScopedglBlendFuncSeparate blendFunc(state);
    state->vtkglEnable(GL_DEPTH_TEST);
    sink.Set("u_opacity", static_cast<float>(opacity));
    if (this->Peel)
    {
      // One layer: the nearest fragment behind the previous layer wins the depth test.
      state->vtkglDisable(GL_BLEND);
      state->vtkglDepthMask(GL_TRUE);
    }
    else if (opacity < 1.0)
    {
      // Premultiplied "over"; translucent meshes do not hide what is drawn after them.
      state->vtkglEnable(GL_BLEND);
      state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
      state->vtkglDepthMask(GL_FALSE);
    }
    else
    {
      state->vtkglDisable(GL_BLEND);
      state->vtkglDepthMask(GL_TRUE);
    }
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(this->Indices.size()), GL_UNSIGNED_INT, nullptr);
  }
  this->Triangles->Release();
  this->VertexArray->Release();
}

namespace
{
// Without a pass: a frame of the mesh's own, for the duration of one render, whose shadow
// source is the shadowing volume, prepared now as vtkDeepShadowPass prepares its volumes.
class ShadowingVolumeFrame
{
public:
  ShadowingVolumeFrame(const deepshadow::PassFrame*& slot, vtkVolume* volume, vtkRenderer* renderer)
  {
    vtkDeepShadowVolumeMapper* mapper = volume ? vtkDeepShadowVolumeMapper::SafeDownCast(volume->GetMapper()) : nullptr;
    if (slot || !mapper || !mapper->GetShadowTechnique() || !volume->GetVisibility())
    {
      return;
    }
    this->Mapper = mapper;
    this->Slot = &slot;
    // The volume keeps the surfaces that cast into it (ParaView's Shadowed Surfaces, set by
    // its representation): the frame hands them back, or the structures would lose them.
    this->Frame.Surfaces = mapper->GetCastingSurfaces();
    this->Frame.SurfaceHolder = mapper;
    mapper->SetPassFrame(&this->Frame);
    this->Frame.Source = mapper->PrepareShadows(renderer, volume);
    this->Frame.SourceTechnique = this->Frame.Source ? mapper->GetShadowTechnique() : nullptr;
    slot = &this->Frame;
  }
  ~ShadowingVolumeFrame()
  {
    if (this->Mapper)
    {
      this->Mapper->SetPassFrame(nullptr);
      *this->Slot = nullptr;
    }
  }
  ShadowingVolumeFrame(const ShadowingVolumeFrame&) = delete;
  void operator=(const ShadowingVolumeFrame&) = delete;

private:
  deepshadow::PassFrame Frame;
  vtkDeepShadowVolumeMapper* Mapper = nullptr;
  const deepshadow::PassFrame** Slot = nullptr;
};
}

void vtkDeepShadowPolyDataMapper::SetShadowingVolume(vtkVolume* volume)
{
  if (volume != this->ShadowingVolume)
  {
    this->ShadowingVolume = volume;
    this->Modified();
  }
}

vtkVolume* vtkDeepShadowPolyDataMapper::GetShadowingVolume()
{
  return this->ShadowingVolume;
}

void vtkDeepShadowPolyDataMapper::RenderPiece(vtkRenderer* renderer, vtkActor* actor)
{
  Internals& impl = *this->Impl;
  const ShadowingVolumeFrame own(impl.Frame, this->ReceiveShadows ? this->ShadowingVolume.GetPointer() : nullptr, renderer);
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  if (!window)
  {
    this->LastError = "vtkDeepShadowPolyDataMapper needs an OpenGL render window";
    vtkErrorMacro(<< this->LastError);
    return;
  }
  if (!impl.Prepare(this, actor))
  {
    this->ReportPrepareError();
    return;
  }
  this->LastError.clear();
  if (impl.UploadGeometry())
  {
    ++this->GeometryUploads;
  }

  // Shader: lit always; shadowed when the pass gave a source and the mesh receives.
  const deepshadow::PassFrame* frame = impl.Frame;
  const deepshadow::ShadowContext* context =
    this->ReceiveShadows && frame ? frame->Source : nullptr;
  vtkDeepShadowTechnique* technique = context ? frame->SourceTechnique : nullptr;
  // What the other shadowing volumes cast, on a grid over this mesh.
  const deepshadow::OtherVolumeShadows* passOthers = frame ? frame->OthersOnto(this) : nullptr;
  const deepshadow::OtherVolumeShadows* others =
    technique && passOthers && passOthers->Any() ? passOthers : nullptr;
  const deepshadow::PeelStep* peel = impl.Peel;
  deepshadow::ComposedFeatures features;
  features.Enabled = { "Lighting", "Phong", "MeshNormal" };
  ChooseSurfaceFeatures(technique, context, others, peel, this->OutputMode == OutputShadowTerm, features);
  const std::string source =
    deepshadow::ComposeShader(vtkDeepShadowSurfaceFS, features.Enabled, features.Runtime);
  this->ShaderFeatures.assign(features.Enabled.begin(), features.Enabled.end());
  if (technique)
  {
    this->ShaderFeatures.push_back("Shadow:" + technique->GetName());
  }
  if (source != impl.LastSource)
  {
    impl.LastSource = source;
    ++this->ShaderCompositions;
  }
  vtkShaderProgram* program =
    window->GetShaderCache()->ReadyShaderProgram(vtkDeepShadowSurfaceVS, source.c_str(), "");
  if (!program)
  {
    this->LastError = "the mesh shader failed to compile (see the messages above)";
    vtkErrorMacro(<< this->LastError);
    return;
  }

  deepshadow::UniformSink sink(program);
  const deepshadow::SurfaceMaterial material = adapter::MakeSurfaceMaterial(actor->GetProperty());
  const std::vector<deepshadow::Light> lights = context ? context->Lights : adapter::MakeLights(renderer);
  SetViewUniforms(sink, renderer, actor, lights, material);
  BindShadowInputs(sink, technique, context, others, peel, lights, this->ShadowBias);
  impl.DrawTriangles(window, program, sink, material.Opacity);
  UnbindShadowInputs(technique, context, others, peel);
}

void vtkDeepShadowPolyDataMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  Internals& impl = *this->Impl;
  if (impl.VertexArray)
  {
    impl.VertexArray->ReleaseGraphicsResources();
    impl.Vertices->ReleaseGraphicsResources();
    impl.Triangles->ReleaseGraphicsResources();
  }
  impl.Uploaded = false;
  impl.VertexArrayProgram = nullptr;
  this->Superclass::ReleaseGraphicsResources(window);
}

void vtkDeepShadowPolyDataMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "CastShadows: " << this->CastShadows << "\n";
  os << indent << "ReceiveShadows: " << this->ReceiveShadows << "\n";
  os << indent << "ShadowingVolume: " << this->ShadowingVolume.GetPointer() << "\n";
  os << indent << "ShadowBias: " << this->ShadowBias << " (0 = automatic)\n";
  os << indent << "OutputMode: " << (this->OutputMode == OutputShadowTerm ? "ShadowTerm" : "Color") << "\n";
  os << indent << "GeometryUploads: " << this->GeometryUploads << "\n";
}
