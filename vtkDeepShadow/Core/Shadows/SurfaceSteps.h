// The casting meshes of a light-space technique whose representation of the volume would
// smear a mesh's sharp crossing (opacity levels, Fourier opacity maps, adaptive volumetric
// shadow maps): the meshes' crossings are kept beside it as at most two steps, and the
// visibility is the product of both (transmittances multiply in any order), exact behind the
// volume and at every mesh that is one of at most two steps. GLSL twins:
// Shaders/Shadows/SurfaceStepsBuild.glsl and SurfaceSteps.glsl.
#ifndef deepshadow_SurfaceSteps_h
#define deepshadow_SurfaceSteps_h

#include "Core/Shadows/LightSpace.h"
#include "vtkDeepShadowCoreModule.h"

#include <array>
#include <functional>

namespace deepshadow
{

/**
 * The casting meshes along a texel's ray as at most two steps: the visibility is 1 before
 * Depths[0], Transmittance[0] from there, Transmittance[1] from Depths[1] on (NoHit: no
 * step). Crossings are added in depth order; when a third step comes, the most transparent
 * of the last two is folded into the step before it (its transmission then counts from that
 * earlier depth): a glass's back face into its front, a glass into the one before it, never
 * an opaque ground (the most opaque step stays where it is).
 */
struct SurfaceSteps
{
  std::array<float, 2> Depths{ { NoHit, NoHit } };
  std::array<float, 2> Transmittance{ { 1.0f, 1.0f } };
};

/** Adds a crossing at `depth` that lets through `transmission` (see SurfaceSteps). */
class VTKDEEPSHADOWCORE_EXPORT SurfaceStepsBuilder
{
public:
  void Add(double depth, double transmission);
  /** Everything the steps let through so far. */
  double Transmittance() const;
  SurfaceSteps Finish() const;

private:
  // Up to three steps: depth and what each lets through on its own.
  std::array<double, 3> Depth{ {} };
  std::array<double, 3> Own{ {} };
  int Count = 0;
};

/** The steps' visibility at `depth`. */
VTKDEEPSHADOWCORE_EXPORT double EvaluateSurfaceSteps(const SurfaceSteps& steps, double depth);

/**
 * Marches a texel's ray (MarchTexelRay over `march`, the face's caster) for such a technique:
 * visit(t, opacity, skipped, volume) sees every sample (opacity 0 where skipped) with the
 * volume's transmittance after it, the meshes' crossings go into `steps`, and the ray stops
 * below 1/512 of what the volume and the meshes let through together, like feelers.
 * `caster` gives the samples' opacity and the meshes' materials.
 */
VTKDEEPSHADOWCORE_EXPORT void MarchBesideSurfaceSteps(const ShadowCaster& march, const ShadowCaster& caster,
  const glm::dvec3& origin, const glm::dvec3& direction, double step, SurfaceStepsBuilder& steps,
  const std::function<void(double t, double opacity, bool skipped, double volume)>& visit);

}
#endif
