// Translucent meshes composited in depth order with a volume along the view ray
// (vtkDeepShadowPass::TranslucentLayers, Rendering/Translucency). A red glass pane cuts
// through the shadow scene's volume, in front of its back half and behind its front half, and
// reaches past the volume's box on every side; a green glass ball hangs in front of the
// volume. The GPU's picture matches the CPU reference, which sorts every mesh crossing and
// volume sample along each ray, within the hybrid tolerances (RMSE <= 2/255, at most 1% of
// pixels beyond 12/255), with shadows and without. Without the layers (VTK's order: glass
// first, the volume over it) the same comparison fails: the test can tell them apart.
// Also: too few layers is said (GetTranslucentLayersOverflowed) and the CPU twin (which keeps
// as many crossings as there are layers) still matches; peeling rebuilds no shadow structure;
// a scene without translucent meshes peels nothing.
#include "DeepShadowTestUtilities.h"
#include "vtkDeepShadowDeepShadowMapTechnique.h"
#include "vtkDeepShadowPass.h"
#include "vtkDeepShadowPolyDataMapper.h"

#include "vtkActor.h"
#include "vtkCubeSource.h"
#include "vtkProperty.h"
#include "vtkSphereSource.h"

using deepshadow::testing::Check;
using deepshadow::testing::Grab;
using deepshadow::testing::HasFeature;
using deepshadow::testing::WithinTolerance;

