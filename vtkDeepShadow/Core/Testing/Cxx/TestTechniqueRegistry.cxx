// The technique registry (ShadowTechniques.h): names, labels, defaults and ranges agree with each
// other and with ShadowParameters, so that the tool, Validate() and the twins read one table.
#include "Core/ShadowParameterText.h"
#include "Core/ShadowTechniques.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <stdexcept>

using namespace deepshadow;

TEST(TechniqueRegistry, EveryNameRoundTripsThroughItsParameters)
{
  // The built-in names, in this order (a technique added later comes in between or after:
  // no edit here).
  const std::vector<std::string> builtIn{ "none", "rays", "rays-cached", "rays-opaque",
    "rays-opaque-cached", "rays-color", "rays-color-cached", "shadowmap", "shadowmap-cached",
    "dsm", "dsm-cached", "dsm-color", "dsm-color-cached", "dsm-clustered", "dsm-clustered-cached",
    "dsm-fixed", "dsm-fixed-cached", "dsm3", "dsm3-cached", "cssm", "cssm-cached", "rmsm", "rmsm-cached" };
  const std::vector<std::string> names = ShadowTechniqueNames();
  auto at = names.begin();
  for (const std::string& name : builtIn)
  {
    at = std::find(at, names.end(), name);
    EXPECT_NE(at, names.end()) << name << " missing or out of order";
  }
  for (const std::string& name : names)
  {
    bool cached = false;
    const ShadowTechniqueInfo* technique = FindShadowTechnique(name, &cached);
    ASSERT_NE(technique, nullptr) << name;
    const ShadowParameters parameters = technique->DefaultParameters(cached);
    EXPECT_EQ(parameters.Name(), name);
    EXPECT_EQ(parameters.Validate(), "") << name;
    EXPECT_EQ(technique->MakeShadow == nullptr, technique->Kind == ShadowKind::None) << name;
  }
  EXPECT_EQ(FindShadowTechnique("none-cached"), nullptr);
  EXPECT_EQ(FindShadowTechnique("magic"), nullptr);
}

TEST(TechniqueRegistry, EveryKeyIsDeclaredOnceAndItsDefaultIsInRange)
{
  std::set<std::string> keys;
  const ShadowParameters defaults;
  for (const ShadowParameterInfo& parameter : ShadowParameterInfos())
  {
    EXPECT_TRUE(keys.insert(parameter.Key).second) << parameter.Key;
    EXPECT_EQ(parameter.Check(parameter.Get(defaults)), "") << parameter.Key;
    // Parsing what Format writes gives the value back.
    EXPECT_EQ(parameter.Parse(parameter.Format(parameter.Get(defaults))), parameter.Get(defaults))
      << parameter.Key;
  }
  for (const ShadowTechniqueInfo& technique : ShadowTechniques())
  {
    for (const std::string& key : technique.Keys)
    {
      EXPECT_NE(FindShadowParameter(key), nullptr) << technique.Name << " reads " << key;
    }
  }
}

TEST(TechniqueRegistry, OneRangeRefusesWhatTheToolRefuses)
{
  const ShadowParameterInfo& epsilon = *FindShadowParameter("epsilon");
  EXPECT_THROW(epsilon.Parse("1.5"), std::invalid_argument);
  EXPECT_THROW(epsilon.Parse("x"), std::invalid_argument);
  ShadowParameters p;
  p.Epsilon = 1.5;
  EXPECT_NE(p.Validate().find("epsilon must be in [0, 1]"), std::string::npos) << p.Validate();
  EXPECT_EQ(FindShadowParameter("cssm-offsets")->Check({ 9.0 }), "cssm-offsets must be 7, 13 or 21");
  EXPECT_EQ(FindShadowParameter("pcf")->Parse("poisson"), std::vector<double>{ 3.0 });
  EXPECT_EQ(FindShadowParameter("bias")->Check({ -1.0 }), "bias must not be negative");
}

TEST(TechniqueRegistry, EveryTechniqueHasAMenuLabelAndGroup)
{
  const auto& groups = deepshadow::ShadowTechniqueGroups();
  for (const deepshadow::ShadowTechniqueInfo& technique : deepshadow::ShadowTechniques())
  {
    EXPECT_FALSE(technique.Label.empty()) << technique.Name;
    if (technique.Kind == deepshadow::ShadowKind::None)
    {
      EXPECT_TRUE(technique.Group.empty());
      continue;
    }
    EXPECT_NE(std::find(groups.begin(), groups.end(), technique.Group), groups.end()) << technique.Name;
    EXPECT_NE(technique.Label, technique.Name) << technique.Name << ": no label of its own";
  }
  EXPECT_EQ(deepshadow::ShadowTechniqueLabel("dsm"), "Deep shadow map (dsm)");
  EXPECT_EQ(deepshadow::ShadowTechniqueLabel("dsm-cached"), "Deep shadow map, cached (dsm-cached)");
  EXPECT_EQ(deepshadow::ShadowTechniqueLabel("none-cached"), "");
  EXPECT_EQ(deepshadow::ShadowTechniqueLabel("nope"), "");
}

TEST(TechniqueRegistry, ParameterTextSplitsAndEditsPairs)
{
  using Pairs = std::vector<std::pair<std::string, std::string>>;
  EXPECT_EQ(deepshadow::SplitShadowParameterText("epsilon=0.01, shadow-map-size=1024\topacity-levels=0.1,0.5,0.9"),
    (Pairs{ { "epsilon", "0.01" }, { "shadow-map-size", "1024" }, { "opacity-levels", "0.1,0.5,0.9" } }));
  EXPECT_TRUE(deepshadow::SplitShadowParameterText("  ").empty());
  EXPECT_THROW(deepshadow::SplitShadowParameterText("0.5 epsilon=1"), std::invalid_argument);
  EXPECT_EQ(deepshadow::SetShadowParameterInText("epsilon=0.01,layers=4", "layers", "8"), "epsilon=0.01 layers=8");
  EXPECT_EQ(deepshadow::SetShadowParameterInText("epsilon=0.01", "layers", "8"), "epsilon=0.01 layers=8");
  EXPECT_EQ(deepshadow::SetShadowParameterInText("epsilon=0.01 layers=8", "epsilon", ""), "layers=8");
  EXPECT_EQ(deepshadow::SetShadowParameterInText("", "pcf", "3x3"), "pcf=3x3");
}
