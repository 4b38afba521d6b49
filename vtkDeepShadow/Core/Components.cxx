#include "Core/Components.h"

#include "Core/OpticalModel.h"

#include <algorithm>

namespace deepshadow
{

glm::dvec4 ComponentSet::Sample(const VolumeGrid& first, const glm::dvec3& index, Interpolation interpolation) const
{
  glm::dvec4 values(0.0);
  for (int i = 0; i < this->Count(); ++i)
  {
    values[i] = this->Grid(first, i).Sample(index, interpolation);
  }
  return values;
}

bool ComponentSet::HasGradients() const
{
  return std::any_of(this->Gradients.begin(), this->Gradients.end(),
    [](const std::optional<GradientOpacity>& gradient) { return gradient.has_value(); });
}

glm::dvec4 ComponentSet::GradientFactors(
  const VolumeGrid& first, const glm::dvec3& index, Interpolation interpolation) const
{
  glm::dvec4 factors(1.0);
  for (int i = 0; i < std::min(this->Count(), static_cast<int>(this->Gradients.size())); ++i)
  {
    if (const std::optional<GradientOpacity>& gradient = this->Gradients[static_cast<size_t>(i)])
    {
      factors[i] = gradient->Factor(this->Grid(first, i), index, interpolation);
    }
  }
  return factors;
}

void ComponentSet::ApplyGradients(
  ComponentColors& colors, const VolumeGrid& first, const glm::dvec3& index, Interpolation interpolation) const
{
  for (int i = 0; i < std::min(this->Count(), static_cast<int>(this->Gradients.size())); ++i)
  {
    const std::optional<GradientOpacity>& gradient = this->Gradients[static_cast<size_t>(i)];
    glm::dvec4& color = colors[static_cast<size_t>(i)];
    if (gradient && color.a > 0.0)
    {
      color.a *= gradient->Factor(this->Grid(first, i), index, interpolation);
    }
  }
}

glm::dvec4 CombineComponents(const ComponentSet& set, const ComponentColors& colors, const glm::dvec4& values)
{
  switch (set.Mode)
  {
    case ComponentMode::LuminanceAlpha:
      return glm::dvec4(glm::dvec3(colors[0]), colors[1].a);
    case ComponentMode::RGBA:
      return glm::dvec4(glm::dvec3(values) * glm::dvec3(set.TextureScale), colors[3].a);
    case ComponentMode::Independent:
    default:
      break;
  }
  // VTK's: every component's weighted opacity sums to the total; components of weight 0 or
  // less add neither colour nor opacity; colour sum(w a c) is premultiplied by alpha.
  double total = 0.0;
  for (int i = 0; i < set.Count(); ++i)
  {
    total += colors[static_cast<size_t>(i)].a * set.Weights[i];
  }
  if (!(total > 0.0))
  {
    return glm::dvec4(0.0);
  }
  glm::dvec3 premultiplied(0.0);
  double alpha = 0.0;
  for (int i = 0; i < set.Count(); ++i)
  {
    const glm::dvec4& c = colors[static_cast<size_t>(i)];
    if (set.Weights[i] <= 0.0)
    {
      continue;
    }
    premultiplied += glm::dvec3(c) * c.a * set.Weights[i];
    alpha += c.a * c.a / total;
  }
  // Weights below 1 can push VTK's alpha past 1; kept an opacity here.
  return alpha > 0.0 ? glm::dvec4(premultiplied / alpha, std::min(alpha, 1.0)) : glm::dvec4(0.0);
}

ComponentLookup::ComponentLookup(
  const ComponentSet& set, const VolumeGrid& grid, const TransferFunction& first, double tableStep, int tableSize,
  bool uncorrected)
  : Set(set)
  , Uncorrected(uncorrected)
{
  for (int i = 0; i < set.Count(); ++i)
  {
    const TransferFunction* function = i == 0 ? &first : &set.Transfers[static_cast<size_t>(i)];
    const glm::dvec2 range = set.Grid(grid, i).GetRange();
    this->Ranges[static_cast<size_t>(i)] = range;
    this->Functions.push_back(function);
    if (tableSize > 0)
    {
      // A step of one unit distance corrects nothing.
      this->Tables.push_back(TransferTable::Sample(
        *function, range.x, range.y, tableSize, uncorrected ? function->OpacityUnitDistance : tableStep));
    }
  }
}

ComponentColors ComponentLookup::Colors(const glm::dvec4& values, double step) const
{
  ComponentColors colors{};
  for (int i = 0; i < this->Set.Count(); ++i)
  {
    const size_t c = static_cast<size_t>(i);
    const double value = this->Set.Mode == ComponentMode::RGBA && i == 3
      ? RGBAOpacityValue(this->Set, values[i], this->Ranges[c])
      : values[i];
    if (!this->Tables.empty())
    {
      colors[c] = this->Tables[c].Lookup(value);
    }
    else
    {
      const TransferFunction& f = *this->Functions[c];
      const double opacity = f.Opacity.Evaluate(value);
      colors[c] = glm::dvec4(
        f.Color(value), this->Uncorrected ? opacity : CorrectOpacity(opacity, step, f.OpacityUnitDistance));
    }
  }
  return colors;
}

}
