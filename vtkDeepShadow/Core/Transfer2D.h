// 2D transfer functions (vtkVolumeProperty::SetTransferFunctionMode(TF_2D)) as VTK 9.1's GPU
// mapper reads them, under composite blending, one component: an RGBA float image whose x axis
// is the scalar over the data's range and whose y axis is the gradient magnitude VTK measures
// (GradientOpacity::Magnitude) over a quarter of that range; colour and opacity both come
// from it, the opacity as given for a sample (not corrected for the step, as VTK's), and the
// colour is lit. VTK resizes the image to its texture (at least 1024 texels an axis, one row
// when the image has one), corners aligned; the lookup reads the image where that texture
// would be read, interpolating linearly (VTK's Lanczos resize is not copied). The CPU twin of
// Rendering/Shaders/Features/Transfer2D.glsl. Shadows are cast by what is drawn: a light ray's
// step of s view steps sees an opacity a as 1 - (1 - a)^s.
#ifndef deepshadow_Transfer2D_h
#define deepshadow_Transfer2D_h

#include "Core/GradientOpacity.h"
#include "Core/VolumeGrid.h"
#include "vtkDeepShadowCoreModule.h"

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <vector>

namespace deepshadow
{

struct VTKDEEPSHADOWCORE_EXPORT Transfer2D
{
  int Width = 0;
  int Height = 0;
  std::vector<float> RGBA; // Width x Height texels, rows of increasing gradient
  glm::dvec2 Range{ 0.0, 1.0 }; // the data's finite range: the scalar axis
  GradientOpacity Gradient;     // how the gradient axis is measured (its Function is unused)

  /** The texel extent VTK's texture gives an image axis of `size` texels. */
  static int TextureSize(int size, bool gradientAxis);
  /**
   * (scale, offset) per axis: the position in the image (texel units, centres at integers) of
   * a normalized scalar (xy) and magnitude (zw), before clamping to the image.
   */
  glm::dvec4 ImageMap() const;
  /** Colour and opacity at data value `scalar` of gradient magnitude `magnitude`. */
  glm::dvec4 Lookup(double scalar, double magnitude) const;
  /** The same for the sample at continuous voxel index `index` of `grid`, of value `scalar`. */
  glm::dvec4 At(const VolumeGrid& grid, const glm::dvec3& index, Interpolation sampling, double scalar) const
  {
    return this->Lookup(scalar, this->Gradient.Magnitude(grid, index, sampling));
  }
};

}
#endif
