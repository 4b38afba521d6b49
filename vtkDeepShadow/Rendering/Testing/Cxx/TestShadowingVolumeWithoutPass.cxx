// A mesh receives a volume's shadows without vtkDeepShadowPass (SetShadowingVolume), as in a
// renderer whose passes belong to someone else (ParaView's views): the shadow scene's volume
// over a ground mesh, drawn by VTK's own passes. The picture matches the one the pass draws
// (with the ground casting nothing, as it then casts nothing), and a check that passes it
// fails on the ground lit without shadows. The volume's own render rebuilds nothing after
// the mesh prepared its structures.
#include "DeepShadowTestUtilities.h"
#include "vtkDeepShadowPass.h"
#include "vtkDeepShadowPolyDataMapper.h"
#include "vtkDeepShadowTechniqueFactory.h"

#include "vtkActor.h"

#include <cstdio>

using deepshadow::testing::Check;
using deepshadow::testing::Grab;
using deepshadow::testing::WithinTolerance;

int TestShadowingVolumeWithoutPass(int, char*[])
{
  bool ok = true;
  deepshadow::testing::ShadowScene scene;
  vtkNew<vtkDeepShadowPolyDataMapper> groundMapper;
  vtkNew<vtkActor> ground;
  scene.AddGround(groundMapper, ground);
  groundMapper->CastShadowsOff();
  vtkSmartPointer<vtkDeepShadowTechnique> technique = vtkDeepShadowTechniqueFactory::New("dsm");
  scene.Mapper->SetShadowTechnique(technique);

  // The pass's picture.
  vtkNew<vtkDeepShadowPass> pass;
  scene.Renderer->SetPass(pass);
  scene.Window->Render();
  const deepshadow::Image withPass = Grab(scene.Window);
  scene.Renderer->SetPass(nullptr);

  // VTK's passes: the ground lit without shadows, then receiving the volume's.
  scene.Window->Render();
  const deepshadow::Image unshadowed = Grab(scene.Window);
  ok = Check("without the pass or a shadowing volume, the ground receives nothing",
         !deepshadow::testing::HasFeature(groundMapper->GetShaderFeatures(), "Shadow:dsm")) && ok;
  groundMapper->SetShadowingVolume(scene.Volume);
  scene.Window->Render();
  const int builds = technique->GetBuildCount();
  scene.Window->Render();
  const deepshadow::Image receiving = Grab(scene.Window);
  if (!groundMapper->GetLastError().empty() || !scene.Mapper->GetLastError().empty())
  {
    std::printf("FAILED: %s%s\n", groundMapper->GetLastError().c_str(), scene.Mapper->GetLastError().c_str());
    return EXIT_FAILURE;
  }
  ok = Check("the ground's shader looks the volume's deep shadow map up",
         deepshadow::testing::HasFeature(groundMapper->GetShaderFeatures(), "Shadow:dsm")) && ok;
  ok = Check("an unchanged frame rebuilds nothing", technique->GetBuildCount() == builds) && ok;
  ok = WithinTolerance("ground receiving without the pass vs the pass", receiving, withPass, 1.0 / 255.0,
         12.0 / 255.0, 0.002) && ok;
  ok = Check("the ground lit without shadows differs from the pass (must fail)",
         !WithinTolerance("ground lit vs the pass", unshadowed, withPass, 1.0 / 255.0, 12.0 / 255.0, 0.002)) &&
    ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
