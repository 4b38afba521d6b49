#include "vtkDeepShadowStandardScene.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkImageData.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkShortArray.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <sstream>

vtkStandardNewMacro(vtkDeepShadowStandardScene);

namespace
{
//------------------------------------------------------------------------------
// Deterministic building blocks. The voxel path uses only correctly rounded IEEE 754
// operations (+, -, *, /, sqrt) and exact ones (floor, fabs, fmod, ldexp, min, max): they give
// the same bits everywhere, unlike libm's exp, sin or atan2.

// PCG-style 32-bit hash (Jarzynski & Olano, "Hash Functions for GPU Rendering", 2020).
inline uint32_t PcgHash(uint32_t v)
{
  const uint32_t state = v * 747796405u + 2891336453u;
  const uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

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
double DetExp(double x)
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
double SegmentDistanceSquared(const double p[3], const double a[3], const double b[3])
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
double ValueNoise(double x, double y, double z, uint32_t seed)
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
};

const SceneSpec Specs[] = {
  { "box", "64^3 uchar: a cube that gets more opaque towards its centre (DSM from 3D textures)",
    { 64, 64, 64 }, { 2.0, 2.0, 2.0 }, VTK_UNSIGNED_CHAR, 0.0, 35.0, 25.0, -55.0, 50.0 },
  { "bucky", "32^3 uchar: C60 buckyball, 60 Gaussian carbon atoms with faint bonds", { 32, 32, 32 },
    { 4.0, 4.0, 4.0 }, VTK_UNSIGNED_CHAR, 0.0, 35.0, 25.0, -55.0, 50.0 },
  { "rods", "64^3 uchar: thin opaque rods crossing along x, y and z (thin occluders)",
    { 64, 64, 64 }, { 2.0, 2.0, 2.0 }, VTK_UNSIGNED_CHAR, 0.0, 30.0, 22.0, -60.0, 45.0 },
  { "clouds", "512x512x32 uchar: fractal value-noise cloud puffs in a flat slab", { 512, 512, 32 },
    { 0.45, 0.45, 0.45 }, VTK_UNSIGNED_CHAR, 0.0, 25.0, 38.0, -40.0, 40.0 },
  { "spheres", "128^3 uchar: seven translucent spheres of different sizes and values (CSSM)",
    { 128, 128, 128 }, { 1.0, 1.0, 1.0 }, VTK_UNSIGNED_CHAR, 0.0, 30.0, 20.0, -45.0, 55.0 },
  { "head", "256x256x160 short: CT-like head phantom in Hounsfield units, 0.9x0.9x1.5 mm",
    { 256, 256, 160 }, { 0.9, 0.9, 1.5 }, VTK_SHORT, -1000.0, 35.0, 12.0, -15.0, 50.0 },
};

const SceneSpec* FindSpec(const std::string& name)
{
  for (const SceneSpec& spec : Specs)
  {
    if (name == spec.Name)
    {
      return &spec;
    }
  }
  return nullptr;
}

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
// "box": translucent faces, dense centre.
void GenerateBox(const Grid& g, unsigned char* out)
{
  const double half = 0.8; // the cube spans [-0.8, 0.8]; empty margin around it
  ForEachSlice(g.Dims[2], [&](int k) {
    const double w = std::fabs(g.Normalized(2, k));
    unsigned char* slice = out + k * g.SliceSize();
    for (int j = 0; j < g.Dims[1]; ++j)
    {
      const double v = std::fabs(g.Normalized(1, j));
      for (int i = 0; i < g.Dims[0]; ++i)
      {
        const double c = std::max(std::max(std::fabs(g.Normalized(0, i)), v), w);
        // One voxel of antialiasing on the faces, then a linear rise to the centre.
        const double cover = Clamp01((half - c) / g.Voxel + 0.5);
        slice[j * g.Dims[0] + i] =
          Quantize<unsigned char>(cover * (40.0 + 215.0 * (1.0 - c / half)), 0.0, 255.0);
      }
    }
  });
}

//------------------------------------------------------------------------------
// "bucky": truncated icosahedron vertices, edge length 2 before scaling.
std::vector<std::array<double, 3>> BuckyAtoms()
{
  const double phi = 0.5 * (1.0 + std::sqrt(5.0));
  const double base[3][3] = { { 0.0, 1.0, 3.0 * phi }, { 1.0, 2.0 + phi, 2.0 * phi },
    { phi, 2.0, 2.0 * phi + 1.0 } };
  std::vector<std::array<double, 3>> atoms;
  for (const auto& t : base)
  {
    for (int signs = 0; signs < 8; ++signs)
    {
      double v[3];
      bool duplicate = false;
      for (int c = 0; c < 3; ++c)
      {
        const bool negative = (signs >> c) & 1;
        duplicate = duplicate || (negative && t[c] == 0.0); // -0 is +0
        v[c] = negative ? -t[c] : t[c];
      }
      if (duplicate)
      {
        continue;
      }
      // The three cyclic permutations.
      atoms.push_back({ v[0], v[1], v[2] });
      atoms.push_back({ v[2], v[0], v[1] });
      atoms.push_back({ v[1], v[2], v[0] });
    }
  }
  return atoms; // 12 + 24 + 24 = 60
}

void GenerateBucky(const Grid& g, unsigned char* out)
{
  auto atoms = BuckyAtoms();
  double radius = 0.0;
  for (const auto& a : atoms)
  {
    radius = std::max(radius, std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]));
  }
  // Bonds are the 90 edges, the pairs at distance 2 (next neighbours are at 2*phi or more).
  std::vector<std::array<int, 2>> bonds;
  for (size_t a = 0; a < atoms.size(); ++a)
  {
    for (size_t b = a + 1; b < atoms.size(); ++b)
    {
      double d2 = 0.0;
      for (int c = 0; c < 3; ++c)
      {
        d2 += (atoms[a][c] - atoms[b][c]) * (atoms[a][c] - atoms[b][c]);
      }
      if (std::fabs(d2 - 4.0) < 1e-6)
      {
        bonds.push_back({ static_cast<int>(a), static_cast<int>(b) });
      }
    }
  }
  const double scale = 0.75 / radius; // the ball fills most of the volume
  for (auto& a : atoms)
  {
    for (double& c : a)
    {
      c *= scale;
    }
  }
  // Atoms about a voxel wide at 32^3, well apart from their neighbours (0.3 away), so that the
  // cage reads as balls and sticks; never much thinner than a voxel, so that low resolution
  // scales still sample them.
  const double sigmaAtom = std::max(0.07, 0.6 * g.Voxel);
  const double sigmaBond = std::max(0.045, 0.4 * g.Voxel); // normalised units
  const double atomK = -0.5 / (sigmaAtom * sigmaAtom), bondK = -0.5 / (sigmaBond * sigmaBond);
  const double atomCut2 = 16.0 * sigmaAtom * sigmaAtom, bondCut2 = 16.0 * sigmaBond * sigmaBond;

  ForEachSlice(g.Dims[2], [&](int k) {
    unsigned char* slice = out + k * g.SliceSize();
    const double p2 = g.Normalized(2, k);
    for (int j = 0; j < g.Dims[1]; ++j)
    {
      const double p1 = g.Normalized(1, j);
      for (int i = 0; i < g.Dims[0]; ++i)
      {
        const double p[3] = { g.Normalized(0, i), p1, p2 };
        double atomSum = 0.0;
        for (const auto& a : atoms)
        {
          const double d2 = (p[0] - a[0]) * (p[0] - a[0]) + (p[1] - a[1]) * (p[1] - a[1]) +
            (p[2] - a[2]) * (p[2] - a[2]);
          if (d2 < atomCut2)
          {
            atomSum += DetExp(d2 * atomK);
          }
        }
        double bond = 0.0;
        for (const auto& b : bonds)
        {
          const double d2 = SegmentDistanceSquared(p, atoms[b[0]].data(), atoms[b[1]].data());
          if (d2 < bondCut2)
          {
            bond = std::max(bond, DetExp(d2 * bondK)); // max: no bright spots where bonds meet
          }
        }
        slice[j * g.Dims[0] + i] = Quantize<unsigned char>(255.0 * atomSum + 100.0 * bond, 0, 255);
      }
    }
  });
}

