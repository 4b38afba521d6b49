#include "SceneSetup.h"

#include "Budget.h"
#include "Look.h"

#include "Core/VolumeGrid.h"

#include "vtkDeepShadowBoundedScene.h"
#include "vtkDeepShadowCSGFilter.h"
#include "vtkDeepShadowHybridScene.h"
#include "vtkDeepShadowMeshReader.h"
#include "vtkDeepShadowImageConversion.h"
#include "vtkDeepShadowPass.h"
#include "vtkDeepShadowPolyDataMapper.h"
#include "vtkDeepShadowVolumePresets.h"
#include "vtkDeepShadowRenderWindow.h"
#include "vtkDeepShadowStandardScene.h"
#include "vtkDeepShadowTechnique.h"
#include "vtkDeepShadowTechniqueFactory.h"
#include "vtkDeepShadowVolumeMapper.h"
#include "vtkDeepShadowVolumeReader.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkProperty.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkDataArray.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

namespace deepshadow
{
namespace tool
{
namespace
{
// --mask: read with the same checks as --volume, and of the volume's dimensions.
vtkSmartPointer<vtkImageData> ReadMask(const std::string& path, vtkImageData* volume)
{
  vtkNew<vtkDeepShadowVolumeReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  if (!reader->GetLastError().empty())
  {
    throw UsageError("--mask: " + reader->GetLastError());
  }
  vtkSmartPointer<vtkImageData> mask = reader->GetOutput();
  int maskDims[3], dims[3];
  mask->GetDimensions(maskDims);
  volume->GetDimensions(dims);
  if (!std::equal(dims, dims + 3, maskDims))
  {
    throw UsageError("--mask: the mask's dimensions " + std::to_string(maskDims[0]) + "x" +
      std::to_string(maskDims[1]) + "x" + std::to_string(maskDims[2]) + " differ from the volume's " +
      std::to_string(dims[0]) + "x" + std::to_string(dims[1]) + "x" + std::to_string(dims[2]));
  }
  return mask;
}

// The range of the finite samples (NaN and +-Inf, which --replace-nonfinite replaces by the
// extremes of the finite ones, would make the transfer function span infinity: blank).
void FiniteRange(vtkImageData* data, double range[2])
{
  range[0] = 0.0;
  range[1] = 1.0;
  vtkDataArray* scalars = data->GetPointData()->GetScalars();
  if (!scalars || scalars->GetNumberOfComponents() != 1)
  {
    return; // the mapper says why it cannot draw it
  }
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (vtkIdType i = 0; i < scalars->GetNumberOfTuples(); ++i)
  {
    const double v = scalars->GetComponent(i, 0);
    if (std::isfinite(v))
    {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  }
  if (!(lo <= hi))
  {
    throw UsageError("the volume has no finite samples");
  }
  range[0] = lo;
  range[1] = hi;
}

// The look of a file given none (--tf): by its modality (vtkDeepShadowVolumePresets::
// ApplyDefault: CT-Bone for CT, MR-Default windowed from the data's histogram otherwise). A
// constant volume has no look that shows it: said, when no --tf is given to replace it.
vtkSmartPointer<vtkVolumeProperty> DefaultProperty(
  vtkImageData* data, const std::string& modality, bool replaced, std::string& look)
{
  double range[2];
  FiniteRange(data, range);
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  property->SetInterpolationTypeToLinear();
  property->SetScalarOpacityUnitDistance(SmallestSpacing(data));
  if (replaced)
  {
    return property;
  }
  if (range[0] == range[1])
  {
    std::ostringstream message;
    message << "the volume is constant (every finite sample is " << range[0] << "): no transfer "
            << "function chosen from its values shows anything of it; give --tf";
    throw UsageError(message.str());
  }
  vtkNew<vtkDeepShadowVolumePresets> presets;
  look = presets->ApplyDefault(modality, data, property);
  if (look.empty())
  {
    throw UsageError(presets->GetLastError());
  }
  property->SetScalarOpacityUnitDistance(SmallestSpacing(data));
  return property;
}
}

double SmallestSpacing(vtkImageData* data)
{
  const double* spacing = data->GetSpacing();
  return std::min({ std::abs(spacing[0]), std::abs(spacing[1]), std::abs(spacing[2]) });
}

vtkSmartPointer<vtkDeepShadowTechnique> MakeTechnique(const Options& options)
{
  // The registry's defaults for the name, the options given applied: its GPU class from the
  // factory, every parameter set (null for none).
  return vtkDeepShadowTechniqueFactory::New(options.TechniqueParameters());
}

namespace
{
// The meshes of a hybrid scene, --ground and --mesh: vtkDeepShadowPolyDataMapper actors under
// a vtkDeepShadowPass, which makes them cast into the volume's shadows and receive them.
// Towards the key light: hybrid meshes and volumes are placed from it (the headlight: from
// the camera).
void TowardsKeyLight(const SceneSetup& setup, const std::vector<LightSpec>& lights,
  const double centre[3], double toLight[3])
{
  toLight[0] = toLight[1] = 0.0;
  toLight[2] = 1.0;
  if (!lights.empty())
  {
    const LightSpec& key = lights.front();
    for (int c = 0; c < 3; ++c)
    {
      toLight[c] = key.Kind == LightSpec::Directional ? key.Vector[c] : key.Vector[c] - centre[c];
    }
  }
  else
  {
    const double* position = setup.Renderer->GetActiveCamera()->GetPosition();
    for (int c = 0; c < 3; ++c)
    {
      toLight[c] = position[c] - centre[c];
    }
  }
}

// A hybrid scene's second volume (the smoke of hybrid-smoke): drawn by its own mapper with a
// technique of the same kind, at the first volume's sample distance (the CPU reference marches
// every volume with one), and the camera widened to show both.
void AddSecondVolume(SceneSetup& setup, const Options& options, const std::vector<LightSpec>& lights,
  const double centre[3])
{
  double toLight[3];
  TowardsKeyLight(setup, lights, centre, toLight);
  double bounds[6];
  setup.Volume->GetBounds(bounds);
  vtkSmartPointer<vtkImageData> smoke = options.VolumeFile.empty()
    ? vtkDeepShadowHybridScene::MakeSmoke(options.Scene, bounds, toLight)
    : nullptr;
  if (!smoke)
  {
    return;
  }
  setup.SecondMapper = vtkSmartPointer<vtkDeepShadowVolumeMapper>::New();
  setup.SecondMapper->SetInputData(smoke);
  double step = options.SampleDistance;
  if (!(step > 0.0))
  {
    // The first volume's default (a generated scene: axis-aligned, not transformed).
    const double* spacing = setup.Data->GetSpacing();
    step = deepshadow::DefaultSampleDistance(
      glm::scale(glm::dmat4(1.0), glm::dvec3(spacing[0], spacing[1], spacing[2])));
  }
  setup.Mapper->SetSampleDistance(step);
  setup.SecondMapper->SetSampleDistance(step);
  setup.SecondMapper->SetJitter(options.Jitter);
  setup.SecondMapper->SetJitterSeed(options.JitterSeed);
  setup.SecondMapper->SetShadingModel(setup.Mapper->GetShadingModel());
  setup.SecondTechnique = MakeTechnique(options);
  setup.SecondMapper->SetShadowTechnique(setup.SecondTechnique);
  setup.SecondVolume = vtkSmartPointer<vtkVolume>::New();
  setup.SecondVolume->SetMapper(setup.SecondMapper);
  setup.SecondVolume->SetProperty(vtkDeepShadowHybridScene::MakeSmokeProperty());
  setup.Renderer->AddVolume(setup.SecondVolume);
  double both[6];
  smoke->GetBounds(both);
  for (int a = 0; a < 3; ++a)
  {
    both[2 * a] = std::min(both[2 * a], bounds[2 * a]);
    both[2 * a + 1] = std::max(both[2 * a + 1], bounds[2 * a + 1]);
  }
  setup.Renderer->ResetCamera(both);
  setup.Renderer->GetActiveCamera()->Zoom(1.15);
  setup.Renderer->ResetCameraClippingRange();
}

void AddMeshes(SceneSetup& setup, const Options& options, const std::vector<LightSpec>& lights,
  const double centre[3])
{
  double toLight[3];
  TowardsKeyLight(setup, lights, centre, toLight);
  const double* bounds = setup.Volume->GetBounds();
  std::vector<vtkDeepShadowHybridScene::Mesh> meshes;
  if (options.VolumeFile.empty())
  {
    meshes = vtkDeepShadowHybridScene::MakeMeshes(options.Scene, bounds, toLight);
  }
  if (options.Ground && meshes.empty())
  {
    meshes.push_back(vtkDeepShadowHybridScene::MakeGround(bounds, toLight));
  }
  for (const MeshSpec& spec : options.Meshes)
  {
    vtkDeepShadowHybridScene::Mesh mesh;
    mesh.PolyData = ReadMesh(spec.File);
    mesh.Opacity = spec.Opacity;
    mesh.Color = spec.Color;
    vtkNew<vtkTransform> transform;
    transform->Translate(spec.Translate.data());
    transform->Scale(spec.Scale, spec.Scale, spec.Scale);
    vtkNew<vtkTransformPolyDataFilter> place;
    place->SetTransform(transform);
    place->SetInputData(mesh.PolyData);
    place->Update();
    mesh.PolyData = place->GetOutput();
    const std::string problem = vtkDeepShadowPolyDataMapper::CheckInput(mesh.PolyData);
    if (!problem.empty())
    {
      throw UsageError("--mesh " + spec.File + " placed by --mesh-transform: " + problem);
    }
    meshes.push_back(mesh);
  }
  if (meshes.empty())
  {
    return;
  }
  vtkNew<vtkDeepShadowPass> pass;
  pass->SetTranslucentLayers(options.TranslucentLayers);
  pass->SetVolumeSegments(options.VolumeSegments);
  setup.Renderer->SetPass(pass);
  setup.Pass = pass;
  for (const auto& mesh : meshes)
  {
    vtkNew<vtkDeepShadowPolyDataMapper> mapper;
    mapper->SetInputData(mesh.PolyData);
    mapper->ScalarVisibilityOff();
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(mesh.Color[0], mesh.Color[1], mesh.Color[2]);
    actor->GetProperty()->SetOpacity(mesh.Opacity);
    actor->GetProperty()->SetAmbient(0.2);
    actor->GetProperty()->SetDiffuse(0.8);
    setup.Renderer->AddActor(actor);
    setup.Meshes.push_back(mapper);
  }
}
}

void RequireSceneName(const std::string& name)
{
  if (vtkDeepShadowBoundedScene::IsSceneName(name) || vtkDeepShadowHybridScene::IsSceneName(name) ||
    vtkDeepShadowStandardScene::IsSceneName(name))
  {
    return;
  }
  std::string names;
  for (const auto& known : vtkDeepShadowStandardScene::GetSceneNames())
  {
    names += (names.empty() ? "" : ", ") + known;
  }
  for (const auto& known : vtkDeepShadowBoundedScene::GetSceneNames())
  {
    names += ", " + known;
  }
  for (const auto& known : vtkDeepShadowHybridScene::GetSceneNames())
  {
    names += ", " + known;
  }
  throw UsageError("unknown scene '" + name + "' (scenes: " + names + ")");
}

namespace
{
// The volume and its property: a file's (read and checked), or a standard scene's (made by
// `scene`, whose key light joins `lights` when none is asked for).
vtkSmartPointer<vtkVolumeProperty> LoadVolume(
  const Options& options, SceneSetup& setup, vtkDeepShadowStandardScene* scene, std::vector<LightSpec>& lights)
{
  vtkSmartPointer<vtkVolumeProperty> property;
  if (options.ObjectCount > 0 && (!options.VolumeFile.empty() || options.Scene != "sparse"))
  {
    throw UsageError("--objects applies to --scene sparse only");
  }
  if (!options.VolumeFile.empty())
  {
    vtkNew<vtkDeepShadowVolumeReader> reader;
    reader->SetFileName(options.VolumeFile.c_str());
    reader->SetSeries(options.Series);
    reader->SetVolumeIndex(options.VolumeIndex);
    reader->Update();
    if (!reader->GetLastError().empty())
    {
      throw UsageError(reader->GetLastError());
    }
    setup.Data = reader->GetOutput();
    setup.Name = options.VolumeFile;
    setup.Modality = reader->GetModality();
    property = DefaultProperty(setup.Data, setup.Modality, !options.TransferFunction.empty(), setup.Look);
  }
  else
  {
    const bool bounded = vtkDeepShadowBoundedScene::IsSceneName(options.Scene);
    const bool hybrid = vtkDeepShadowHybridScene::IsSceneName(options.Scene);
    RequireSceneName(options.Scene);
    scene->SetScene(bounded ? vtkDeepShadowBoundedScene::GetVolumeSceneName(options.Scene)
        : hybrid        ? vtkDeepShadowHybridScene::GetVolumeSceneName(options.Scene)
                        : options.Scene);
    scene->SetResolutionScale(options.SceneScale);
    scene->SetObjectCount(options.ObjectCount);
    setup.Data = scene->GetVolume();
    setup.GenerationSeconds = scene->GetLastGenerationTime();
    setup.Name = options.Scene;
    property = scene->GetVolumeProperty();
    if (lights.empty())
    {
      LightSpec key;
      scene->GetLightDirection(key.Vector.data());
      lights.push_back(key);
    }
  }
  return property;
}

// The bounds: a bounded scene's meshes, or the files given, combined by the expression and
// checked by CGAL (a bad bound is a usage error, an empty result is said). Returns the
// evaluated mesh (--csg-mesh draws it), null without bounds.
vtkSmartPointer<vtkPolyData> BuildBounds(const Options& options, SceneSetup& setup)
{
  if (vtkDeepShadowBoundedScene::IsSceneName(options.Scene) && options.VolumeFile.empty())
  {
    setup.Bounds = vtkDeepShadowBoundedScene::MakeBounds(options.Scene, setup.Data->GetBounds());
    setup.BoundExpression = vtkDeepShadowBoundedScene::GetBoundExpression(options.Scene);
  }
  if (!options.BoundFiles.empty())
  {
    setup.Bounds.clear();
    setup.BoundExpression.clear();
    for (const std::string& file : options.BoundFiles)
    {
      setup.Bounds.push_back(ReadMesh(file));
    }
  }
  if (!options.Csg.empty())
  {
    if (setup.Bounds.empty())
    {
      throw UsageError("--csg needs bounds (--bound FILE, repeatable)");
    }
    setup.BoundExpression = options.Csg;
  }
  else if (options.CsgMesh && setup.Bounds.empty())
  {
    throw UsageError("--csg-mesh needs bounds (--bound FILE, repeatable)");
  }
  vtkSmartPointer<vtkPolyData> csgMesh;
  if (!setup.Bounds.empty())
  {
    // CGAL checks every bound (closed, not self-intersecting, bounding a volume) and
    // evaluates the expression: a bad bound is a usage error, an empty result is said.
    vtkNew<vtkDeepShadowCSGFilter> csg;
    for (const auto& bound : setup.Bounds)
    {
      csg->AddInputData(bound);
    }
    csg->SetExpression(setup.BoundExpression);
    csg->SetMaximumTriangleWork(options.CsgMaxWork);
    csg->Update();
    if (!csg->GetLastError().empty())
    {
      throw UsageError(csg->GetLastError());
    }
    setup.CsgMilliseconds = csg->GetLastMilliseconds();
    setup.BoundIsEmpty = csg->GetResultIsEmpty();
    if (setup.BoundIsEmpty)
    {
      std::fprintf(stderr, "deepshadow: the bound encloses nothing (its CSG result is empty): the volume is not drawn\n");
    }
    csgMesh = csg->GetOutput();
  }
  return csgMesh;
}

// The volume mapper with the options' sampling, shading, mask, technique and bounds.
void MakeMapper(const Options& options, SceneSetup& setup, vtkPolyData* csgMesh)
{
  setup.Mapper = vtkSmartPointer<vtkDeepShadowVolumeMapper>::New();
  setup.Mapper->SetInputData(setup.Data);
  setup.Mapper->SetSampleDistance(options.SampleDistance);
  setup.Mapper->SetJitter(options.Jitter);
  setup.Mapper->SetJitterSeed(options.JitterSeed);
  setup.Mapper->SetShadingModel(options.VTKShading ? vtkDeepShadowVolumeMapper::VTK_SHADING
                                                   : vtkDeepShadowVolumeMapper::BLINN_PHONG_SHADING);
  setup.Mapper->SetEmptySpaceSkipping(options.EmptySpaceSkipping);
  setup.Mapper->SetReplaceNonFiniteScalars(options.ReplaceNonFinite);
  if (!options.IsoValues.empty())
  {
    setup.Mapper->SetBlendModeToIsoSurface();
  }
  if (!options.MaskFile.empty())
  {
    setup.Mapper->SetMaskInput(ReadMask(options.MaskFile, setup.Data));
    setup.Mapper->SetMaskTypeToBinary();
  }
  setup.Technique = MakeTechnique(options);
  setup.Mapper->SetShadowTechnique(setup.Technique);
  if (options.CsgMesh && csgMesh)
  {
    setup.Mapper->AddBound(csgMesh);
  }
  else
  {
    for (const auto& bound : setup.Bounds)
    {
      setup.Mapper->AddBound(bound);
    }
    setup.Mapper->SetBoundExpression(setup.BoundExpression);
  }
}

// The lights asked for, as scene lights (none: VTK's automatic headlight).
void AddLights(SceneSetup& setup, const std::vector<LightSpec>& lights, const double* centre)
{
  for (const LightSpec& spec : lights)
  {
    vtkNew<vtkLight> light;
    light->SetLightTypeToSceneLight();
    light->SetIntensity(spec.Intensity);
    const double* v = spec.Vector.data();
    if (spec.Kind == LightSpec::Directional)
    {
      light->SetPositional(false);
      light->SetFocalPoint(centre);
      light->SetPosition(centre[0] + v[0], centre[1] + v[1], centre[2] + v[2]);
    }
    else
    {
      light->SetPositional(true);
      light->SetPosition(v[0], v[1], v[2]);
      light->SetFocalPoint(centre);
      light->SetConeAngle(spec.Kind == LightSpec::Spot ? spec.ConeAngle : 180.0);
    }
    setup.Renderer->AddLight(light);
  }
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

  std::vector<LightSpec> lights = options.Lights;
  vtkNew<vtkDeepShadowStandardScene> scene;
  vtkSmartPointer<vtkVolumeProperty> property = LoadVolume(options, setup, scene, lights);
  ApplyAppearance(options, setup.Data, property);
  MakeMapper(options, setup, BuildBounds(options, setup));
  setup.Volume = vtkSmartPointer<vtkVolume>::New();
  setup.Volume->SetMapper(setup.Mapper);
  setup.Volume->SetProperty(property);
  setup.Renderer->AddVolume(setup.Volume);
  // What the mapper cannot render (a placement single precision or VTK's camera cannot
  // resolve: a 1e-30 volume is blank on the GPU and in the CPU reference alike) is refused
  // for every command, before the camera is set up on it.
  setup.Mapper->GetBounds();
  if (!setup.Mapper->GetLastError().empty())
  {
    throw UsageError("cannot render " + setup.Name + ": " + setup.Mapper->GetLastError());
  }

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
  ApplyView(options, setup.Renderer, setup.Volume);
  setup.Renderer->ResetCameraClippingRange();

  // The lights asked for (the renderer's ambient keeps unlit parts readable); none: VTK's
  // automatic headlight.
  const double* centre = setup.Volume->GetCenter();
  AddMeshes(setup, options, lights, centre);
  AddSecondVolume(setup, options, lights, centre);
  AddLights(setup, lights, centre);
  if (options.Command == "render" || options.Command == "reference")
  {
    RequireInView(setup.Renderer, options.Width, options.Height);
  }
  // Before the first frame allocates them: the frame, the shadow structures, the GPU copy.
  RequireWithinBudget(options, setup.Data, setup.Pass != nullptr, setup.SecondVolume ? 2 : 1);
  return setup;
}

double RenderFrame(vtkDeepShadowRenderWindow* window)
{
  const auto start = std::chrono::steady_clock::now();
  window->Render();
  window->WaitForCompletion();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void RequireContext(vtkDeepShadowRenderWindow* window)
{
  if (!window->HasContext())
  {
    // The machine lacks what the chosen backend needs (a driver, libOSMesa): the user's to mend.
    throw UsageError(std::string("no headless ") + window->GetBackendAsString() +
      " context: " + window->GetLastError() + " (--backend chooses another)");
  }
}

void RequireDrawn(const SceneSetup& setup)
{
  RequireContext(setup.Window);
  if (!setup.Mapper->GetLastError().empty())
  {
    throw UsageError("cannot render " + setup.Name + ": " + setup.Mapper->GetLastError());
  }
  for (const auto& mesh : setup.Meshes)
  {
    if (!mesh->GetLastError().empty())
    {
      throw UsageError("cannot render " + setup.Name + "'s mesh: " + mesh->GetLastError());
    }
  }
}

vtkSmartPointer<vtkPolyData> ReadMesh(const std::string& path)
{
  vtkNew<vtkDeepShadowMeshReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  if (!reader->GetLastError().empty())
  {
    throw UsageError(reader->GetLastError());
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->ShallowCopy(reader->GetOutput());
  // Before any VTK filter sees it: they trust the point ids.
  const std::string problem = vtkDeepShadowPolyDataMapper::CheckInput(mesh);
  if (!problem.empty())
  {
    throw UsageError("cannot use mesh '" + path + "': " + problem);
  }
  return mesh;
}

std::string RendererString(vtkDeepShadowRenderWindow* window)
{
  const std::string renderer = window->GetOpenGLRenderer();
  return renderer.empty() ? "unknown" : renderer;
}

void WritePNG(vtkImageData* image, const std::string& path)
{
  if (!deepshadow::WritePNG(image, path))
  {
    throw UsageError("cannot write " + path);
  }
}

std::string PNGBytes(vtkImageData* image)
{
  const std::string bytes = deepshadow::EncodePNG(image);
  if (bytes.empty())
  {
    throw UsageError("the picture could not be encoded as PNG");
  }
  return bytes;
}

std::string PNGBytes(vtkDeepShadowRenderWindow* window)
{
  return PNGBytes(ToImageData(CaptureWindow(window)));
}

}
}
