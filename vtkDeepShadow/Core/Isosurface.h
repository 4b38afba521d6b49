// Isosurface blending (VTK's ISOSURFACE_BLEND), the CPU twin of
// Rendering/Shaders/Features/Isosurface.glsl. A ray shows a surface where its scalar crosses
// one of the property's contour values between two samples, with the transfer function's
// colour and its opacity, uncorrected, at that value; shaded at the sample after the crossing.
// As in VTK's mapper: the first sample of a ray only finds where it starts among the values,
// and one crossing counts per step at most (a ray that jumps over several contours in one step
// shows the next ones at the samples after).
//
// Shadows: the light's rays meet the same crossings, each letting through 1 - its opacity, so
// every technique sees the surfaces as what casts. A view sample that shows a surface receives
// light from the sample before it (the viewer's side of the surface), moved
// IsoReceiverOffset towards the light: there the surface itself is not between the receiver
// and a light it faces, and a map's depths, which step from lit to shadowed within a feeler
// step of the surface, do not shadow it at its own depth (acne). A surface that faces away
// from the light moves into its solid and stays shadowed by it.
#ifndef deepshadow_Isosurface_h
#define deepshadow_Isosurface_h

#include "vtkDeepShadowCoreModule.h" // For export macro

#include <cmath>
#include <vector>

namespace deepshadow
{

/** At most this many contour values are drawn (the lowest ones; the shaders' array size). */
constexpr int MaxIsoValues = 16;

/** World distance towards the light at which a surface receives (two feeler steps). */
inline double IsoReceiverOffset(double feelerStep)
{
  return 2.0 * feelerStep;
}

/** The crossings of one ray, sample by sample. */
class VTKDEEPSHADOWCORE_EXPORT IsoCrossings
{
public:
  /**
   * `values`: the contour values, sorted (not owned). Null: no isosurface blending, and
   * Next() hands every scalar back.
   */
  explicit IsoCrossings(const std::vector<double>* values)
    : Values(values)
  {
  }

  /** The contour crossed since the previous sample, or NoCrossing(); without values, `scalar`. */
  double Next(double scalar);

  static double NoCrossing() { return std::nan(""); }
  static bool IsCrossing(double value) { return !std::isnan(value); }

private:
  const std::vector<double>* Values;
  long Interval = -1; // values at or below the previous sample; -1: no sample yet
};

}
#endif