//------------------------------------------------------------------------------
// "rods": three rods along each axis, placed so that some cross and some pass close by.
void GenerateRods(const Grid& g, unsigned char* out)
{
  // Offsets of the rods along an axis in the two other axes, in cyclic order (axis+1, axis+2).
  const double offsets[3][2] = { { -0.45, -0.45 }, { 0.0, 0.45 }, { 0.45, 0.0 } };
  // Radius of two voxels at full resolution, but never thinner than most of a voxel so that the
  // rods survive low resolution scales.
  const double radius = std::max(4.0 / 63.0, 0.8 * g.Voxel);
  const double halfLength = 0.85;

  ForEachSlice(g.Dims[2], [&](int k) {
    unsigned char* slice = out + k * g.SliceSize();
    for (int j = 0; j < g.Dims[1]; ++j)
    {
      for (int i = 0; i < g.Dims[0]; ++i)
      {
        const double p[3] = { g.Normalized(0, i), g.Normalized(1, j), g.Normalized(2, k) };
        double cover = 0.0;
        for (int axis = 0; axis < 3; ++axis)
        {
          const double along = std::fabs(p[axis]);
          const double endCover = Clamp01((halfLength - along) / g.Voxel + 0.5);
          if (endCover <= 0.0)
          {
            continue;
          }
          const double a = p[(axis + 1) % 3], b = p[(axis + 2) % 3];
          for (const auto& o : offsets)
          {
            const double r = std::sqrt((a - o[0]) * (a - o[0]) + (b - o[1]) * (b - o[1]));
            cover = std::max(cover, std::min(endCover, Clamp01((radius - r) / g.Voxel + 0.5)));
          }
        }
        slice[j * g.Dims[0] + i] = Quantize<unsigned char>(255.0 * cover, 0, 255);
      }
    }
  });
}

//------------------------------------------------------------------------------
// "clouds": fBm of value noise, evaluated separably per slice (lattice planes interpolated in
// z, then rows in y, then voxels in x), so that six octaves over 8 M voxels stay cheap.
void GenerateClouds(const Grid& g, unsigned char* out)
{
  const int octaves = 6;
  // Gain 0.4 rather than 0.5: soft, billowy edges rather than rocky detail.
  auto amplitude = [](int o) {
    double a = 1.0;
    for (int i = 0; i < o; ++i)
    {
      a *= 0.4;
    }
    return a;
  };
  const double baseCell = 36.0; // world units: several puffs across the 230-unit slab
  const double extent[2] = { 2.0 * g.HalfExtent[0], 2.0 * g.HalfExtent[1] };
  double ampSum = 0.0;
  for (int o = 0; o < octaves; ++o)
  {
    ampSum += amplitude(o);
  }
  const int nx = g.Dims[0], ny = g.Dims[1];

  ForEachSlice(g.Dims[2], [&](int k) {
    std::vector<double> sum(static_cast<size_t>(nx) * ny, 0.0);
    std::vector<double> plane, row;
    const double z = k * g.Spacing[2]; // lattice coordinates start at the grid origin
    for (int o = 0; o < octaves; ++o)
    {
      const double cell = std::ldexp(baseCell, -o);
      const double amp = amplitude(o);
      const uint32_t seed = 0x9e3779b9u * static_cast<uint32_t>(o + 1);
      const int cx = static_cast<int>(std::floor(extent[0] / cell)) + 2;
      const int cy = static_cast<int>(std::floor(extent[1] / cell)) + 2;
      const double fz = z / cell;
      const int iz = static_cast<int>(std::floor(fz));
      const double tz = SmoothStep(0.0, 1.0, fz - iz);
      plane.resize(static_cast<size_t>(cx) * cy);
      for (int ly = 0; ly < cy; ++ly)
      {
        for (int lx = 0; lx < cx; ++lx)
        {
          plane[ly * cx + lx] =
            Lerp(HashUnit(Hash3(lx, ly, iz, seed)), HashUnit(Hash3(lx, ly, iz + 1, seed)), tz);
        }
      }
      row.resize(cx);
      for (int j = 0; j < ny; ++j)
      {
        const double fy = j * g.Spacing[1] / cell;
        const int iy = std::min(static_cast<int>(std::floor(fy)), cy - 2);
        const double ty = SmoothStep(0.0, 1.0, fy - iy);
        for (int lx = 0; lx < cx; ++lx)
        {
          row[lx] = Lerp(plane[iy * cx + lx], plane[(iy + 1) * cx + lx], ty);
        }
        double* s = sum.data() + static_cast<size_t>(j) * nx;
        for (int i = 0; i < nx; ++i)
        {
          const double fx = i * g.Spacing[0] / cell;
          const int ix = std::min(static_cast<int>(std::floor(fx)), cx - 2);
          s[i] += amp * Lerp(row[ix], row[ix + 1], SmoothStep(0.0, 1.0, fx - ix));
        }
      }
    }
    // Flatten: the threshold rises away from a mid-plane set a little low, faster below it,
    // so that the puffs have flattish bases and domed tops.
    const double h = g.Normalized(2, k) + 0.2;
    const double threshold = -0.07 + (h < 0.0 ? 0.4 : 0.15) * h * h;
    unsigned char* slice = out + k * g.SliceSize();
    for (int j = 0; j < ny; ++j)
    {
      // Clouds thin out towards the sides rather than being cut by them.
      const double edgeY = std::fabs(g.Normalized(1, j));
      for (int i = 0; i < nx; ++i)
      {
        const double edge = std::max(std::fabs(g.Normalized(0, i)), edgeY);
        const size_t at = static_cast<size_t>(j) * nx + i;
        const double density =
          (sum[at] / ampSum - 0.5) - threshold - 0.25 * SmoothStep(0.75, 1.0, edge);
        // A wide ramp: soft edges, and density that keeps rising inside (shading needs
        // gradients).
        slice[at] = Quantize<unsigned char>(255.0 * SmoothStep(0.0, 0.3, density), 0, 255);
      }
    }
  });
}

