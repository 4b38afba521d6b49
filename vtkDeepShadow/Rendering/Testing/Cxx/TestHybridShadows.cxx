// Hybrid scenes (vtkDeepShadowPass, vtkDeepShadowPolyDataMapper): the shadow scene's volume
// over a ground mesh, an opaque rod through it and a translucent blue glass slab between the
// light and part of it. For every technique: meshes cast into the volume's structure and
// receive from it, GPU against the CPU twin within the stated tolerances; the physics shows
// (the ground is shadowed, the glass tints blue); shadow structures are rebuilt only when a
// casting mesh changed; bad meshes are clear messages, not crashes.
//
// Stated tolerances (GPU vs CPU twin), as TestShadowTechniques: RMSE <= 2/255 (translucent)
// or 4/255 (binary), at most 1% (3%) of pixels beyond 12/255 (24/255). Rasterized mesh
// edges fall on slightly different pixels than the CPU's ray crossings: a few pixels along
// silhouettes differ; the fractions above hold them.
#include "DeepShadowTestUtilities.h"
#include "vtkDeepShadowDeepShadowMapTechnique.h"
#include "vtkDeepShadowOpacityLevelsTechnique.h"
#include "vtkDeepShadowPass.h"
#include "vtkDeepShadowPolyDataMapper.h"
#include "vtkDeepShadowRayTechnique.h"
#include "vtkDeepShadowShadowMapTechnique.h"
#include "vtkDeepShadowStochasticShadowMapTechnique.h"

#include "vtkActor.h"
#include "vtkCubeSource.h"
#include "vtkCylinderSource.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkCellArray.h"

#include <limits>
#include <vector>

using deepshadow::testing::Check;
using deepshadow::testing::Grab;
using deepshadow::testing::WithinTolerance;

