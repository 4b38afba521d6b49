// The technique registry (ShadowTechniques.h): names, defaults and ranges agree with each
// other and with ShadowParameters, so that the tool, Validate() and the twins read one table.
#include "Core/ShadowTechniques.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

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