//------------------------------------------------------------------------------
// "spheres": non-overlapping spheres, each with its own scalar value.
struct SphereSpec
{
  double C[3];
  double R;
  double Value;
};

const SphereSpec TestSpheres[] = {
  { { 0.0, 0.0, 0.0 }, 0.35, 200.0 },
  { { -0.55, -0.45, 0.35 }, 0.22, 60.0 },
  { { 0.55, -0.35, 0.45 }, 0.18, 100.0 },
  { { 0.5, 0.55, -0.3 }, 0.25, 140.0 },
  { { -0.5, 0.5, -0.45 }, 0.20, 240.0 },
  { { 0.05, -0.6, -0.55 }, 0.15, 170.0 },
  { { -0.15, 0.55, 0.6 }, 0.12, 30.0 },
};

void GenerateSpheres(const Grid& g, unsigned char* out)
{
  ForEachSlice(g.Dims[2], [&](int k) {
    unsigned char* slice = out + k * g.SliceSize();
    for (int j = 0; j < g.Dims[1]; ++j)
    {
      for (int i = 0; i < g.Dims[0]; ++i)
      {
        const double p[3] = { g.Normalized(0, i), g.Normalized(1, j), g.Normalized(2, k) };
        double value = 0.0;
        for (const SphereSpec& s : TestSpheres)
        {
          const double r = std::sqrt((p[0] - s.C[0]) * (p[0] - s.C[0]) +
            (p[1] - s.C[1]) * (p[1] - s.C[1]) + (p[2] - s.C[2]) * (p[2] - s.C[2]));
          // A gentle +-8 rise towards the centre, inside the colour band of the sphere's value:
          // the gradient gives interior samples a normal, so that they are shaded too.
          const double inner = s.Value - 8.0 + 16.0 * Clamp01(1.0 - (r * r) / (s.R * s.R));
          value = std::max(value, inner * Clamp01((s.R - r) / g.Voxel + 0.5));
        }
        slice[j * g.Dims[0] + i] = Quantize<unsigned char>(value, 0, 255);
      }
    }
  });
}

//------------------------------------------------------------------------------
// "head": a CT-like phantom built from signed distance fields in millimetres.
struct Ellipsoid
{
  double C[3];
  double R[3];
};

// Approximate signed distance to an ellipsoid: exact on the surface and along the axes, close
// nearby, which is what the few-millimetre tissue layers need.
double EllipsoidDistance(const double p[3], const Ellipsoid& e)
{
  double k0 = 0.0, k1 = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    const double q = (p[c] - e.C[c]) / e.R[c];
    k0 += q * q;
    k1 += q * q / (e.R[c] * e.R[c]);
  }
  if (k1 <= 0.0)
  {
    return -std::min(std::min(e.R[0], e.R[1]), e.R[2]);
  }
  k0 = std::sqrt(k0);
  return k0 * (k0 - 1.0) / std::sqrt(k1);
}

// The same for an ellipse in the xy plane (an infinite vertical elliptic cylinder).
double EllipseDistance(double x, double y, double cx, double cy, double rx, double ry)
{
  const double qx = (x - cx) / rx, qy = (y - cy) / ry;
  const double k0 = std::sqrt(qx * qx + qy * qy);
  const double k1 = std::sqrt(qx * qx / (rx * rx) + qy * qy / (ry * ry));
  return k1 > 0.0 ? k0 * (k0 - 1.0) / k1 : -std::min(rx, ry);
}

// Distance to a capsule (segment a-b, radius r).
double CapsuleDistance(const double p[3], const double a[3], const double b[3], double r)
{
  return std::sqrt(SegmentDistanceSquared(p, a, b)) - r;
}

// True if p is farther than `margin` outside the ellipsoid's bounding box (cheap rejection).
inline bool Far(const double p[3], const Ellipsoid& e, double margin)
{
  for (int c = 0; c < 3; ++c)
  {
    if (std::fabs(p[c] - e.C[c]) > e.R[c] + margin)
    {
      return true;
    }
  }
  return false;
}

// The same ellipsoid, its surface moved inwards by about d.
inline Ellipsoid Inset(const Ellipsoid& e, double d)
{
  return { { e.C[0], e.C[1], e.C[2] }, { e.R[0] - d, e.R[1] - d, e.R[2] - d } };
}

// Signed distance to the shell [inner, outer] of depths below a surface at distance d.
inline double Shell(double d, double inner, double outer)
{
  return std::max(d + inner, -outer - d);
}

// Front-to-back composition of tissues in priority order. Each region covers a fraction of the
// voxel, estimated from its signed distance over `width` (about a voxel): an area-sampled
// phantom, so that shaded surfaces show no voxel terraces. What a region leaves uncovered goes
// to the regions after it.
class Composer
{
public:
  explicit Composer(double width)
    : HalfWidth(0.5 * width)
    , InvWidth(1.0 / width)
  {
  }

  /** True once the voxel is fully covered: later regions cannot contribute. */
  bool Full() const { return this->Remaining <= 0.0; }

  /** True if a region at this distance cannot reach the voxel (skip computing its value). */
  bool Misses(double distance) const { return distance >= this->HalfWidth; }

  void Add(double distance, double value)
  {
    const double c = Clamp01(0.5 - distance * this->InvWidth);
    this->Sum += this->Remaining * c * value;
    this->Remaining *= 1.0 - c;
  }

  double Finish(double value) const { return this->Sum + this->Remaining * value; }

  const double HalfWidth;

private:
  const double InvWidth;
  double Sum = 0.0;
  double Remaining = 1.0;
};

