// vtkDeepShadowVolumePresets: the named presets, window/level, ParaView preset files, and
// bad files (one error, the property unchanged).
#include "vtkDeepShadowVolumePresets.h"

#include "vtkColorTransferFunction.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkVolumeProperty.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <string>

namespace
{
std::string WriteFile(const std::string& name, const std::string& text)
{
  const std::string path = ::testing::TempDir() + "/" + name;
  std::ofstream(path) << text;
  return path;
}

std::vector<double> OpacityNode(vtkVolumeProperty* property, int i)
{
  std::vector<double> node(4);
  property->GetScalarOpacity()->GetNodeValue(i, node.data());
  return node;
}

// One call must leave a preset's property whole, or (failing) the property untouched.
struct Quiet
{
  Quiet() { vtkObject::GlobalWarningDisplayOff(); }
  ~Quiet() { vtkObject::GlobalWarningDisplayOn(); }
};

const char* ParaViewPreset = R"([
  {
    "ColorSpace" : "Lab",
    "Name" : "Bone test",
    "RGBPoints" : [ -1000, 0, 0, 0, 300, 0.9, 0.8, 0.7, 2000, 1, 1, 1 ],
    "Points" : [ -1000, 0, 0.5, 0, 200, 0, 0.5, 0, 600, 0.8, 0.4, 0.2, 2000, 0.9, 0.5, 0 ]
  },
  {
    "Name" : "Second",
    "RGBPoints" : [ 0, 1, 0, 0, 10, 0, 0, 1 ]
  }
])";
}

TEST(VolumePresets, EveryNamedPresetLoadsWithItsLighting)
{
  const auto names = vtkDeepShadowVolumePresets::GetPresetNames();
  for (const char* expected : { "CT-Bone", "CT-Skin", "CT-Muscle", "CT-Soft-Tissue", "CT-Lung",
         "MR-Default", "MR-Angio" })
  {
    EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
  }
  for (const auto& name : names)
  {
    vtkNew<vtkVolumeProperty> property;
    vtkNew<vtkDeepShadowVolumePresets> presets;
    ASSERT_TRUE(presets->ApplyPreset(name, property)) << name << ": " << presets->GetLastError();
    EXPECT_FALSE(vtkDeepShadowVolumePresets::GetPresetDescription(name).empty());
    EXPECT_GE(property->GetScalarOpacity()->GetSize(), 4) << name;
    EXPECT_GE(property->GetRGBTransferFunction()->GetSize(), 4) << name;
    EXPECT_EQ(property->GetInterpolationType(), VTK_LINEAR_INTERPOLATION);
  }
  // CT-Bone: Slicer's values, in Hounsfield units; case does not matter.
  vtkNew<vtkVolumeProperty> bone;
  vtkNew<vtkDeepShadowVolumePresets> presets;
  ASSERT_TRUE(presets->ApplyPreset("ct-bone", bone));
  EXPECT_DOUBLE_EQ(OpacityNode(bone, 2)[0], 641.385);
  EXPECT_DOUBLE_EQ(OpacityNode(bone, 2)[1], 0.715686);
  EXPECT_EQ(bone->GetShade(), 1);
  EXPECT_DOUBLE_EQ(bone->GetSpecularPower(), 10.0);
  vtkNew<vtkVolumeProperty> soft;
  ASSERT_TRUE(presets->ApplyPreset("CT-Soft-Tissue", soft));
  EXPECT_EQ(soft->GetShade(), 0);
}

TEST(VolumePresets, WindowLevelMapsThePresetsIntervalAndKeepsItsShape)
{
  vtkNew<vtkVolumeProperty> property;
  vtkNew<vtkDeepShadowVolumePresets> presets;
  presets->SetWindowLevel(400.0, 200.0);
  ASSERT_TRUE(presets->ApplyPreset("CT-Bone", property));
  // CT-Bone's interval is its inner opacity nodes, -16.4458 to 641.385: now 0 to 400.
  EXPECT_NEAR(OpacityNode(property, 1)[0], 0.0, 1e-9);
  EXPECT_NEAR(OpacityNode(property, 2)[0], 400.0, 1e-9);
  EXPECT_DOUBLE_EQ(OpacityNode(property, 2)[1], 0.715686);
  double node[6];
  property->GetRGBTransferFunction()->GetNodeValue(2, node);
  EXPECT_NEAR(node[0], 400.0, 1e-9);
  Quiet quiet;
  presets->SetWindowLevel(0.0, 10.0);
  EXPECT_NE(presets->GetLastError().find("window"), std::string::npos);
  EXPECT_DOUBLE_EQ(presets->GetWindow(), 400.0) << "a refused window keeps the last one";
}

