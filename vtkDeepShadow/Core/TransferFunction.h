// Transfer functions as exact piecewise-linear functions of the scalar, and their GPU tables.
//
// The CPU reference evaluates PiecewiseLinear exactly (double). The GPU mapper looks up a
// table sampled from the same function (SampleTable) with linear filtering; TableLookup is
// that lookup's CPU twin, so tests can bound the table error separately from everything else.
#ifndef deepshadow_TransferFunction_h
#define deepshadow_TransferFunction_h

#include "vtkDeepShadowCoreModule.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <utility>
#include <vector>

namespace deepshadow
{

/** y(x) through sorted nodes, linear between them. Outside: end values, or 0 if !Clamp. */
class VTKDEEPSHADOWCORE_EXPORT PiecewiseLinear
{
public:
  PiecewiseLinear() = default;
  /** Nodes need not be sorted; equal x keep their given order (a step). */
  explicit PiecewiseLinear(std::vector<std::pair<double, double>> nodes, bool clamp = true);

  void AddNode(double x, double y);
  bool Empty() const { return this->Nodes.empty(); }
  const std::vector<std::pair<double, double>>& GetNodes() const { return this->Nodes; }
  bool GetClamp() const { return this->Clamp; }

  double Evaluate(double x) const;
  /** Exact maximum of the function over [lo, hi] (lo <= hi). */
  double MaxOver(double lo, double hi) const;

private:
  std::vector<std::pair<double, double>> Nodes;
  bool Clamp = true;
};

/** Colour and opacity of a scalar, as VTK's vtkVolumeProperty holds them (one component). */
struct VTKDEEPSHADOWCORE_EXPORT TransferFunction
{
  PiecewiseLinear Red, Green, Blue;
  PiecewiseLinear Opacity;
  /** World distance over which Opacity is defined (vtkVolumeProperty's unit distance). */
  double OpacityUnitDistance = 1.0;

  glm::dvec3 Color(double scalar) const;
  /** Convenience for tests: grey ramp colour, given opacity nodes. */
  static TransferFunction Grey(std::vector<std::pair<double, double>> opacityNodes);
};

/**
 * GPU table of a transfer function over [rangeMin, rangeMax]: `size` RGBA texels, texel i at
 * scalar rangeMin + i (rangeMax - rangeMin) / (size - 1); alpha is the opacity corrected for
 * `stepLength` (see CorrectOpacity), because that is what the ray caster looks up per sample.
 */
struct VTKDEEPSHADOWCORE_EXPORT TransferTable
{
  double RangeMin = 0.0;
  double RangeMax = 1.0;
  int Size = 0;
  std::vector<float> RGBA;

  static TransferTable Sample(const TransferFunction& function, double rangeMin, double rangeMax,
    int size, double stepLength);

  /** Texture coordinate of `scalar` so that texel centres hit the sampled scalars. */
  double TextureCoordinate(double scalar) const;
  /** (scale, offset) with TextureCoordinate(s) = s * scale + offset (the GPU's u_tableMap). */
  glm::dvec2 CoordinateMap() const;
  /** CPU twin of the GPU's linearly filtered lookup. */
  glm::dvec4 Lookup(double scalar) const;
};

}
#endif
