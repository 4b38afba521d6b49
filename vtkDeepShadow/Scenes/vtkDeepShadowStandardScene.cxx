#include "vtkDeepShadowStandardScene.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkImageData.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkShortArray.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolumeProperty.h"

#include "StandardSceneSparse.h"
#include "StandardSceneVoxels.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

vtkStandardNewMacro(vtkDeepShadowStandardScene);

namespace scenes = deepshadow::scenes;
using scenes::Clamp;
using scenes::Grid;
using scenes::SceneSpec;

namespace
{
const SceneSpec Specs[] = {
  { "box", "64^3 uchar: a cube that gets more opaque towards its centre (DSM from 3D textures)",
    { 64, 64, 64 }, { 2.0, 2.0, 2.0 }, VTK_UNSIGNED_CHAR, 0.0, 35.0, 25.0, -55.0, 50.0, { 0.0, 0.0, 0.0, 0.0 } },
  { "bucky", "32^3 uchar: C60 buckyball, 60 Gaussian carbon atoms with faint bonds", { 32, 32, 32 },
    { 4.0, 4.0, 4.0 }, VTK_UNSIGNED_CHAR, 0.0, 35.0, 25.0, -55.0, 50.0, { 0.0, 0.0, 0.0, 0.0 } },
  { "rods", "64^3 uchar: thin opaque rods crossing along x, y and z (thin occluders)",
    { 64, 64, 64 }, { 2.0, 2.0, 2.0 }, VTK_UNSIGNED_CHAR, 0.0, 30.0, 22.0, -60.0, 45.0, { 0.0, 0.0, 0.0, 0.0 } },
  { "clouds", "512x512x32 uchar: fractal value-noise cloud puffs in a flat slab", { 512, 512, 32 },
    { 0.45, 0.45, 0.45 }, VTK_UNSIGNED_CHAR, 0.0, 25.0, 38.0, -40.0, 40.0, { 0.0, 0.0, 0.0, 0.0 } },
  { "spheres", "128^3 uchar: seven translucent spheres of different sizes and values (CSSM)",
    { 128, 128, 128 }, { 1.0, 1.0, 1.0 }, VTK_UNSIGNED_CHAR, 0.0, 30.0, 20.0, -45.0, 55.0, { 0.0, 0.0, 0.0, 0.0 } },
  { "head", "256x256x160 short: CT-like head phantom in Hounsfield units, 0.9x0.9x1.5 mm",
    { 256, 256, 160 }, { 0.9, 0.9, 1.5 }, VTK_SHORT, -1000.0, 35.0, 12.0, -15.0, 50.0, { 0.0, 0.0, 0.0, 0.0 } },
  { "sparse", "256x256x48 uchar: 19 small objects far apart in a wide flat slab, the camera close to one (clustered DSM)",
    { 256, 256, 48 }, { 1.0, 1.0, 1.0 }, VTK_UNSIGNED_CHAR, 0.0, 45.0, 12.0, scenes::sparse::LightAzimuth,
    scenes::sparse::LightElevation,
    { scenes::sparse::Focus[0], scenes::sparse::Focus[1], scenes::sparse::Focus[2], scenes::sparse::FocusRadius } },
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
// Recommended transfer functions.

// One flat colour band of +-12 around each value (value, r, g, b): a colour per object.
template <size_t N>
void AddColorBands(vtkColorTransferFunction* color, const double (&bands)[N][4])
{
  for (const auto& b : bands)
  {
    color->AddRGBPoint(b[0] - 12.0, b[1], b[2], b[3]);
    color->AddRGBPoint(b[0] + 12.0, b[1], b[2], b[3]);
  }
}

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
    AddColorBands(color, bands);
  }
  else if (name == "sparse")
  {
    // Green and cyan objects translucent, blue half, purple, red and orange ones opaque.
    property->SetAmbient(0.3);
    opacity->AddPoint(0.0, 0.0);
    opacity->AddPoint(25.0, 0.0);
    opacity->AddPoint(45.0, 0.05);
    opacity->AddPoint(110.0, 0.1);
    opacity->AddPoint(155.0, 0.55);
    opacity->AddPoint(255.0, 0.9);
    const double bands[][4] = { { 60.0, 0.3, 0.85, 0.35 }, { 100.0, 0.25, 0.8, 0.9 },
      { 140.0, 0.3, 0.4, 1.0 }, { 170.0, 0.7, 0.35, 0.9 }, { 200.0, 0.95, 0.3, 0.25 },
      { 240.0, 1.0, 0.65, 0.15 } };
    AddColorBands(color, bands);
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

void vtkDeepShadowStandardScene::SetObjectCount(int count)
{
  count = std::clamp(count, 0, GetMaxObjectCount());
  if (count != this->ObjectCount)
  {
    this->ObjectCount = count;
    this->Invalidate();
  }
}

int vtkDeepShadowStandardScene::GetMaxObjectCount()
{
  return scenes::sparse::Objects + scenes::sparse::ExtraObjects;
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
    scenes::GenerateHead(g, array->GetPointer(0));
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
      scenes::GenerateBox(g, out);
    }
    else if (this->Scene == "bucky")
    {
      scenes::GenerateBucky(g, out);
    }
    else if (this->Scene == "rods")
    {
      scenes::GenerateRods(g, out);
    }
    else if (this->Scene == "clouds")
    {
      scenes::GenerateClouds(g, out);
    }
    else if (this->Scene == "sparse")
    {
      scenes::GenerateSparse(g, out, this->ObjectCount);
    }
    else
    {
      scenes::GenerateSpheres(g, out);
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

  // A scene with a focus: that sphere in the 30-degree view cone with a 12 % margin.
  const double tanHalf = std::tan(15.0 * 3.14159265358979323846 / 180.0) / 1.12;
  if (spec.Focus[3] > 0.0)
  {
    const double distance = spec.Focus[3] / std::sin(std::atan(tanHalf));
    camera->SetFocalPoint(spec.Focus[0], spec.Focus[1], spec.Focus[2]);
    camera->SetPosition(spec.Focus[0] + distance * dir[0], spec.Focus[1] + distance * dir[1],
      spec.Focus[2] + distance * dir[2]);
    camera->SetViewUp(trueUp);
    camera->SetViewAngle(30.0);
    return;
  }
  // Otherwise the smallest distance at which every corner of the bounds lies inside that cone
  // (square viewport).
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

double* vtkDeepShadowStandardScene::GetLightDirection()
{
  this->GetLightDirection(this->LightDirection);
  return this->LightDirection;
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
  os << indent << "ObjectCount: " << this->ObjectCount << "\n";
  os << indent << "Dimensions: " << dims[0] << " " << dims[1] << " " << dims[2] << "\n";
  os << indent << "Spacing: " << spacing[0] << " " << spacing[1] << " " << spacing[2] << "\n";
  os << indent << "Volume: " << (this->Volume ? "generated" : "(none)") << "\n";
  os << indent << "LastGenerationTime: " << this->LastGenerationTime << "\n";
}