namespace hu
{
const double Air = -1000.0;
const double Skin = 45.0;
const double Fat = -90.0;
const double Muscle = 50.0;
const double CSF = 8.0;
const double Grey = 40.0;
const double White = 27.0;
const double Cortical = 1450.0;
const double Diploe = 700.0;
const double SkullBase = 1200.0;
const double FaceBone = 950.0;
const double Mandible = 1300.0;
const double Teeth = 2200.0;
const double Cancellous = 320.0;
const double Vertebra = 1100.0;
const double Disc = 85.0;
const double Vitreous = 12.0;
const double Lens = 90.0;
const double Sclera = 55.0;
const double OrbitFat = -80.0;
const double SinusAir = -980.0;
const double ThinBone = 550.0;
}

// The anatomy, in mm; the volume spans about +-115 in x and y and +-119 in z.
struct HeadModel
{
  // Skin: a union of smooth shapes.
  Ellipsoid Cranium{ { 0.0, 8.0, 28.0 }, { 74.0, 96.0, 84.0 } };
  Ellipsoid Face{ { 0.0, -38.0, -22.0 }, { 66.0, 56.0, 72.0 } };
  Ellipsoid Jaw{ { 0.0, -48.0, -76.0 }, { 44.0, 44.0, 28.0 } };
  Ellipsoid Nose{ { 0.0, -94.0, -18.0 }, { 10.0, 15.0, 24.0 } };
  Ellipsoid NoseTip{ { 0.0, -104.0, -32.0 }, { 10.0, 9.0, 9.0 } };
  Ellipsoid Ears[2] = { { { 74.0, 12.0, -4.0 }, { 6.0, 15.0, 26.0 } },
    { { -74.0, 12.0, -4.0 }, { 6.0, 15.0, 26.0 } } };
  Ellipsoid Nostrils[2] = { { { 5.5, -100.0, -39.0 }, { 3.5, 14.0, 3.5 } },
    { { -5.5, -100.0, -39.0 }, { 3.5, 14.0, 3.5 } } };
  // Bone surfaces under the skin.
  Ellipsoid SkullOuter = Inset(Cranium, 6.0);
  Ellipsoid FaceBoneOuter = Inset(Face, 8.0);
  // Brain.
  Ellipsoid Ventricles[3] = { { { 10.0, 2.0, 30.0 }, { 6.0, 28.0, 9.0 } },
    { { -10.0, 2.0, 30.0 }, { 6.0, 28.0, 9.0 } }, { { 0.0, 6.0, 12.0 }, { 2.5, 12.0, 9.0 } } };
  Ellipsoid DeepGrey[2] = { { { 17.0, 4.0, 14.0 }, { 10.0, 15.0, 10.0 } },
    { { -17.0, 4.0, 14.0 }, { 10.0, 15.0, 10.0 } } };
  // Face.
  Ellipsoid Orbits[2] = { { { 32.0, -58.0, 6.0 }, { 19.0, 20.0, 18.0 } },
    { { -32.0, -58.0, 6.0 }, { 19.0, 20.0, 18.0 } } };
  Ellipsoid Eyes[2] = { { { 33.0, -68.0, 6.0 }, { 12.0, 12.0, 12.0 } },
    { { -33.0, -68.0, 6.0 }, { 12.0, 12.0, 12.0 } } };
  Ellipsoid Lenses[2] = { { { 33.0, -79.0, 6.0 }, { 4.5, 2.0, 4.5 } },
    { { -33.0, -79.0, 6.0 }, { 4.5, 2.0, 4.5 } } };
  Ellipsoid NasalAperture{ { 0.0, -86.0, -24.0 }, { 14.0, 16.0, 18.0 } };
  Ellipsoid NasalCavity{ { 0.0, -64.0, -20.0 }, { 10.0, 26.0, 20.0 } };
  Ellipsoid AirSpaces[3] = { { { 0.0, -34.0, -20.0 }, { 11.0, 12.0, 10.0 } }, // nasopharynx
    { { 24.0, -58.0, -26.0 }, { 12.0, 16.0, 14.0 } },                         // maxillary sinuses
    { { -24.0, -58.0, -26.0 }, { 12.0, 16.0, 14.0 } } };
  Ellipsoid Rami[2] = { { { 46.0, -2.0, -45.0 }, { 4.5, 12.0, 30.0 } },
    { { -46.0, -2.0, -45.0 }, { 4.5, 12.0, 30.0 } } };

  // Signed distance to the skin, a smooth union. Two shortcuts keep it cheap, neither changes
  // the phantom: a smooth minimum is never above its parts, so once a part is deeper than
  // `deep` (where the caller no longer needs the exact value) that part is returned; and a part
  // more than `SkinMargin` away cannot change the union near the surface, so it is skipped.
  static constexpr double SkinMargin = 30.0;
  static constexpr double FarAway = 1e9;

  double Part(const double p[3], const Ellipsoid& e) const
  {
    return Far(p, e, SkinMargin) ? FarAway : EllipsoidDistance(p, e);
  }

  double SkinDistance(const double p[3], double deep) const
  {
    double d = EllipsoidDistance(p, this->Cranium);
    if (d <= deep)
    {
      return d;
    }
    const double face = this->Part(p, this->Face);
    if (face <= deep)
    {
      return face;
    }
    d = SMin(d, face, 18.0);
    d = SMin(d, this->Part(p, this->Jaw), 14.0);
    const double neck = p[2] > -35.0 + SkinMargin || std::fabs(p[0]) > 50.0 + SkinMargin
      ? FarAway
      : std::max(EllipseDistance(p[0], p[1], 0.0, 18.0, 50.0, 52.0), p[2] + 35.0);
    d = SMin(d, neck, 18.0);
    d = SMin(d, this->Part(p, this->Nose), 6.0);
    d = SMin(d, this->Part(p, this->NoseTip), 5.0);
    return SMin(d, std::min(this->Part(p, this->Ears[0]), this->Part(p, this->Ears[1])), 4.0);
  }

  // Height of the floor of the cranial cavity: anterior fossa above the orbits, middle fossa
  // at ear level, posterior fossa low at the back.
  static double SkullBase(double y)
  {
    return Lerp(Lerp(20.0, -8.0, SmoothStep(-45.0, -25.0, y)), -38.0, SmoothStep(10.0, 35.0, y));
  }