TEST(VolumePresets, ParaViewPresetFilesLoadWithMidpointsSharpnessAndColourSpace)
{
  const std::string path = WriteFile("bone-test.json", ParaViewPreset);
  vtkNew<vtkVolumeProperty> property;
  vtkNew<vtkDeepShadowVolumePresets> presets;
  ASSERT_TRUE(presets->Apply(path, property)) << presets->GetLastError();
  ASSERT_EQ(property->GetScalarOpacity()->GetSize(), 4);
  EXPECT_EQ(OpacityNode(property, 2), (std::vector<double>{ 600, 0.8, 0.4, 0.2 }));
  EXPECT_EQ(property->GetRGBTransferFunction()->GetColorSpace(), VTK_CTF_LAB);
  EXPECT_EQ(property->GetRGBTransferFunction()->GetSize(), 3);

  // The second preset by name; it has no opacity, so the property keeps the first's.
  presets->SetPresetName("second");
  ASSERT_TRUE(presets->ApplyFile(path, property)) << presets->GetLastError();
  EXPECT_EQ(property->GetRGBTransferFunction()->GetSize(), 2);
  EXPECT_EQ(property->GetScalarOpacity()->GetSize(), 4);
}

TEST(VolumePresets, BadNamesAndFilesAreOneErrorAndLeaveThePropertyAlone)
{
  Quiet quiet;
  struct Case
  {
    const char* Name;
    std::string Text; // empty: no file
    const char* Needle;
    const char* OrNeedle = nullptr; // a second accepted wording
  };
  const std::vector<Case> cases = {
    { "missing", "", "neither a transfer-function preset (CT-Bone" },
    { "not-json.json", "RGBPoints: 1 2 3", "not JSON" },
    { "no-rgb.json", R"([{"Name":"x","Points":[0,0,0.5,0]}])", "no \"RGBPoints\"" },
    { "count.json", R"([{"RGBPoints":[0,0,0,0,1,1,1]}])", "whole nodes of 4" },
    { "text.json", R"([{"RGBPoints":[0,0,0,"red"]}])", "not a finite number" },
    // jsoncpp up to 1.9.5 refuses 1e999; 1.9.6 (Debian 13) reads it as infinity.
    { "huge.json", R"([{"RGBPoints":[0,0,0,0,1e999,1,1,1]}])", "not JSON", "\"RGBPoints\"[4] is not a finite number" },
    { "order.json", R"([{"RGBPoints":[5,0,0,0,1,1,1,1]}])", "must not decrease" },
    { "range.json", R"([{"RGBPoints":[0,0,0,0,1,1,2,1]}])", "outside [0, 1]" },
    { "opacity.json", R"([{"RGBPoints":[0,0,0,0,1,1,1,1],"Points":[0,1.5,0.5,0]}])",
      "outside [0, 1]" },
    { "empty.json", "[]", "holds no preset object" },
    { "deep.json", std::string(500, '[') + std::string(500, ']'), "not JSON" },
  };
  for (const Case& c : cases)
  {
    const std::string path = c.Text.empty() ? "/nonexistent/preset.json" : WriteFile(c.Name, c.Text);
    vtkNew<vtkVolumeProperty> property;
    vtkNew<vtkPiecewiseFunction> before;
    before->AddPoint(0.0, 0.25);
    property->SetScalarOpacity(before);
    vtkNew<vtkDeepShadowVolumePresets> presets;
    EXPECT_FALSE(presets->Apply(path, property)) << c.Name;
    const std::string& error = presets->GetLastError();
    EXPECT_TRUE(error.find(c.Needle) != std::string::npos || (c.OrNeedle && error.find(c.OrNeedle) != std::string::npos))
      << c.Name << ": " << error;
    EXPECT_EQ(property->GetScalarOpacity(), before.GetPointer()) << c.Name;
  }
  vtkNew<vtkDeepShadowVolumePresets> presets;
  vtkNew<vtkVolumeProperty> property;
  EXPECT_FALSE(presets->ApplyPreset("CT-Nothing", property));
  EXPECT_NE(presets->GetLastError().find("MR-Angio"), std::string::npos);
  presets->SetMaximumFileBytes(10);
  EXPECT_FALSE(presets->ApplyFile(WriteFile("big.json", ParaViewPreset), property));
  EXPECT_NE(presets->GetLastError().find("limit 10"), std::string::npos);
  presets->SetMaximumFileBytes(1e6);
  presets->SetPresetName("absent");
  EXPECT_FALSE(presets->ApplyFile(WriteFile("bone-test.json", ParaViewPreset), property));
  EXPECT_NE(presets->GetLastError().find("no preset named 'absent'"), std::string::npos);
}
