// The "head" standard scene: a CT-like phantom in Hounsfield units.
#include "StandardSceneVoxels.h"

#include <vector>

namespace deepshadow
{
namespace scenes
{
namespace
{
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

  // Hounsfield value of the phantom at p before the scanner blur and noise: the regions in
  // priority order; once the voxel is covered the rest are not evaluated.
  double Value(const double p[3], Composer& out) const
  {
    this->Skin(p, out);
    if (out.Full())
    {
      return out.Finish(0.0);
    }
    this->FaceSoftParts(p, out);
    if (out.Full())
    {
      return out.Finish(0.0);
    }
    this->Vault(p, out);
    if (out.Full())
    {
      return out.Finish(0.0);
    }
    this->FaceBones(p, out);
    this->Spine(p, out);
    return out.Finish(hu::Muscle);
  }

  // Skin, the fat under it, the nostrils.
  void Skin(const double p[3], Composer& out) const
  {
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
  }

  // Teeth, eyes, air spaces.
  void FaceSoftParts(const double p[3], Composer& out) const
  {
    const double x = p[0], y = p[1], z = p[2];
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
  }

  void Vault(const double p[3], Composer& out) const
  {
    const double x = p[0], y = p[1], z = p[2];
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
  }

  void FaceBones(const double p[3], Composer& out) const
  {
    const double x = p[0], y = p[1], z = p[2];
    const double base = SkullBase(y);
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
  }

  void Spine(const double p[3], Composer& out) const
  {
    const double x = p[0], y = p[1], z = p[2];
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

}
}