  // The brain; depth is the distance below the brain surface (mm).
  void Brain(const double p[3], double depth, Composer& out) const
  {
    for (const Ellipsoid& v : this->Ventricles)
    {
      if (!Far(p, v, out.HalfWidth))
      {
        out.Add(EllipsoidDistance(p, v), hu::CSF - 2.0);
      }
    }
    // Interhemispheric fissure above the corpus callosum and in front of and behind it.
    out.Add(std::max(std::fabs(p[0]) - 1.3, std::min(38.0 - p[2], 50.0 - std::fabs(p[1] - 5.0))),
      hu::CSF);
    for (const Ellipsoid& d : this->DeepGrey)
    {
      if (!Far(p, d, out.HalfWidth))
      {
        out.Add(EllipsoidDistance(p, d), hu::Grey - 2.0);
      }
    }
    if (out.Full())
    {
      return;
    }
    // Sulci follow the zero crossings of a smooth noise; grey matter lines the surface and the
    // sulci. The cerebellum (low at the back) is folded finer.
    const bool cerebellum = p[1] > 22.0 && p[2] < -12.0;
    const double cell = cerebellum ? 6.0 : 11.0;
    const double n = ValueNoise(p[0] / cell, p[1] / cell, p[2] / cell, 0x5bd1e995u) - 0.5;
    // |n| in noise units to mm, roughly: the noise changes by ~1 per cell.
    const double band = std::fabs(n) * cell;
    out.Add(std::max(band - 1.0, depth - 16.0), hu::CSF);
    out.Add(
      std::min(depth - 3.0, std::max(band - (cerebellum ? 2.0 : 2.5), depth - 20.0)), hu::Grey);
    out.Add(-1e9, hu::White);
  }

  // Hounsfield value of the phantom at p before the scanner blur and noise.
  double Value(const double p[3], Composer& out) const
  {
    const double x = p[0], y = p[1], z = p[2];
    // Below -6 - HalfWidth the skin and fat layers no longer reach the voxel.
    const double skin = this->SkinDistance(p, -6.0 - out.HalfWidth);
    double air = -skin;
    for (const Ellipsoid& n : this->Nostrils)
    {
      if (!Far(p, n, out.HalfWidth))
      {
        air = std::min(air, EllipsoidDistance(p, n));
      }
    }
    out.Add(air, hu::Air);
    out.Add(-2.5 - skin, hu::Skin);
    out.Add(-6.0 - skin, hu::Fat);
    if (out.Full())
    {
      return out.Finish(0.0);
    }

    // Dental arches: upper and lower rows of teeth on a U, meeting at z = -60.5. The position
    // along the arch is a pseudo-angle (no atan2: it must be bit-exact); 16 teeth per row.
    if (y < -25.0 && z > -74.0 && z < -46.0)
    {
      const double ring = EllipseDistance(x, y, 0.0, -10.0, 36.0, 66.0);
      const double u = x / 36.0, v = (y + 10.0) / 66.0;
      const double along = u / (std::fabs(u) + std::fabs(v)) / 0.1 + 0.5;
      const double gap = (std::fabs(along - std::floor(along) - 0.5) - 0.4) * 6.0; // mm
      out.Add(std::max(std::max(std::fabs(ring) - 3.6, std::fabs(z + 60.5) - 10.0),
                std::max(std::max(0.5 - std::fabs(z + 60.5), y + 28.0), gap)),
        hu::Teeth);
    }

    // Eyes: lens, sclera, vitreous.
    for (int e = 0; e < 2; ++e)
    {
      if (!Far(p, this->Eyes[e], out.HalfWidth))
      {
        const double d = EllipsoidDistance(p, this->Eyes[e]);
        out.Add(EllipsoidDistance(p, this->Lenses[e]), hu::Lens);
        out.Add(Shell(d, 0.0, 1.2), hu::Sclera);
        out.Add(d, hu::Vitreous);
      }
    }

    // Air spaces: sinuses, nasal cavity (with its septum), pharynx, airway.
    for (const Ellipsoid& a : this->AirSpaces)
    {
      if (!Far(p, a, out.HalfWidth))
      {
        out.Add(EllipsoidDistance(p, a), hu::SinusAir);
      }
    }
    if (!Far(p, this->NasalCavity, out.HalfWidth))
    {
      const double d = EllipsoidDistance(p, this->NasalCavity);
      // Septum: bone at the back, cartilage (soft-tissue values) at the front.
      out.Add(
        std::max(std::max(d, std::fabs(x) - 1.2), -36.0 - z), y > -74.0 ? hu::ThinBone : 150.0);
      out.Add(d, hu::SinusAir);
    }
    out.Add(std::max(EllipseDistance(x, y, 0.0, -14.0, 11.0, 6.0), std::fabs(z + 60.0) - 40.0),
      hu::SinusAir); // oropharynx
    out.Add(std::max(EllipseDistance(x, y, 0.0, -16.0, 8.0, 8.0), z + 100.0), hu::SinusAir);
    if (out.Full())
    {
      return out.Finish(0.0);
    }

    // Cranial vault: cortical tables around the diploe, thicker towards the base; the skull
    // base plate (thin over the orbits, thick at the back) with the foramen magnum; the brain.
    const double outer = EllipsoidDistance(p, this->SkullOuter);
    const double base = SkullBase(y);
    const double aboveBase = base - 9.0 - z; // the vault reaches down to the base plate
    if (!out.Misses(std::max(outer, aboveBase)))
    {
      const double thickness = 6.0 + 5.0 * SmoothStep(40.0, -30.0, z);
      out.Add(std::max(Shell(outer, 0.0, 1.6), aboveBase), hu::Cortical);
      out.Add(std::max(Shell(outer, thickness - 1.6, thickness), aboveBase), hu::Cortical);
      out.Add(std::max(Shell(outer, 0.0, thickness), aboveBase), hu::Diploe);
      const double cavity = outer + thickness; // inside the skull's inner table
      const double plate = Lerp(4.0, 9.0, SmoothStep(-30.0, 20.0, y));
      const double foramen = EllipseDistance(x, y, 0.0, 22.0, 14.0, 15.0);
      out.Add(std::max(std::max(cavity, std::fabs(z - base + 0.5 * plate) - 0.5 * plate), -foramen),
        hu::SkullBase);
      const double brain = std::max(cavity, base - z);
      if (!out.Misses(brain))
      {
        const double depth = -brain; // below the inner surface of the cavity
        out.Add(std::max(brain, depth - 1.5), hu::CSF);
        if (!out.Full())
        {
          Composer tissue(2.0 * out.HalfWidth);
          this->Brain(p, depth - 1.5, tissue);
          out.Add(brain, tissue.Finish(hu::White));
        }
      }
    }
    // Brainstem through the foramen magnum.
    out.Add(std::max(EllipseDistance(x, y, 0.0, 20.0, 11.0, 11.0), std::max(-55.0 - z, z - base)),
      hu::White + 3.0);
    if (out.Full())
    {
      return out.Finish(0.0);
    }

    // Orbits: fat around the eye, bony walls open at the front.
    for (const Ellipsoid& o : this->Orbits)
    {
      if (!Far(p, o, 3.0 + out.HalfWidth))
      {
        const double d = EllipsoidDistance(p, o);
        out.Add(d, hu::OrbitFat);
        out.Add(std::max(Shell(d, -2.5, 0.0), -70.0 - y), hu::FaceBone);
      }
    }
    // Thin walls of the maxillary sinuses, hard palate.
    for (int s = 1; s <= 2; ++s)
    {
      if (!Far(p, this->AirSpaces[s], 1.5 + out.HalfWidth))
      {
        out.Add(EllipsoidDistance(p, this->AirSpaces[s]) - 1.5, hu::ThinBone);
      }
    }
    out.Add(std::max(EllipseDistance(x, y, 0.0, -50.0, 24.0, 24.0), std::fabs(z + 42.5) - 2.5),
      hu::FaceBone);
    // Facial skeleton: a shell under the front of the face from the orbits down to the upper
    // teeth (wide at the cheekbones, narrow below them), with the pear-shaped nasal aperture;
    // zygomatic arches towards the ears.
    const double faceRegion = std::max(
      std::max(y + 35.0, std::fabs(x) - (z < -15.0 ? 30.0 : 48.0)), std::max(-50.0 - z, z - base));
    if (!out.Misses(faceRegion))
    {
      out.Add(std::max(std::max(Shell(EllipsoidDistance(p, this->FaceBoneOuter), 0.0, 4.5),
                         -EllipsoidDistance(p, this->NasalAperture)),
                faceRegion),
        hu::FaceBone);
    }
    for (double side : { -1.0, 1.0 })
    {
      const double a[3] = { side * 50.0, -62.0, -12.0 }, b[3] = { side * 62.0, 2.0, -8.0 };
      out.Add(CapsuleDistance(p, a, b, 4.0), hu::FaceBone);
    }

    // Mandible: a U-shaped bar under the lower teeth, rising towards the rami at the back.
    if (y < 0.0 && z < -60.0)
    {
      const double ring = std::fabs(EllipseDistance(x, y, 0.0, -10.0, 40.0, 70.0));
      const double bottom = Lerp(-94.0, -80.0, SmoothStep(-80.0, -5.0, y));
      const double bar = std::max(std::max(ring - 3.5, y + 5.0), std::max(z + 66.0, bottom - z));
      out.Add(Shell(bar, 0.0, 1.8), hu::Mandible);
      out.Add(bar, hu::Cancellous + 200.0);
    }
    for (const Ellipsoid& r : this->Rami)
    {
      if (!Far(p, r, out.HalfWidth))
      {
        out.Add(EllipsoidDistance(p, r), hu::Mandible);
      }
    }

    // Cervical spine: cord in the canal, posterior arch, vertebral bodies with discs.
    if (z < -40.0 + out.HalfWidth)
    {
      const double below = z + 40.0;
      out.Add(std::max(EllipseDistance(x, y, 0.0, 27.0, 5.0, 5.0), below), hu::White + 8.0);
      out.Add(std::max(EllipseDistance(x, y, 0.0, 27.0, 8.0, 8.0), below), hu::CSF);
      out.Add(std::max(EllipseDistance(x, y, 0.0, 27.0, 13.0, 12.0), below), hu::Vertebra);
      const double body = std::max(EllipseDistance(x, y, 0.0, 9.0, 13.0, 10.0), below);
      const double level = std::fmod(z + 400.0, 17.0); // 17 mm per vertebra, 4 mm discs
      const double disc =
        level < 4.0 ? -std::min(level, 4.0 - level) : std::min(level - 4.0, 17.0 - level);
      out.Add(std::max(body, disc), hu::Disc);
      out.Add(std::max(body, -1.5 - body), hu::Vertebra);
      out.Add(body, hu::Cancellous);
    }
    return out.Finish(hu::Muscle);
  }
};

