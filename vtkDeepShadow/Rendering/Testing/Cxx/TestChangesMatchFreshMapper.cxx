// A change on an already-rendered mapper gives the picture a freshly built one gives: after
// a light move, an opacity change and a data change, with no technique and with every
// technique of the registry, cached or not (and chunked where it reads chunk-nodes), so a
// new technique is checked without an edit here. The rebuild tests count the passes that
// run; this one checks the pictures they make, with the regression-image comparison
// (MatchesBaseline). Each change must also show (the picture after it differs from the one
// before), or a change that was ignored would pass.
#include "Core/ShadowTechniques.h"
#include "DeepShadowTestUtilities.h"

#include <functional>

using deepshadow::testing::BaselineTolerance;
using deepshadow::testing::Check;
using deepshadow::testing::Grab;
using deepshadow::testing::ShadowScene;

namespace
{
// Every technique the registry names, as "NAME", "NAME-cached" or "NAME chunked", with its
// parameters at their defaults but small maps and caches (the scene is 48^3 at 160^2).
std::vector<std::pair<std::string, deepshadow::ShadowParameters>> Techniques()
{
  std::vector<std::pair<std::string, deepshadow::ShadowParameters>> all;
  for (const std::string& name : deepshadow::ShadowTechniqueNames())
  {
    bool cached = false;
    const deepshadow::ShadowTechniqueInfo* info = deepshadow::FindShadowTechnique(name, &cached);
    deepshadow::ShadowParameters p = info->DefaultParameters(cached);
    p.MapSize = 128;
    p.VolumeSize = 48;
    all.emplace_back(name, p);
    if (!cached && info->Reads("chunk-nodes"))
    {
      deepshadow::FindShadowParameter("chunk-nodes")->Set(p, { 4.0 });
      all.emplace_back(name + " chunked", p);
    }
  }
  return all;
}

vtkSmartPointer<vtkDeepShadowTechnique> Make(const deepshadow::ShadowParameters& p)
{
  return p.Kind == deepshadow::ShadowKind::None ? nullptr : vtkDeepShadowTechniqueFactory::New(p);
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
  for (const auto& [technique, parameters] : Techniques())
  {
    for (const Change& change : changes)
    {
      // Rendered, then changed, then rendered again.
      ShadowScene rendered;
      rendered.Mapper->SetShadowTechnique(Make(parameters));
      rendered.Window->Render();
      const deepshadow::Image before = Grab(rendered.Window);
      change.Apply(rendered);
      rendered.Window->Render();
      const deepshadow::Image after = Grab(rendered.Window);
      // Built with the change from the start.
      ShadowScene fresh;
      change.Apply(fresh);
      fresh.Mapper->SetShadowTechnique(Make(parameters));
      fresh.Window->Render();
      std::string how;
      const bool same =
        deepshadow::testing::MatchesBaseline(after, Grab(fresh.Window), BaselineTolerance(), how);
      const double shown = deepshadow::Compare(before, after).RMSE;
      ok = Check(technique + ", " + change.Name + ": as a fresh mapper (" + how + ")",
             same) && ok;
      ok = Check(technique + ", " + change.Name + ": the change shows (RMSE " +
               std::to_string(shown).substr(0, 6) + " >= 0.002)",
             shown >= 0.002) && ok;
    }
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
