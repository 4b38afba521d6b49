// Power-moment transmittance ("moments"; moment-based order-independent transparency,
// Muenstermann, Krumpen, Klein and Peters, I3D 2018, after moment shadow mapping, Peters and
// Klein 2015), CPU twin: a rival of the deep shadow map at a fixed number of bits per texel.
// Along each texel's ray the volume's optical depth is a distribution over normalized depth
// z = 2 t / End - 1 in [-1, 1); the map keeps its total b0 and its first M power moments
// b_k = (1 / b0) sum tau z^k (each sample a box one step wide, whose moments are exact). The
// lookup reconstructs how much of b0 lies in front of a depth from the moments alone: the
// moments are biased a little towards those of the uniform distribution (which keeps their
// Hankel matrix invertible in float), the point's depth and the N = M / 2 roots of the kernel
// polynomial (H c = (1, z, ..., z^N)) are the support of a distribution with those moments,
// and the absorbed fraction is the integral of the polynomial through 1 at the roots in front
// of z, 0 behind it and Overestimation at z itself (0 would be the lower bound). T = exp(-b0 F).
//
// The ray's end and the first absorbing sample's start ride in one float, as the Fourier
// opacity map keeps them (FourierEnd, PackFourierEnd): 0 in front of the medium, b0 past End.
// One texel is 2 + M floats, in RGBA layers: End (with First), b0, b_1, ..., b_M; M = 2, 4
// or 6 moments fill 1, 2 or 2 layers (128 to 256 bits). Casting meshes are steps beside it
// (SurfaceSteps, one more layer). Grey only; bilinear across the four nearest texels; rays
// stop below 1/512 of what the volume and the meshes let through together, like feelers.
// GLSL twins: Shaders/Shadows/PowerMomentMapBuild.glsl and PowerMomentMap.glsl.
#ifndef deepshadow_PowerMomentMap_h
#define deepshadow_PowerMomentMap_h

#include "Core/Shadows/LightSpace.h"
#include "Core/Shadows/SurfaceSteps.h"
#include "vtkDeepShadowCoreModule.h"

#include <vector>

namespace deepshadow
{

/** The registry's kind of power-moment maps ("moments"). */
constexpr ShadowKind PowerMomentKind = ShadowKind(11);

/** The moments parameter: power moments per texel, 2, 4 or 6 (ShadowParameters::Extra). */
VTKDEEPSHADOWCORE_EXPORT int PowerMomentCount(const ShadowParameters& parameters);

/** RGBA layers of one texel for `moments` moments: (2 + moments) / 4, rounded up. */
inline int PowerMomentLayers(int moments)
{
  return (2 + moments + 3) / 4;
}

/** The bias towards the uniform distribution's moments, per moment count (measured). */
VTKDEEPSHADOWCORE_EXPORT double PowerMomentBias(int moments);
/** The weight of the point's own depth in the absorbed fraction (0: the lower bound). */
constexpr double PowerMomentOverestimation = 0.25;

/** Accumulates one texel's moments, sample by sample. */
class VTKDEEPSHADOWCORE_EXPORT PowerMomentBuilder
{
public:
  /** `moments` moments over depths [0, end) (a FourierEnd) of samples `step` long. */
  PowerMomentBuilder(int moments, double end, double step);
  /** Optical depth `tau` spread evenly over the sample centred at `depth`. */
  void Add(double depth, double tau);
  /** End (with First), b0, b_1, ... as the map stores them (floats, padded to whole layers). */
  std::vector<float> Finish() const;

private:
  int Moments;
  double End;
  double Step;
  double First = 0.0; // where the first absorbing sample starts
  double Total = 0.0;
  std::vector<double> Sums; // sum of tau times the box's k-th moment, k = 1, 2, ...
};

/**
 * The fraction of a distribution on [-1, 1] that lies in front of `z`, from its normalized
 * moments b_1 ... b_M (`b`, M = `moments`), biased by PowerMomentBias; in [0, 1].
 */
VTKDEEPSHADOWCORE_EXPORT double PowerMomentFractionBefore(const double* b, int moments, double z);

/** The optical depth at `depth` of a stored texel (see the header). */
VTKDEEPSHADOWCORE_EXPORT double PowerMomentOpticalDepth(const float* texel, int moments, double depth);

class VTKDEEPSHADOWCORE_EXPORT PowerMomentMap : public LightSpaceShadow
{
public:
  PowerMomentMap(const ShadowParameters& parameters, const ShadowCaster& caster, const Light& light,
    double step, int threads);
  /** As the GPU stores it: the moments' layers, and one of steps with casting meshes. */
  size_t Bytes() const override
  {
    return (this->Texels.size() + this->Steps.size() * 4) * sizeof(float);
  }

protected:
  glm::dvec3 MapVisibility(const MapPoint& point) const override;

private:
  int Moments;
  int Floats; // per texel: 4 per layer
  std::vector<float> Texels;
  std::vector<SurfaceSteps> Steps; // per texel, when meshes cast; else empty
};

}
#endif
