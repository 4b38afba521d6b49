#include "RayCast/UserShaderCode.h"

#include "vtkDeepShadowFeatureUserShader.h"

#include "vtkOpenGLShaderProperty.h"
#include "vtkOpenGLUniforms.h"
#include "vtkShader.h"
#include "vtkVolume.h"

#include <algorithm>

namespace deepshadow
{
namespace
{
// Each VTK tag we take: our hook, and what VTK's mapper writes there that applies here.
struct Hook
{
  const char* Tag;
  std::string UserShaderCode::*Code;
  const char* Standard;
};

const std::vector<Hook>& Hooks()
{
  static const std::vector<Hook> hooks = {
    { "//VTK::Base::Dec", &UserShaderCode::Dec, "" },
    { "//VTK::Base::Init", &UserShaderCode::Init, "" },
    { "//VTK::Base::Impl", &UserShaderCode::Impl, "g_skip = false;" },
    { "//VTK::Base::Exit", &UserShaderCode::Exit, "" },
    { "//VTK::RenderToImage::Exit", &UserShaderCode::Output, "" },
  };
  return hooks;
}

// `text` with every `tag` in it replaced by `standard`.
std::string Expand(std::string text, const std::string& tag, const std::string& standard)
{
  for (size_t at = text.find(tag); at != std::string::npos; at = text.find(tag, at + standard.size()))
  {
    text.replace(at, tag.size(), standard);
  }
  return text;
}
}

bool UserShaderCode::Empty() const
{
  return this->Dec.empty() && this->Init.empty() && this->Impl.empty() && this->Exit.empty() &&
    this->Output.empty() && this->Uniforms.empty() && this->Refusal.empty();
}

UserShaderCode ReadUserShaderCode(vtkVolume* volume)
{
  UserShaderCode code;
  auto* property = volume ? vtkOpenGLShaderProperty::SafeDownCast(volume->GetShaderProperty()) : nullptr;
  if (!property)
  {
    return code;
  }
  std::vector<std::string> refused;
  if (property->HasVertexShaderCode() || property->HasFragmentShaderCode() || property->HasGeometryShaderCode())
  {
    refused.emplace_back("a whole shader (Set...ShaderCode)");
  }
  for (const auto& [spec, value] : property->GetAllShaderReplacements())
  {
    const auto hook = std::find_if(Hooks().begin(), Hooks().end(),
      [&](const Hook& h) { return spec.OriginalValue == h.Tag; });
    if (spec.ShaderType != vtkShader::Fragment)
    {
      refused.push_back((spec.ShaderType == vtkShader::Vertex ? "vertex " : "geometry ") + spec.OriginalValue);
    }
    else if (hook == Hooks().end() || !spec.ReplaceFirst)
    {
      // After VTK's own replacements a tag is gone: only its code could be matched, and ours
      // is not VTK's.
      refused.push_back(spec.OriginalValue + (hook == Hooks().end() ? "" : " (after VTK's replacements)"));
    }
    else
    {
      code.*(hook->Code) += Expand(value.Replacement, hook->Tag, hook->Standard) + "\n";
    }
  }
  if (vtkUniforms* uniforms = property->GetFragmentCustomUniforms())
  {
    if (auto* gl = vtkOpenGLUniforms::SafeDownCast(uniforms))
    {
      code.Uniforms = gl->GetDeclarations();
    }
  }
  if (!refused.empty())
  {
    std::string list;
    for (const std::string& r : refused)
    {
      list += (list.empty() ? "" : ", ") + r;
    }
    std::string taken;
    for (const Hook& hook : Hooks())
    {
      taken += (taken.empty() ? "" : ", ") + std::string(hook.Tag);
    }
    code = UserShaderCode();
    code.Refusal = "the volume's vtkShaderProperty replaces what this mapper's shader has no place for: " +
      list + " (fragment replacements of " + taken +
      ", before VTK's, are taken): the volume is drawn without its replacements";
  }
  return code;
}

ShaderFeature UserShaderFeature(const UserShaderCode& code)
{
  std::string source = vtkDeepShadowFeatureUserShader;
  auto insert = [&source](const std::string& part, const std::string& text) {
    const std::string tag = "//@" + part + "\n";
    const size_t at = source.find(tag);
    if (at != std::string::npos)
    {
      const size_t end = source.find("//@", at + tag.size());
      source.insert(end == std::string::npos ? source.size() : end, text + "\n");
    }
  };
  insert("Dec", code.Uniforms + code.Dec);
  insert("Init", code.Init);
  insert("Impl", code.Impl);
  insert("Exit", code.Exit);
  insert("Output", code.Output);
  return ShaderFeature("UserShader", source);
}

}
