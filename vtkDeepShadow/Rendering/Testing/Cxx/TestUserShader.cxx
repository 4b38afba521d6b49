// A volume's vtkShaderProperty runs in our shader where VTK 9.1's mapper runs it: VTK's own
// TestGPURayCastUserShader code (the depth of the first visible sample written as the
// colour: //VTK::Base::Dec, Init, Impl and //VTK::RenderToImage::Exit with VTK's names), and a
// tint from a custom uniform at //VTK::Base::Exit, each drawn by our mapper and by VTK's in
// one run (RMSE <= 0.01; the depth picture 0.02, see below). A tag with no counterpart (//VTK::Shading::Impl) refuses the
// replacements in one message, and the volume is drawn without them.
#include "DeepShadowTestUtilities.h"
#include "vtkDeepShadowRenderWindow.h"
#include "vtkDeepShadowVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkShaderProperty.h"
#include "vtkUniforms.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <string>

using deepshadow::testing::Check;
using deepshadow::testing::Grab;
using deepshadow::testing::WithinTolerance;

namespace
{
// VTK's TestGPURayCastUserShader replacements, as that test writes them.
void AddDepthShader(vtkShaderProperty* shader)
{
  shader->AddFragmentShaderReplacement("//VTK::Base::Dec", true,
    "//VTK::Base::Dec\n bool l_updateDepth;\n vec3 l_opaqueFragPos;", false);
  shader->AddFragmentShaderReplacement("//VTK::Base::Init", true,
    "//VTK::Base::Init\n l_updateDepth = true;\n l_opaqueFragPos = vec3(0.0);", false);
  shader->AddFragmentShaderReplacement("//VTK::Base::Impl", true,
    "//VTK::Base::Impl\n    if(!g_skip && g_srcColor.a > 0.0 && l_updateDepth)\n      {\n"
    "      l_opaqueFragPos = g_dataPos;\n      l_updateDepth = false;\n      }",
    false);
  shader->AddFragmentShaderReplacement("//VTK::RenderToImage::Exit", true,
    "//VTK::RenderToImage::Exit\n  if (l_opaqueFragPos == vec3(0.0))\n    {\n    fragOutput0 = vec4(0.0);\n    }\n"
    "  else\n    {\n    vec4 depthValue = in_projectionMatrix * in_modelViewMatrix *\n"
    "                      in_volumeMatrix[0] * in_textureDatasetMatrix[0] *\n"
    "                      vec4(l_opaqueFragPos, 1.0);\n    depthValue /= depthValue.w;\n"
    "    fragOutput0 = vec4(vec3(0.5 * (gl_DepthRange.far -\n"
    "                       gl_DepthRange.near) * depthValue.z + 0.5 *\n"
    "                      (gl_DepthRange.far + gl_DepthRange.near)), 1.0);\n    }",
    false);
}

void AddTint(vtkShaderProperty* shader)
{
  const float tint[3] = { 0.3f, 1.0f, 0.6f };
  shader->GetFragmentCustomUniforms()->SetUniform3f("u_tint", tint);
  shader->AddFragmentShaderReplacement("//VTK::Base::Exit", true, "//VTK::Base::Exit\n  g_fragColor.rgb *= u_tint;", false);
}

deepshadow::Image Draw(vtkRenderWindow* window, vtkGPUVolumeRayCastMapper* mapper, vtkImageData* data,
  vtkShaderProperty* shader)
{
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.0, 0.0, 0.0);
  window->GetRenderers()->RemoveAllItems();
  window->AddRenderer(renderer);
  mapper->SetInputData(data);
  mapper->SetAutoAdjustSampleDistances(false);
  mapper->SetSampleDistance(0.5f);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(deepshadow::testing::MakeComparisonProperty(true));
  if (shader)
  {
    volume->SetShaderProperty(shader);
  }
  renderer->AddVolume(volume);
  deepshadow::testing::ApplyComparisonView(renderer);
  window->Render();
  return Grab(window);
}
}

int TestUserShader(int, char*[])
{
  auto data = deepshadow::testing::MakeTestVolume(VTK_UNSIGNED_CHAR, 40);
  vtkNew<vtkDeepShadowRenderWindow> window;
  window->SetSize(160, 160);
  bool ok = true;

  vtkNew<vtkShaderProperty> depth;
  AddDepthShader(depth);
  vtkNew<vtkShaderProperty> tint;
  AddTint(tint);
  // The depth picture is black or a depth: on the silhouette one sample decides between them
  // (9 of 25,600 pixels here), so its RMSE bound is 0.02 with at most 0.5 % of pixels off.
  struct Case
  {
    const char* Name;
    vtkShaderProperty* Shader;
    double MaxRMSE, MaxFraction;
  };
  deepshadow::Image plain;
  for (const Case& c : { Case{ "VTK's TestGPURayCastUserShader code (the first sample's depth)", depth.Get(), 0.02, 0.005 },
         Case{ "a tint from a custom uniform at //VTK::Base::Exit", tint.Get(), 0.01, 0.03 } })
  {
    vtkNew<vtkGPUVolumeRayCastMapper> theirs;
    vtkNew<vtkDeepShadowVolumeMapper> ours;
    const deepshadow::Image vtks = Draw(window, theirs, data, c.Shader);
    const deepshadow::Image drawn = Draw(window, ours, data, c.Shader);
    ok &= Check(std::string(c.Name) + ": taken, not refused", ours->GetUnsupportedSettings().empty() &&
        std::find(ours->GetShaderFeatures().begin(), ours->GetShaderFeatures().end(), "UserShader") !=
          ours->GetShaderFeatures().end());
    ok &= WithinTolerance((std::string(c.Name) + ": ours against VTK's").c_str(), drawn, vtks, c.MaxRMSE, 8.0 / 255.0,
      c.MaxFraction);
    vtkNew<vtkDeepShadowVolumeMapper> without;
    plain = Draw(window, without, data, nullptr);
    const deepshadow::ImageDifference d = deepshadow::Compare(drawn, plain, 8.0 / 255.0);
    std::printf("%s: against the picture without it: RMSE %.5f\n", c.Name, d.RMSE);
    ok &= Check(std::string(c.Name) + ": changes the picture", d.RMSE > 0.02);
  }

  // No place for //VTK::Shading::Impl here: one message, drawn without the replacements.
  vtkNew<vtkShaderProperty> shading;
  AddTint(shading);
  shading->AddFragmentShaderReplacement("//VTK::Shading::Impl", true, "//VTK::Shading::Impl\n", false);
  vtkNew<vtkDeepShadowVolumeMapper> refused;
  const deepshadow::Image drawn = Draw(window, refused, data, shading);
  const std::vector<std::string> said = refused->GetUnsupportedSettings();
  for (const std::string& s : said)
  {
    std::printf("said: %s\n", s.c_str());
  }
  ok &= Check("a tag without a counterpart is said, naming it",
    said.size() == 1 && said[0].find("//VTK::Shading::Impl") != std::string::npos);
  ok &= WithinTolerance("refused: drawn without the replacements", drawn, plain, 0.5 / 255.0, 8.0 / 255.0, 0.0);
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
