#include "Core/Image.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace deepshadow
{

Image Image::FromBytes(const uint8_t* pixels, int width, int height, int components)
{
  Image image(width, height);
  for (size_t p = 0; p < static_cast<size_t>(width) * height; ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      image.RGB[3 * p + c] = pixels[components * p + c] / 255.0;
    }
  }
  return image;
}

std::vector<uint8_t> Image::ToBytes() const
{
  std::vector<uint8_t> bytes(this->RGB.size());
  for (size_t i = 0; i < this->RGB.size(); ++i)
  {
    const double v = std::isfinite(this->RGB[i]) ? this->RGB[i] : 0.0;
    bytes[i] = static_cast<uint8_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
  }
  return bytes;
}

ImageDifference Compare(const Image& a, const Image& b, double threshold)
{
  if (a.Width != b.Width || a.Height != b.Height)
  {
    throw std::invalid_argument("Compare: images differ in size");
  }
  ImageDifference d;
  double sumSquares = 0.0, sumAbs = 0.0;
  size_t above = 0;
  const size_t pixels = static_cast<size_t>(a.Width) * a.Height;
  for (size_t p = 0; p < pixels; ++p)
  {
    double pixelMax = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      const double e = std::abs(a.RGB[3 * p + c] - b.RGB[3 * p + c]);
      sumSquares += e * e;
      sumAbs += e;
      pixelMax = std::max(pixelMax, e);
    }
    d.MaxAbs = std::max(d.MaxAbs, pixelMax);
    above += pixelMax > threshold ? 1 : 0;
  }
  const double n = std::max<size_t>(1, 3 * pixels);
  d.RMSE = std::sqrt(sumSquares / n);
  d.MeanAbs = sumAbs / n;
  d.FractionAbove = pixels ? static_cast<double>(above) / pixels : 0.0;
  return d;
}

Image AbsoluteDifference(const Image& a, const Image& b, double gain)
{
  Image d(a.Width, a.Height);
  for (size_t i = 0; i < d.RGB.size() && i < b.RGB.size(); ++i)
  {
    d.RGB[i] = std::min(1.0, gain * std::abs(a.RGB[i] - b.RGB[i]));
  }
  return d;
}

}