// [1 2 1] / 4 along one axis of a float volume: a little of a CT's point-spread function.
void Blur121(const Grid& g, const std::vector<float>& in, std::vector<float>& out, int axis)
{
  const vtkIdType stride[3] = { 1, g.Dims[0], g.SliceSize() };
  const vtkIdType s = stride[axis];
  const int n = g.Dims[axis];
  ForEachSlice(g.Dims[2], [&](int k) {
    for (int j = 0; j < g.Dims[1]; ++j)
    {
      for (int i = 0; i < g.Dims[0]; ++i)
      {
        const int idx[3] = { i, j, k };
        const vtkIdType c = k * g.SliceSize() + static_cast<vtkIdType>(j) * g.Dims[0] + i;
        const vtkIdType lo = idx[axis] > 0 ? c - s : c;
        const vtkIdType hi = idx[axis] < n - 1 ? c + s : c;
        out[c] = 0.25f * in[lo] + 0.5f * in[c] + 0.25f * in[hi];
      }
    }
  });
}

void GenerateHead(const Grid& g, short* out)
{
  const HeadModel head;
  // Partial-volume width: the largest spacing, so no boundary is sharper than a voxel.
  const double width = std::max(std::max(g.Spacing[0], g.Spacing[1]), g.Spacing[2]);
  std::vector<float> a(static_cast<size_t>(g.Size())), b(a.size());
  ForEachSlice(g.Dims[2], [&](int k) {
    float* slice = a.data() + k * g.SliceSize();
    for (int j = 0; j < g.Dims[1]; ++j)
    {
      for (int i = 0; i < g.Dims[0]; ++i)
      {
        const double p[3] = { g.World(0, i), g.World(1, j), g.World(2, k) };
        Composer composer(width);
        slice[j * g.Dims[0] + i] = static_cast<float>(head.Value(p, composer));
      }
    }
  });
  Blur121(g, a, b, 0);
  Blur121(g, b, a, 1);
  Blur121(g, a, b, 2);
  // A little noise, triangular in +-10 HU, hashed from the voxel index.
  ForEachSlice(g.Dims[2], [&](int k) {
    for (vtkIdType v = k * g.SliceSize(); v < (k + 1) * g.SliceSize(); ++v)
    {
      const uint32_t h = PcgHash(static_cast<uint32_t>(v) ^ 0x68e31da4u);
      const double noise = 10.0 * (HashUnit(h) + HashUnit(PcgHash(h)) - 1.0);
      out[v] = Quantize<short>(b[v] + noise, -1024.0, 3071.0);
    }
  });
}