namespace
{
// A square of two triangles at height z, no normals (the mapper computes them).
vtkSmartPointer<vtkPolyData> Ground(double half, double z)
{
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(-half, -half, z);
  points->InsertNextPoint(half, -half, z);
  points->InsertNextPoint(half, half, z);
  points->InsertNextPoint(-half, half, z);
  vtkNew<vtkCellArray> polys;
  const vtkIdType quad[4] = { 0, 1, 2, 3 }; // a quad: the mapper triangulates it
  polys->InsertNextCell(4, quad);
  auto ground = vtkSmartPointer<vtkPolyData>::New();
  ground->SetPoints(points);
  ground->SetPolys(polys);
  return ground;
}

struct Case
{
  const char* Name;
  vtkSmartPointer<vtkDeepShadowTechnique> Technique;
  bool Binary;
};

// Mean colour over a rectangle of pixels.
glm::dvec3 Mean(const deepshadow::Image& image, int x0, int x1, int y0, int y1)
{
  glm::dvec3 sum(0.0);
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      sum += image.At(x, y);
  return sum / double((x1 - x0) * (y1 - y0));
}

// The frame after the first rebuilds nothing (VTK creating a mapper's default lookup table
// on first use once made the meshes be gathered, and the shadows built, twice).
bool SecondFrameRebuildsNothing(deepshadow::testing::ShadowScene& scene, vtkDeepShadowPass* pass)
{
  vtkDeepShadowRenderWindow* window = scene.Window;
  bool ok = true;
  vtkNew<vtkDeepShadowDeepShadowMapTechnique> first;
  scene.Mapper->SetShadowTechnique(first);
  scene.Data->Modified(); // uploaded again inside PrepareShadows, which must still not draw
  window->Render();
  const auto& passes = scene.Mapper->GetLastPasses();
  ok = Check("a data upload before the meshes: the volume is drawn once",
         std::count(passes.begin(), passes.end(), "ray-cast") == 1 &&
           std::count(passes.begin(), passes.end(), "volume-upload") == 1) && ok;
  const int builds = first->GetBuildCount(), sets = pass->GetSurfaceSetBuilds();
  window->Render();
  ok = Check("the second frame rebuilds nothing", first->GetBuildCount() == builds &&
         pass->GetSurfaceSetBuilds() == sets && builds == 1) && ok;
  scene.Mapper->SetShadowTechnique(nullptr);
  return ok;
}

// Every technique of the hybrid scene, `dsm` (the coloured deep shadow map) among them.
std::vector<Case> MakeCases(vtkSmartPointer<vtkDeepShadowDeepShadowMapTechnique>& dsm)
{
  std::vector<Case> cases;
  cases.push_back({ "rays", vtkSmartPointer<vtkDeepShadowRayTechnique>::New(), false });
  auto opaqueRays = vtkSmartPointer<vtkDeepShadowRayTechnique>::New();
  opaqueRays->OpaqueOn();
  cases.push_back({ "rays-opaque", opaqueRays, true });
  auto cachedRays = vtkSmartPointer<vtkDeepShadowRayTechnique>::New();
  cachedRays->CachedOn();
  cases.push_back({ "rays-cached", cachedRays, false });
  cases.push_back({ "shadowmap", vtkSmartPointer<vtkDeepShadowShadowMapTechnique>::New(), true });
  dsm = vtkSmartPointer<vtkDeepShadowDeepShadowMapTechnique>::New();
  dsm->ColoredOn();
  cases.push_back({ "dsm-color", dsm, false });
  cases.push_back({ "dsm3", vtkSmartPointer<vtkDeepShadowOpacityLevelsTechnique>::New(), false });
  cases.push_back({ "cssm", vtkSmartPointer<vtkDeepShadowStochasticShadowMapTechnique>::New(), false });
  return cases;
}

// GPU against the CPU twin for every case; `colored`: the coloured deep shadow map's picture.
bool MatchTwins(deepshadow::testing::ShadowScene& scene, const std::vector<Case>& cases,
  vtkDeepShadowPolyDataMapper* groundMapper, deepshadow::Image& colored)
{
  bool ok = true;
  for (const Case& c : cases)
  {
    deepshadow::Image gpu;
    const std::string name = std::string("hybrid ") + c.Name;
    ok = scene.MatchesTwin(name.c_str(), c.Technique, c.Binary ? 4.0 / 255.0 : 2.0 / 255.0,
      c.Binary ? 24.0 / 255.0 : 12.0 / 255.0, c.Binary ? 0.03 : 0.01, gpu) && ok;
    ok = Check(name + ": the ground receives (its shader looks the structure up)",
      groundMapper->GetShaderFeatures().back() == "Shadow:" + c.Technique->GetName()) && ok;
    if (std::string(c.Name) == "dsm-color")
    {
      colored = gpu;
    }
  }
  return ok;
}

// Physics, on the coloured deep shadow map: much of the lit ground is darker with shadows;
// where the glass's shadow falls, the light is bluer than without it.
bool ShadowsShow(vtkDeepShadowRenderWindow* window, vtkDeepShadowPolyDataMapper* glassMapper,
  const deepshadow::Image& unshadowed, const deepshadow::Image& colored)
{
  bool ok = true;
  int groundPixels = 0, darker = 0;
  for (int y = 0; y < unshadowed.Height; ++y)
    for (int x = 0; x < unshadowed.Width; ++x)
    {
      const glm::dvec3 before = unshadowed.At(x, y), after = colored.At(x, y);
      if (before.r > 0.6 && std::abs(before.r - before.b) < 0.1) // the light grey ground
      {
        ++groundPixels;
        darker += after.g < 0.8 * before.g ? 1 : 0;
      }
    }
  ok = Check("the volume, rod and glass shadow the ground (" + std::to_string(darker) + " of " +
         std::to_string(groundPixels) + " pixels darker)", groundPixels > 0 && darker > groundPixels / 10) && ok;
  glassMapper->CastShadowsOff();
  window->Render();
  const deepshadow::Image noGlassShadow = Grab(window);
  glassMapper->CastShadowsOn();
  glm::dvec3 with(0.0), without(0.0);
  for (int y = 0; y < colored.Height; ++y)
    for (int x = 0; x < colored.Width; ++x)
    {
      if (glm::length(colored.At(x, y) - noGlassShadow.At(x, y)) > 0.05)
      {
        with += colored.At(x, y);
        without += noGlassShadow.At(x, y);
      }
    }
  ok = Check("the glass's shadow is blue",
         with.b > 0.0 && with.b / with.r > 1.5 * without.b / std::max(without.r, 1e-9)) && ok;
  return ok;
}

// Rebuilds: a camera move or a mesh that only receives rebuilds nothing; moving the rod does.
// `keep`: what it adds to the scene, alive to the end as before.
bool RebuildsOnlyForCasters(deepshadow::testing::ShadowScene& scene, vtkDeepShadowPass* pass,
  vtkActor* rod, std::vector<vtkSmartPointer<vtkObjectBase>>& keep)
{
  vtkDeepShadowRenderWindow* window = scene.Window;
  vtkRenderer* renderer = scene.Renderer;
  vtkCamera* camera = renderer->GetActiveCamera();
  bool ok = true;
  vtkDeepShadowTechnique* technique = scene.Mapper->GetShadowTechnique();
  window->Render();
  const int builds = technique->GetBuildCount();
  const int sets = pass->GetSurfaceSetBuilds();
  const int uploads = scene.Mapper->GetSurfaceUploads();
  camera->Azimuth(10.0);
  window->Render();
  vtkNew<vtkDeepShadowPolyDataMapper> receiverMapper;
  receiverMapper->SetInputData(Ground(20.0, -50.0));
  receiverMapper->CastShadowsOff();
  vtkNew<vtkActor> receiver;
  receiver->SetMapper(receiverMapper);
  renderer->AddActor(receiver);
  window->Render();
  ok = Check("camera move and a receiver-only mesh: no shadow rebuild",
         technique->GetBuildCount() == builds && pass->GetSurfaceSetBuilds() == sets &&
           scene.Mapper->GetSurfaceUploads() == uploads) && ok;
  rod->SetPosition(0.0, -10.0, 25.0);
  window->Render();
  ok = Check("moving the rod rebuilds the surfaces and the structure once",
         technique->GetBuildCount() == builds + 1 && pass->GetSurfaceSetBuilds() == sets + 1 &&
           scene.Mapper->GetSurfaceUploads() == uploads + 1) && ok;
  renderer->RemoveActor(receiver);
  rod->SetPosition(0.0, -20.0, 25.0);
  camera->Azimuth(-10.0);
  keep.insert(keep.end(), { receiverMapper.Get(), receiver.Get() });
  return ok;
}

// Bad meshes: NaN points and no polygons are messages; the rest of the scene still renders.
// `keep`: what it adds to the scene (the message capture included), alive to the end as before.
bool BadMeshes(deepshadow::testing::ShadowScene& scene, vtkDeepShadowPass* pass,
  std::vector<vtkSmartPointer<vtkObjectBase>>& keep)
{
  vtkDeepShadowRenderWindow* window = scene.Window;
  vtkRenderer* renderer = scene.Renderer;
  bool ok = true;
  vtkSmartPointer<vtkPolyData> bad = Ground(10.0, 0.0);
  bad->GetPoints()->SetPoint(1, std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0);
  vtkNew<vtkDeepShadowPolyDataMapper> badMapper;
  badMapper->SetInputData(bad);
  vtkNew<vtkActor> badActor;
  badActor->SetMapper(badMapper);
  renderer->AddActor(badActor);
  vtkNew<deepshadow::testing::MessageCapture> messages;
  messages->Watch(badMapper);
  messages->Watch(pass);
  window->Render();
  ok = Check("a mesh with NaN points is reported (" + badMapper->GetLastError() + ")",
         badMapper->GetLastError().find("not finite") != std::string::npos) && ok;
  // An empty mesh has no bounds: VTK's culler leaves it out, as it does for any actor.
  vtkNew<vtkPolyData> empty;
  badMapper->SetInputData(empty);
  window->Render();
  ok = Check("an empty mesh draws and casts nothing, the others still cast",
         pass->GetCastingMeshes() == 3 && pass->GetLastError().empty()) && ok;
  renderer->RemoveActor(badActor);
  keep.insert(keep.end(), { bad.Get(), badMapper.Get(), badActor.Get(), messages.Get(), empty.Get() });
  return ok;
}
}

