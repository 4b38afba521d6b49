// Closed-form answers for homogeneous media, shared by the CPU (Core) and GPU
// (Rendering) tests: what light gets through a body of known shape and opacity, computed
// from geometry alone and never from a renderer of this project, so that a mistake a
// technique shares with its twin still fails.
//
// A homogeneous medium of opacity `a` per `unitDistance` (vtkVolumeProperty's scalar opacity
// and ScalarOpacityUnitDistance) has extinction sigma = -ln(1 - a) / unitDistance, so a path
// of length L inside it lets through T = (1 - a)^(L / unitDistance) = exp(-sigma L)
// (Beer-Lambert). A medium of colour c lets through, per channel, exp(-sigma (1 - c) L):
// it stops (1 - c) of what it absorbs, the model of coloured shadows (paper 003).
#ifndef deepshadow_testing_ClosedForm_h
#define deepshadow_testing_ClosedForm_h

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace deepshadow
{
namespace closedform
{

/** Extinction coefficient of opacity `a` per `unitDistance`. */
inline double Extinction(double a, double unitDistance)
{
  return -std::log(1.0 - a) / unitDistance;
}

/** Beer-Lambert: what a path of `length` through the medium lets through. */
inline double Transmittance(double a, double unitDistance, double length)
{
  return std::exp(-Extinction(a, unitDistance) * length);
}

/** The same for a medium of colour `color`, per channel. */
inline glm::dvec3 ColoredTransmittance(
  double a, double unitDistance, const glm::dvec3& color, double length)
{
  return glm::exp(-Extinction(a, unitDistance) * (1.0 - color) * length);
}

/**
 * Length of the part of the segment p + s d, s in [0, maxS], that lies inside the sphere
 * (centre, radius); `d` is a unit vector.
 */
inline double SphereChord(const glm::dvec3& centre, double radius, const glm::dvec3& p,
  const glm::dvec3& d, double maxS = std::numeric_limits<double>::infinity())
{
  const glm::dvec3 m = p - centre;
  const double b = glm::dot(m, d);
  const double disc = b * b - (glm::dot(m, m) - radius * radius);
  if (disc <= 0.0)
  {
    return 0.0;
  }
  const double root = std::sqrt(disc);
  const double s0 = std::max(-b - root, 0.0), s1 = std::min(-b + root, maxS);
  return std::max(s1 - s0, 0.0);
}

/**
 * Length of the part of the segment p + s d, s in [0, maxS], inside the axis-aligned box
 * [lo, hi]; `d` is a unit vector.
 */
inline double BoxPath(const glm::dvec3& lo, const glm::dvec3& hi, const glm::dvec3& p,
  const glm::dvec3& d, double maxS = std::numeric_limits<double>::infinity())
{
  double s0 = 0.0, s1 = maxS;
  for (int axis = 0; axis < 3; ++axis)
  {
    if (d[axis] == 0.0)
    {
      if (p[axis] < lo[axis] || p[axis] > hi[axis])
      {
        return 0.0;
      }
      continue;
    }
    double a = (lo[axis] - p[axis]) / d[axis], b = (hi[axis] - p[axis]) / d[axis];
    if (a > b)
    {
      std::swap(a, b);
    }
    s0 = std::max(s0, a);
    s1 = std::min(s1, b);
  }
  return std::max(s1 - s0, 0.0);
}

/**
 * How far a discrete march of `step` may be from Beer-Lambert, relative to T: a path is
 * covered by whole samples, so it may count up to one sample more or less than its length.
 */
inline double SamplingError(double transmittance, double sigma, double step)
{
  return transmittance * (std::exp(sigma * step) - 1.0);
}

/**
 * How far the discrete coloured model, prod (1 - alpha (1 - c)) with alpha the opacity of a
 * step, lies above exp(-sigma (1 - c) L) (it does, by concavity), over a path of `length`.
 */
inline double ColoredStepError(double sigma, double step, double c, double length)
{
  const double alpha = 1.0 - std::exp(-sigma * step);
  const double discrete = 1.0 - alpha * (1.0 - c), continuous = std::exp(-sigma * (1.0 - c) * step);
  const double steps = std::ceil(length / step) + 1.0;
  return std::pow(discrete, steps) - std::pow(continuous, steps);
}

/**
 * A scalar field whose iso-surface 0.5 is the sphere (centre, radius): 1 inside, 0 outside,
 * linear in the distance across four units around the surface. Every grid cell the surface
 * crosses then lies on the ramp, away from its clamped ends, and trilinear interpolation puts
 * the surface within about (1/8)(2/radius)/4 of the sphere (a ramp one unit wide met the clamp
 * in such cells and moved the surface 0.07 unit inwards).
 */
inline float BallField(const glm::dvec3& p, const glm::dvec3& centre, double radius)
{
  return static_cast<float>(std::clamp(0.5 + 0.25 * (radius - glm::length(p - centre)), 0.0, 1.0));
}

}
}
#endif
