// The "sparse" standard scene: small objects far apart in a wide, flat, mostly empty volume.
#include "StandardSceneSparse.h"
#include "StandardSceneVoxels.h"

#include <vector>

namespace deepshadow
{
namespace scenes
{
namespace
{
enum class Kind
{
  Ball,     // a solid sphere
  Shell,    // a hollow sphere
  Molecule, // seven balls: one in the middle, six along the axes
  Torus,    // a ring around the z or x axis
  Cube,     // a solid cube
  Cross     // three rods along the axes
};

struct SparseObject
{
  Kind Shape;
  double Centre[3];
  double Radius;
  double Value; // the colour band (the transfer function's)
  int Axis;     // the torus's: 2 (z) or 0 (x)
};

double Length(double x, double y, double z)
{
  return std::sqrt(x * x + y * y + z * z);
}

// Signed distance (negative inside) from p, relative to the object's centre.
double Distance(const SparseObject& o, const double p[3])
{
  const double r = o.Radius;
  const double x = p[0], y = p[1], z = p[2];
  switch (o.Shape)
  {
    case Kind::Ball:
      return Length(x, y, z) - r;
    case Kind::Shell:
      return std::fabs(Length(x, y, z) - 0.8 * r) - 0.2 * r;
    case Kind::Molecule:
    {
      double d = Length(x, y, z) - 0.4 * r;
      const double a = 0.62 * r;
      for (int axis = 0; axis < 3; ++axis)
      {
        for (const double s : { -a, a })
        {
          const double q[3] = { x - (axis == 0 ? s : 0.0), y - (axis == 1 ? s : 0.0), z - (axis == 2 ? s : 0.0) };
          d = std::min(d, Length(q[0], q[1], q[2]) - 0.36 * r);
        }
      }
      return d;
    }
    case Kind::Torus:
    {
      // Around z, or around x (axis 0).
      const double u = o.Axis == 0 ? y : x, v = o.Axis == 0 ? z : y, w = o.Axis == 0 ? x : z;
      const double ring = std::sqrt(u * u + v * v) - 0.72 * r;
      return std::sqrt(ring * ring + w * w) - 0.28 * r;
    }
    case Kind::Cube:
      return std::max({ std::fabs(x), std::fabs(y), std::fabs(z) }) - 0.7 * r;
    case Kind::Cross:
    default:
    {
      double d = 1e30;
      const double c[3] = { x, y, z };
      for (int axis = 0; axis < 3; ++axis)
      {
        const double a = c[(axis + 1) % 3], b = c[(axis + 2) % 3];
        d = std::min(d, std::max(std::sqrt(a * a + b * b) - 0.2 * r, std::fabs(c[axis]) - r));
      }
      return d;
    }
  }
}

// The objects: the focus and its ring by hand, the others one per free cell, their shape,
// colour, size and place from the cell's hash; `count` (0: all 19) keeps the first, or adds
// up to 5 more, smaller, between cells away from the focus (scaling studies).
std::vector<SparseObject> SparseObjects(int count)
{
  std::vector<SparseObject> objects;
  objects.push_back({ Kind::Molecule, { sparse::Focus[0], sparse::Focus[1], sparse::Focus[2] }, 11.0, 200.0, 2 });
  objects.push_back({ Kind::Torus,
    { sparse::FocusCaster[0], sparse::FocusCaster[1], sparse::FocusCaster[2] }, 9.0, 240.0, 2 });
  const double values[6] = { 60.0, 100.0, 140.0, 170.0, 200.0, 240.0 };
  for (int row = 0; row < sparse::Rows; ++row)
  {
    for (int column = 0; column < sparse::Columns; ++column)
    {
      const bool free = (column == sparse::FocusCell[0] && row == sparse::FocusCell[1]) ||
        (column == sparse::MeshCells[0][0] && row == sparse::MeshCells[0][1]) ||
        (column == sparse::MeshCells[1][0] && row == sparse::MeshCells[1][1]);
      if (free)
      {
        continue;
      }
      const int index = row * sparse::Columns + column;
      const auto unit = [&](uint32_t salt) { return HashUnit(Hash3(column, row, static_cast<int>(salt), 0x5a17u)); };
      SparseObject o;
      o.Shape = static_cast<Kind>(index % 6);
      o.Value = values[(index * 5 + 1) % 6];
      o.Radius = 7.0 + 4.0 * unit(0);
      o.Centre[0] = sparse::CellX(column) + 12.0 * (unit(1) - 0.5);
      o.Centre[1] = sparse::CellY(row) + 12.0 * (unit(2) - 0.5);
      o.Centre[2] = (22.0 - o.Radius) * (2.0 * unit(3) - 1.0);
      o.Axis = unit(4) < 0.5 ? 0 : 2;
      objects.push_back(o);
    }
  }
  // Between the cells: radius 7 to 9 leaves at least 2 units to the cells' objects (at most
  // 17 from their centre, 26 to 28 away).
  const double between[sparse::ExtraObjects][2] = { { -78.0, -56.0 }, { -26.0, 0.0 }, { 26.0, -56.0 },
    { -78.0, 56.0 }, { 26.0, 56.0 } };
  for (int e = 0; e < sparse::ExtraObjects && count > static_cast<int>(objects.size()); ++e)
  {
    const auto unit = [&](uint32_t salt) { return HashUnit(Hash3(e, 7, static_cast<int>(salt), 0xe17au)); };
    SparseObject o;
    o.Shape = static_cast<Kind>((e + 2) % 6);
    o.Value = values[(e * 5 + 3) % 6];
    o.Radius = 7.0 + 2.0 * unit(0);
    o.Centre[0] = between[e][0];
    o.Centre[1] = between[e][1];
    o.Centre[2] = (22.0 - o.Radius) * (2.0 * unit(3) - 1.0);
    o.Axis = unit(4) < 0.5 ? 0 : 2;
    objects.push_back(o);
  }
  if (count > 0 && count < static_cast<int>(objects.size()))
  {
    objects.resize(static_cast<size_t>(count));
  }
  return objects;
}
}

//------------------------------------------------------------------------------
// Each object is drawn over its own box of voxels (the objects do not overlap): a one-voxel
// antialiased surface and a gentle +-8 rise towards the inside, within the object's colour
// band, so that inner samples have a gradient to be shaded by.
void GenerateSparse(const Grid& g, unsigned char* out, int count)
{
  std::fill(out, out + g.Size(), static_cast<unsigned char>(0));
  const double voxel = std::max({ g.Spacing[0], g.Spacing[1], g.Spacing[2] });
  const std::vector<SparseObject> objects = SparseObjects(count);
  ForEachSlice(g.Dims[2], [&](int k) {
    unsigned char* slice = out + k * g.SliceSize();
    const double z = g.World(2, k);
    for (const SparseObject& o : objects)
    {
      const double reach = o.Radius + 2.0 * voxel;
      if (std::fabs(z - o.Centre[2]) > reach)
      {
        continue;
      }
      const auto first = [&](int axis) {
        return std::max(0, static_cast<int>(std::floor((o.Centre[axis] - reach - g.Origin[axis]) / g.Spacing[axis])));
      };
      const auto last = [&](int axis) {
        return std::min(g.Dims[axis] - 1, static_cast<int>(std::floor((o.Centre[axis] + reach - g.Origin[axis]) / g.Spacing[axis])) + 1);
      };
      for (int j = first(1); j <= last(1); ++j)
      {
        for (int i = first(0); i <= last(0); ++i)
        {
          const double p[3] = { g.World(0, i) - o.Centre[0], g.World(1, j) - o.Centre[1], z - o.Centre[2] };
          const double d = Distance(o, p);
          const double inner = o.Value - 8.0 + 16.0 * Clamp01(-d / (0.5 * o.Radius));
          const double value = inner * Clamp01(0.5 - d / voxel);
          unsigned char& voxelValue = slice[j * g.Dims[0] + i];
          voxelValue = std::max(voxelValue, Quantize<unsigned char>(value, 0, 255));
        }
      }
    }
  });
}

}
}
