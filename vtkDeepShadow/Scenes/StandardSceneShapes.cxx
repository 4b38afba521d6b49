// The analytic standard scenes: "box", "bucky", "rods" and "spheres".
#include "StandardSceneVoxels.h"

#include <array>
#include <vector>

namespace deepshadow
{
namespace scenes
{
namespace
{
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

namespace
{
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
}

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

}
}
