#include "ShaderComposer.h"

#include "vtkDeepShadowFeatureBound.h"
#include "vtkDeepShadowFeatureSources.h"
#include "vtkDeepShadowFeatureTranslucentLayers.h"
#include "vtkDeepShadowFeatureVolumeSegments.h"

#include <sstream>
#include <stdexcept>

namespace deepshadow
{

ShaderFeature::ShaderFeature(std::string name, const std::string& source)
  : Name(std::move(name))
{
  std::istringstream lines(source);
  std::string line, part;
  while (std::getline(lines, line))
  {
    if (line.rfind("//@", 0) == 0)
    {
      part = line.substr(3);
      this->Parts[part];
      continue;
    }
    if (!part.empty())
    {
      this->Parts[part] += line + "\n";
    }
  }
}

std::string ShaderFeature::Part(const std::string& part) const
{
  auto it = this->Parts.find(part);
  return it == this->Parts.end() ? std::string() : it->second;
}

const std::map<std::string, ShaderFeature>& EmbeddedShaderFeatures()
{
  static const std::map<std::string, ShaderFeature> features = [] {
    std::map<std::string, ShaderFeature> all;
    for (const FeatureSource& feature : FeatureSources)
    {
      all[feature.Name] = ShaderFeature(feature.Name, feature.Source);
    }
    return all;
  }();
  return features;
}

std::string GlslConstantArray(const std::string& type, const std::string& name,
  const std::string& count, const std::vector<std::string>& elements)
{
  std::ostringstream text;
  text << "//@Dec\n#define " << count << " " << elements.size() << "\nconst " << type << " " << name
       << "[" << elements.size() << "] = " << type << "[" << elements.size() << "](";
  for (size_t k = 0; k < elements.size(); ++k)
  {
    text << (k ? ", " : "") << elements[k];
  }
  text << ");\n";
  return text.str();
}

namespace
{
// A sized feature: its source with `defines` at the top of its Dec part.
// `defines` at the start of the part that is spliced first.
ShaderFeature WithDefines(const char* name, std::string source, const std::string& defines,
  const std::string& part = "Dec")
{
  const std::string tag = "//@" + part + "\n";
  source.insert(source.find(tag) + tag.size(), defines + "\n");
  return ShaderFeature(name, source);
}
}

ShaderFeature BoundShaderFeature(int leaves)
{
  return WithDefines("Bound", vtkDeepShadowFeatureBound, "#define BOUND_LEAVES " + std::to_string(leaves));
}

ShaderFeature ComponentsShaderFeature(int count, int mode, bool litApart, bool gradientOpacity)
{
  return WithDefines("Components", vtkDeepShadowFeatureComponents,
    "#define COMPONENT_COUNT " + std::to_string(count) + "\n#define COMPONENT_MODE " + std::to_string(mode) +
      (litApart ? "\n#define COMPONENTS_LIT_APART" : "") +
      (gradientOpacity ? "\n#define COMPONENT_GRADIENT_OPACITY" : ""));
}

ShaderFeature TranslucentLayersShaderFeature(int layers, int segmentSlices)
{
  std::string defines = "#define TRANSLUCENT_LAYERS " + std::to_string(layers) +
    "\n#define SEGMENT_SLICES " + std::to_string(segmentSlices) + "\n#define LOAD_TRANSLUCENT_LAYERS";
  for (int k = 0; k < layers; ++k)
  {
    defines += " LOAD_LAYER(" + std::to_string(k) + ")";
  }
  return WithDefines("TranslucentLayers", vtkDeepShadowFeatureTranslucentLayers, defines);
}

ShaderFeature VTKShadingShaderFeature(int path, bool reflection)
{
  return WithDefines("VTKShading", vtkDeepShadowFeatureVTKShading,
    "#define VTK_SHADING_PATH " + std::to_string(path) + "\n#define VTK_SHADING_REFLECTION " + (reflection ? "1" : "0"));
}

ShaderFeature LightingShaderFeature(bool positional, bool fromEye)
{
  return WithDefines("Lighting", vtkDeepShadowFeatureLighting,
    std::string("#define POSITIONAL_LIGHTS ") + (positional ? "1" : "0") + "\n#define LIGHT_FROM_EYE " + (fromEye ? "1" : "0"));
}

ShaderFeature ShadowRatioShaderFeature(bool shaded)
{
  return WithDefines("ShadowRatio", vtkDeepShadowFeatureShadowRatio, shaded ? "#define SHADOW_RATIO_SHADED" : "");
}

ShaderFeature VolumeSegmentsShaderFeature(int segments)
{
  std::string outputs = "#define SEGMENT_OUTPUTS";
  std::string writes = "#define WRITE_VOLUME_SEGMENTS";
  for (int k = 0; k < segments; ++k)
  {
    const std::string n = std::to_string(k);
    outputs += " layout(location = " + n + ") out uvec4 segmentOut" + n + ";";
    writes += " segmentOut" + n + " = segmentTexel(" + n + ", rayOrigin, rayDirection);";
  }
  return WithDefines("VolumeSegments", vtkDeepShadowFeatureVolumeSegments,
    "#define VOLUME_SEGMENTS " + std::to_string(segments) + "\n" + outputs + "\n" + writes, "Output");
}

std::string ComposeShader(const std::string& shaderTemplate, const std::set<std::string>& enabled,
  const std::map<std::string, ShaderFeature>& runtime)
{
  static const std::string prefix = "//DeepShadow::";
  const auto& features = EmbeddedShaderFeatures();
  std::string source = shaderTemplate;
  // Expanded parts may hold tags of their own; bound the depth to catch cycles.
  for (int depth = 0; depth < 8; ++depth)
  {
    bool expanded = false;
    size_t at = source.find(prefix);
    while (at != std::string::npos)
    {
      const size_t end = source.find_first_of("\r\n", at);
      const std::string tag = source.substr(at + prefix.size(), end - at - prefix.size());
      const size_t separator = tag.find("::");
      const std::string feature = tag.substr(0, separator);
      const std::string part = separator == std::string::npos ? "" : tag.substr(separator + 2);
      std::string replacement;
      if (runtime.count(feature))
      {
        replacement = runtime.at(feature).Part(part);
      }
      else if (enabled.count(feature))
      {
        auto it = features.find(feature);
        if (it == features.end())
        {
          throw std::logic_error("shader feature " + feature + " is not embedded");
        }
        replacement = it->second.Part(part);
      }
      source.replace(at, end - at, replacement);
      expanded = true;
      // Tags inside the replacement are expanded by the next pass.
      at = source.find(prefix, at + replacement.size());
    }
    if (!expanded)
    {
      return source;
    }
  }
  throw std::logic_error("shader feature tags nest too deeply (a cycle?)");
}

}
