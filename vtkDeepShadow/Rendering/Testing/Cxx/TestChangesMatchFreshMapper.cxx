// A change on an already-rendered mapper gives the picture a freshly built one gives: after
// a light move, an opacity change and a data change, with no technique and with techniques
// that cache work between frames (cached rays, shadow map, deep shadow map, opacity levels,
// stochastic shadow map). The rebuild tests count the passes that run; this one checks the
// pictures they make, with the regression-image comparison (MatchesBaseline). Each change
// must also show (the picture after it differs from the one before), or a change that was
// ignored would pass.
#include "DeepShadowTestUtilities.h"
#include "vtkDeepShadowDeepShadowMapTechnique.h"
#include "vtkDeepShadowOpacityLevelsTechnique.h"
#include "vtkDeepShadowRayTechnique.h"
#include "vtkDeepShadowShadowMapTechnique.h"
#include "vtkDeepShadowStochasticShadowMapTechnique.h"

#include <functional>

using deepshadow::testing::BaselineTolerance;
using deepshadow::testing::Check;
using deepshadow::testing::Grab;
using deepshadow::testing::ShadowScene;

namespace
{
vtkSmartPointer<vtkDeepShadowTechnique> Make(const std::string& name)
{
  if (name == "rays-cached")
  {
    auto rays = vtkSmartPointer<vtkDeepShadowRayTechnique>::New();
    rays->CachedOn();
    rays->SetShadowVolumeSize(48);
    return rays;
  }
  vtkSmartPointer<vtkDeepShadowLightSpaceTechnique> map;
  if (name == "shadowmap")
  {
    map = vtkSmartPointer<vtkDeepShadowShadowMapTechnique>::New();
  }
  else if (name == "dsm-color")
  {
    auto dsm = vtkSmartPointer<vtkDeepShadowDeepShadowMapTechnique>::New();
    dsm->ColoredOn();
    map = dsm;
  }
  else if (name == "dsm3")
  {
    map = vtkSmartPointer<vtkDeepShadowOpacityLevelsTechnique>::New();
  }
  else if (name == "cssm")
  {
    map = vtkSmartPointer<vtkDeepShadowStochasticShadowMapTechnique>::New();
  }
  if (map)
  {
    map->SetMapSize(128);
  }
  return map; // null for none
}

struct Change
{
  const char* Name;
  std::function<void(ShadowScene&)> Apply;
};

// The pillar (value 140) taken out of the data, in place.
void RemovePillar(ShadowScene& scene)
{
  auto* values = static_cast<unsigned char*>(scene.Data->GetScalarPointer());
  const vtkIdType count = scene.Data->GetNumberOfPoints();
  for (vtkIdType i = 0; i < count; ++i)
  {
    values[i] = values[i] == 140 ? 0 : values[i];
  }
  scene.Data->Modified();
}
}

int TestChangesMatchFreshMapper(int, char*[])
{
  const Change changes[] = {
    { "light move", [](ShadowScene& s) { s.Light->SetPosition(-0.6, 0.4, 1.0); } },
    { "opacity change",
      [](ShadowScene& s) {
        s.Opacity->RemovePoint(200);
        s.Opacity->AddPoint(200, 0.35);
      } },
    { "data change", RemovePillar },
  };
  bool ok = true;
  for (const char* technique : { "none", "rays-cached", "shadowmap", "dsm-color", "dsm3", "cssm" })
  {
    for (const Change& change : changes)
    {
      // Rendered, then changed, then rendered again.
      ShadowScene rendered;
      rendered.Mapper->SetShadowTechnique(Make(technique));
      rendered.Window->Render();
      const deepshadow::Image before = Grab(rendered.Window);
      change.Apply(rendered);
      rendered.Window->Render();
      const deepshadow::Image after = Grab(rendered.Window);
      // Built with the change from the start.
      ShadowScene fresh;
      change.Apply(fresh);
      fresh.Mapper->SetShadowTechnique(Make(technique));
      fresh.Window->Render();
      std::string how;
      const bool same =
        deepshadow::testing::MatchesBaseline(after, Grab(fresh.Window), BaselineTolerance(), how);
      const double shown = deepshadow::Compare(before, after).RMSE;
      ok = Check(std::string(technique) + ", " + change.Name + ": as a fresh mapper (" + how + ")",
             same) && ok;
      ok = Check(std::string(technique) + ", " + change.Name + ": the change shows (RMSE " +
               std::to_string(shown).substr(0, 6) + " >= 0.002)",
             shown >= 0.002) && ok;
    }
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
