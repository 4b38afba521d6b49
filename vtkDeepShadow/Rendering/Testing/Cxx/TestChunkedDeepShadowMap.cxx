// Chunked node memory of deep shadow maps on the GPU (SetChunkNodes, paper 000, section 5) on
// the rods: the picture of layers that never overflow, in fewer bytes, where 8 layers
// overflow; against its CPU twin; a pool too small built again with a doubled bound and said
// once; rebuilt only when something changed; composed only when in use.
#include "DeepShadowTestUtilities.h"
#include "vtkDeepShadowDeepShadowMapTechnique.h"
#include "vtkDeepShadowRenderWindow.h"
#include "vtkDeepShadowVolumeMapper.h"

#include "vtkCamera.h"

using deepshadow::testing::Check;
using deepshadow::testing::Grab;
using deepshadow::testing::WithinTolerance;

namespace
{
bool Identical(const deepshadow::Image& a, const deepshadow::Image& b)
{
  return deepshadow::Compare(a, b, 0.0).MaxAbs == 0.0;
}
}

int TestChunkedDeepShadowMap(int, char*[])
{
  vtkNew<vtkDeepShadowRenderWindow> window;
  window->SetSize(160, 160);
  deepshadow::testing::StandardSceneView view("rods", 0.5, true);
  window->AddRenderer(view.Renderer);
  view.Renderer->SetBackground(0.08, 0.09, 0.12);
  vtkNew<vtkDeepShadowDeepShadowMapTechnique> dsm;
  dsm->SetMapSize(128);
  view.Mapper->SetShadowTechnique(dsm);
  bool ok = true;

  // Fixed layers: 8 overflow (their bound is doubled), 64 do not.
  window->Render();
  const deepshadow::Image eight = Grab(window);
  std::printf("8 layers: %lld texels overflowed, nodes %.2f average, %d at most\n", dsm->GetTexelsOverflowed(),
    dsm->GetNodesAverage(), dsm->GetNodesMax());
  ok = Check("8 layers overflow on the rods", dsm->GetTexelsOverflowed() > 0) && ok;
  ok = Check("fixed layers: no chunked code composed",
         view.Mapper->GetFragmentShaderSource().find("#define DSM_CHUNKED") == std::string::npos) && ok;
  const int layersNeeded = dsm->GetNodesMax();
  dsm->SetLayers(64);
  window->Render();
  const deepshadow::Image all = Grab(window);
  ok = Check("64 layers do not overflow", dsm->GetTexelsOverflowed() == 0) && ok;
  dsm->SetLayers(layersNeeded);
  window->Render();
  const long long fixedBytes = dsm->GetShadowBytes();

  // Chunked: every node kept, the same picture, in less memory than the layers that hold them.
  dsm->SetLayers(8);
  dsm->SetChunkNodes(4);
  window->Render();
  const deepshadow::Image chunked = Grab(window);
  std::printf("chunked: %lld chunks of %lld bytes used, pool %lld bytes, %lld bytes in all; %d layers: %lld bytes\n",
    dsm->GetChunksUsed(), dsm->GetChunkBytes(), dsm->GetPoolBytes(), dsm->GetShadowBytes(), layersNeeded, fixedBytes);
  ok = Check("chunked code composed", view.Mapper->GetFragmentShaderSource().find("#define DSM_CHUNKED") != std::string::npos) && ok;
  ok = Check("chunked: no texel overflowed, the bound asked for",
         dsm->GetTexelsOverflowed() == 0 && dsm->GetEpsilonMax() == static_cast<float>(dsm->GetEpsilon())) && ok;
  ok = Check("chunked: the picture of layers that never overflow", Identical(chunked, all)) && ok;
  ok = Check("(8 layers' picture differs from it)", !Identical(eight, all)) && ok;
  ok = Check("chunked: fewer bytes than the layers that hold every node",
         dsm->GetChunksUsed() > 0 && dsm->GetShadowBytes() < fixedBytes / 2) && ok;
  ok = WithinTolerance("chunked vs CPU twin", chunked, deepshadow::testing::Reference(view.Renderer, true),
         2.0 / 255.0, 12.0 / 255.0, 0.01) && ok;

  // Nothing changed, or only the camera: no rebuild.
  const int builds = view.Mapper->GetShadowBuilds();
  window->Render();
  view.Renderer->GetActiveCamera()->Azimuth(2.0);
  window->Render();
  ok = Check("unchanged light and volume: no rebuild", view.Mapper->GetShadowBuilds() == builds) && ok;

  // A pool too small for the nodes: built again with a doubled bound, said once, and still
  // the twin's picture (which doubles the same way).
  vtkNew<deepshadow::testing::MessageCapture> messages;
  messages->Watch(dsm);
  dsm->SetPoolMegabytes(0.15);
  window->Render();
  const deepshadow::Image small = Grab(window);
  std::printf("pool of 0.15 MB: bound %.3f, %lld chunks used\n", dsm->GetEpsilonMax(), dsm->GetChunksUsed());
  ok = Check("small pool: the bound doubled, some chunks used", dsm->GetEpsilonMax() > 2.0 * dsm->GetEpsilon() - 1e-6 &&
         dsm->GetEpsilonMax() < 1.0 && dsm->GetChunksUsed() > 0) && ok;
  ok = Check("small pool: within the pool", dsm->GetChunksUsed() * dsm->GetChunkBytes() <= 0.15 * 1048576.0) && ok;
  ok = Check("small pool: said once", messages->Warnings.size() == 1 &&
         messages->Warnings.front().find("node pool") != std::string::npos) && ok;
  ok = WithinTolerance("small pool vs CPU twin", small, deepshadow::testing::Reference(view.Renderer, true),
         2.0 / 255.0, 12.0 / 255.0, 0.01) && ok;
  view.Renderer->GetActiveCamera()->Azimuth(2.0);
  window->Render();
  ok = Check("small pool: not said again", messages->Warnings.size() == 1) && ok;
  ok = Check("no error", view.Mapper->GetLastError().empty() && messages->Errors.empty()) && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
