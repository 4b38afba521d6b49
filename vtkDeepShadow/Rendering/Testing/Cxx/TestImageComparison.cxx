// The regression-image comparison of our tests (deepshadow::testing::MatchesBaseline, used by
// RegressionTestImage) fails where it must, and VTK 9.1's does not:
//   1. every baseline matches itself and none of the other baselines of its size (different
//      scenes); VTK's comparison (vtkTesting, threshold 0.15) is shown on the pair issue 17
//      names, TestShadowTechniques' picture against TestBoundedVolume's baseline;
//   2. on one scene, a picture made with another shadow technique fails, while the same
//      technique rendered again by a freshly built scene passes.
// The end-to-end case (a test run against another test's baseline fails) is the ctest
// DeepShadow::SwappedBaseline (Rendering/Testing/Cxx/CMakeLists.txt).
#include "DeepShadowTestUtilities.h"
#include "vtkDeepShadowDeepShadowMapTechnique.h"
#include "vtkDeepShadowOpacityLevelsTechnique.h"
#include "vtkDeepShadowRayTechnique.h"
#include "vtkDeepShadowShadowMapTechnique.h"
#include "vtkDeepShadowStochasticShadowMapTechnique.h"

#include "vtkTesting.h"

#include <vtksys/Directory.hxx>
#include <vtksys/SystemTools.hxx>

#include <map>

using deepshadow::testing::BaselineTolerance;
using deepshadow::testing::Check;
using deepshadow::testing::MatchesBaseline;