//------------------------------------------------------------------------------
// Recommended transfer functions.
void BuildProperty(const std::string& name, vtkColorTransferFunction* color,
  vtkPiecewiseFunction* opacity, vtkVolumeProperty* property)
{
  property->SetAmbient(0.25);
  property->SetDiffuse(0.8);
  property->SetSpecular(0.25);
  property->SetSpecularPower(20.0);
  if (name == "box")
  {
    property->SetAmbient(0.35);
    opacity->AddPoint(0.0, 0.0);
    opacity->AddPoint(20.0, 0.0);
    opacity->AddPoint(40.0, 0.015);
    opacity->AddPoint(255.0, 0.35);
    color->AddRGBPoint(0.0, 0.1, 0.2, 0.7);
    color->AddRGBPoint(40.0, 0.2, 0.45, 0.95);
    color->AddRGBPoint(150.0, 0.95, 0.75, 0.3);
    color->AddRGBPoint(255.0, 1.0, 0.35, 0.15);
  }
  else if (name == "bucky")
  {
    // Bonds (about 100) translucent blue, atoms (up to 255) opaque warm white.
    opacity->AddPoint(0.0, 0.0);
    opacity->AddPoint(40.0, 0.0);
    opacity->AddPoint(90.0, 0.2);
    opacity->AddPoint(170.0, 0.9);
    opacity->AddPoint(255.0, 0.95);
    color->AddRGBPoint(0.0, 0.2, 0.35, 0.7);
    color->AddRGBPoint(100.0, 0.35, 0.55, 0.95);
    color->AddRGBPoint(170.0, 0.95, 0.9, 0.8);
    color->AddRGBPoint(255.0, 1.0, 0.97, 0.9);
  }
  else if (name == "rods")
  {
    opacity->AddPoint(0.0, 0.0);
    opacity->AddPoint(30.0, 0.0);
    opacity->AddPoint(128.0, 0.7);
    opacity->AddPoint(255.0, 0.95);
    color->AddRGBPoint(0.0, 0.55, 0.25, 0.1);
    color->AddRGBPoint(128.0, 0.85, 0.55, 0.25);
    color->AddRGBPoint(255.0, 0.95, 0.8, 0.5);
  }
  else if (name == "clouds")
  {
    property->SetAmbient(0.6);
    property->SetDiffuse(0.6);
    property->SetSpecular(0.0);
    opacity->AddPoint(0.0, 0.0);
    opacity->AddPoint(8.0, 0.0);
    opacity->AddPoint(60.0, 0.05);
    opacity->AddPoint(255.0, 0.25);
    color->AddRGBPoint(0.0, 0.9, 0.93, 1.0);
    color->AddRGBPoint(255.0, 1.0, 1.0, 1.0);
  }
  else if (name == "spheres")
  {
    property->SetAmbient(0.35);
    // One colour band per sphere value; opacity grows a little with the value.
    opacity->AddPoint(0.0, 0.0);
    opacity->AddPoint(15.0, 0.0);
    opacity->AddPoint(25.0, 0.04);
    opacity->AddPoint(255.0, 0.12);
    const double bands[][4] = { { 30.0, 0.95, 0.95, 0.2 }, { 60.0, 0.2, 0.85, 0.3 },
      { 100.0, 0.2, 0.8, 0.9 }, { 140.0, 0.25, 0.35, 1.0 }, { 170.0, 0.7, 0.3, 0.95 },
      { 200.0, 1.0, 0.3, 0.25 }, { 240.0, 1.0, 0.6, 0.1 } };
    for (const auto& b : bands)
    {
      color->AddRGBPoint(b[0] - 12.0, b[1], b[2], b[3]);
      color->AddRGBPoint(b[0] + 12.0, b[1], b[2], b[3]);
    }
  }
  else if (name == "head")
  {
    // The air/skin partial-volume range draws the skin as a thin translucent surface, fat and
    // soft tissue stay faint, bone is opaque.
    opacity->AddPoint(-1024.0, 0.0);
    opacity->AddPoint(-700.0, 0.0);
    opacity->AddPoint(-500.0, 0.3);
    opacity->AddPoint(-300.0, 0.3);
    opacity->AddPoint(-150.0, 0.0);
    opacity->AddPoint(20.0, 0.0);
    opacity->AddPoint(60.0, 0.004);
    opacity->AddPoint(150.0, 0.0);
    opacity->AddPoint(300.0, 0.05);
    opacity->AddPoint(700.0, 0.7);
    opacity->AddPoint(3071.0, 0.9);
    color->AddRGBPoint(-1024.0, 0.0, 0.0, 0.0);
    color->AddRGBPoint(-600.0, 0.93, 0.72, 0.58);
    color->AddRGBPoint(-300.0, 0.93, 0.72, 0.58);
    color->AddRGBPoint(-100.0, 0.9, 0.8, 0.5);
    color->AddRGBPoint(50.0, 0.75, 0.3, 0.25);
    color->AddRGBPoint(200.0, 0.95, 0.85, 0.7);
    color->AddRGBPoint(700.0, 1.0, 0.98, 0.92);
    color->AddRGBPoint(3071.0, 1.0, 1.0, 1.0);
  }
}

void Direction(double azimuthDeg, double elevationDeg, double dir[3])
{
  const double d2r = 3.14159265358979323846 / 180.0;
  const double az = azimuthDeg * d2r, el = elevationDeg * d2r;
  dir[0] = std::sin(az) * std::cos(el);
  dir[1] = -std::cos(az) * std::cos(el);
  dir[2] = std::sin(el);
}
}

//------------------------------------------------------------------------------
vtkDeepShadowStandardScene::vtkDeepShadowStandardScene()
  : Scene("box")
{
}

vtkDeepShadowStandardScene::~vtkDeepShadowStandardScene() = default;

//------------------------------------------------------------------------------
std::vector<std::string> vtkDeepShadowStandardScene::GetSceneNames()
{
  std::vector<std::string> names;
  for (const SceneSpec& spec : Specs)
  {
    names.emplace_back(spec.Name);
  }
  return names;
}

std::string vtkDeepShadowStandardScene::GetSceneDescription(const std::string& name)
{
  const SceneSpec* spec = FindSpec(name);
  return spec ? spec->Description : "";
}

bool vtkDeepShadowStandardScene::IsSceneName(const std::string& name)
{
  return FindSpec(name) != nullptr;
}

//------------------------------------------------------------------------------
bool vtkDeepShadowStandardScene::SetScene(const std::string& name)
{
  if (!FindSpec(name))
  {
    std::ostringstream valid;
    for (const SceneSpec& spec : Specs)
    {
      valid << (&spec == Specs ? "" : ", ") << spec.Name;
    }
    vtkErrorMacro(<< "Unknown scene '" << name << "'; valid scenes: " << valid.str());
    return false;
  }
  this->Scene = name;
  this->Invalidate();
  return true;
}

const std::string& vtkDeepShadowStandardScene::GetScene() const
{
  return this->Scene;
}

void vtkDeepShadowStandardScene::SetResolutionScale(double scale)
{
  scale = Clamp(scale, 0.01, 2.0);
  if (scale != this->ResolutionScale)
  {
    this->ResolutionScale = scale;
    this->Invalidate();
  }
}

