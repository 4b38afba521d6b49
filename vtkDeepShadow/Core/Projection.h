// The blend modes that project the samples of a ray instead of compositing them, as VTK's GPU
// mapper draws them: maximum and minimum intensity (the colour and opacity of the extreme
// scalar), average intensity and additive (grey: the mean, or the sum, of opacity x scalar,
// scalars normalized over the data's range). The CPU twin of
// Rendering/Shaders/Features/Projection.glsl. Opacities are the transfer function's own,
// except for additive blending, where VTK's mapper sums opacities corrected for the sample
// distance (measured against it: at steps of 0.5 and 0.25 units, uncorrected sums came out
// 2 and 4 times VTK's).
//
// Several components (ComponentProjection), as VTK 9.1's shader projects them:
//   - independent: each component keeps its own extreme (or sum); maximum and minimum give
//     colour sum(w_c a_c c_c) and opacity sum(w_c a_c) at the components' extremes; average
//     and additive give grey sum(w_c S_c), S_c a component's mean (or sum) of opacity x
//     normalized value, components that counted nothing left out;
//   - dependent (luminance + opacity, RGBA): the extremes keep the whole sample whose opacity
//     component (the last) is extreme, drawn as one sample is; average and additive sum
//     component 0 weighted by the sample's opacity.
// Two of VTK 9.1's ways are not followed (its shader's slips, Documentation/VolumeMapper.md says where):
// minimum intensity over independent components keeps each component's maximum and writes
// its opacity into blue (here: each component's minimum, opacity as for the maximum); over
// luminance + opacity VTK compares a channel the texture does not have and keeps the ray's
// first sample (here: the sample of extreme opacity component, as for RGBA).
#ifndef deepshadow_Projection_h
#define deepshadow_Projection_h

#include "Core/Components.h"
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

/** One ray's projection of a volume of several components (see above). */
class VTKDEEPSHADOWCORE_EXPORT ComponentProjection
{
public:
  /**
   * `lookup`: each component's colour and opacity (its opacities corrected for `step` only
   * for additive blending); it must outlive this.
   */
  ComponentProjection(const ProjectionSettings& settings, const ComponentLookup& lookup, double step);

  /** A sample: its components' data values. */
  void Add(const glm::dvec4& values);

  /** The pixel, premultiplied (none when no sample counted). */
  glm::dvec4 Result() const;

private:
  /** Component c's value over its range, in [0, 1] where the value lies in the range. */
  double Normalized(int c, double value) const;
  bool Counts(double value) const;

  ProjectionSettings Settings;
  const ComponentLookup& Lookup;
  double Step;
  bool Independent;
  glm::dvec4 Extremes{ 0.0 };
  glm::dvec4 Sums{ 0.0 };
  glm::dvec4 Counted{ 0.0 };
  bool Any = false;
};

}
#endif