namespace
{
// VTK's verdict on `picture` against `baseline` at its default threshold.
int VTKComparison(const std::string& picture, const std::string& baseline, const std::string& temporary)
{
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(picture.c_str());
  // vtkTesting reads a relative -V below its data root.
  vtkNew<vtkTesting> testing;
  for (const std::string& argument : { std::string("-V"), baseline, std::string("-T"), temporary })
  {
    testing->AddArgument(argument.c_str());
  }
  return testing->RegressionTest(reader, 0.15);
}

bool Baselines(const std::string& directory, const std::string& temporary)
{
  bool ok = true;
  vtksys::Directory listing;
  listing.Load(directory);
  std::map<std::string, deepshadow::Image> baselines;
  for (unsigned long i = 0; i < listing.GetNumberOfFiles(); ++i)
  {
    const std::string name = listing.GetFile(i);
    deepshadow::Image image;
    if (name.size() > 4 && name.compare(name.size() - 4, 4, ".png") == 0 &&
      deepshadow::testing::LoadPNG(directory + "/" + name, image))
    {
      baselines[name] = image;
    }
  }
  ok = Check(std::to_string(baselines.size()) + " baselines read", baselines.size() >= 10) && ok;
  double closest = 1.0;
  std::string closestPair;
  int pairs = 0;
  for (auto a = baselines.begin(); a != baselines.end(); ++a)
  {
    std::string how;
    ok = Check(a->first + " matches itself", MatchesBaseline(a->second, a->second, BaselineTolerance(), how)) && ok;
    for (auto b = std::next(a); b != baselines.end(); ++b)
    {
      if (a->second.Width != b->second.Width || a->second.Height != b->second.Height)
      {
        continue;
      }
      ++pairs;
      if (MatchesBaseline(a->second, b->second, BaselineTolerance(), how))
      {
        ok = Check(a->first + " passes against " + b->first + ": " + how, false) && ok;
      }
      const double rmse = deepshadow::Compare(a->second, b->second).RMSE;
      if (rmse < closest)
      {
        closest = rmse;
        closestPair = a->first + " and " + b->first;
      }
    }
  }
  std::printf("%d pairs of baselines of one size, all told apart; the closest, %s, differ by RMSE %.4f\n",
    pairs, closestPair.c_str(), closest);

  const std::string picture = vtksys::SystemTools::CollapseFullPath(directory + "/TestShadowTechniques.png");
  const std::string other = vtksys::SystemTools::CollapseFullPath(directory + "/TestBoundedVolume.png");
  std::string how;
  const bool ours = MatchesBaseline(baselines["TestShadowTechniques.png"], baselines["TestBoundedVolume.png"],
    BaselineTolerance(), how);
  ok = Check("ours: TestShadowTechniques against TestBoundedVolume's baseline fails (" + how + ")", !ours) && ok;
  const int vtk = VTKComparison(picture, other, temporary);
  std::printf("VTK 9.1's comparison (threshold 0.15) of the same: %s\n",
    vtk == vtkTesting::PASSED ? "passes (a different scene!)" : "fails");
  return ok;
}

vtkSmartPointer<vtkDeepShadowTechnique> Make(const std::string& name)
{
  if (name == "rays" || name == "rays-cached" || name == "rays-opaque")
  {
    auto rays = vtkSmartPointer<vtkDeepShadowRayTechnique>::New();
    rays->SetCached(name == "rays-cached");
    rays->SetOpaque(name == "rays-opaque");
    rays->SetShadowVolumeSize(48);
    return rays;
  }
  if (name == "shadowmap")
  {
    auto map = vtkSmartPointer<vtkDeepShadowShadowMapTechnique>::New();
    map->SetMapSize(128);
    return map;
  }
  if (name == "dsm" || name == "dsm-color")
  {
    auto dsm = vtkSmartPointer<vtkDeepShadowDeepShadowMapTechnique>::New();
    dsm->SetMapSize(128);
    dsm->SetColored(name == "dsm-color");
    return dsm;
  }
  if (name == "dsm3")
  {
    auto levels = vtkSmartPointer<vtkDeepShadowOpacityLevelsTechnique>::New();
    levels->SetMapSize(128);
    return levels;
  }
  if (name == "cssm")
  {
    auto cssm = vtkSmartPointer<vtkDeepShadowStochasticShadowMapTechnique>::New();
    cssm->SetMapSize(128);
    return cssm;
  }
  return nullptr; // none
}

deepshadow::Image Render(const std::string& technique)
{
  deepshadow::testing::ShadowScene scene;
  scene.Mapper->SetShadowTechnique(Make(technique));
  scene.Window->Render();
  return deepshadow::testing::Grab(scene.Window);
}

bool Techniques()
{
  bool ok = true;
  const std::vector<std::string> names = { "none", "rays", "rays-opaque", "rays-cached",
    "shadowmap", "dsm", "dsm-color", "dsm3", "cssm" };
  std::map<std::string, deepshadow::Image> pictures;
  for (const std::string& name : names)
  {
    pictures[name] = Render(name);
  }
  std::string how;
  // The same technique, rendered again from scratch: it passes (exactly, here).
  for (const std::string& name : { "none", "dsm", "cssm" })
  {
    ok = Check(std::string("a fresh ") + name + " passes against its own picture",
           MatchesBaseline(Render(name), pictures[name], BaselineTolerance(), how)) && ok;
  }
  // Every other technique fails against each technique's picture.
  std::printf("RMSE between techniques on the shadow test scene (160x160):\n%-12s", "");
  for (const std::string& b : names)
  {
    std::printf(" %11s", b.c_str());
  }
  std::printf("\n");
  for (const std::string& a : names)
  {
    std::printf("%-12s", a.c_str());
    for (const std::string& b : names)
    {
      const bool same = a == b;
      const bool passes = MatchesBaseline(pictures[a], pictures[b], BaselineTolerance(), how);
      std::printf(" %9.4f%s", deepshadow::Compare(pictures[a], pictures[b]).RMSE,
        same ? "  " : passes ? " !" : "  ");
      ok = (same == passes) && ok;
    }
    std::printf("\n");
  }
  MatchesBaseline(pictures["dsm3"], pictures["dsm"], BaselineTolerance(), how);
  std::printf("the closest pair, opacity levels against a deep shadow map: %s\n", how.c_str());
  return Check("every technique fails against every other's picture (a '!' above would not)", ok);
}
}

int TestImageComparison(int argc, char* argv[])
{
  const char* directory = std::getenv("DEEPSHADOW_BASELINES");
  std::string temporary = ".";
  for (int i = 1; i + 1 < argc; ++i)
  {
    temporary = std::string(argv[i]) == "-T" ? argv[i + 1] : temporary;
  }
  if (!directory)
  {
    std::printf("DEEPSHADOW_BASELINES is not set (ctest sets it to Rendering/Testing/Data/Baseline)\n");
    return EXIT_FAILURE;
  }
  bool ok = Baselines(directory, temporary);
  ok = Techniques() && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
