// Fourier opacity maps (Jansen and Bavoil, "Fourier Opacity Mapping", I3D 2010), CPU twin: a
// rival of the deep shadow map at a fixed number of bits per texel. Along each texel's ray
// the volume's extinction is a function of normalized depth x = t / End in [0, 1); the map
// keeps its mean (the total optical depth) and its first N cosine-sine pairs. The optical
// depth up to x is the series integrated,
//   tau(x) = Total x + sum_k A_k sin(2 pi k x) + B_k (1 - cos(2 pi k x)),
// with A_k, B_k the coefficients already divided by 2 pi k, and the visibility exp(-tau),
// tau clamped to [0, Total] (a truncated series rings around sharp fronts; the clamp keeps
// it a transmittance). Each sample is a piece of constant extinction over its step: its
// coefficients are those of a point at its centre times sinc(k step / End), one factor for
// the whole texel since every sample has the same step. End is the ray's exit from the
// volume's box plus one step, per texel, so that no sample wraps around the period.
//
// A truncated series also rings in front of the medium, where nothing absorbs: the depth
// of the first absorbing sample's start, First, makes tau 0 before it. It rides in End's 12
// lowest mantissa bits, as a fraction of End in 4095ths rounded down (End is rounded up to
// a multiple of 4096 ulps first, which costs nothing: any End past the last sample serves).
//
// One texel is 2 + 2N floats, in RGBA layers: End (with First), Total, A_1, B_1, A_2, B_2,
// ...; N = 1, 3, 7 or 15 pairs fill 1, 2, 4 or 8 layers (128 to 1024 bits). Casting meshes are steps, not
// extinction (their sharp crossing would ring): one more layer of SurfaceSteps, as opacity
// levels keep them. Grey only; bilinear across the four nearest texels; rays stop below 1/512
// of what the volume and the meshes let through together, like feelers.
// GLSL twins: Shaders/Shadows/FourierOpacityMapBuild.glsl and FourierOpacityMap.glsl.
#ifndef deepshadow_FourierOpacityMap_h
#define deepshadow_FourierOpacityMap_h

#include "Core/Shadows/LightSpace.h"
#include "Core/Shadows/SurfaceSteps.h"
#include "vtkDeepShadowCoreModule.h"

#include <vector>

namespace deepshadow
{

/** The registry's kind of Fourier opacity maps ("fom"). */
constexpr ShadowKind FourierOpacityKind = ShadowKind(7);

/** The fom-terms parameter: cosine-sine pairs per texel (ShadowParameters::Extra). */
VTKDEEPSHADOWCORE_EXPORT int FourierTerms(const ShadowParameters& parameters);

/** RGBA layers of one texel's series for `terms` pairs: (2 + 2 terms) / 4. */
inline int FourierLayers(int terms)
{
  return (2 + 2 * terms + 3) / 4;
}

/**
 * A sample's optical depth from its opacity, as the series of fom and moments add it: an
 * opaque sample counts as 1/1024 let through (the ray stops after it anyway), so that the
 * series stays finite.
 */
VTKDEEPSHADOWCORE_EXPORT double SampleOpticalDepth(double opacity);

/** End rounded up to a float whose 12 lowest mantissa bits are free (for First). */
VTKDEEPSHADOWCORE_EXPORT float FourierEnd(double end);
/** The stored End: `end` (a FourierEnd) with `first` in its 12 lowest bits. */
VTKDEEPSHADOWCORE_EXPORT float PackFourierEnd(float end, double first);
/** End and First from a stored End. */
VTKDEEPSHADOWCORE_EXPORT void UnpackFourierEnd(float stored, double& end, double& first);

/** Accumulates one texel's series, sample by sample. */
class VTKDEEPSHADOWCORE_EXPORT FourierSeriesBuilder
{
public:
  /** A series of `terms` pairs over depths [0, end) (a FourierEnd) of samples `step` long. */
  FourierSeriesBuilder(int terms, double end, double step);
  /** Optical depth `tau` spread evenly over the sample centred at `depth`. */
  void Add(double depth, double tau);
  /** End, Total, A_1, B_1, ... as the map stores them (floats, padded to whole layers). */
  std::vector<float> Finish() const;

private:
  int Terms;
  double End;
  double Step;
  double First = 0.0; // where the first absorbing sample starts
  double Total = 0.0;
  std::vector<double> Sums; // sum of tau cos(2 pi k x), sum of tau sin(2 pi k x), k = 1, 2, ...
};

/** tau(depth) of a stored series (see the header), clamped to [0, Total]. */
VTKDEEPSHADOWCORE_EXPORT double FourierOpticalDepth(const float* series, int terms, double depth);

class VTKDEEPSHADOWCORE_EXPORT FourierOpacityMap : public LightSpaceShadow
{
public:
  FourierOpacityMap(const ShadowParameters& parameters, const ShadowCaster& caster,
    const Light& light, double step, int threads);
  /** As the GPU stores it: the series' layers, and one of steps with casting meshes. */
  size_t Bytes() const override
  {
    return (this->Series.size() + this->Steps.size() * 4) * sizeof(float);
  }

protected:
  glm::dvec3 MapVisibility(const MapPoint& point) const override;

private:
  int Terms;
  int Floats; // per texel: 4 per layer
  std::vector<float> Series;
  std::vector<SurfaceSteps> Steps; // per texel, when meshes cast; else empty
};

}
#endif
