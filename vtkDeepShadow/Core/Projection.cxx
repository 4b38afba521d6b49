#include "Projection.h"

#include <glm/common.hpp>

#include <algorithm>

namespace deepshadow
{

namespace
{
// A ray that counted no sample (masked, outside the bound or the average's range): nothing,
// but additive's sum of nothing is opaque black, as VTK's mapper draws it.
glm::dvec4 NothingCounted(BlendMode mode)
{
  return mode == BlendMode::Additive ? glm::dvec4(0.0, 0.0, 0.0, 1.0) : glm::dvec4(0.0);
}
}

ProjectionAccumulator::ProjectionAccumulator(const ProjectionSettings& settings)
  : Settings(settings)
{
}

void ProjectionAccumulator::Add(double scalar, double opacity)
{
  const ProjectionSettings& s = this->Settings;
  switch (s.Mode)
  {
    case BlendMode::Maximum:
      this->Extreme = this->Any ? std::max(this->Extreme, scalar) : scalar;
      break;
    case BlendMode::Minimum:
      this->Extreme = this->Any ? std::min(this->Extreme, scalar) : scalar;
      break;
    case BlendMode::Average:
    case BlendMode::Additive:
    {
      if (s.Mode == BlendMode::Average && !(scalar >= s.AverageMin && scalar <= s.AverageMax))
      {
        return;
      }
      const double span = s.RangeMax > s.RangeMin ? s.RangeMax - s.RangeMin : 1.0;
      this->Sum += opacity * (scalar - s.RangeMin) / span;
      ++this->Count;
      break;
    }
    case BlendMode::Composite:
      return;
  }
  this->Any = true;
}

glm::dvec4 ProjectionAccumulator::Result(const std::function<glm::dvec4(double)>& colorOpacity) const
{
  if (!this->Any)
  {
    return NothingCounted(this->Settings.Mode);
  }
  switch (this->Settings.Mode)
  {
    case BlendMode::Maximum:
    case BlendMode::Minimum:
    {
      const glm::dvec4 c = colorOpacity(this->Extreme);
      return { c.r * c.a, c.g * c.a, c.b * c.a, c.a };
    }
    case BlendMode::Average:
    case BlendMode::Additive:
    {
      const double grey = std::clamp(
        this->Settings.Mode == BlendMode::Average ? this->Sum / static_cast<double>(this->Count) : this->Sum,
        0.0, 1.0);
      return { grey, grey, grey, 1.0 };
    }
    case BlendMode::Composite:
      break;
  }
  return glm::dvec4(0.0);
}

ComponentProjection::ComponentProjection(
  const ProjectionSettings& settings, const ComponentLookup& lookup, double step)
  : Settings(settings)
  , Lookup(lookup)
  , Step(step)
  , Independent(lookup.GetSet().Mode == ComponentMode::Independent)
{
}

double ComponentProjection::Normalized(int c, double value) const
{
  const glm::dvec2& range = this->Lookup.GetRange(c);
  const double span = range.y > range.x ? range.y - range.x : 1.0;
  return (value - range.x) / span;
}

bool ComponentProjection::Counts(double value) const
{
  return this->Settings.Mode == BlendMode::Additive ||
    (value >= this->Settings.AverageMin && value <= this->Settings.AverageMax);
}

void ComponentProjection::Add(const glm::dvec4& values)
{
  const int count = this->Lookup.GetSet().Count();
  const BlendMode mode = this->Settings.Mode;
  if (mode == BlendMode::Maximum || mode == BlendMode::Minimum)
  {
    const bool maximum = mode == BlendMode::Maximum;
    if (this->Independent)
    {
      for (int c = 0; c < count; ++c)
      {
        const double v = values[c];
        this->Extremes[c] = !this->Any ? v : maximum ? std::max(this->Extremes[c], v) : std::min(this->Extremes[c], v);
      }
    }
    else
    {
      // The whole sample whose opacity component is extreme (strictly: the first one wins).
      const int key = count - 1;
      if (!this->Any || (maximum ? values[key] > this->Extremes[key] : values[key] < this->Extremes[key]))
      {
        this->Extremes = values;
      }
    }
    this->Any = true;
    return;
  }
  if (mode != BlendMode::Average && mode != BlendMode::Additive)
  {
    return;
  }
  const ComponentColors colors = this->Lookup.Colors(values, this->Step);
  if (this->Independent)
  {
    for (int c = 0; c < count; ++c)
    {
      if (this->Counts(values[c]))
      {
        this->Sums[c] += colors[static_cast<size_t>(c)].a * this->Normalized(c, values[c]);
        this->Counted[c] += 1.0;
        this->Any = true;
      }
    }
  }
  else if (this->Counts(values[0]))
  {
    this->Sums[0] += CombineComponents(this->Lookup.GetSet(), colors, values).a * this->Normalized(0, values[0]);
    this->Counted[0] += 1.0;
    this->Any = true;
  }
}

glm::dvec4 ComponentProjection::Result() const
{
  if (!this->Any)
  {
    return NothingCounted(this->Settings.Mode);
  }
  const ComponentSet& set = this->Lookup.GetSet();
  const BlendMode mode = this->Settings.Mode;
  if (mode == BlendMode::Maximum || mode == BlendMode::Minimum)
  {
    const ComponentColors colors = this->Lookup.Colors(this->Extremes, this->Step);
    if (!this->Independent)
    {
      const glm::dvec4 c = CombineComponents(set, colors, this->Extremes);
      return { c.r * c.a, c.g * c.a, c.b * c.a, c.a };
    }
    // Summed with every weight (VTK's), kept within what a pixel holds.
    glm::dvec4 sum(0.0);
    for (int c = 0; c < set.Count(); ++c)
    {
      const glm::dvec4& color = colors[static_cast<size_t>(c)];
      sum += set.Weights[c] * color.a * glm::dvec4(glm::dvec3(color), 1.0);
    }
    return glm::clamp(sum, 0.0, 1.0);
  }
  double grey = 0.0;
  for (int c = 0; c < (this->Independent ? set.Count() : 1); ++c)
  {
    if (this->Counted[c] > 0.0)
    {
      const double weight = this->Independent ? set.Weights[c] : 1.0;
      grey += weight * (mode == BlendMode::Average ? this->Sums[c] / this->Counted[c] : this->Sums[c]);
    }
  }
  grey = std::clamp(grey, 0.0, 1.0);
  return { grey, grey, grey, 1.0 };
}

}
