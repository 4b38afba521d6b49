// Clipping planes and cropping as VTK's mapper draws them, and the light sees the same cut.
//
// Each cut (an oblique plane, two planes, a plane under a rotated and scaled prop, cropping
// to a sub-volume, a cross, an inverted cross, an inverted fence) is drawn by our mapper and
// by VTK's in one run and compared with TestVolumeMapperMatchesVTK's shaded tolerance (RMSE
// 0.007, at most 0.5% of pixels off by more than 16/255); the control, ours without the cut,
// must fall outside it. On the CPU reference the cut is the same (GPU vs CPU twin within its
// tolerance), and with a deep shadow map the floor under a removed half of the ball is lit:
// the cut half casts no shadow.
#include "DeepShadowTestUtilities.h"
#include "vtkDeepShadowDeepShadowMapTechnique.h"

#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkTransform.h"

#include <functional>

using deepshadow::testing::Check;
using deepshadow::testing::Grab;
using deepshadow::testing::WithinTolerance;

namespace
{
using Cut = std::function<void(vtkVolumeMapper*, vtkVolume*)>;

void AddPlane(vtkVolumeMapper* mapper, double ox, double oy, double oz, double nx, double ny, double nz)
{
  vtkNew<vtkPlane> plane;
  plane->SetOrigin(ox, oy, oz);
  plane->SetNormal(nx, ny, nz);
  mapper->AddClippingPlane(plane);
}

void Crop(vtkVolumeMapper* mapper, int flags)
{
  mapper->CroppingOn();
  mapper->SetCroppingRegionPlanes(-6.0, 5.0, -7.0, 4.0, -5.0, 8.0);
  mapper->SetCroppingRegionFlags(flags);
}

// MakeTestVolume with the comparison look, shaded, under the headlight; `cut` applied to
// the mapper (ours, or VTK's when `vtks`) unless `uncut`.
deepshadow::Image Draw(vtkRenderWindow* window, const Cut& cut, bool vtks, bool uncut)
{
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.1, 0.1, 0.2);
  window->GetRenderers()->RemoveAllItems();
  window->AddRenderer(renderer);
  vtkNew<vtkDeepShadowVolumeMapper> ours;
  vtkNew<vtkGPUVolumeRayCastMapper> theirs;
  theirs->SetAutoAdjustSampleDistances(0);
  vtkVolumeMapper* mapper = vtks ? static_cast<vtkVolumeMapper*>(theirs) : static_cast<vtkVolumeMapper*>(ours);
  ours->SetSampleDistance(0.5f);
  theirs->SetSampleDistance(0.5f);
  mapper->SetInputData(deepshadow::testing::MakeTestVolume(VTK_UNSIGNED_CHAR));
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(deepshadow::testing::MakeComparisonProperty(true));
  renderer->AddVolume(volume);
  if (!uncut)
  {
    cut(mapper, volume);
  }
  deepshadow::testing::ApplyComparisonView(renderer);
  window->Render();
  if (!ours->GetLastError().empty())
  {
    std::printf("ours: %s\n", ours->GetLastError().c_str());
  }
  return Grab(window);
}
}

int TestCutsMatchVTK(int, char*[])
{
  const std::vector<std::pair<const char*, Cut>> cuts = {
    { "an oblique clipping plane",
      [](vtkVolumeMapper* m, vtkVolume*) { AddPlane(m, 2.0, -3.0, 1.0, 1.0, 0.4, -0.3); } },
    { "two clipping planes",
      [](vtkVolumeMapper* m, vtkVolume*) {
        AddPlane(m, 0.0, 0.0, 5.0, 0.0, 0.0, -1.0);
        AddPlane(m, -4.0, 0.0, 0.0, 1.0, 1.0, 0.0);
      } },
    { "a clipping plane, rotated and scaled prop",
      [](vtkVolumeMapper* m, vtkVolume* v) {
        v->RotateZ(30.0);
        v->RotateX(-20.0);
        v->SetScale(1.2, 0.9, 1.0);
        AddPlane(m, 3.0, 0.0, 0.0, -1.0, 0.2, 0.0);
      } },
    { "cropping to a sub-volume", [](vtkVolumeMapper* m, vtkVolume*) { Crop(m, VTK_CROP_SUBVOLUME); } },
    { "cropping to a cross", [](vtkVolumeMapper* m, vtkVolume*) { Crop(m, VTK_CROP_CROSS); } },
    { "cropping to an inverted cross", [](vtkVolumeMapper* m, vtkVolume*) { Crop(m, VTK_CROP_INVERTED_CROSS); } },
    { "cropping to an inverted fence", [](vtkVolumeMapper* m, vtkVolume*) { Crop(m, VTK_CROP_INVERTED_FENCE); } },
  };
  vtkNew<vtkDeepShadowRenderWindow> window;
  window->SetSize(200, 200);
  bool ok = true;
  for (const auto& [name, cut] : cuts)
  {
    const deepshadow::Image ours = Draw(window, cut, false, false);
    const deepshadow::Image vtks = Draw(window, cut, true, false);
    const deepshadow::Image uncut = Draw(window, cut, false, true);
    ok = WithinTolerance(name, ours, vtks, 0.007, 16.0 / 255.0, 0.005) && ok;
    ok = !WithinTolerance((std::string(name) + ", ours uncut (must fail)").c_str(), uncut, vtks,
           0.007, 16.0 / 255.0, 0.005) && ok;
  }

  // The CPU reference cuts the same; the light sees the cut.
  deepshadow::testing::ShadowScene scene;
  vtkNew<vtkDeepShadowDeepShadowMapTechnique> dsm;
  scene.Mapper->SetShadowTechnique(dsm);
  scene.Window->Render();
  const deepshadow::Image whole = Grab(scene.Window);
  AddPlane(scene.Mapper, -3.0, 0.0, 0.0, -1.0, 0.0, 0.0); // keeps x < -3: half the ball goes
  scene.Window->Render();
  const deepshadow::Image halved = Grab(scene.Window);
  ok = WithinTolerance("clipped shadow scene vs CPU twin", halved,
         deepshadow::testing::Reference(scene.Renderer, true), 1.5 / 255.0, 6.0 / 255.0, 0.005) && ok;
  // The floor under the removed half: lit now where the ball shadowed it before.
  double brighter = 0.0;
  int pixels = 0;
  for (int y = 0; y < halved.Height; ++y)
    for (int x = 0; x < halved.Width; ++x)
    {
      const double before = glm::dot(whole.At(x, y), glm::dvec3(1.0 / 3.0));
      const double after = glm::dot(halved.At(x, y), glm::dvec3(1.0 / 3.0));
      if (after > before + 0.08)
      {
        brighter += after - before;
        ++pixels;
      }
    }
  ok = Check("the cut half casts no shadow: " + std::to_string(pixels) + " pixels brighter",
         pixels > 100) && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
