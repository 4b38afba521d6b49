#include "Sampling/SamplingFeatures.h"

#include "GL/UniformSink.h"
#include "Sampling/ShadowContext.h"

#include "vtkTextureObject.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <string>

namespace deepshadow
{

namespace
{
using Context = ShadowContext;

// The volume's texture and the maps from its texels to the tables.
void BindSampling(const Context& context, UniformSink& sink)
{
  context.Volume->Activate();
  sink.Set("u_volume", context.Volume->GetTextureUnit());
  sink.Set("u_scalarMap", glm::vec2(context.ScalarMap));
  sink.Set("u_tableMap", glm::vec2(context.ShaderTableMap()));
  sink.Set("u_dims", glm::vec3(context.Dims));
  sink.Set("u_worldToIndex", glm::mat4(context.WorldToIndex));
}

// Isosurface blending's contour values, in the shaders' scalar (clamped to what a float holds).
void BindIsosurface(const Context& context, UniformSink& sink)
{
  std::vector<float> values;
  for (double value : context.IsoValues)
  {
    values.push_back(static_cast<float>(
      std::clamp(value * context.ShaderScalar.x + context.ShaderScalar.y, -1.0e38, 1.0e38)));
  }
  sink.Set("u_isoValues", values);
  sink.Set("u_isoCount", static_cast<int>(values.size()));
}

void ComposeComponents(const Context& context, ComposedFeatures& features)
{
  features.Runtime["Components"] = ComponentsShaderFeature(1 + static_cast<int>(context.OtherComponents.size()),
    static_cast<int>(context.Mode), context.ComponentsLitApart, context.ComponentGradientTable != nullptr);
  features.Labels.emplace_back("Components");
}

// Per component: its texture (1..), its maps to its table and colour, and the weights.
void BindComponentMaps(const Context& context, UniformSink& sink)
{
  for (int c = 0; c <= static_cast<int>(context.OtherComponents.size()); ++c)
  {
    const std::string index = "[" + std::to_string(c) + "]";
    const glm::dvec2 scalarMap =
      c == 0 ? context.ScalarMap : context.OtherComponents[static_cast<size_t>(c - 1)].ScalarMap;
    // RGBA's colour: the texture value, from the shaders' scalar.
    const glm::dvec2 shaderScalar =
      c == 0 ? context.ShaderScalar : context.OtherComponents[static_cast<size_t>(c - 1)].ShaderScalar;
    const double colorScale = context.TextureScale[c] / shaderScalar.x;
    sink.Set(("u_componentScalarMap" + index).c_str(), glm::vec2(scalarMap));
    sink.Set(("u_componentTableMap" + index).c_str(), glm::vec2(context.ComponentTableMap(c)));
    sink.Set(("u_componentColorMap" + index).c_str(), glm::vec2(colorScale, -shaderScalar.y * colorScale));
    if (c > 0)
    {
      sink.Set(("u_component" + std::to_string(c)).c_str(),
        context.OtherComponents[static_cast<size_t>(c - 1)].Texture->GetTextureUnit());
    }
  }
  sink.Set("u_componentWeight", glm::vec4(context.Weights));
}

// Independent components' own gradient opacities: one table, a row per component.
void BindComponentGradients(const Context& context, UniformSink& sink)
{
  // Per component: the shaders' scalar back to data units, and its largest magnitude (0: none).
  glm::vec4 unit(1.0f), largest(0.0f);
  glm::dvec3 indexScale(1.0);
  for (size_t c = 0; c < context.ComponentGradients.size(); ++c)
  {
    if (const std::optional<GradientOpacity>& gradient = context.ComponentGradients[c])
    {
      const glm::length_t i = static_cast<glm::length_t>(c);
      unit[i] = static_cast<float>(
        1.0 / (c == 0 ? context.ShaderScalar : context.OtherComponents[c - 1].ShaderScalar).x);
      largest[i] = static_cast<float>(gradient->MaxMagnitude);
      indexScale = gradient->IndexScale;
    }
  }
  sink.Set("u_componentGradientOpacity", context.ComponentGradientTable->GetTextureUnit());
  sink.Set("u_componentGradientMap", glm::vec2(context.ComponentGradientMap));
  sink.Set("u_componentGradientScale", glm::vec3(indexScale));
  sink.Set("u_componentGradientUnit", unit);
  sink.Set("u_componentGradientMax", largest);
  sink.Set("u_gradientReach", static_cast<float>(context.GradientReach));
}

void BindComponents(const Context& context, UniformSink& sink)
{
  for (const Context::Component& component : context.OtherComponents)
  {
    component.Texture->Activate();
  }
  BindComponentMaps(context, sink);
  if (context.ComponentGradientTable)
  {
    context.ComponentGradientTable->Activate();
    BindComponentGradients(context, sink);
  }
}

void UnbindComponents(const Context& context)
{
  for (const Context::Component& component : context.OtherComponents)
  {
    component.Texture->Deactivate();
  }
  if (context.ComponentGradientTable)
  {
    context.ComponentGradientTable->Deactivate();
  }
}

void BindGradientOpacity(const Context& context, UniformSink& sink)
{
  context.GradientOpacityTable->Activate();
  sink.Set("u_gradientOpacity", context.GradientOpacityTable->GetTextureUnit());
  sink.Set("u_gradientOpacityMap", glm::vec2(context.GradientOpacityMap));
  // The shaders' scalar is the data's times ShaderScalar.x: back to data units.
  sink.Set("u_gradientOpacityScale", glm::vec3(context.Gradient.IndexScale / context.ShaderScalar.x));
  sink.Set("u_gradientOpacityMax", static_cast<float>(context.Gradient.MaxMagnitude));
  sink.Set("u_gradientReach", static_cast<float>(context.GradientReach));
}

void BindTransfer2D(const Context& context, UniformSink& sink)
{
  const Transfer2D& shape = context.Transfer2DShape;
  const glm::dvec2 range = context.ShaderRange();
  const double span = range.y > range.x ? range.y - range.x : 1.0;
  context.Transfer2DImage->Activate();
  sink.Set("u_transfer2D", context.Transfer2DImage->GetTextureUnit());
  sink.Set("u_transfer2DSize", glm::vec2(shape.Width, shape.Height));
  sink.Set("u_transfer2DImageMap", glm::vec4(shape.ImageMap()));
  sink.Set("u_transfer2DNormalize", glm::vec2(1.0 / span, -range.x / span));
  // The shaders' scalar is the data's times ShaderScalar.x: back to data units.
  sink.Set("u_transfer2DGradientScale", glm::vec3(shape.Gradient.IndexScale / context.ShaderScalar.x));
  sink.Set("u_transfer2DGradientMax", static_cast<float>(shape.Gradient.MaxMagnitude));
  sink.Set("u_transfer2DViewStep", static_cast<float>(context.ShadowStep));
  sink.Set("u_gradientReach", static_cast<float>(context.GradientReach));
}

// A binary mask or a label map (and its labels' tables).
void BindMask(const Context& context, UniformSink& sink)
{
  context.Mask->Activate();
  sink.Set("u_mask", context.Mask->GetTextureUnit());
  sink.Set("u_maskToData", glm::vec2(context.MaskToData));
  if (context.LabelTable)
  {
    context.LabelTable->Activate();
    sink.Set("u_labelTable", context.LabelTable->GetTextureUnit());
    sink.Set("u_labelCount", context.LabelCount);
    sink.Set("u_maskToLabel", glm::vec2(context.MaskToLabel));
    sink.Set("u_maskBlendFactor", static_cast<float>(context.MaskBlendFactor));
    sink.Set("u_labelViewStep", static_cast<float>(context.ShadowStep));
  }
}

void UnbindMask(const Context& context)
{
  context.Mask->Deactivate();
  if (context.LabelTable)
  {
    context.LabelTable->Deactivate();
  }
}

void BindEmptySpace(const Context& context, UniformSink& sink)
{
  context.Occupancy->Activate();
  sink.Set("u_occupancy", context.Occupancy->GetTextureUnit());
  sink.Set("u_blockSize", context.BlockSize);
}

void BindBound(const Context& context, UniformSink& sink)
{
  context.Bound->Nodes->Activate();
  context.Bound->Triangles->Activate();
  sink.Set("u_boundNodes", context.Bound->Nodes->GetTextureUnit());
  sink.Set("u_boundTriangles", context.Bound->Triangles->GetTextureUnit());
  sink.Set("u_boundLeafRoot", context.Bound->LeafRoots);
  sink.Set("u_boundTruth", context.Bound->TruthTable);
}

void BindSurfaces(const Context& context, UniformSink& sink)
{
  context.Surfaces->Nodes->Activate();
  context.Surfaces->Triangles->Activate();
  sink.Set("u_surfaceNodes", context.Surfaces->Nodes->GetTextureUnit());
  sink.Set("u_surfaceTriangles", context.Surfaces->Triangles->GetTextureUnit());
  sink.Set("u_surfaceRoot", context.Surfaces->Root);
  sink.Set("u_surfaceTransmission", context.Surfaces->Transmission);
}

bool SurfacesMet(const SamplingUse& use)
{
  return use.Surfaces && use.Context.Surfaces;
}
}

const std::vector<SamplingFeature>& SamplingFeatures()
{
  // In this order: composition and binding follow it.
  static const std::vector<SamplingFeature> features = {
    { "VolumeSampling", [](const SamplingUse&) { return true; }, nullptr, BindSampling,
      [](const Context& context) { context.Volume->Deactivate(); } },
    { "Isosurface", [](const SamplingUse& use) { return !use.Context.IsoValues.empty(); }, nullptr,
      BindIsosurface, nullptr },
    { "Components", [](const SamplingUse& use) { return !use.Context.OtherComponents.empty(); },
      ComposeComponents, BindComponents, UnbindComponents },
    { "GradientOpacity", [](const SamplingUse& use) { return use.Context.GradientOpacityTable != nullptr; },
      nullptr, BindGradientOpacity, [](const Context& context) { context.GradientOpacityTable->Deactivate(); } },
    // The light's per-sample opacity factor, which the two above set in the feelers (a label
    // map replaces opacity instead).
    { "OpacityScale",
      [](const SamplingUse& use) { return use.Context.GradientOpacityTable || use.Context.MaskFeature() == "Mask"; },
      nullptr, nullptr, nullptr },
    { "Transfer2D", [](const SamplingUse& use) { return use.Context.Transfer2DImage != nullptr; }, nullptr,
      BindTransfer2D, [](const Context& context) { context.Transfer2DImage->Deactivate(); } },
    { "Mask", [](const SamplingUse& use) { return use.Context.MaskFeature() == "Mask"; }, nullptr, BindMask,
      UnbindMask },
    { "LabelMap", [](const SamplingUse& use) { return use.Context.MaskFeature() == "LabelMap"; }, nullptr,
      BindMask, UnbindMask },
    { "EmptySpace", [](const SamplingUse& use) { return use.Context.Occupancy != nullptr; }, nullptr,
      BindEmptySpace, [](const Context& context) { context.Occupancy->Deactivate(); } },
    { "TriangleHierarchy", [](const SamplingUse& use) { return use.Context.Bound || SurfacesMet(use); },
      nullptr, nullptr, nullptr },
    { "Bound", [](const SamplingUse& use) { return use.Context.Bound != nullptr; },
      [](const Context& context, ComposedFeatures& features) {
        features.Runtime["Bound"] = BoundShaderFeature(static_cast<int>(context.Bound->LeafRoots.size()));
        features.Labels.emplace_back("Bound");
      },
      BindBound,
      [](const Context& context) {
        context.Bound->Nodes->Deactivate();
        context.Bound->Triangles->Deactivate();
      } },
    { "Surfaces", SurfacesMet, nullptr, BindSurfaces,
      [](const Context& context) {
        context.Surfaces->Nodes->Deactivate();
        context.Surfaces->Triangles->Deactivate();
      } },
  };
  return features;
}

void ComposeSamplingFeatures(const SamplingUse& use, ComposedFeatures& features)
{
  for (const SamplingFeature& feature : SamplingFeatures())
  {
    if (!feature.Enabled(use))
    {
      continue;
    }
    if (feature.Compose)
    {
      feature.Compose(use.Context, features);
    }
    else
    {
      features.Enabled.insert(feature.Name);
    }
  }
}

void BindSamplingFeatures(const SamplingUse& use, UniformSink& sink)
{
  for (const SamplingFeature& feature : SamplingFeatures())
  {
    if (feature.Bind && feature.Enabled(use))
    {
      feature.Bind(use.Context, sink);
    }
  }
}

void UnbindSamplingFeatures(const SamplingUse& use)
{
  for (const SamplingFeature& feature : SamplingFeatures())
  {
    if (feature.Unbind && feature.Enabled(use))
    {
      feature.Unbind(use.Context);
    }
  }
}

}
