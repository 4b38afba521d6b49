#include "RayCast/VolumeFeatures.h"

#include "CoreAdapter.h"
#include "Core/ShadowSubsampling.h"
#include "GL/FramebufferCopy.h"
#include "LightingUniforms.h"
#include "Shadows/OtherVolumeShadows.h"
#include "Translucency/TranslucentLayers.h"
#include "RayCast/RayCastFrame.h"
#include "RayCast/UserShaderCode.h"
#include "Sampling/SamplingFeatures.h"
#include "vtkDeepShadowTechniqueInternals.h"

#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkRenderer.h"
#include "vtkTextureObject.h"
#include "vtkVolume.h"

#include <glm/matrix.hpp>

#include <algorithm>
#include <string>
#include <utility>

namespace deepshadow
{

namespace
{
using Frame = RayCastFrame;

// The sampling features of the same name (Sampling/SamplingFeatures) composed these entries'
// GLSL and bind the volume's part; the entries bind what the view adds.
void ComposedBySampling(const Frame&, ComposedFeatures&) {}

// The template's own uniforms: the ray (camera, viewport, step) and the view's table.
void BindViewRay(const Frame& f, UniformSink& sink)
{
  const ShadowContext& c = f.Context;
  f.Transfer->Activate();
  sink.Set("u_transfer", f.Transfer->GetTextureUnit());
  sink.Set("u_boxMax", glm::vec3(c.Dims - 1));
  sink.Set("u_clipToWorld", glm::mat4(f.View.GetInverseViewProjection()));
  sink.Set("u_indexToClip", glm::mat4(f.View.GetViewProjection() * c.IndexToWorld));
  // Segments are drawn into their own target, its viewport at (0, 0).
  sink.Set("u_viewport", glm::vec4(f.Segments ? 0.0f : static_cast<float>(f.X0),
                           f.Segments ? 0.0f : static_cast<float>(f.Y0), static_cast<float>(f.Width),
                           static_cast<float>(f.Height)));
  sink.Set("u_step", static_cast<float>(c.ViewStep));
  sink.Set("u_terminationOpacity", f.TerminationOpacity);
}

// Components 1..'s tables of the view, and each component's material.
void BindComponentTables(const Frame& f, UniformSink& sink)
{
  const ShadowContext& c = f.Context;
  for (size_t i = 0; i < c.OtherComponents.size(); ++i)
  {
    f.ComponentTransfers[i]->Activate();
    sink.Set(("u_componentTransfer" + std::to_string(i + 1)).c_str(), f.ComponentTransfers[i]->GetTextureUnit());
  }
  for (int i = 0; i <= static_cast<int>(c.OtherComponents.size()); ++i)
  {
    // Dependent components are lit with component 0's material (as VTK's).
    const Material m = adapter::MakeMaterial(f.Property, c.Mode == ComponentMode::Independent ? i : 0);
    sink.Set(("u_componentMaterial[" + std::to_string(i) + "]").c_str(),
      glm::vec4(m.Ambient, m.Diffuse, m.Specular, m.SpecularPower));
  }
}

void UnbindComponentTables(const Frame& f)
{
  for (vtkTextureObject* table : f.ComponentTransfers)
  {
    table->Deactivate();
  }
}

// The normalization of a component's shaders' scalar over its data range, and the average's
// scalar range in that scalar (clamped to what a float holds).
std::pair<glm::vec2, glm::vec2> ProjectionMaps(
  const glm::dvec2& dataRange, const glm::dvec2& shaderScalar, const ProjectionSettings& projection)
{
  const glm::dvec2 range = dataRange * shaderScalar.x + shaderScalar.y;
  const double span = range.y > range.x ? range.y - range.x : 1.0;
  auto toShader = [&shaderScalar](double scalar) {
    return static_cast<float>(std::clamp(scalar * shaderScalar.x + shaderScalar.y, -3.0e38, 3.0e38));
  };
  return { glm::vec2(1.0 / span, -range.x / span),
    glm::vec2(toShader(projection.AverageMin), toShader(projection.AverageMax)) };
}

// The projection's mode and maps: the volume's, and each component's for volumes of several.
void BindProjection(const Frame& f, UniformSink& sink)
{
  const ShadowContext& c = f.Context;
  sink.Set("u_blendMode", static_cast<int>(f.Projection.Mode));
  const auto [normalize, average] = ProjectionMaps(c.Range, c.ShaderScalar, f.Projection);
  sink.Set("u_normalizeMap", normalize);
  sink.Set("u_averageRange", average);
  for (size_t i = 0; i < c.OtherComponents.size() + (c.OtherComponents.empty() ? 0 : 1); ++i)
  {
    const auto [componentNormalize, componentAverage] = i == 0
      ? std::make_pair(normalize, average)
      : ProjectionMaps(c.OtherComponents[i - 1].Range, c.OtherComponents[i - 1].ShaderScalar, f.Projection);
    const std::string index = "[" + std::to_string(i) + "]";
    sink.Set(("u_componentNormalizeMap" + index).c_str(), componentNormalize);
    sink.Set(("u_componentAverageRange" + index).c_str(), componentAverage);
  }
}

// Surfaces are met by the feelers of lookups only; light-space builds have their own.
SamplingUse Sampling(const Frame& f)
{
  return { f.Context, f.Technique && f.Technique->NeedsFeeler() };
}

// Gradient shading; the shadow term needs no normal.
bool Normals(const Frame& f)
{
  return f.Lit && f.Shade && !f.ShadowTerm;
}

void BindLighting(const Frame& f, UniformSink& sink)
{
  SetLightingUniforms(sink, f.Context.Lights, f.Renderer, adapter::MakeMaterial(f.Property), true, !Normals(f));
  if (Normals(f))
  {
    const VolumeShading& shading = f.Context.Shading;
    sink.Set("u_ambientLight", glm::vec3(shading.Ambient));
    sink.Set("u_indexGradientToNormal", glm::mat3(shading.IndexGradientToNormal));
  }
  sink.Set("u_gradientReach", static_cast<float>(f.Context.GradientReach));
}

// VTK's shading of a shaded volume (Core/VolumeShading.h): its path's code and frame.
bool VTKShading(const Frame& f)
{
  return Normals(f) && f.Context.Shading.Path != ShadingPath::BlinnPhong;
}

void BindVTKShading(const Frame& f, UniformSink& sink)
{
  const VolumeShading& shading = f.Context.Shading;
  sink.Set("u_worldToShading", glm::mat3(shading.WorldToShading));
  sink.Set("u_eye", glm::vec3(shading.Eye));
  sink.Set("u_mirrorCentre", glm::vec3(shading.MirrorCentre));
  sink.Set("u_lightingTransform", glm::mat4(shading.LightingTransform));
}

// A vtkShaderProperty's code: the matrices and camera VTK's names stand for.
void BindUserShader(const Frame& f, UniformSink& sink)
{
  vtkCamera* camera = f.Renderer->GetActiveCamera();
  const glm::dmat4 view = adapter::ToGlm(camera->GetModelViewTransformMatrix());
  const glm::dmat4 projection =
    adapter::ToGlm(camera->GetProjectionTransformMatrix(f.Renderer->GetTiledAspectRatio(), -1.0, 1.0));
  const glm::dmat4 volume = adapter::ToGlm(f.Volume->GetMatrix());
  // VTK's texture-to-dataset matrix spans the first to the last point over [0, 1]: index
  // (Dims - 1) t, in dataset coordinates (the volume's matrix undone).
  glm::dmat4 textureToIndex(1.0);
  for (int axis = 0; axis < 3; ++axis)
  {
    textureToIndex[axis][axis] = std::max(f.Context.Dims[axis] - 1, 1);
  }
  const glm::dmat4 textureToDataset = glm::inverse(volume) * f.Context.IndexToWorld * textureToIndex;
  sink.Set("in_projectionMatrix", glm::mat4(projection));
  sink.Set("in_modelViewMatrix", glm::mat4(view));
  sink.Set("in_inverseModelViewMatrix", glm::mat4(glm::inverse(view)));
  sink.Set("in_volumeMatrix[0]", glm::mat4(volume));
  sink.Set("in_inverseVolumeMatrix[0]", glm::mat4(glm::inverse(volume)));
  sink.Set("in_textureDatasetMatrix[0]", glm::mat4(textureToDataset));
  sink.Set("in_inverseTextureDatasetMatrix[0]", glm::mat4(glm::inverse(textureToDataset)));
  double eye[3];
  camera->GetPosition(eye);
  sink.Set("in_cameraPos", glm::vec3(eye[0], eye[1], eye[2]));
  sink.Set("u_textureSize", glm::vec3(f.Context.Dims));
}

void ComposeShadow(const Frame& f, ComposedFeatures& features)
{
  // The slots (shadowed lights) known: the per-sample arrays sized and the loop unrolled.
  const int slots = vtkDeepShadowTechnique::Internals::SlotCount(f.Technique);
  const std::string defines = "//@Dec\n#define SHADOW_SLOTS " + std::to_string(slots) + "\n#define SHADOW_SLOT_ARRAY " +
    std::to_string(std::max(slots, 1)) + "\n";
  features.Runtime["Shadow"] = ShaderFeature("Shadow", defines + f.Technique->GetShaderFeatureSource());
  if (f.Technique->NeedsFeeler())
  {
    features.Enabled.insert("Feeler");
  }
  for (const std::string& feature : f.Technique->GetLookupFeatures())
  {
    features.Enabled.insert(feature);
  }
  features.Labels.push_back("Shadow:" + f.Technique->GetName());
}
}

namespace
{
// What the view adds to the volume's data features.
std::vector<VolumeFeature> ViewPartsOfDataFeatures()
{
  return {
    { "VolumeSampling", [](const Frame&) { return true; }, ComposedBySampling, BindViewRay,
      [](const Frame& f) { f.Transfer->Deactivate(); } },
    { "Components", [](const Frame& f) { return !f.Context.OtherComponents.empty(); }, ComposedBySampling,
      BindComponentTables, UnbindComponentTables },
    { "LabelMap", [](const Frame& f) { return f.Context.MaskFeature() == "LabelMap"; }, ComposedBySampling,
      [](const Frame& f, UniformSink& sink) { sink.Set("u_labelUnlitWeight", f.ShadowTerm ? 0.0f : 1.0f); },
      nullptr },
    { "Isosurface", [](const Frame& f) { return !f.Context.IsoValues.empty(); }, ComposedBySampling,
      [](const Frame& f, UniformSink& sink) {
        sink.Set("u_isoReceiverOffset", f.Technique ? static_cast<float>(IsoReceiverOffset(
                                                        f.Technique->GetStepFactor() * f.Context.ShadowStep))
                                                    : 0.0f);
      },
      nullptr },
  };
}

// How samples are lit and blended: the opaque scene's depth, lighting and shading, the
// user's code, jitter, projections and isosurfaces.
std::vector<VolumeFeature> ShadingFeatures()
{
  return {
    { "OpaqueDepth", [](const Frame& f) { return f.Opaque != nullptr; }, nullptr,
      [](const Frame& f, UniformSink& sink) {
        f.Opaque->GetDepth()->Activate();
        sink.Set("u_opaqueDepth", f.Opaque->GetDepth()->GetTextureUnit());
      },
      [](const Frame& f) { f.Opaque->GetDepth()->Deactivate(); } },
    { "Lighting", [](const Frame& f) { return f.Lit; },
      [](const Frame& f, ComposedFeatures& features) {
        const std::vector<Light>& lights = f.Context.Lights;
        const auto any = [&](bool Light::*field) {
          return std::any_of(lights.begin(), lights.end(), [&](const Light& light) { return light.*field; });
        };
        features.Runtime["Lighting"] = LightingShaderFeature(any(&Light::Positional), any(&Light::ShadedFromEye));
        features.Labels.emplace_back("Lighting");
      },
      BindLighting, nullptr },
    { "Gradient", Normals, nullptr, nullptr, nullptr },
    { "Phong", Normals, nullptr, nullptr, nullptr },
    { "UserShader", [](const Frame& f) { return f.UserCode != nullptr; },
      [](const Frame& f, ComposedFeatures& features) {
        features.Runtime["UserShader"] = UserShaderFeature(*f.UserCode);
        features.Labels.emplace_back("UserShader");
      },
      BindUserShader, nullptr },
    { "VTKShading", VTKShading,
      [](const Frame& f, ComposedFeatures& features) {
        features.Runtime["VTKShading"] = VTKShadingShaderFeature(static_cast<int>(f.Context.Shading.Path),
          f.Context.Shading.Revision == VTKShadingRevision::Reflection);
        features.Labels.emplace_back("VTKShading");
      },
      BindVTKShading, nullptr },
    { "Isotropic", [](const Frame& f) { return f.Lit && !Normals(f); }, nullptr,
      [](const Frame& f, UniformSink& sink) {
        sink.Set("u_isotropicLightScale", static_cast<float>(IsotropicLightScale(f.Context.Lights)));
        sink.Set("u_isotropicUnlooped", UnloopedDiffuse(f.Context.Lights));
      },
      nullptr },
    { "DatasetOpacity", [](const Frame& f) { return f.WorldToDataset.has_value(); }, nullptr,
      [](const Frame& f, UniformSink& sink) {
        sink.Set("u_worldToDataset", glm::mat3(*f.WorldToDataset));
        sink.Set("u_datasetScale", static_cast<float>(f.DatasetScale));
      },
      nullptr },
    { "ShadowTerm", [](const Frame& f) { return f.ShadowTerm; }, nullptr, nullptr, nullptr },
    { "ShadowRatio", [](const Frame& f) { return f.RatioPass == Frame::ShadowRatioPass::Coarse; },
      [](const Frame& f, ComposedFeatures& features) {
        features.Runtime["ShadowRatio"] = ShadowRatioShaderFeature(Normals(f));
        features.Labels.emplace_back("ShadowRatio");
      },
      [](const Frame& f, UniformSink& sink) { sink.Set("u_ratioScale", static_cast<float>(f.RatioScale)); },
      nullptr },
    { "ShadowRatioApply", [](const Frame& f) { return f.RatioPass == Frame::ShadowRatioPass::Full; }, nullptr,
      [](const Frame& f, UniformSink& sink) {
        f.RatioTexels->Activate();
        sink.Set("u_shadowRatio", f.RatioTexels->GetTextureUnit());
        f.RatioGuides->Activate();
        sink.Set("u_ratioGuide", f.RatioGuides->GetTextureUnit());
        sink.Set("u_ratioScale", static_cast<float>(f.RatioScale));
        sink.Set("u_ratioGuideScale", static_cast<float>(ShadowRatioGuideScale));
      },
      [](const Frame& f) {
        f.RatioTexels->Deactivate();
        f.RatioGuides->Deactivate();
      } },
    { "Hash", [](const Frame& f) { return f.Jitter; }, nullptr, nullptr, nullptr },
    { "Jitter", [](const Frame& f) { return f.Jitter; }, nullptr,
      [](const Frame& f, UniformSink& sink) { sink.Set("u_jitterSeed", f.JitterSeed); }, nullptr },
    { "Projection", [](const Frame& f) { return f.Projection.Mode != BlendMode::Composite; }, nullptr,
      BindProjection, nullptr },
  };
}

// What shadows and interleaves the march: the technique, the other volumes' shadows, the
// translucent meshes' layers and the second volume's segments.
std::vector<VolumeFeature> ShadowAndMergeFeatures()
{
  return {
    { "Shadow", [](const Frame& f) { return f.Technique != nullptr; }, ComposeShadow,
      [](const Frame& f, UniformSink& sink)
      { vtkDeepShadowTechnique::Internals::Bind(f.Technique, sink, f.Context); },
      [](const Frame& f) { f.Technique->Unbind(); } },
    { "ShadowGrid", [](const Frame& f) { return f.Others != nullptr; }, nullptr, nullptr, nullptr },
    { "OtherVolumeShadows", [](const Frame& f) { return f.Others != nullptr; }, nullptr,
      [](const Frame& f, UniformSink& sink) {
        f.Others->Activate(sink, static_cast<int>(f.Context.Lights.size()));
      },
      [](const Frame& f) { f.Others->Deactivate(); } },
    { "TranslucentLayers", [](const Frame& f) { return f.Layers != nullptr; },
      [](const Frame& f, ComposedFeatures& features) {
        features.Enabled.insert("TranslucentLayers");
        features.Runtime["TranslucentLayers"] = f.Layers->GetShaderFeature();
      },
      [](const Frame& f, UniformSink& sink) { f.Layers->Activate(sink); },
      [](const Frame& f) { f.Layers->Deactivate(); } },
    { "VolumeSegments", [](const Frame& f) { return f.Segments != nullptr; },
      [](const Frame& f, ComposedFeatures& features) {
        features.Enabled.insert("VolumeSegments");
        features.Runtime["VolumeSegments"] = VolumeSegmentsShaderFeature(f.Segments->GetSegments());
      },
      [](const Frame& f, UniformSink& sink) {
        sink.Set("u_worldToClip", glm::mat4(f.View.GetViewProjection()));
      },
      nullptr },
  };
}
}

const std::vector<VolumeFeature>& VolumeFeatures()
{
  // In this order: composition and binding follow it.
  static const std::vector<VolumeFeature> features = [] {
    std::vector<VolumeFeature> all;
    for (auto group : { ViewPartsOfDataFeatures(), ShadingFeatures(), ShadowAndMergeFeatures() })
    {
      all.insert(all.end(), group.begin(), group.end());
    }
    return all;
  }();
  return features;
}

ComposedFeatures ComposeVolumeFeatures(const RayCastFrame& frame)
{
  ComposedFeatures composed;
  ComposeSamplingFeatures(Sampling(frame), composed);
  for (const VolumeFeature& feature : VolumeFeatures())
  {
    if (!feature.Enabled(frame))
    {
      continue;
    }
    if (feature.Compose)
    {
      feature.Compose(frame, composed);
    }
    else
    {
      composed.Enabled.insert(feature.Name);
    }
  }
  return composed;
}

void BindVolumeFeatures(const RayCastFrame& frame, UniformSink& sink)
{
  BindSamplingFeatures(Sampling(frame), sink);
  for (const VolumeFeature& feature : VolumeFeatures())
  {
    if (feature.Bind && feature.Enabled(frame))
    {
      feature.Bind(frame, sink);
    }
  }
}

void UnbindVolumeFeatures(const RayCastFrame& frame)
{
  for (const VolumeFeature& feature : VolumeFeatures())
  {
    if (feature.Unbind && feature.Enabled(frame))
    {
      feature.Unbind(frame);
    }
  }
  UnbindSamplingFeatures(Sampling(frame));
}

}
