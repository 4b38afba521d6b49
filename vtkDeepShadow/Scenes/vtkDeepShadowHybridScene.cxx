#include "vtkDeepShadowHybridScene.h"

#include "vtkDeepShadowBoundedScene.h"

#include "StandardSceneSparse.h"

#include "vtkCellArray.h"
#include "vtkColorTransferFunction.h"
#include "vtkImageData.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <vector>

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

// Where "hybrid-smoke" puts its cup: on the ground, beside the volume on the side the light
// comes from (so the smoke rising from it shadows the volume). `up` is the light axis.
struct CupPlace
{
  int Up = 2;
  double Side = 1.0;     // +1: the light is on the positive side of Up
  int Lateral = 0;       // the axis the cup is moved along
  double LateralSide = 1.0; // +1: the cup is on the positive side of the volume
  double Base[3] = { 0.0, 0.0, 0.0 }; // centre of the cup's bottom
  double Radius = 0.0;
  double Height = 0.0;
};

CupPlace PlaceCup(const double b[6], const double toLight[3])
{
  CupPlace cup;
  LightAxis(toLight, cup.Up, cup.Side);
  cup.Lateral = cup.Up == 0 ? 1 : 0;
  for (int a = 0; a < 3; ++a)
  {
    if (a != cup.Up && std::abs(toLight[a]) > std::abs(toLight[cup.Lateral]))
    {
      cup.Lateral = a;
    }
  }
  cup.LateralSide = toLight[cup.Lateral] >= 0.0 ? 1.0 : -1.0;
  const double size = Extent(b);
  cup.Radius = 0.09 * size;
  cup.Height = 0.22 * size;
  for (int a = 0; a < 3; ++a)
  {
    cup.Base[a] = 0.5 * (b[2 * a] + b[2 * a + 1]);
  }
  // On the ground (MakeGround's near face), one cup beyond the volume's side.
  const double face = cup.Side > 0.0 ? b[2 * cup.Up] : b[2 * cup.Up + 1];
  cup.Base[cup.Up] = face - cup.Side * 0.04 * size;
  cup.Base[cup.Lateral] = cup.LateralSide > 0.0 ? b[2 * cup.Lateral + 1] + 1.6 * cup.Radius
                                                : b[2 * cup.Lateral] - 1.6 * cup.Radius;
  return cup;
}

// A closed cylinder of `sides` sides along axis `up` (towards `side`). The caps have points of
// their own, so that the sides' point normals stay horizontal.
vtkSmartPointer<vtkPolyData> Cylinder(const CupPlace& cup, int sides)
{
  const int u = (cup.Up + 1) % 3, v = (cup.Up + 2) % 3;
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> polys;
  for (int copy = 0; copy < 2; ++copy) // rings 0, 1: the sides; 2, 3: the caps
  {
    for (int ring = 0; ring < 2; ++ring)
    {
      for (int i = 0; i < sides; ++i)
      {
        const double angle = 2.0 * 3.14159265358979323846 * i / sides;
        double p[3] = { cup.Base[0], cup.Base[1], cup.Base[2] };
        p[u] += cup.Radius * std::cos(angle);
        p[v] += cup.Radius * std::sin(angle);
        p[cup.Up] += ring * cup.Side * cup.Height;
        points->InsertNextPoint(p);
      }
    }
  }
  // Outward, counter-clockwise seen from outside.
  const bool flip = cup.Side < 0.0;
  for (int i = 0; i < sides; ++i)
  {
    const vtkIdType j = (i + 1) % sides;
    const vtkIdType quad[4] = { i, j, sides + j, sides + i };
    const vtkIdType flipped[4] = { i, sides + i, sides + j, j };
    polys->InsertNextCell(4, flip ? flipped : quad);
  }
  // A ring in ascending order faces +axis `up`: the cap at the base faces away from the cup
  // (-side), the other one towards `side`.
  for (int ring = 0; ring < 2; ++ring)
  {
    const bool facesUp = (ring == 1) == (cup.Side > 0.0);
    std::vector<vtkIdType> cap;
    for (int i = 0; i < sides; ++i)
    {
      cap.push_back(2 * sides + ring * sides + (facesUp ? i : sides - 1 - i));
    }
    polys->InsertNextCell(static_cast<vtkIdType>(cap.size()), cap.data());
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  return mesh;
}
}

