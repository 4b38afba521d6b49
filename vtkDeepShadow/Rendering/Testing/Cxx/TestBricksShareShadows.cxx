// A volume split into two bricks, each drawn by its own mapper as one MPI rank draws its
// piece under ParaView, shares its light-space shadows through vtkDeepShadowBrickExchange:
// the ball in the upper brick shadows the floor in the lower one. The exchange here is an
// in-process store standing in for MPI (the ParaView tests run the MPI one), so the bricks
// draw one after the other and the second frame is the one that sees both.
//
// Checks, for every light-space technique: the two bricks with the exchange against the whole
// volume drawn by one mapper, within what two bricks cost without shadows (measured first:
// RMSE 0.0031 at step 0.25) + 1/255 (2/255 for the binary shadow map; measured 0.0033 to
// 0.0055); the same without the exchange must fail (0.045 to 0.062: the floor is lit); the
// floor under the ball darkens; what the exchange moved is counted. A frame with nothing
// changed rebuilds nothing and moves the same bytes. The totals are scanned along the light
// (vtkDeepShadowBrickExchange::SendReceive); gathered instead, the picture is the same.
#include "DeepShadowTestUtilities.h"
#include "vtkDeepShadowBrickExchange.h"
#include "vtkDeepShadowLightSpaceTechnique.h"
#include "vtkDeepShadowTechniqueFactory.h"

#include "vtkExtractVOI.h"
#include "vtkObjectFactory.h"

#include <cstdio>
#include <map>
#include <memory>
#include <tuple>

using deepshadow::testing::Check;
using deepshadow::testing::Grab;
using deepshadow::testing::ShadowScene;
using deepshadow::testing::WithinTolerance;

namespace
{
// What every brick last sent, by kind: the frame's first gather (box, shape and lights, 10
// values), the totals, and the scan's messages (by sender, receiver and tag).
struct Store
{
  std::map<int, std::vector<float>> Boxes;
  std::map<int, std::vector<float>> Totals;
  std::map<std::tuple<int, int, int>, std::vector<float>> Messages;
};

// An exchange within one process: a brick's gather, or a message it receives, is what the
// others last sent, and for a brick that has not drawn yet what it would send with nothing:
// no box, totals of 1.
class InProcessExchange : public vtkDeepShadowBrickExchange
{
public:
  static InProcessExchange* New();
  vtkTypeMacro(InProcessExchange, vtkDeepShadowBrickExchange);
  std::shared_ptr<Store> Shared;
  int Brick = 0;
  int Bricks = 2;

  int GetNumberOfBricks() override { return this->Bricks; }
  int GetLocalBrick() override { return this->Brick; }
  bool AllGather(const std::vector<float>& local, std::vector<float>& all) override
  {
    const bool box = local.size() == 10;
    auto& posted = box ? this->Shared->Boxes : this->Shared->Totals;
    posted[this->Brick] = local;
    all.clear();
    for (int b = 0; b < this->Bricks; ++b)
    {
      auto found = posted.find(b);
      if (found != posted.end() && found->second.size() == local.size())
      {
        all.insert(all.end(), found->second.begin(), found->second.end());
      }
      else if (box)
      {
        all.insert(all.end(), { 1, 1, 1, -1, -1, -1 }); // no box (min > max)
        all.insert(all.end(), local.begin() + 6, local.end());
      }
      else
      {
        all.insert(all.end(), local.size(), 1.0f);
      }
    }
    return true;
  }
  bool CanSendReceive() override { return true; }
  bool SendReceive(int to, const std::vector<float>& send, int from, std::vector<float>& received, bool,
    int tag) override
  {
    if (to >= 0)
    {
      this->Shared->Messages[std::make_tuple(this->Brick, to, tag)] = send;
    }
    if (from >= 0)
    {
      auto found = this->Shared->Messages.find(std::make_tuple(from, this->Brick, tag));
      const bool sent = found != this->Shared->Messages.end() && found->second.size() == received.size();
      std::fill(received.begin(), received.end(), 1.0f);
      if (sent)
      {
        received = found->second;
      }
    }
    return true;
  }
};
vtkStandardNewMacro(InProcessExchange);

// The mean of the floor in the ball's shadow, over the channels.
double FloorBrightness(const deepshadow::Image& image)
{
  const glm::dvec3 floor = ShadowScene::FloorUnderBall(image);
  return floor.x + floor.y + floor.z;
}
}

