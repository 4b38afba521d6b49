// The blend modes that project the samples of a ray instead of compositing them, as VTK's GPU
// mapper draws them: maximum and minimum intensity (the colour and opacity of the extreme
// scalar), average intensity and additive (grey: the mean, or the sum, of opacity x scalar,
// scalars normalized over the data's range). The CPU twin of
// Rendering/Shaders/Features/Projection.glsl. Opacities are the transfer function's own,
// except for additive blending, where VTK's mapper sums opacities corrected for the sample
// distance (measured against it: at steps of 0.5 and 0.25 units, uncorrected sums came out
// 2 and 4 times VTK's).
#ifndef deepshadow_Projection_h
#define deepshadow_Projection_h

#include "vtkDeepShadowCoreModule.h" // For export macro

#include <glm/vec4.hpp>

#include <functional>

namespace deepshadow
{

enum class BlendMode
{
  Composite,
  Maximum,
  Minimum,
  Average,
  Additive
};

struct ProjectionSettings
{
  BlendMode Mode = BlendMode::Composite;
  /** The data's scalar range: scalars are normalized over it (as VTK's in_scalarsRange). */
  double RangeMin = 0.0;
  double RangeMax = 1.0;
  /** Average intensity counts only scalars in [AverageMin, AverageMax] (VTK's AverageIPScalarRange). */
  double AverageMin = -1e300;
  double AverageMax = 1e300;

  /** Whether the opacities summed are corrected for the sample distance (additive, as VTK). */
  bool CorrectsOpacity() const { return this->Mode == BlendMode::Additive; }
};

/** One ray's projection: Add() every sample taken, then Result(). */
class VTKDEEPSHADOWCORE_EXPORT ProjectionAccumulator
{
public:
  explicit ProjectionAccumulator(const ProjectionSettings& settings);

  /** A sample: its scalar and the (uncorrected) opacity of that scalar. */
  void Add(double scalar, double opacity);

  /**
   * The pixel, premultiplied: for the extremes, `colorOpacity` of the extreme scalar (RGB,
   * opacity); for average and additive, grey with opacity 1 (none when no sample counted).
   */
  glm::dvec4 Result(const std::function<glm::dvec4(double)>& colorOpacity) const;

private:
  ProjectionSettings Settings;
  double Extreme = 0.0;
  bool Any = false;
  double Sum = 0.0;
  long Count = 0;
};

}
#endif