std::vector<std::string> vtkDeepShadowHybridScene::GetSceneNames()
{
  return { "hybrid-ground", "hybrid-glass", "hybrid-rod", "hybrid-smoke", "hybrid-sparse" };
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
  if (name == "hybrid-smoke")
  {
    return "the head beside a smoking cup of coffee (the smoke a second volume), over a ground";
  }
  if (name == "hybrid-sparse")
  {
    return "the sparse scene over a ground, with an opaque box and a translucent blue prism among its objects";
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
  if (name == "hybrid-rod" || name == "hybrid-smoke")
  {
    return "head";
  }
  if (name == "hybrid-sparse")
  {
    return "sparse";
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
  else if (name == "hybrid-sparse")
  {
    // Standing on the ground, in the cells the sparse scene leaves free: an opaque box and a
    // tall translucent blue prism (glass).
    namespace sparse = deepshadow::scenes::sparse;
    const double ground = side > 0.0 ? b[2 * axis] - 0.04 * size : b[2 * axis + 1] + 0.04 * size;
    const double centre[2] = { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]) };
    const auto standing = [&](double x, double y, double halfWidth, double height) {
      const double box[6] = { centre[0] + x - halfWidth, centre[0] + x + halfWidth, centre[1] + y - halfWidth,
        centre[1] + y + halfWidth, std::min(ground, ground + side * height), std::max(ground, ground + side * height) };
      return vtkDeepShadowBoundedScene::MakeBox(box);
    };
    Mesh box;
    box.PolyData = standing(sparse::CellX(sparse::MeshCells[0][0]), sparse::CellY(sparse::MeshCells[0][1]), 10.0, 16.0);
    box.Color = { { 0.8, 0.75, 0.6 } };
    meshes.push_back(box);
    CupPlace prism;
    prism.Up = axis;
    prism.Side = side;
    prism.Base[0] = centre[0] + sparse::CellX(sparse::MeshCells[1][0]);
    prism.Base[1] = centre[1] + sparse::CellY(sparse::MeshCells[1][1]);
    prism.Base[2] = ground;
    prism.Radius = 8.0;
    prism.Height = 36.0;
    Mesh tower;
    tower.PolyData = Cylinder(prism, 8);
    tower.Color = { { 0.3, 0.5, 1.0 } };
    tower.Opacity = 0.5;
    meshes.push_back(tower);
  }
  else if (name == "hybrid-smoke")
  {
    Mesh cup;
    cup.PolyData = Cylinder(PlaceCup(b, toLight), 32);
    cup.Color = { { 0.92, 0.9, 0.85 } };
    meshes.push_back(cup);
  }
  return meshes;
}

vtkSmartPointer<vtkImageData> vtkDeepShadowHybridScene::MakeSmoke(
  const std::string& name, const double b[6], const double toLight[3])
{
  if (name != "hybrid-smoke")
  {
    return nullptr;
  }
  const CupPlace cup = PlaceCup(b, toLight);
  const double size = Extent(b);
  // A plume from the cup's rim up to 1.2 volume sizes above the ground, drifting over the
  // volume: 40 x 40 x 64 points (64 along the light axis).
  const double height = 1.15 * size, width = 0.55 * size;
  const int across = 40, along = 64;
  auto image = vtkSmartPointer<vtkImageData>::New();
  int dims[3];
  double spacing[3], origin[3];
  const double lateralSide = -cup.LateralSide; // the plume drifts towards the volume
  for (int a = 0; a < 3; ++a)
  {
    const bool up = a == cup.Up;
    dims[a] = up ? along : across;
    spacing[a] = (up ? height : width) / (dims[a] - 1);
    double lo = cup.Base[a] - 0.5 * width;
    if (up)
    {
      lo = cup.Side > 0.0 ? cup.Base[a] + cup.Height : cup.Base[a] - cup.Height - height;
    }
    else if (a == cup.Lateral)
    {
      lo = cup.Base[a] - 0.5 * width + lateralSide * 0.2 * width; // drifts towards the volume
    }
    origin[a] = lo;
  }
  image->SetDimensions(dims);
  image->SetSpacing(spacing);
  image->SetOrigin(origin);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  auto* density = static_cast<unsigned char*>(image->GetScalarPointer());
  for (int k = 0; k < dims[2]; ++k)
    for (int j = 0; j < dims[1]; ++j)
      for (int i = 0; i < dims[0]; ++i)
      {
        const int index[3] = { i, j, k };
        double p[3];
        for (int a = 0; a < 3; ++a)
        {
          p[a] = origin[a] + index[a] * spacing[a];
        }
        // h in [0, 1] up the plume; the axis drifts towards the volume and sways.
        const double h = cup.Side > 0.0 ? (p[cup.Up] - origin[cup.Up]) / height
                                         : (origin[cup.Up] + height - p[cup.Up]) / height;
        double r2 = 0.0;
        for (int a = 0; a < 3; ++a)
        {
          if (a == cup.Up)
          {
            continue;
          }
          double axis = cup.Base[a];
          if (a == cup.Lateral)
          {
            axis += lateralSide * (0.35 * h * h * width + 0.03 * width * std::sin(5.0 * h));
          }
          else
          {
            axis += 0.03 * width * std::sin(4.0 * h + 1.0);
          }
          r2 += (p[a] - axis) * (p[a] - axis);
        }
        const double radius = cup.Radius * (0.6 + 1.8 * h);
        const double wisps = 0.85 + 0.15 * std::sin(11.0 * h + 0.04 * (p[0] + p[1] + p[2]));
        const double value = std::exp(-r2 / (radius * radius)) * (1.0 - h * h) * std::min(1.0, 8.0 * h) * wisps;
        density[i + dims[0] * (j + dims[1] * k)] = static_cast<unsigned char>(std::lround(255.0 * std::clamp(value, 0.0, 1.0)));
      }
  return image;
}

vtkSmartPointer<vtkVolumeProperty> vtkDeepShadowHybridScene::MakeSmokeProperty()
{
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0, 0.75, 0.75, 0.78);
  color->AddRGBPoint(255, 0.95, 0.95, 0.97);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0, 0.0);
  opacity->AddPoint(15, 0.0);
  opacity->AddPoint(255, 0.35);
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetInterpolationTypeToLinear();
  property->SetAmbient(0.35);
  property->SetDiffuse(0.75);
  property->ShadeOff();
  return property;
}

void vtkDeepShadowHybridScene::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
