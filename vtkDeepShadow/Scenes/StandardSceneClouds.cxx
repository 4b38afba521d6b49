// The "clouds" standard scene: fractal value noise.
#include "StandardSceneVoxels.h"

#include <vector>

namespace deepshadow
{
namespace scenes
{

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

}
}
