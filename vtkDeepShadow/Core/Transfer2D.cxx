#include "Core/Transfer2D.h"

#include <algorithm>
#include <cmath>

namespace deepshadow
{

int Transfer2D::TextureSize(int size, bool gradientAxis)
{
  if (gradientAxis && size <= 1)
  {
    return 1;
  }
  int texels = 1024;
  while (texels < size)
  {
    texels *= 2;
  }
  return texels;
}

glm::dvec4 Transfer2D::ImageMap() const
{
  // Normalized t reads texel t W - 0.5 of the W-texel texture, which spans the image's
  // corners: image position (t W - 0.5) (size - 1) / (W - 1).
  auto axis = [](int size, int texels) {
    if (texels <= 1 || size <= 1)
    {
      return glm::dvec2(0.0, 0.0);
    }
    const double stretch = (size - 1.0) / (texels - 1.0);
    return glm::dvec2(texels * stretch, -0.5 * stretch);
  };
  const glm::dvec2 x = axis(this->Width, TextureSize(this->Width, false));
  const glm::dvec2 y = axis(this->Height, TextureSize(this->Height, true));
  return { x.x, x.y, y.x, y.y };
}

glm::dvec4 Transfer2D::Lookup(double scalar, double magnitude) const
{
  if (this->Width < 1 || this->Height < 1)
  {
    return glm::dvec4(0.0);
  }
  const double span = this->Range.y > this->Range.x ? this->Range.y - this->Range.x : 1.0;
  const double s = std::clamp((scalar - this->Range.x) / span, 0.0, 1.0);
  const double g = std::clamp(magnitude / this->Gradient.MaxMagnitude, 0.0, 1.0);
  const glm::dvec4 map = this->ImageMap();
  const double x = std::clamp(s * map.x + map.y, 0.0, this->Width - 1.0);
  const double y = std::clamp(g * map.z + map.w, 0.0, this->Height - 1.0);
  const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
  const int x1 = std::min(x0 + 1, this->Width - 1), y1 = std::min(y0 + 1, this->Height - 1);
  const double fx = x - x0, fy = y - y0;
  auto texel = [this](int i, int j) {
    const float* t = &this->RGBA[4 * (static_cast<size_t>(i) + static_cast<size_t>(this->Width) * j)];
    return glm::dvec4(t[0], t[1], t[2], t[3]);
  };
  return (1.0 - fy) * ((1.0 - fx) * texel(x0, y0) + fx * texel(x1, y0)) +
    fy * ((1.0 - fx) * texel(x0, y1) + fx * texel(x1, y1));
}

}
