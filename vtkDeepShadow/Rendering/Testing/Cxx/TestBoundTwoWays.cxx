// Two ways to the same bounded picture: the CSG expression evaluated per ray from the leaves'
// crossings (vtkDeepShadowVolumeMapper::AddBound + SetBoundExpression), and the CGAL result
// mesh of vtkDeepShadowCSGFilter used as a single bound. Both bound the same solid, so the
// pictures agree, on the GPU and on the CPU twin, with shadows.
//
// Stated tolerance: RMSE <= 1/255 and <= 0.5% of pixels beyond 12/255. The two differ only
// where a sample lies within rounding of a face: corefinement splits the leaves' triangles,
// so the crossings are computed from other (coplanar) triangles.
#include "DeepShadowTestUtilities.h"
#include "vtkDeepShadowBoundedScene.h"
#include "vtkDeepShadowCSGFilter.h"
#include "vtkDeepShadowDeepShadowMapTechnique.h"
#include "vtkDeepShadowRenderWindow.h"
#include "vtkDeepShadowVolumeMapper.h"

#include "vtkPolyData.h"

using deepshadow::testing::Check;
using deepshadow::testing::Grab;
using deepshadow::testing::Reference;
using deepshadow::testing::WithinTolerance;

int TestBoundTwoWays(int argc, char* argv[])
{
  deepshadow::testing::ShadowScene scene;
  vtkDeepShadowVolumeMapper* mapper = scene.Mapper;
  auto dsm = vtkSmartPointer<vtkDeepShadowDeepShadowMapTechnique>::New();
  dsm->SetMapSize(128);
  mapper->SetShadowTechnique(dsm);

  // union(A, C) minus B: a box up to the ball's middle, a torus around the pillar's top,
  // minus a sphere that bites into the ball's lower half.
  const double box[6] = { -50.0, 50.0, -50.0, 50.0, -50.0, 12.0 };
  const double ball[3] = { -4.7, -12.0, 4.0 };
  const double pillar[3] = { 25.9, -14.1, 22.0 };
  std::vector<vtkSmartPointer<vtkPolyData>> leaves{ vtkDeepShadowBoundedScene::MakeBox(box),
    vtkDeepShadowBoundedScene::MakeSphere(ball, 10.0, 64),
    vtkDeepShadowBoundedScene::MakeTorus(pillar, 5.0, 4.0, 64) };
  const std::string expression = "diff(union(A,C),B)";

  bool ok = true;
  for (const auto& leaf : leaves)
  {
    mapper->AddBound(leaf);
  }
  mapper->SetBoundExpression(expression);
  scene.Window->Render();
  ok = Check("per ray: drawn (" + mapper->GetLastError() + ")", mapper->GetLastError().empty()) && ok;
  const deepshadow::Image perRay = Grab(scene.Window);
  const deepshadow::Image perRayCPU = Reference(scene.Renderer, true);

  vtkNew<vtkDeepShadowCSGFilter> csg;
  for (const auto& leaf : leaves)
  {
    csg->AddInputData(leaf);
  }
  csg->SetExpression(expression);
  csg->Update();
  ok = Check("CGAL: no error (" + csg->GetLastError() + ")", csg->GetLastError().empty()) && ok;
  std::printf("CGAL: %lld triangles in %.1f ms\n", static_cast<long long>(csg->GetOutput()->GetNumberOfCells()),
    csg->GetLastMilliseconds());
  mapper->RemoveAllBounds();
  mapper->AddBound(csg->GetOutput());
  mapper->SetBoundExpression("");
  scene.Window->Render();
  ok = Check("CGAL mesh: drawn (" + mapper->GetLastError() + ")", mapper->GetLastError().empty()) && ok;
  const deepshadow::Image mesh = Grab(scene.Window);

  ok = WithinTolerance("GPU: per-ray CSG vs the CGAL mesh", perRay, mesh, 1.0 / 255.0, 12.0 / 255.0, 0.005) && ok;
  ok = WithinTolerance("CPU twin: per-ray CSG vs the CGAL mesh", perRayCPU, Reference(scene.Renderer, true),
         1.0 / 255.0, 12.0 / 255.0, 0.005) && ok;
  ok = WithinTolerance("CGAL mesh: GPU vs CPU twin", mesh, Reference(scene.Renderer, true), 2.0 / 255.0,
         12.0 / 255.0, 0.01) && ok;
  ok = Check("the bound changed the picture",
         deepshadow::Compare(mesh, deepshadow::Image(mesh.Width, mesh.Height), 0.1).FractionAbove > 0.05) && ok;

  const int result = deepshadow::testing::RegressionTestImage(scene.Window, argc, argv);
  return ok && result != vtkTesting::FAILED ? EXIT_SUCCESS : EXIT_FAILURE;
}
