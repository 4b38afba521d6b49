// Internal to DeepShadow::Scenes: the layout of the "sparse" standard scene, shared by its
// generator (StandardSceneSparse.cxx) and its hybrid variant (vtkDeepShadowHybridScene), which
// puts meshes into the cells the generator leaves free.
//
// Paper 000's Fig. 3 situation: small objects spread over an extent many times their size, the
// camera close to one of them, far from the centre of the light's view. World units (voxels at
// scale 1): the volume spans 255 x 255 x 47 around the origin.
#ifndef deepshadow_StandardSceneSparse_h
#define deepshadow_StandardSceneSparse_h

namespace deepshadow
{
namespace scenes
{
namespace sparse
{
// A 5 x 4 grid of cells, one object (radius 7 to 11, jittered) per cell: 19 objects with the
// focus's ring; SetObjectCount keeps fewer, or adds up to ExtraObjects between the cells.
constexpr int Objects = 19;
constexpr int ExtraObjects = 5;
constexpr int Columns = 5;
constexpr int Rows = 4;
inline double CellX(int column)
{
  return (column - 2) * 52.0;
}
inline double CellY(int row)
{
  return (row - 1.5) * 56.0;
}
// The cell of the object the camera looks at (placed by hand, with the ring that shadows it),
// and the two cells the hybrid variant fills with meshes.
constexpr int FocusCell[2] = { 4, 0 };
constexpr int MeshCells[2][2] = { { 0, 3 }, { 2, 2 } };
// The object the camera looks at, and the radius of the sphere ApplyCamera frames around it.
constexpr double Focus[3] = { 96.0, -84.0, -8.0 };
constexpr double FocusRadius = 24.0;
// A ring between it and the light (Focus + 26 units towards the light, 10 along +x), whose
// shadow falls on its +x half.
constexpr double FocusCaster[3] = { 106.0, -100.7, 11.9 };
// The key light (azimuth, elevation in degrees; the spec table's convention): mostly along z,
// so that the hybrid variant's ground lies under the slab.
constexpr double LightAzimuth = 0.0;
constexpr double LightElevation = 50.0;
}
}
}
#endif
