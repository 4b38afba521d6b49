#include "vtkDeepShadowHybridScene.h"

#include "vtkDeepShadowBoundedScene.h"

#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkDeepShadowHybridScene);

namespace
{
// The axis the light comes most along, and from which side (+1: from the positive side).
void LightAxis(const double toLight[3], int& axis, double& side)
{
  axis = 0;
  for (int a = 1; a < 3; ++a)
  {
    if (std::abs(toLight[a]) > std::abs(toLight[axis]))
    {
      axis = a;
    }
  }
  side = toLight[axis] >= 0.0 ? 1.0 : -1.0;
}

double Extent(const double b[6])
{
  return std::max({ b[1] - b[0], b[3] - b[2], b[5] - b[4] });
}

// A box whose extent along `axis` is [from, to] (either order), and around the volume's
// centre by `halfWidth` on the other axes (shifted by `shift` on the first of them).
vtkSmartPointer<vtkPolyData> Slab(const double b[6], int axis, double from, double to, double halfWidth,
  double shift = 0.0)
{
  double box[6];
  int other = 0;
  for (int a = 0; a < 3; ++a)
  {
    const double centre = 0.5 * (b[2 * a] + b[2 * a + 1]);
    if (a == axis)
    {
      box[2 * a] = std::min(from, to);
      box[2 * a + 1] = std::max(from, to);
      continue;
    }
    const double offset = other++ == 0 ? shift : 0.0;
    box[2 * a] = centre + offset - halfWidth;
    box[2 * a + 1] = centre + offset + halfWidth;
  }
  return vtkDeepShadowBoundedScene::MakeBox(box);
}
}

std::vector<std::string> vtkDeepShadowHybridScene::GetSceneNames()
{
  return { "hybrid-ground", "hybrid-glass", "hybrid-rod" };
}

bool vtkDeepShadowHybridScene::IsSceneName(const std::string& name)
{
  const auto names = GetSceneNames();
  return std::find(names.begin(), names.end(), name) != names.end();
}

std::string vtkDeepShadowHybridScene::GetSceneDescription(const std::string& name)
{
  if (name == "hybrid-ground")
  {
    return "the spheres over a ground plane that receives their shadows";
  }
  if (name == "hybrid-glass")
  {
    return "the box scene over a ground, a translucent blue glass slab between light and volume";
  }
  if (name == "hybrid-rod")
  {
    return "the head with an opaque rod through it (a tool), over a ground";
  }
  return std::string();
}

std::string vtkDeepShadowHybridScene::GetVolumeSceneName(const std::string& name)
{
  if (name == "hybrid-ground")
  {
    return "spheres";
  }
  if (name == "hybrid-glass")
  {
    return "box";
  }
  if (name == "hybrid-rod")
  {
    return "head";
  }
  return std::string();
}

vtkDeepShadowHybridScene::Mesh vtkDeepShadowHybridScene::MakeGround(const double b[6], const double toLight[3])
{
  int axis = 2;
  double side = 1.0;
  LightAxis(toLight, axis, side);
  const double size = Extent(b);
  // Just beyond the volume's face away from the light; thin, 1.6 volumes wide.
  const double face = side > 0.0 ? b[2 * axis] : b[2 * axis + 1];
  const double near = face - side * 0.04 * size, far = near - side * 0.01 * size;
  Mesh ground;
  ground.PolyData = Slab(b, axis, near, far, 0.8 * size);
  ground.Color = { { 0.85, 0.85, 0.8 } };
  return ground;
}

std::vector<vtkDeepShadowHybridScene::Mesh> vtkDeepShadowHybridScene::MakeMeshes(
  const std::string& name, const double b[6], const double toLight[3])
{
  if (!IsSceneName(name))
  {
    return {};
  }
  std::vector<Mesh> meshes{ MakeGround(b, toLight) };
  int axis = 2;
  double side = 1.0;
  LightAxis(toLight, axis, side);
  const double size = Extent(b);
  if (name == "hybrid-glass")
  {
    // Between the light and the half of the volume on the first other axis's positive side.
    const double face = side > 0.0 ? b[2 * axis + 1] : b[2 * axis];
    Mesh glass;
    glass.PolyData = Slab(b, axis, face + side * 0.2 * size, face + side * 0.23 * size, 0.3 * size, 0.25 * size);
    glass.Opacity = 0.5;
    glass.Color = { { 0.25, 0.45, 1.0 } };
    meshes.push_back(glass);
  }
  else if (name == "hybrid-rod")
  {
    // Across the head along its longest lateral axis, a little above the centre.
    const int along = axis == 0 ? 1 : 0;
    double rod[6];
    for (int a = 0; a < 3; ++a)
    {
      const double centre = 0.5 * (b[2 * a] + b[2 * a + 1]) + (a == axis ? side * 0.1 * size : 0.0);
      const double half = a == along ? 0.65 * size : 0.015 * size;
      rod[2 * a] = centre - half;
      rod[2 * a + 1] = centre + half;
    }
    Mesh tool;
    tool.PolyData = vtkDeepShadowBoundedScene::MakeBox(rod);
    tool.Color = { { 0.75, 0.75, 0.8 } };
    meshes.push_back(tool);
  }
  return meshes;
}

void vtkDeepShadowHybridScene::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