int TestHybridShadows(int argc, char* argv[])
{
  deepshadow::testing::ShadowScene scene;
  vtkDeepShadowRenderWindow* window = scene.Window;
  vtkRenderer* renderer = scene.Renderer;
  bool ok = true;
  vtkNew<vtkDeepShadowPass> pass;
  renderer->SetPass(pass);

  // The volume spans [-47, 47]^3: the ground lies under it, the rod runs through the ball's
  // height along x, the glass covers the volume's +x half well above it.
  vtkNew<vtkDeepShadowPolyDataMapper> groundMapper;
  groundMapper->SetInputData(Ground(110.0, -52.0));
  vtkNew<vtkActor> ground;
  ground->SetMapper(groundMapper);
  ground->GetProperty()->SetColor(0.85, 0.85, 0.8);
  renderer->AddActor(ground);

  vtkNew<vtkCylinderSource> rodSource;
  rodSource->SetRadius(3.0);
  rodSource->SetHeight(120.0);
  rodSource->SetResolution(24);
  vtkNew<vtkDeepShadowPolyDataMapper> rodMapper;
  rodMapper->SetInputConnection(rodSource->GetOutputPort());
  vtkNew<vtkActor> rod;
  rod->SetMapper(rodMapper);
  rod->RotateZ(90.0); // the cylinder's axis is y: along x now
  rod->SetPosition(0.0, -20.0, 25.0);
  rod->GetProperty()->SetColor(0.7, 0.7, 0.75);
  rod->GetProperty()->SetSpecular(0.3);
  renderer->AddActor(rod);

  vtkNew<vtkCubeSource> slab;
  slab->SetBounds(5.0, 80.0, -80.0, 80.0, 70.0, 73.0);
  vtkNew<vtkDeepShadowPolyDataMapper> glassMapper;
  glassMapper->SetInputConnection(slab->GetOutputPort());
  glassMapper->ReceiveShadowsOff();
  vtkNew<vtkActor> glass;
  glass->SetMapper(glassMapper);
  glass->GetProperty()->SetColor(0.2, 0.4, 1.0);
  glass->GetProperty()->SetOpacity(0.5);
  renderer->AddActor(glass);

  // Seen from a little above the ground, so the glass does not lie over the volume.
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, -3.0, 0.5);
  camera->SetFocalPoint(0.0, 0.0, -0.1);
  renderer->ResetCamera();
  camera->Zoom(1.2);
  renderer->ResetCameraClippingRange();
  window->SetSize(200, 160);

  window->Render();
  const deepshadow::Image unshadowed = Grab(window);
  ok = WithinTolerance("hybrid, no shadows", unshadowed, deepshadow::testing::Reference(renderer, true),
    2.0 / 255.0, 12.0 / 255.0, 0.01) && ok;

  ok = SecondFrameRebuildsNothing(scene, pass) && ok;

  vtkSmartPointer<vtkDeepShadowDeepShadowMapTechnique> dsm;
  const std::vector<Case> cases = MakeCases(dsm);
  deepshadow::Image colored;
  ok = MatchTwins(scene, cases, groundMapper, colored) && ok;

  ok = ShadowsShow(window, glassMapper, unshadowed, colored) && ok;

  std::vector<vtkSmartPointer<vtkObjectBase>> keep;
  ok = RebuildsOnlyForCasters(scene, pass, rod, keep) && ok;

  ok = BadMeshes(scene, pass, keep) && ok;

  // The baseline: the coloured deep shadow map of the hybrid scene.
  scene.Mapper->SetShadowTechnique(dsm);
  window->Render();
  const int result = deepshadow::testing::RegressionTestImage(window, argc, argv);
  return ok && result != vtkTesting::FAILED ? EXIT_SUCCESS : EXIT_FAILURE;
}
