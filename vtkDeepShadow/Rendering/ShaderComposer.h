// Internal: composes GLSL from a template and the features in use.
//
// A template marks insertion points with tags `//DeepShadow::<Feature>::<Part>`. A feature is
// a GLSL file (Shaders/Features/<Feature>.glsl) split into parts by `//@<Part>` lines. A tag
// becomes the part's text when the feature is enabled and nothing otherwise, so code of a
// feature that is off is never compiled. Tags inside spliced parts are expanded too.
#ifndef vtkDeepShadowShaderComposer_h
#define vtkDeepShadowShaderComposer_h

#include <map>
#include <set>
#include <string>
#include <vector>

namespace deepshadow
{

class ShaderFeature
{
public:
  ShaderFeature() = default;
  ShaderFeature(std::string name, const std::string& source);

  const std::string& GetName() const { return this->Name; }
  /** Text of a part, or "" if the feature has no such part. */
  std::string Part(const std::string& part) const;

private:
  std::string Name;
  std::map<std::string, std::string> Parts;
};

/** The features a shader is composed of. */
struct ComposedFeatures
{
  std::set<std::string> Enabled;                // embedded features, by name
  std::map<std::string, ShaderFeature> Runtime; // built for this frame (they count as enabled)
  std::vector<std::string> Labels;              // reported after Enabled (e.g. "Shadow:DSM")
};

/** The features embedded in the library (each .glsl of Shaders/Features), by name (Jitter, Phong, ...). */
const std::map<std::string, ShaderFeature>& EmbeddedShaderFeatures();

/** The Bound feature for a region of `leaves` leaves (BOUND_LEAVES defined in its Dec part). */
ShaderFeature BoundShaderFeature(int leaves);

/**
 * The Components feature for `count` components (2 to 4) of mode `mode` (deepshadow::
 * ComponentMode), lit apart or not (COMPONENT_COUNT, COMPONENT_MODE, COMPONENTS_LIT_APART),
 * each with its own gradient opacity or not (COMPONENT_GRADIENT_OPACITY).
 */
ShaderFeature ComponentsShaderFeature(int count, int mode, bool litApart, bool gradientOpacity);

/**
 * The TranslucentLayers feature for `layers` peeled layers and `segmentSlices` slices of
 * other volumes' segments (Rendering/Translucency).
 */
ShaderFeature TranslucentLayersShaderFeature(int layers, int segmentSlices);

/**
 * The VTKShading feature for VTK's lighting path `path` (1 to 3, VTK_SHADING_PATH), VTK 9.2's
 * reflected light or VTK 9.1's half vector (VTK_SHADING_REFLECTION).
 */
ShaderFeature VTKShadingShaderFeature(int path, bool reflection);
/**
 * The Lighting feature without the code no light of the frame needs: a positional light's
 * (POSITIONAL_LIGHTS 0) and the lone headlight shaded from the eye (LIGHT_FROM_EYE 0). The
 * embedded Lighting keeps both (the meshes' shader).
 */
ShaderFeature LightingShaderFeature(bool positional, bool fromEye);
/**
 * The ShadowRatio feature (the coarse pass of shadows while interacting), for a shaded volume
 * (SHADOW_RATIO_SHADED: the unshadowed colour is the sample lit with its shadows off) or not
 * (the sample's colour before lighting).
 */
ShaderFeature ShadowRatioShaderFeature(bool shaded);
/** The VolumeSegments feature: the march written as `segments` pieces (Rendering/Translucency). */
ShaderFeature VolumeSegmentsShaderFeature(int segments);

/**
 * Expands every tag of `shaderTemplate`; features not in `enabled` expand to nothing.
 * `runtime` features (built at run time, e.g. a shadow technique's "Shadow") take precedence
 * over the embedded ones of the same name; they count as enabled.
 */
std::string ComposeShader(const std::string& shaderTemplate, const std::set<std::string>& enabled,
  const std::map<std::string, ShaderFeature>& runtime = {});

/**
 * A Dec part that puts a table of Core's into GLSL: "#define COUNT n" and
 * "const TYPE NAME[n] = TYPE[n](elements...)", each element GLSL text such as "vec2(1, 2)".
 */
std::string GlslConstantArray(const std::string& type, const std::string& name,
  const std::string& count, const std::vector<std::string>& elements);

}
#endif