int TestTranslucentLayers(int argc, char* argv[])
{
  deepshadow::testing::ShadowScene scene;
  vtkDeepShadowRenderWindow* window = scene.Window;
  vtkRenderer* renderer = scene.Renderer;
  bool ok = true;
  vtkNew<vtkDeepShadowPass> pass;
  renderer->SetPass(pass);

  // The volume spans [-47, 47]^3 and the camera looks along +y (from y < 0).
  vtkNew<vtkCubeSource> paneSource;
  paneSource->SetBounds(-75.0, 75.0, -8.0, -4.0, -60.0, 70.0);
  vtkNew<vtkDeepShadowPolyDataMapper> paneMapper;
  paneMapper->SetInputConnection(paneSource->GetOutputPort());
  vtkNew<vtkActor> pane;
  pane->SetMapper(paneMapper);
  pane->GetProperty()->SetColor(1.0, 0.35, 0.3);
  pane->GetProperty()->SetOpacity(0.35);
  renderer->AddActor(pane);

  vtkNew<vtkSphereSource> ballSource;
  ballSource->SetCenter(-30.0, -70.0, -10.0);
  ballSource->SetRadius(14.0);
  ballSource->SetThetaResolution(32);
  ballSource->SetPhiResolution(16);
  vtkNew<vtkDeepShadowPolyDataMapper> ballMapper;
  ballMapper->SetInputConnection(ballSource->GetOutputPort());
  vtkNew<vtkActor> ball;
  ball->SetMapper(ballMapper);
  ball->GetProperty()->SetColor(0.3, 1.0, 0.4);
  ball->GetProperty()->SetOpacity(0.4);
  renderer->AddActor(ball);

  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.3, -3.0, 0.8);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0.0, 0.0, 1.0);
  renderer->ResetCamera();
  camera->Zoom(1.2);
  renderer->ResetCameraClippingRange();
  window->SetSize(200, 160);

  // 1. No shadows: the layers merged into the march against the CPU's sorted compositing.
  window->Render();
  const deepshadow::Image merged = Grab(window);
  const deepshadow::Image reference = deepshadow::testing::Reference(renderer, true);
  ok = WithinTolerance("glass in and before the volume, merged", merged, reference, 2.0 / 255.0,
         12.0 / 255.0, 0.01) && ok;
  ok = Check("4 layers peeled, none left over, the volume merges them",
         pass->GetPeeledLayers() == 4 && !pass->GetTranslucentLayersOverflowed() &&
           HasFeature(scene.Mapper, "TranslucentLayers") && pass->GetTranslucentLayerBytes() > 0) && ok;

  // 2. VTK's order (layers off) differs from the reference: the comparison above can fail.
  pass->SetTranslucentLayers(0);
  window->Render();
  const deepshadow::Image unsorted = Grab(window);
  ok = Check("without the layers the picture is not the sorted one",
         !WithinTolerance("glass blended before the volume (expected to differ)", unsorted, reference,
           2.0 / 255.0, 12.0 / 255.0, 0.01) &&
           pass->GetPeeledLayers() == 0 && !HasFeature(scene.Mapper, "TranslucentLayers")) && ok;

  // 3. Too few layers: said; the CPU twin leaves out the same crossings (only the nearest
  //    one per ray), while the exact reference keeps them all.
  pass->SetTranslucentLayers(1);
  window->Render();
  ok = Check("one layer is too few for a pane seen through its two faces",
         pass->GetPeeledLayers() == 1 && pass->GetTranslucentLayersOverflowed()) && ok;
  ok = WithinTolerance("one layer, against the twin that peels one layer", Grab(window),
         deepshadow::testing::Reference(renderer, true), 2.0 / 255.0, 12.0 / 255.0, 0.01) && ok;
  ok = Check("one layer differs from the exact picture",
         !WithinTolerance("one layer, against the exact reference (expected to differ)", Grab(window),
           deepshadow::testing::Reference(renderer, false), 2.0 / 255.0, 12.0 / 255.0, 0.01)) && ok;
  pass->SetTranslucentLayers(4);

  // 4. With shadows (the glass casts a red shadow into the volume): still the sorted picture,
  //    and frames that only peel rebuild nothing.
  vtkNew<vtkDeepShadowDeepShadowMapTechnique> dsm;
  dsm->ColoredOn();
  deepshadow::Image shadowed;
  ok = scene.MatchesTwin("glass in and before the volume, dsm-color", dsm, 2.0 / 255.0,
         12.0 / 255.0, 0.01, shadowed) && ok;
  const int builds = dsm->GetBuildCount();
  camera->Azimuth(5.0);
  window->Render();
  camera->Azimuth(-5.0);
  window->Render();
  ok = Check("peeling rebuilds no shadow structure", dsm->GetBuildCount() == builds) && ok;

  // 5. Opaque meshes only: nothing is peeled.
  pane->GetProperty()->SetOpacity(1.0);
  ball->GetProperty()->SetOpacity(1.0);
  window->Render();
  ok = Check("no translucent mesh: no layers", pass->GetPeeledLayers() == 0 &&
         !HasFeature(scene.Mapper, "TranslucentLayers")) && ok;
  pane->GetProperty()->SetOpacity(0.35);
  ball->GetProperty()->SetOpacity(0.4);

  // 6. A second volume: defined, not sorted with the first. The first volume in the renderer
  //    merges the layers; the second is blended over the picture, as VTK does.
  {
    vtkNew<vtkDeepShadowVolumeMapper> secondMapper;
    secondMapper->SetShadingModelToBlinnPhong(); // as the scene's
    secondMapper->SetInputData(deepshadow::testing::MakeShadowVolume(16));
    vtkNew<vtkVolume> second;
    second->SetMapper(secondMapper);
    second->SetProperty(scene.Property);
    second->SetPosition(60.0, -60.0, 0.0);
    renderer->AddVolume(second);
    window->Render();
    ok = Check("two volumes: the first merges the layers and the second's segments",
           pass->GetPeeledLayers() == 4 && HasFeature(scene.Mapper, "TranslucentLayers") &&
             !HasFeature(secondMapper, "TranslucentLayers") && HasFeature(secondMapper, "VolumeSegments") &&
             pass->GetMergedVolumes() == 1 && secondMapper->GetLastError().empty() &&
             scene.Mapper->GetLastError().empty()) && ok;
    renderer->RemoveVolume(second);
  }

  window->Render();
  const int result = deepshadow::testing::RegressionTestImage(window, argc, argv);
  return ok && result != vtkTesting::FAILED ? EXIT_SUCCESS : EXIT_FAILURE;
}
