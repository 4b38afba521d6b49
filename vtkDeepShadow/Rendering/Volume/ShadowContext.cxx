#include "Volume/ShadowContext.h"

#include "vtkTextureObject.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>

namespace deepshadow
{

std::vector<double> ShadowContext::TransferKey(bool colors) const
{
  std::vector<double> key{ this->Transfer.OpacityUnitDistance };
  auto add = [&key](const PiecewiseLinear& function) {
    key.push_back(static_cast<double>(function.GetNodes().size()));
    for (const auto& [x, y] : function.GetNodes())
    {
      key.insert(key.end(), { x, y });
    }
  };
  add(this->Transfer.Opacity);
  if (colors)
  {
    add(this->Transfer.Red);
    add(this->Transfer.Green);
    add(this->Transfer.Blue);
  }
  key.push_back(static_cast<double>(this->IsoValues.size()));
  key.insert(key.end(), this->IsoValues.begin(), this->IsoValues.end());
  if (this->Mask)
  {
    key.push_back(static_cast<double>(this->MaskVersion));
    key.insert(key.end(), this->LabelKey.begin(), this->LabelKey.end());
  }
  key.insert(key.end(), this->Transfer2DKey.begin(), this->Transfer2DKey.end());
  if (this->GradientOpacityTable)
  {
    add(this->Gradient.Function);
    key.insert(key.end(), { this->Gradient.MaxMagnitude, this->Gradient.IndexScale.x,
                            this->Gradient.IndexScale.y, this->Gradient.IndexScale.z });
  }
  key.push_back(static_cast<double>(this->OtherComponents.size()));
  if (!this->OtherComponents.empty())
  {
    key.insert(key.end(), { static_cast<double>(this->Mode), this->Weights.x, this->Weights.y, this->Weights.z,
                            this->Weights.w, this->TextureScale.x });
    for (const std::optional<GradientOpacity>& gradient : this->ComponentGradients)
    {
      key.push_back(gradient ? gradient->MaxMagnitude : -1.0);
      if (gradient)
      {
        add(gradient->Function);
        key.insert(key.end(), { gradient->IndexScale.x, gradient->IndexScale.y, gradient->IndexScale.z });
      }
    }
    for (const Component& component : this->OtherComponents)
    {
      key.push_back(component.Transfer.OpacityUnitDistance);
      add(component.Transfer.Opacity);
      if (colors)
      {
        add(component.Transfer.Red);
        add(component.Transfer.Green);
        add(component.Transfer.Blue);
      }
    }
  }
  return key;
}

void ShadowContext::AddVolumeFeatures(std::set<std::string>& enabled,
  std::map<std::string, ShaderFeature>& runtime, bool surfaces) const
{
  enabled.insert("VolumeSampling");
  if (!this->OtherComponents.empty())
  {
    runtime["Components"] = ComponentsShaderFeature(1 + static_cast<int>(this->OtherComponents.size()),
      static_cast<int>(this->Mode), this->ComponentsLitApart, this->ComponentGradientTable != nullptr);
  }
  if (!this->IsoValues.empty())
  {
    enabled.insert("Isosurface");
  }
  if (this->GradientOpacityTable)
  {
    enabled.insert("GradientOpacity");
  }
  if (this->Transfer2DImage)
  {
    enabled.insert("Transfer2D");
  }
  if (this->Mask)
  {
    enabled.insert(this->MaskFeature());
  }
  // A label map replaces opacity instead of scaling it.
  if (this->GradientOpacityTable || (this->Mask && !this->LabelTable))
  {
    enabled.insert("OpacityScale");
  }
  if (this->Occupancy)
  {
    enabled.insert("EmptySpace");
  }
  if (this->Bound)
  {
    enabled.insert("TriangleHierarchy");
    runtime["Bound"] = BoundShaderFeature(static_cast<int>(this->Bound->LeafRoots.size()));
  }
  if (surfaces && this->Surfaces)
  {
    enabled.insert("TriangleHierarchy");
    enabled.insert("Surfaces");
  }
}

glm::dvec2 ShadowContext::ShaderTableMap() const
{
  // coordinate = scalar * TableMap.x + TableMap.y, scalar = (s - ShaderScalar.y) / ShaderScalar.x
  const double scale = this->TableMap.x / this->ShaderScalar.x;
  return { scale, this->TableMap.y - this->ShaderScalar.y * scale };
}

glm::dvec2 ShadowContext::ShaderRange() const
{
  return this->Range * this->ShaderScalar.x + this->ShaderScalar.y;
}

glm::dvec2 ShadowContext::ComponentTableMap(int c) const
{
  if (c == 0)
  {
    return this->ShaderTableMap();
  }
  const Component& component = this->OtherComponents[static_cast<size_t>(c - 1)];
  TransferTable table; // its table spans its range, TableSize texels
  table.RangeMin = component.Range.x;
  table.RangeMax = component.Range.y;
  table.Size = this->TableSize;
  glm::dvec2 map = table.CoordinateMap(); // data value -> coordinate
  if (this->Mode == ComponentMode::RGBA && c == 3)
  {
    // Looked up at RGBAOpacityValue: range.x + value * scale * (range.y - range.x).
    const double width = component.Range.y - component.Range.x;
    map = { map.x * this->TextureScale[3] * width, map.x * component.Range.x + map.y };
  }
  // From the shaders' scalar: value = (s - ShaderScalar.y) / ShaderScalar.x.
  const double scale = map.x / component.ShaderScalar.x;
  return { scale, map.y - component.ShaderScalar.y * scale };
}

void ShadowContext::SetComponentUniforms(UniformSink& sink) const
{
  for (int c = 0; c <= static_cast<int>(this->OtherComponents.size()); ++c)
  {
    const std::string index = "[" + std::to_string(c) + "]";
    const glm::dvec2 scalarMap = c == 0 ? this->ScalarMap : this->OtherComponents[static_cast<size_t>(c - 1)].ScalarMap;
    // RGBA's colour: the texture value, from the shaders' scalar.
    const glm::dvec2 shaderScalar =
      c == 0 ? this->ShaderScalar : this->OtherComponents[static_cast<size_t>(c - 1)].ShaderScalar;
    const double colorScale = this->TextureScale[c] / shaderScalar.x;
    sink.Set(("u_componentScalarMap" + index).c_str(), glm::vec2(scalarMap));
    sink.Set(("u_componentTableMap" + index).c_str(), glm::vec2(this->ComponentTableMap(c)));
    sink.Set(("u_componentColorMap" + index).c_str(), glm::vec2(colorScale, -shaderScalar.y * colorScale));
    if (c > 0)
    {
      sink.Set(("u_component" + std::to_string(c)).c_str(),
        this->OtherComponents[static_cast<size_t>(c - 1)].Texture->GetTextureUnit());
    }
  }
  sink.Set("u_componentWeight", glm::vec4(this->Weights));
  if (this->ComponentGradientTable)
  {
    // Per component: the shaders' scalar back to data units, and its largest magnitude (0: none).
    glm::vec4 unit(1.0f), largest(0.0f);
    glm::dvec3 indexScale(1.0);
    for (size_t c = 0; c < this->ComponentGradients.size(); ++c)
    {
      if (const std::optional<GradientOpacity>& gradient = this->ComponentGradients[c])
      {
        const glm::length_t i = static_cast<glm::length_t>(c);
        unit[i] = static_cast<float>(1.0 / (c == 0 ? this->ShaderScalar : this->OtherComponents[c - 1].ShaderScalar).x);
        largest[i] = static_cast<float>(gradient->MaxMagnitude);
        indexScale = gradient->IndexScale;
      }
    }
    sink.Set("u_componentGradientOpacity", this->ComponentGradientTable->GetTextureUnit());
    sink.Set("u_componentGradientMap", glm::vec2(this->ComponentGradientMap));
    sink.Set("u_componentGradientScale", glm::vec3(indexScale));
    sink.Set("u_componentGradientUnit", unit);
    sink.Set("u_componentGradientMax", largest);
    sink.Set("u_gradientReach", static_cast<float>(this->GradientReach));
  }
}

void ShadowContext::SetVolumeUniforms(UniformSink& sink) const
{
  this->SetSamplingUniforms(sink);
  if (!this->OtherComponents.empty())
  {
    this->SetComponentUniforms(sink);
  }
  if (this->GradientOpacityTable)
  {
    this->SetGradientOpacityUniforms(sink);
  }
  if (this->Transfer2DImage)
  {
    this->SetTransfer2DUniforms(sink);
  }
  if (this->Mask)
  {
    this->SetMaskUniforms(sink);
  }
  if (this->Occupancy)
  {
    this->SetEmptySpaceUniforms(sink);
  }
  if (this->Bound)
  {
    this->SetBoundUniforms(sink);
  }
  if (this->Surfaces)
  {
    this->SetSurfacesUniforms(sink);
  }
}

void ShadowContext::SetSamplingUniforms(UniformSink& sink) const
{
  sink.Set("u_volume", this->Volume->GetTextureUnit());
  sink.Set("u_scalarMap", glm::vec2(this->ScalarMap));
  sink.Set("u_tableMap", glm::vec2(this->ShaderTableMap()));
  sink.Set("u_dims", glm::vec3(this->Dims));
  sink.Set("u_worldToIndex", glm::mat4(this->WorldToIndex));
  if (!this->IsoValues.empty())
  {
    std::vector<float> values;
    for (double value : this->IsoValues)
    {
      values.push_back(static_cast<float>(
        std::clamp(value * this->ShaderScalar.x + this->ShaderScalar.y, -1.0e38, 1.0e38)));
    }
    sink.Set("u_isoValues", values);
    sink.Set("u_isoCount", static_cast<int>(values.size()));
  }
}

void ShadowContext::SetGradientOpacityUniforms(UniformSink& sink) const
{
  sink.Set("u_gradientOpacity", this->GradientOpacityTable->GetTextureUnit());
  sink.Set("u_gradientOpacityMap", glm::vec2(this->GradientOpacityMap));
  // The shaders' scalar is the data's times ShaderScalar.x: back to data units.
  sink.Set("u_gradientOpacityScale", glm::vec3(this->Gradient.IndexScale / this->ShaderScalar.x));
  sink.Set("u_gradientOpacityMax", static_cast<float>(this->Gradient.MaxMagnitude));
  sink.Set("u_gradientReach", static_cast<float>(this->GradientReach));
}

void ShadowContext::SetTransfer2DUniforms(UniformSink& sink) const
{
  const Transfer2D& shape = this->Transfer2DShape;
  const glm::dvec2 range = this->ShaderRange();
  const double span = range.y > range.x ? range.y - range.x : 1.0;
  sink.Set("u_transfer2D", this->Transfer2DImage->GetTextureUnit());
  sink.Set("u_transfer2DSize", glm::vec2(shape.Width, shape.Height));
  sink.Set("u_transfer2DImageMap", glm::vec4(shape.ImageMap()));
  sink.Set("u_transfer2DNormalize", glm::vec2(1.0 / span, -range.x / span));
  // The shaders' scalar is the data's times ShaderScalar.x: back to data units.
  sink.Set("u_transfer2DGradientScale", glm::vec3(shape.Gradient.IndexScale / this->ShaderScalar.x));
  sink.Set("u_transfer2DGradientMax", static_cast<float>(shape.Gradient.MaxMagnitude));
  sink.Set("u_transfer2DViewStep", static_cast<float>(this->ShadowStep));
  sink.Set("u_gradientReach", static_cast<float>(this->GradientReach));
}

void ShadowContext::SetMaskUniforms(UniformSink& sink) const
{
  sink.Set("u_mask", this->Mask->GetTextureUnit());
  sink.Set("u_maskToData", glm::vec2(this->MaskToData));
  if (this->LabelTable)
  {
    sink.Set("u_labelTable", this->LabelTable->GetTextureUnit());
    sink.Set("u_labelCount", this->LabelCount);
    sink.Set("u_maskToLabel", glm::vec2(this->MaskToLabel));
    sink.Set("u_maskBlendFactor", static_cast<float>(this->MaskBlendFactor));
    sink.Set("u_labelViewStep", static_cast<float>(this->ShadowStep));
  }
}

void ShadowContext::SetEmptySpaceUniforms(UniformSink& sink) const
{
  sink.Set("u_occupancy", this->Occupancy->GetTextureUnit());
  sink.Set("u_blockSize", this->BlockSize);
}

void ShadowContext::SetBoundUniforms(UniformSink& sink) const
{
  sink.Set("u_boundNodes", this->Bound->Nodes->GetTextureUnit());
  sink.Set("u_boundTriangles", this->Bound->Triangles->GetTextureUnit());
  sink.Set("u_boundLeafRoot", this->Bound->LeafRoots);
  sink.Set("u_boundTruth", this->Bound->TruthTable);
}

void ShadowContext::SetSurfacesUniforms(UniformSink& sink) const
{
  sink.Set("u_surfaceNodes", this->Surfaces->Nodes->GetTextureUnit());
  sink.Set("u_surfaceTriangles", this->Surfaces->Triangles->GetTextureUnit());
  sink.Set("u_surfaceRoot", this->Surfaces->Root);
  sink.Set("u_surfaceTransmission", this->Surfaces->Transmission);
}

void ShadowContext::ActivateVolumeTextures() const
{
  this->Volume->Activate();
  for (const Component& component : this->OtherComponents)
  {
    component.Texture->Activate();
  }
  if (this->GradientOpacityTable)
  {
    this->GradientOpacityTable->Activate();
  }
  if (this->ComponentGradientTable)
  {
    this->ComponentGradientTable->Activate();
  }
  if (this->Transfer2DImage)
  {
    this->Transfer2DImage->Activate();
  }
  if (this->Mask)
  {
    this->Mask->Activate();
  }
  if (this->LabelTable)
  {
    this->LabelTable->Activate();
  }
  if (this->Occupancy)
  {
    this->Occupancy->Activate();
  }
  if (this->Bound)
  {
    this->Bound->Nodes->Activate();
    this->Bound->Triangles->Activate();
  }
  if (this->Surfaces)
  {
    this->Surfaces->Nodes->Activate();
    this->Surfaces->Triangles->Activate();
  }
}

void ShadowContext::DeactivateVolumeTextures() const
{
  this->Volume->Deactivate();
  for (const Component& component : this->OtherComponents)
  {
    component.Texture->Deactivate();
  }
  if (this->GradientOpacityTable)
  {
    this->GradientOpacityTable->Deactivate();
  }
  if (this->ComponentGradientTable)
  {
    this->ComponentGradientTable->Deactivate();
  }
  if (this->Transfer2DImage)
  {
    this->Transfer2DImage->Deactivate();
  }
  if (this->Mask)
  {
    this->Mask->Deactivate();
  }
  if (this->LabelTable)
  {
    this->LabelTable->Deactivate();
  }
  if (this->Occupancy)
  {
    this->Occupancy->Deactivate();
  }
  if (this->Bound)
  {
    this->Bound->Nodes->Deactivate();
    this->Bound->Triangles->Deactivate();
  }
  if (this->Surfaces)
  {
    this->Surfaces->Nodes->Deactivate();
    this->Surfaces->Triangles->Deactivate();
  }
}

}
