// A volume bounded by closed meshes combined by CSG (vtkDeepShadowVolumeMapper::AddBound):
// the ball of the shadow scene is cut away by diff(box, sphere), and with it its shadow, for
// every technique; GPU and CPU twin agree; special bounds (touching the volume's faces, much
// larger, entirely outside, empty, open) do what their documentation says; the bound is
// rebuilt, and shadows recomputed, only when it changed.
//
// Stated tolerances (GPU vs CPU twin): as TestShadowTechniques and TestDeepShadowTechniques,
// RMSE <= 2/255 (translucent) or 4/255 (binary) and <= 1% (3%) of pixels beyond 12/255
// (24/255). A sample that lies within float rounding of a bound's face can fall either side
// on the GPU and the CPU; on these scenes that moves no pixel beyond those tolerances.
#include "DeepShadowTestUtilities.h"
#include "vtkDeepShadowDeepShadowMapTechnique.h"
#include "vtkDeepShadowRayTechnique.h"
#include "vtkDeepShadowRenderWindow.h"
#include "vtkDeepShadowShadowMapTechnique.h"
#include "vtkDeepShadowStochasticShadowMapTechnique.h"
#include "vtkDeepShadowVolumeMapper.h"

#include "vtkCellArray.h"
#include "vtkCubeSource.h"
#include "vtkPolyData.h"
#include "vtkSphereSource.h"

using deepshadow::testing::Check;
using deepshadow::testing::Grab;
using deepshadow::testing::HasFeature;
using deepshadow::testing::WithinTolerance;

namespace
{
vtkSmartPointer<vtkPolyData> Cube(double lo, double hi)
{
  vtkNew<vtkCubeSource> cube; // quads with unshared points per face: merged by the mapper
  cube->SetBounds(lo, hi, lo, hi, lo, hi);
  cube->Update();
  return cube->GetOutput();
}

vtkSmartPointer<vtkPolyData> Sphere(double x, double y, double z, double radius)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(x, y, z);
  sphere->SetRadius(radius);
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(32);
  sphere->Update();
  return sphere->GetOutput();
}

struct Case
{
  const char* Name;
  vtkSmartPointer<vtkDeepShadowTechnique> Technique;
  bool Binary;
};
}

