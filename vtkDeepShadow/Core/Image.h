// Linear-RGB images in double precision, and the error measures every report uses.
#ifndef deepshadow_Image_h
#define deepshadow_Image_h

#include "vtkDeepShadowCoreModule.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace deepshadow
{

/** RGB image, rows bottom to top (OpenGL and vtkImageData order), values nominally [0, 1]. */
struct VTKDEEPSHADOWCORE_EXPORT Image
{
  int Width = 0;
  int Height = 0;
  std::vector<double> RGB;

  Image() = default;
  Image(int width, int height)
    : Width(width)
    , Height(height)
    , RGB(3 * static_cast<size_t>(width) * height, 0.0)
  {
  }

  glm::dvec3 At(int x, int y) const
  {
    const size_t i = 3 * (static_cast<size_t>(y) * this->Width + x);
    return { this->RGB[i], this->RGB[i + 1], this->RGB[i + 2] };
  }
  void Set(int x, int y, const glm::dvec3& c)
  {
    const size_t i = 3 * (static_cast<size_t>(y) * this->Width + x);
    this->RGB[i] = c.r;
    this->RGB[i + 1] = c.g;
    this->RGB[i + 2] = c.b;
  }

  /** From 8-bit RGB or RGBA pixels (bottom row first). */
  static Image FromBytes(const uint8_t* pixels, int width, int height, int components);
  /** To 8-bit RGB, rounding and clamping each channel. */
  std::vector<uint8_t> ToBytes() const;
};

struct ImageDifference
{
  double RMSE = 0.0;       // over all channels of all pixels
  double MaxAbs = 0.0;     // largest channel difference
  double MeanAbs = 0.0;
  /** Share of pixels with some channel differing by more than `threshold` (see Compare). */
  double FractionAbove = 0.0;
};

/** Channel-wise comparison of equally sized images; `threshold` defines FractionAbove. */
VTKDEEPSHADOWCORE_EXPORT ImageDifference Compare(
  const Image& a, const Image& b, double threshold = 0.0);

/** |a - b| per channel, scaled by `gain` and clamped (for looking at differences). */
VTKDEEPSHADOWCORE_EXPORT Image AbsoluteDifference(const Image& a, const Image& b, double gain);

}
#endif
