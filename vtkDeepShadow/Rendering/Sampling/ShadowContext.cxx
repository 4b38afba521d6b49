#include "Sampling/ShadowContext.h"

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

}