void vtkDeepShadowStandardScene::Invalidate()
{
  this->Volume = nullptr;
  this->Property = nullptr;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkDeepShadowStandardScene::GetDimensions(int dims[3]) const
{
  const Grid g(*FindSpec(this->Scene), this->ResolutionScale);
  std::copy(g.Dims, g.Dims + 3, dims);
}

void vtkDeepShadowStandardScene::GetSpacing(double spacing[3]) const
{
  const Grid g(*FindSpec(this->Scene), this->ResolutionScale);
  std::copy(g.Spacing, g.Spacing + 3, spacing);
}

void vtkDeepShadowStandardScene::GetOrigin(double origin[3]) const
{
  const Grid g(*FindSpec(this->Scene), this->ResolutionScale);
  std::copy(g.Origin, g.Origin + 3, origin);
}

int vtkDeepShadowStandardScene::GetScalarType() const
{
  return FindSpec(this->Scene)->ScalarType;
}

double vtkDeepShadowStandardScene::GetBackgroundValue() const
{
  return FindSpec(this->Scene)->Background;
}

//------------------------------------------------------------------------------
vtkImageData* vtkDeepShadowStandardScene::GetVolume()
{
  if (this->Volume)
  {
    return this->Volume;
  }
  const auto start = std::chrono::steady_clock::now();
  const SceneSpec& spec = *FindSpec(this->Scene);
  const Grid g(spec, this->ResolutionScale);

  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(g.Dims);
  image->SetSpacing(g.Spacing);
  image->SetOrigin(g.Origin);
  if (spec.ScalarType == VTK_SHORT)
  {
    auto array = vtkSmartPointer<vtkShortArray>::New();
    array->SetNumberOfValues(g.Size());
    GenerateHead(g, array->GetPointer(0));
    array->SetName("scalars");
    image->GetPointData()->SetScalars(array);
  }
  else
  {
    auto array = vtkSmartPointer<vtkUnsignedCharArray>::New();
    array->SetNumberOfValues(g.Size());
    unsigned char* out = array->GetPointer(0);
    if (this->Scene == "box")
    {
      GenerateBox(g, out);
    }
    else if (this->Scene == "bucky")
    {
      GenerateBucky(g, out);
    }
    else if (this->Scene == "rods")
    {
      GenerateRods(g, out);
    }
    else if (this->Scene == "clouds")
    {
      GenerateClouds(g, out);
    }
    else
    {
      GenerateSpheres(g, out);
    }
    array->SetName("scalars");
    image->GetPointData()->SetScalars(array);
  }
  this->Volume = image;
  this->LastGenerationTime =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return this->Volume;
}

//------------------------------------------------------------------------------
vtkVolumeProperty* vtkDeepShadowStandardScene::GetVolumeProperty()
{
  if (this->Property)
  {
    return this->Property;
  }
  const SceneSpec& spec = *FindSpec(this->Scene);
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkColorTransferFunction> color;
  vtkNew<vtkPiecewiseFunction> opacity;
  BuildProperty(this->Scene, color, opacity, property);
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->ShadeOn();
  property->SetInterpolationTypeToLinear();
  // One voxel at full resolution: the look stays the same at any resolution scale.
  property->SetScalarOpacityUnitDistance(
    std::min(std::min(spec.Spacing[0], spec.Spacing[1]), spec.Spacing[2]));
  this->Property = property;
  return this->Property;
}

//------------------------------------------------------------------------------
void vtkDeepShadowStandardScene::ApplyCamera(vtkCamera* camera)
{
  if (!camera)
  {
    vtkErrorMacro(<< "ApplyCamera: no camera given");
    return;
  }
  const SceneSpec& spec = *FindSpec(this->Scene);
  const Grid g(spec, this->ResolutionScale);
  double dir[3];
  Direction(spec.CameraAzimuth, spec.CameraElevation, dir);
  const double up[3] = { 0.0, 0.0, 1.0 };
  // Camera basis: right = up x dir, true up = dir x right.
  double right[3] = { up[1] * dir[2] - up[2] * dir[1], up[2] * dir[0] - up[0] * dir[2],
    up[0] * dir[1] - up[1] * dir[0] };
  const double rn = std::sqrt(right[0] * right[0] + right[1] * right[1] + right[2] * right[2]);
  for (double& c : right)
  {
    c /= rn;
  }
  const double trueUp[3] = { dir[1] * right[2] - dir[2] * right[1],
    dir[2] * right[0] - dir[0] * right[2], dir[0] * right[1] - dir[1] * right[0] };

  // Smallest distance at which every corner of the bounds lies inside the 30-degree view cone
  // (square viewport), with a 12 % margin.
  const double tanHalf = std::tan(15.0 * 3.14159265358979323846 / 180.0) / 1.12;
  double distance = 0.0;
  for (int corner = 0; corner < 8; ++corner)
  {
    double c[3];
    for (int a = 0; a < 3; ++a)
    {
      c[a] = ((corner >> a) & 1) ? g.HalfExtent[a] : -g.HalfExtent[a];
    }
    const double x = c[0] * right[0] + c[1] * right[1] + c[2] * right[2];
    const double y = c[0] * trueUp[0] + c[1] * trueUp[1] + c[2] * trueUp[2];
    const double z = c[0] * dir[0] + c[1] * dir[1] + c[2] * dir[2];
    distance = std::max(distance, z + std::max(std::fabs(x), std::fabs(y)) / tanHalf);
  }
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetPosition(distance * dir[0], distance * dir[1], distance * dir[2]);
  camera->SetViewUp(trueUp);
  camera->SetViewAngle(30.0);
}

void vtkDeepShadowStandardScene::GetLightDirection(double dir[3])
{
  const SceneSpec& spec = *FindSpec(this->Scene);
  Direction(spec.LightAzimuth, spec.LightElevation, dir);
}

double vtkDeepShadowStandardScene::GetSuggestedSampleDistance()
{
  double spacing[3];
  this->GetSpacing(spacing);
  return 0.5 * std::min(std::min(spacing[0], spacing[1]), spacing[2]);
}

//------------------------------------------------------------------------------
void vtkDeepShadowStandardScene::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  int dims[3];
  double spacing[3];
  this->GetDimensions(dims);
  this->GetSpacing(spacing);
  os << indent << "Scene: " << this->Scene << "\n";
  os << indent << "ResolutionScale: " << this->ResolutionScale << "\n";
  os << indent << "Dimensions: " << dims[0] << " " << dims[1] << " " << dims[2] << "\n";
  os << indent << "Spacing: " << spacing[0] << " " << spacing[1] << " " << spacing[2] << "\n";
  os << indent << "Volume: " << (this->Volume ? "generated" : "(none)") << "\n";
  os << indent << "LastGenerationTime: " << this->LastGenerationTime << "\n";
}