int TestBoundedVolume(int argc, char* argv[])
{
  deepshadow::testing::ShadowScene scene;
  vtkDeepShadowRenderWindow* window = scene.Window;
  vtkDeepShadowVolumeMapper* mapper = scene.Mapper;
  bool ok = true;

  window->Render();
  const deepshadow::Image unbounded = Grab(window);
  ok = Check("no bound: no Bound code in the shader", !HasFeature(mapper, "Bound")) && ok;

  // The volume spans [-47, 47]^3; the ball is centred at (-4.7, 0, 9.4), radius 14.1.
  vtkSmartPointer<vtkPolyData> box = Cube(-50.0, 50.0);
  vtkSmartPointer<vtkPolyData> ballCut = Sphere(-4.7, 0.0, 9.4, 16.0);
  mapper->AddBound(box);
  mapper->AddBound(ballCut);
  mapper->SetBoundExpression("diff(A,B)");
  window->Render();
  ok = Check("bounded: the Bound feature is composed", HasFeature(mapper, "Bound")) && ok;
  ok = Check("bounded: no error (" + mapper->GetLastError() + ")", mapper->GetLastError().empty()) && ok;
  const deepshadow::Image cut = Grab(window);
  ok = WithinTolerance("bounded, no shadows", cut, deepshadow::testing::Reference(scene.Renderer, true),
         2.0 / 255.0, 12.0 / 255.0, 0.01) && ok;
  ok = Check("the ball is cut away (the picture changed)",
         deepshadow::Compare(cut, unbounded, 0.1).FractionAbove > 0.01) && ok;
  const double litFloor = scene.FloorUnderBall(cut).r;

  auto rays = vtkSmartPointer<vtkDeepShadowRayTechnique>::New();
  auto cached = vtkSmartPointer<vtkDeepShadowRayTechnique>::New();
  cached->SetCached(true);
  cached->SetShadowVolumeSize(48);
  auto map = vtkSmartPointer<vtkDeepShadowShadowMapTechnique>::New();
  map->SetMapSize(128);
  map->SetThreshold(0.3);
  auto dsm = vtkSmartPointer<vtkDeepShadowDeepShadowMapTechnique>::New();
  dsm->SetMapSize(128);
  auto cssm = vtkSmartPointer<vtkDeepShadowStochasticShadowMapTechnique>::New();
  cssm->SetMapSize(128);
  cssm->SetSeed(7);
  const Case cases[] = { { "rays", rays, false }, { "rays-cached", cached, false },
    { "shadowmap", map, true }, { "dsm", dsm, false }, { "cssm", cssm, false } };
  for (const Case& c : cases)
  {
    deepshadow::Image gpu;
    const std::string name = std::string("bounded, ") + c.Name;
    ok = scene.MatchesTwin(name.c_str(), c.Technique, (c.Binary ? 4.0 : 2.0) / 255.0,
           (c.Binary ? 24.0 : 12.0) / 255.0, c.Binary ? 0.03 : 0.01, gpu) && ok;
    // The ball is gone, and so is its shadow: the floor under it stays lit (with the ball it
    // falls below half the unshadowed value, TestShadowTechniques; the pillar's shadow reaches
    // the edge of the measured patch).
    const double floor = scene.FloorUnderBall(gpu).r;
    ok = Check(name + ": the floor under the cut ball is lit (" + std::to_string(floor) + " vs " +
               std::to_string(litFloor) + " unshadowed)", floor > 0.7 * litFloor) && ok;
  }

  // Observability: a camera move re-uploads nothing; a changed bound rebuilds the bound and
  // the shadows; the same bound again rebuilds nothing.
  mapper->SetShadowTechnique(dsm);
  window->Render();
  const int boundBuilds = mapper->GetBoundBuilds();
  const int shadowBuilds = mapper->GetShadowBuilds();
  scene.Renderer->GetActiveCamera()->Azimuth(10.0);
  window->Render();
  ok = Check("camera move: only ray-cast runs", mapper->GetLastPasses() == std::vector<std::string>{ "ray-cast" }) && ok;
  scene.Renderer->GetActiveCamera()->Azimuth(-10.0);
  ballCut->DeepCopy(Sphere(-4.7, -12.0, 9.4, 10.0)); // a bite out of the ball's front
  window->Render();
  ok = Check("changed bound: rebuilt once", mapper->GetBoundBuilds() == boundBuilds + 1) && ok;
  ok = Check("changed bound: the shadows are rebuilt", mapper->GetShadowBuilds() == shadowBuilds + 1) && ok;
  window->Render();
  ok = Check("same bound: nothing rebuilt", mapper->GetBoundBuilds() == boundBuilds + 1 &&
         mapper->GetShadowBuilds() == shadowBuilds + 1) && ok;
  deepshadow::Image bitten;
  ok = scene.MatchesTwin("bounded by a smaller bite, dsm", dsm, 2.0 / 255.0, 12.0 / 255.0, 0.01, bitten) && ok;
  ok = Check("a smaller bite: the ball's remains cast a shadow",
         scene.FloorUnderBall(bitten).r < 0.6 * litFloor) && ok;

  // A bound touching the volume's faces, or much larger: the same picture as no bound.
  mapper->SetShadowTechnique(nullptr);
  for (double half : { 47.0, 5000.0 })
  {
    mapper->RemoveAllBounds();
    mapper->AddBound(Cube(-half, half));
    mapper->SetBoundExpression("");
    window->Render();
    const std::string name = half == 47.0 ? "a bound on the volume's faces" : "a bound 100 times larger";
    ok = WithinTolerance(name.c_str(), Grab(window), unbounded, 0.5 / 255.0, 2.0 / 255.0, 0.0) && ok;
  }
  // A bound entirely outside the volume: nothing is drawn.
  mapper->RemoveAllBounds();
  mapper->AddBound(Sphere(200.0, 0.0, 0.0, 20.0));
  window->Render();
  ok = Check("a bound outside the volume: only the background",
         deepshadow::testing::CoveredFraction(Grab(window), { 0.05, 0.05, 0.08 }) == 0.0) && ok;

  // An empty bound (an empty CSG result) encloses nothing: nothing drawn, and said so.
  vtkNew<deepshadow::testing::MessageCapture> messages;
  messages->Watch(mapper);
  mapper->RemoveAllBounds();
  vtkNew<vtkPolyData> empty;
  mapper->AddBound(empty);
  window->Render();
  ok = Check("an empty bound: a warning", !messages->Warnings.empty() &&
         messages->Warnings.back().find("encloses nothing") != std::string::npos) && ok;
  ok = Check("an empty bound: only the background",
         deepshadow::testing::CoveredFraction(Grab(window), { 0.05, 0.05, 0.08 }) == 0.0) && ok;

  // An open bound is an error naming it; the volume is not drawn.
  vtkSmartPointer<vtkPolyData> open = Cube(-50.0, 50.0);
  open->BuildLinks();
  open->DeleteCell(5);
  open->RemoveDeletedCells();
  mapper->RemoveAllBounds();
  mapper->AddBound(Sphere(0.0, 0.0, 0.0, 30.0));
  mapper->AddBound(open);
  window->Render();
  ok = Check("an open bound: an error naming it (" + mapper->GetLastError() + ")",
         messages->ErrorContains("bound B is not closed: 4 border edges")) && ok;
  // A bad expression is an error too.
  mapper->RemoveAllBounds();
  mapper->AddBound(box);
  mapper->SetBoundExpression("union(A,B)");
  window->Render();
  ok = Check("a bad expression: an error (" + mapper->GetLastError() + ")",
         messages->ErrorContains("bound B is not given")) && ok;

  // The picture kept as the regression baseline: the cut ball with deep shadows.
  mapper->RemoveAllBounds();
  mapper->AddBound(box);
  mapper->AddBound(Sphere(-4.7, -12.0, 9.4, 10.0));
  mapper->SetBoundExpression("difference(A,B)");
  mapper->SetShadowTechnique(dsm);
  window->Render();
  const int result = deepshadow::testing::RegressionTestImage(window, argc, argv);
  return ok && result != vtkTesting::FAILED ? EXIT_SUCCESS : EXIT_FAILURE;
}
