// Internal to DeepShadow::Scenes: what the standard scene generators share. The volumes are
// built from deterministic blocks only, so that every machine gets the same bytes; each scene
// family has its own file (StandardSceneShapes, StandardSceneClouds, StandardSceneHead).
#ifndef deepshadow_StandardSceneVoxels_h
#define deepshadow_StandardSceneVoxels_h

#include "Core/Jitter.h"

#include "vtkSMPTools.h"
#include "vtkType.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace deepshadow
{
namespace scenes
{
//------------------------------------------------------------------------------
// Deterministic building blocks. The voxel path uses only correctly rounded IEEE 754
// operations (+, -, *, /, sqrt) and exact ones (floor, fabs, fmod, ldexp, min, max): they give
// the same bits everywhere, unlike libm's exp, sin or atan2.

// Hashes: Core's PcgHash (Jitter.h), the one the jitter uses on the CPU and the GPU.
inline uint32_t Hash3(int x, int y, int z, uint32_t seed)
{
  return PcgHash(seed +
    PcgHash(static_cast<uint32_t>(x) +
      PcgHash(static_cast<uint32_t>(y) + PcgHash(static_cast<uint32_t>(z)))));
}

// Uniform in [0, 1) from the top 24 bits.
inline double HashUnit(uint32_t h)
{
  return static_cast<double>(h >> 8) * (1.0 / 16777216.0);
}

// exp(x) from a Cody-Waite reduction and a Taylor polynomial: within about one ulp of
// std::exp, and bit-identical on every machine.
inline double DetExp(double x)
{
  if (x < -700.0)
  {
    return 0.0;
  }
  x = std::min(x, 700.0);
  const double k = std::floor(x * 1.4426950408889634 + 0.5);
  const double r = (x - k * 6.93147180369123816490e-01) - k * 1.90821492927058770002e-10;
  double p = 1.0;
  for (int n = 13; n >= 1; --n)
  {
    p = 1.0 + p * r / n;
  }
  return std::ldexp(p, static_cast<int>(k));
}

inline double Clamp(double x, double lo, double hi)
{
  return x < lo ? lo : (x > hi ? hi : x);
}

inline double Clamp01(double x)
{
  return Clamp(x, 0.0, 1.0);
}

// Squared distance from p to the segment a-b.
inline double SegmentDistanceSquared(const double p[3], const double a[3], const double b[3])
{
  double e[3], q[3], ee = 0.0, qe = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    e[c] = b[c] - a[c];
    q[c] = p[c] - a[c];
    ee += e[c] * e[c];
    qe += q[c] * e[c];
  }
  const double t = Clamp01(qe / ee);
  double d2 = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    d2 += (q[c] - t * e[c]) * (q[c] - t * e[c]);
  }
  return d2;
}

inline double Lerp(double a, double b, double t)
{
  return a + (b - a) * t;
}

inline double SmoothStep(double e0, double e1, double x)
{
  const double t = Clamp01((x - e0) / (e1 - e0));
  return t * t * (3.0 - 2.0 * t);
}

// Polynomial smooth minimum (blends two distance fields over a width k).
inline double SMin(double a, double b, double k)
{
  const double h = std::max(k - std::fabs(a - b), 0.0) / k;
  return std::min(a, b) - h * h * k * 0.25;
}

// Value noise in [0, 1): trilinear interpolation of hashed lattice values, smoothstep fade.
inline double ValueNoise(double x, double y, double z, uint32_t seed)
{
  const double fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
  const int ix = static_cast<int>(fx), iy = static_cast<int>(fy), iz = static_cast<int>(fz);
  const double tx = SmoothStep(0.0, 1.0, x - fx);
  const double ty = SmoothStep(0.0, 1.0, y - fy);
  const double tz = SmoothStep(0.0, 1.0, z - fz);
  double c[2][2];
  for (int b = 0; b < 2; ++b)
  {
    for (int a = 0; a < 2; ++a)
    {
      c[b][a] = Lerp(HashUnit(Hash3(ix, iy + a, iz + b, seed)),
        HashUnit(Hash3(ix + 1, iy + a, iz + b, seed)), tx);
    }
  }
  return Lerp(Lerp(c[0][0], c[0][1], ty), Lerp(c[1][0], c[1][1], ty), tz);
}

// Rounds to the nearest integer and clamps to the range of T.
template <typename T>
inline T Quantize(double v, double lo, double hi)
{
  return static_cast<T>(std::floor(Clamp(v, lo, hi) + 0.5));
}

//------------------------------------------------------------------------------
// A scene's size and look, as specified at resolution scale 1 (vtkDeepShadowStandardScene.cxx
// holds the table).
struct SceneSpec
{
  const char* Name;
  const char* Description;
  int Dims[3];
  double Spacing[3];
  int ScalarType;
  double Background;
  // Views as azimuth/elevation in degrees: azimuth 0 looks from -y, positive turns towards +x.
  double CameraAzimuth, CameraElevation;
  double LightAzimuth, LightElevation;
  // The sphere the camera frames (world x, y, z, radius); radius 0: the whole volume.
  double Focus[4];
};

//------------------------------------------------------------------------------
// The sampling grid at a resolution scale. The world-space extent is that of the spec at
// scale 1, centred on the origin.
struct Grid
{
  int Dims[3];
  double Spacing[3];
  double Origin[3];
  double HalfExtent[3];
  double Voxel; // largest spacing in normalised units (volume spans [-1, 1] on each axis)

  Grid(const SceneSpec& spec, double scale)
  {
    this->Voxel = 0.0;
    for (int a = 0; a < 3; ++a)
    {
      const int n = std::max(2, static_cast<int>(std::floor(spec.Dims[a] * scale + 0.5)));
      const double extent = (spec.Dims[a] - 1) * spec.Spacing[a];
      this->Dims[a] = n;
      this->Spacing[a] = extent / (n - 1);
      this->HalfExtent[a] = 0.5 * extent;
      this->Origin[a] = -this->HalfExtent[a];
      this->Voxel = std::max(this->Voxel, this->Spacing[a] / this->HalfExtent[a]);
    }
  }

  double World(int axis, int i) const { return this->Origin[axis] + i * this->Spacing[axis]; }
  double Normalized(int axis, int i) const { return this->World(axis, i) / this->HalfExtent[axis]; }
  vtkIdType SliceSize() const { return static_cast<vtkIdType>(this->Dims[0]) * this->Dims[1]; }
  vtkIdType Size() const { return this->SliceSize() * this->Dims[2]; }
};

// Calls body(k) for every slice k, in parallel. Each voxel depends only on its own indices,
// so the result does not depend on the number of threads.
template <typename F>
void ForEachSlice(int slices, F&& body)
{
  vtkSMPTools::For(0, slices, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType k = begin; k < end; ++k)
    {
      body(static_cast<int>(k));
    }
  });
}

//------------------------------------------------------------------------------
// The generators, one voxel value per grid node.
void GenerateBox(const Grid& g, unsigned char* out);
void GenerateBucky(const Grid& g, unsigned char* out);
void GenerateRods(const Grid& g, unsigned char* out);
void GenerateSpheres(const Grid& g, unsigned char* out);
void GenerateClouds(const Grid& g, unsigned char* out);
void GenerateSparse(const Grid& g, unsigned char* out, int count); // count 0: all
void GenerateHead(const Grid& g, short* out);

}
}
#endif
