#include "Projection.h"

#include <algorithm>

namespace deepshadow
{

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
    return glm::dvec4(0.0);
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

}
