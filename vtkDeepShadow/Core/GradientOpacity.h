// Gradient opacity (vtkVolumeProperty::SetGradientOpacity) as VTK's GPU mapper applies it under
// composite blending: a sample's opacity, corrected for the step, times the function of its
// gradient magnitude. VTK measures that magnitude by central differences one voxel apart, each
// axis in data units per mean spacing (the dataset's spacing, not the prop's scale), and clamps
// it to a quarter of the data's range. The CPU twin of
// Rendering/Shaders/Features/GradientOpacity.glsl. Shadows are cast with it too: what it
// leaves transparent casts nothing (ShadowCaster::Gradient).
#ifndef deepshadow_GradientOpacity_h
#define deepshadow_GradientOpacity_h

#include "Core/TransferFunction.h"
#include "Core/VolumeGrid.h"
#include "vtkDeepShadowCoreModule.h" // For export macro

#include <glm/vec3.hpp>

namespace deepshadow
{

struct VTKDEEPSHADOWCORE_EXPORT GradientOpacity
{
  PiecewiseLinear Function;
  /** A quarter of the data's scalar range (VTK's largest magnitude; 1 for a flat range). */
  double MaxMagnitude = 1.0;
  /** Per index axis: the mean of the dataset's spacings over that axis' spacing. */
  glm::dvec3 IndexScale{ 1.0 };

  /** For data of this range and spacing. */
  static GradientOpacity For(const PiecewiseLinear& function, const glm::dvec2& range,
    const glm::dvec3& spacing);

  /** The gradient magnitude VTK measures at continuous voxel index `index`, clamped. */
  double Magnitude(const VolumeGrid& grid, const glm::dvec3& index, Interpolation sampling) const;
  /** The factor the sample's opacity is multiplied by. */
  double Factor(const VolumeGrid& grid, const glm::dvec3& index, Interpolation sampling) const
  {
    return this->Function.Evaluate(this->Magnitude(grid, index, sampling));
  }
};

}
#endif
