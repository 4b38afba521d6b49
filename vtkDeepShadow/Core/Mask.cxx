#include "Core/Mask.h"
#include "Core/OpticalModel.h"

#include <algorithm>
#include <cmath>

namespace deepshadow
{

glm::dvec2 LabelMap::LabelMapping() const
{
  const double count = static_cast<double>(this->Count());
  const double span = this->MaskRange.y - this->MaskRange.x;
  // A mask of one value: label N where it is above 0 (VTK's texture range is then 1e-6 wide).
  if (!(span > 0.0))
  {
    return { 0.0, this->MaskRange.x > 0.0 ? count : 0.0 };
  }
  // VTK reads an 8-bit mask as a fraction 256/255 too large, which keeps exact labels from
  // rounding down; a margin of 1/1000 of a label does the same here.
  return { count / span, -this->MaskRange.x * count / span + 1.0e-3 };
}

int LabelMap::LabelOf(double maskValue) const
{
  const glm::dvec2 mapping = this->LabelMapping();
  const double label = std::floor(maskValue * mapping.x + mapping.y);
  return static_cast<int>(std::clamp(label, 0.0, static_cast<double>(this->Count())));
}

LabelledSample LabelMap::Apply(const glm::dvec4& volume, double scalar, int label, double stepRatio,
  const std::vector<TransferTable>* tables) const
{
  if (label <= 0 || label > this->Count())
  {
    return { volume };
  }
  const size_t row = static_cast<size_t>(label - 1);
  glm::dvec4 own;
  if (tables)
  {
    own = (*tables)[row].Lookup(scalar);
  }
  else
  {
    const TransferFunction& f = this->Functions[row];
    own = glm::dvec4(f.Color(scalar), f.Opacity.Evaluate(scalar));
  }
  own.a = CorrectOpacity(own.a, stepRatio, 1.0); // its opacity holds for one view step
  if (this->BlendFactor >= 1.0)
  {
    return { own };
  }
  const double f = this->BlendFactor;
  const glm::dvec4 drawn = volume.a > 0.0 ? volume : glm::dvec4(0.0);
  if (own.a > 0.0)
  {
    return { (1.0 - f) * drawn + f * own };
  }
  return { (1.0 - f) * drawn, f * glm::dvec3(own) };
}

}