int TestBricksShareShadows(int, char*[])
{
  bool ok = true;
  ShadowScene scene;
  // Bricks: z index [0, 20] (the floor) and [20, 47] (the ball), sharing the plane k = 20.
  vtkNew<vtkExtractVOI> lowerPiece, upperPiece;
  lowerPiece->SetInputData(scene.Data);
  lowerPiece->SetVOI(0, 47, 0, 47, 0, 20);
  upperPiece->SetInputData(scene.Data);
  upperPiece->SetVOI(0, 47, 0, 47, 20, 47);
  lowerPiece->Update();
  upperPiece->Update();
  vtkNew<vtkDeepShadowVolumeMapper> lowerMapper, upperMapper;
  lowerMapper->SetShadingModelToBlinnPhong(); // as the whole volume's: VTK's shading
  upperMapper->SetShadingModelToBlinnPhong(); // depends on each brick's box
  lowerMapper->SetInputData(lowerPiece->GetOutput());
  upperMapper->SetInputData(upperPiece->GetOutput());
  vtkNew<vtkVolume> lower, upper;
  lower->SetMapper(lowerMapper);
  upper->SetMapper(upperMapper);
  lower->SetProperty(scene.Property);
  upper->SetProperty(scene.Property);
  // Each brick starts its samples at its own box: short steps keep the thin floor from
  // banding differently in the bricks and in the whole volume.
  for (vtkDeepShadowVolumeMapper* mapper : { scene.Mapper.GetPointer(), lowerMapper.GetPointer(), upperMapper.GetPointer() })
  {
    mapper->SetSampleDistance(0.25);
  }

  // What drawing two bricks instead of one costs without shadows (their samples fall at other
  // depths, and the two pictures are composited at the shared face): the tolerance below.
  scene.Mapper->SetShadowTechnique(nullptr);
  scene.Window->Render();
  const deepshadow::Image wholeUnshadowed = Grab(scene.Window);
  scene.Renderer->RemoveAllViewProps();
  scene.Renderer->AddVolume(lower);
  scene.Renderer->AddVolume(upper);
  scene.Window->Render();
  const deepshadow::ImageDifference compositing =
    deepshadow::Compare(Grab(scene.Window), wholeUnshadowed, 24.0 / 255.0);
  std::printf("two bricks vs the whole volume, no shadows: RMSE %.5f, %.4f%% of pixels > 24/255\n",
    compositing.RMSE, 100.0 * compositing.FractionAbove);

  for (const char* name : { "dsm", "dsm-color", "dsm3", "cssm", "dsm-cached", "shadowmap" })
  {
    const bool binary = std::string(name) == "shadowmap";
    // The whole volume.
    scene.Renderer->RemoveAllViewProps();
    scene.Renderer->AddVolume(scene.Volume);
    scene.Mapper->SetShadowTechnique(vtkDeepShadowTechniqueFactory::New(name));
    scene.Window->Render();
    const deepshadow::Image whole = Grab(scene.Window);

    // The bricks, farther from the camera first (the camera looks down onto the floor).
    scene.Renderer->RemoveAllViewProps();
    scene.Renderer->AddVolume(lower);
    scene.Renderer->AddVolume(upper);
    auto lowerTechnique = vtkSmartPointer<vtkDeepShadowLightSpaceTechnique>::Take(
      vtkDeepShadowLightSpaceTechnique::SafeDownCast(vtkDeepShadowTechnique::NewFromName(name)));
    auto upperTechnique = vtkSmartPointer<vtkDeepShadowLightSpaceTechnique>::Take(
      vtkDeepShadowLightSpaceTechnique::SafeDownCast(vtkDeepShadowTechnique::NewFromName(name)));
    lowerMapper->SetShadowTechnique(lowerTechnique);
    upperMapper->SetShadowTechnique(upperTechnique);
    scene.Window->Render();
    const deepshadow::Image alone = Grab(scene.Window);

    auto store = std::make_shared<Store>();
    vtkNew<InProcessExchange> lowerExchange, upperExchange;
    lowerExchange->Shared = upperExchange->Shared = store;
    lowerExchange->Brick = 0;
    upperExchange->Brick = 1;
    lowerTechnique->SetBrickExchange(lowerExchange);
    upperTechnique->SetBrickExchange(upperExchange);
    scene.Window->Render(); // the lower brick has not seen the upper one's totals yet
    scene.Window->Render();
    if (!lowerMapper->GetLastError().empty() || !upperMapper->GetLastError().empty())
    {
      std::printf("%s: %s%s FAILED\n", name, lowerMapper->GetLastError().c_str(), upperMapper->GetLastError().c_str());
      ok = false;
      continue;
    }
    const deepshadow::Image shared = Grab(scene.Window);
    const int builds = lowerTechnique->GetBuildCount() + upperTechnique->GetBuildCount();
    const long long bytes = lowerExchange->GetLastBytes();
    std::printf("%s: the lower brick gathered %lld bytes in %.2f ms per frame\n", name, bytes,
      lowerExchange->GetLastMilliseconds());

    const std::string what = std::string(name) + ", two bricks";
    const double tolerance = compositing.RMSE + (binary ? 2.0 : 1.0) / 255.0;
    ok = WithinTolerance((what + " sharing shadows vs the whole volume").c_str(), shared, whole, tolerance,
           24.0 / 255.0, binary ? 0.01 : 0.002) && ok;
    ok = Check((what + " each alone differ from the whole volume (must fail)").c_str(),
           !WithinTolerance((what + " alone vs the whole volume").c_str(), alone, whole, tolerance,
             24.0 / 255.0, binary ? 0.01 : 0.002)) && ok;
    std::printf("%s: floor under the ball %.3f alone, %.3f sharing, %.3f whole\n", what.c_str(),
      FloorBrightness(alone), FloorBrightness(shared), FloorBrightness(whole));
    ok = Check((what + ": the ball darkens the other brick's floor").c_str(),
           FloorBrightness(shared) < 0.8 * FloorBrightness(alone)) && ok;

    // Nothing changed: nothing is rebuilt, the same totals are gathered again.
    scene.Window->Render();
    ok = Check((what + ": an unchanged frame rebuilds nothing").c_str(),
           lowerTechnique->GetBuildCount() + upperTechnique->GetBuildCount() == builds) && ok;
    ok = Check((what + ": an unchanged frame gathers the same bytes").c_str(),
           lowerExchange->GetLastBytes() == bytes && bytes > 0) && ok;

    // The totals were scanned along the light (the upper brick first: it receives nothing);
    // gathered instead, the picture is the same.
    ok = Check((what + ": scanned, the upper brick first").c_str(),
           lowerExchange->GetLastScanned() && upperExchange->GetLastScanned() &&
             lowerExchange->GetLastMessages() == 2 && upperExchange->GetLastMessages() == 1) && ok;
    lowerExchange->ScanOff();
    upperExchange->ScanOff();
    scene.Window->Render(); // the lower brick has not seen the upper one's gathered totals yet
    scene.Window->Render();
    const deepshadow::Image gathered = Grab(scene.Window);
    std::printf("%s: gathered, the lower brick received %lld bytes in %d messages\n", name,
      lowerExchange->GetLastBytes(), lowerExchange->GetLastMessages());
    ok = Check((what + ": gathered instead of scanned, the same picture").c_str(),
           !lowerExchange->GetLastScanned() && deepshadow::Compare(gathered, shared, 0.0).RMSE == 0.0) && ok;
  }

  // Bricks that overlap (a ghost layer) have no order: each casts no shadow on the other,
  // said once by each, not every frame.
  {
    upperPiece->SetVOI(0, 47, 0, 47, 18, 47);
    upperPiece->Update();
    auto lowerTechnique = vtkSmartPointer<vtkDeepShadowLightSpaceTechnique>::Take(
      vtkDeepShadowLightSpaceTechnique::SafeDownCast(vtkDeepShadowTechnique::NewFromName("dsm")));
    auto upperTechnique = vtkSmartPointer<vtkDeepShadowLightSpaceTechnique>::Take(
      vtkDeepShadowLightSpaceTechnique::SafeDownCast(vtkDeepShadowTechnique::NewFromName("dsm")));
    auto store = std::make_shared<Store>();
    vtkNew<InProcessExchange> lowerExchange, upperExchange;
    lowerExchange->Shared = upperExchange->Shared = store;
    upperExchange->Brick = 1;
    lowerTechnique->SetBrickExchange(lowerExchange);
    upperTechnique->SetBrickExchange(upperExchange);
    lowerMapper->SetShadowTechnique(lowerTechnique);
    upperMapper->SetShadowTechnique(upperTechnique);
    vtkNew<deepshadow::testing::MessageCapture> messages;
    messages->Watch(lowerTechnique);
    messages->Watch(upperTechnique);
    for (int frame = 0; frame < 3; ++frame)
    {
      scene.Window->Render();
    }
    int said = 0;
    for (const std::string& warning : messages->Warnings)
    {
      said += warning.find("bricks overlap") != std::string::npos ? 1 : 0;
    }
    std::printf("overlapping bricks, 3 frames: said %d times\n", said);
    ok = Check("overlapping bricks: said once by each brick", said == 2) && ok;
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
