#include "Look.h"

#include "SceneSetup.h"

#include "Core/Isosurface.h"

#include "vtkDeepShadowVolumePresets.h"

#include "vtkCamera.h"
#include "vtkContourValues.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtk_jsoncpp.h"

#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <sstream>

namespace deepshadow
{
namespace tool
{
namespace
{
// Patient directions in world coordinates, DICOM's (LPS: +x the patient's left, +y
// posterior, +z superior), where a reader that honours the direction matrix puts the data:
// the direction from the centre towards the camera, and the view-up.
struct PatientView
{
  const char* Name;
  std::array<double, 3> ToCamera;
  std::array<double, 3> Up;
};
const PatientView PatientViews[] = {
  { "anterior", { 0, -1, 0 }, { 0, 0, 1 } },
  { "posterior", { 0, 1, 0 }, { 0, 0, 1 } },
  { "left", { 1, 0, 0 }, { 0, 0, 1 } },
  { "right", { -1, 0, 0 }, { 0, 0, 1 } },
  { "superior", { 0, 0, 1 }, { 0, -1, 0 } },
  { "inferior", { 0, 0, -1 }, { 0, -1, 0 } },
};

std::string ViewNames()
{
  std::string names;
  for (const PatientView& view : PatientViews)
  {
    names += (names.empty() ? "" : "|") + std::string(view.Name);
  }
  return names;
}

double ParseAngle(const std::string& key, const std::string& text)
{
  const double value = ParseNumber(key, text);
  if (std::abs(value) > 360.0)
  {
    throw UsageError(key + " is in degrees, within [-360, 360]");
  }
  return value;
}

// A JSON array of three finite numbers, or UsageError.
std::array<double, 3> Vector3(const ::Json::Value& value, const std::string& what)
{
  std::array<double, 3> v{};
  if (!value.isArray() || value.size() != 3)
  {
    throw UsageError(what + " must be an array of three numbers");
  }
  for (::Json::ArrayIndex c = 0; c < 3; ++c)
  {
    if (!value[c].isNumeric() || !std::isfinite(value[c].asDouble()))
    {
      throw UsageError(what + " must be an array of three finite numbers");
    }
    v[c] = value[c].asDouble();
  }
  return v;
}

// View angles a camera file may give: VTK clamps to [1e-8, 179] without a word, and pictures
// were measured right down to 1e-5 degrees (a camera 3e8 away framing a 52-unit volume) but
// not at 3e-6; 1e-4 keeps a factor of ten.
constexpr double MinViewAngle = 1e-4;
constexpr double MaxViewAngle = 179.0;

void ReadCamera(const std::string& path, vtkCamera* camera)
{
  const std::string where = "camera file '" + path + "'";
  if (!vtksys::SystemTools::FileExists(path, true))
  {
    throw UsageError("cannot read " + where + ": no such file");
  }
  // At most the limit is read, whatever the file's size claims (/dev/urandom claims none).
  constexpr size_t limit = 1024 * 1024;
  std::ifstream in(path, std::ios::binary);
  std::string text(limit + 1, '\0');
  in.read(&text[0], static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<size_t>(std::max<std::streamsize>(in.gcount(), 0)));
  if (text.size() > limit)
  {
    throw UsageError("cannot read " + where + ": larger than a camera needs (1 MiB)");
  }
  std::istringstream file(text);
  ::Json::CharReaderBuilder builder;
  builder["stackLimit"] = 16;
  ::Json::Value root;
  std::string errors;
  bool parsed = false;
  try
  {
    parsed = ::Json::parseFromStream(builder, file, &root, &errors);
  }
  catch (const std::exception& e)
  {
    errors = e.what();
  }
  if (!parsed || !root.isObject())
  {
    throw UsageError("cannot read " + where + ": not a JSON object (" +
      errors.substr(0, errors.find('\n')) + ")");
  }
  // render --json writes the camera under "camera"; a file of only the camera works too.
  const ::Json::Value& c = root.isMember("camera") ? root["camera"] : root;
  const auto position = Vector3(c["position"], where + ": \"position\"");
  const auto focal = Vector3(c["focal_point"], where + ": \"focal_point\"");
  const auto up = Vector3(c["view_up"], where + ": \"view_up\"");
  double toFocal[3] = { focal[0] - position[0], focal[1] - position[1], focal[2] - position[2] };
  double cross[3];
  vtkMath::Cross(toFocal, up.data(), cross);
  if (vtkMath::Norm(toFocal) == 0.0 || vtkMath::Norm(cross) <= 1e-9 * vtkMath::Norm(toFocal) * vtkMath::Norm(up.data()))
  {
    throw UsageError(where + ": the position is the focal point, or the view-up is along the "
      "view direction");
  }
  if (c.isMember("view_angle") && !c["view_angle"].isNumeric())
  {
    throw UsageError(where + ": \"view_angle\" must be a number of degrees, not " +
      (c["view_angle"].isString() ? "the string \"" + c["view_angle"].asString().substr(0, 20) + "\""
                                  : std::string("a value of another type")));
  }
  const double angle = c.isMember("view_angle") ? c["view_angle"].asDouble() : 30.0;
  if (!(angle >= MinViewAngle && angle <= MaxViewAngle))
  {
    std::ostringstream message;
    message << where << ": \"view_angle\" must be in [" << MinViewAngle << ", " << MaxViewAngle
            << "] degrees, not " << angle;
    throw UsageError(message.str());
  }
  camera->SetPosition(position.data());
  camera->SetFocalPoint(focal.data());
  camera->SetViewUp(up.data());
  camera->SetViewAngle(angle);
  camera->OrthogonalizeViewUp();
}
}

bool ParseLookOption(Options& o, const std::string& key, const std::function<std::string()>& next)
{
  if (key == "--tf")
  {
    o.TransferFunction = next();
  }
  else if (key == "--window" || key == "--opacity-unit-distance")
  {
    const double value = ParseNumber(key, next());
    if (!(value > 0.0))
    {
      throw UsageError(key + " must be positive");
    }
    (key == "--window" ? o.Window : o.OpacityUnitDistance) = value;
  }
  else if (key == "--level")
  {
    o.Level = ParseNumber(key, next());
  }
  else if (key == "--shade")
  {
    const std::string value = next();
    if (value != "on" && value != "off")
    {
      throw UsageError("--shade takes on or off, not '" + value + "'");
    }
    o.Shade = value == "on";
    o.ShadeGiven = true;
  }
  else if (key == "--isosurface")
  {
    o.IsoValues.clear();
    std::stringstream values(next());
    for (std::string part; std::getline(values, part, ',');)
    {
      o.IsoValues.push_back(ParseNumber(key, part));
    }
    if (o.IsoValues.size() > static_cast<size_t>(MaxIsoValues))
    {
      throw UsageError("--isosurface takes at most " + std::to_string(MaxIsoValues) + " contour values");
    }
  }
  else if (key == "--gradient-opacity")
  {
    o.GradientOpacityFull = ParseNumber(key, next());
    if (!(o.GradientOpacityFull > 0.0))
    {
      throw UsageError("--gradient-opacity must be positive");
    }
  }
  else if (key == "--ambient" || key == "--diffuse" || key == "--specular")
  {
    const double value = ParseNumber(key, next());
    if (value < 0.0 || value > 1.0)
    {
      throw UsageError(key + " must be in [0, 1]");
    }
    (key == "--ambient" ? o.Ambient : key == "--diffuse" ? o.Diffuse : o.Specular) = value;
  }
  else if (key == "--view")
  {
    o.View = vtksys::SystemTools::LowerCase(next());
    if (std::none_of(std::begin(PatientViews), std::end(PatientViews),
          [&](const PatientView& view) { return o.View == view.Name; }))
    {
      throw UsageError("--view takes " + ViewNames() + ", not '" + o.View + "'");
    }
  }
  else if (key == "--azimuth" || key == "--elevation" || key == "--roll")
  {
    const double value = ParseAngle(key, next());
    (key == "--azimuth" ? o.Azimuth : key == "--elevation" ? o.Elevation : o.Roll) = value;
  }
  else if (key == "--zoom")
  {
    o.Zoom = ParseNumber(key, next());
    if (!(o.Zoom >= 0.01 && o.Zoom <= 100.0))
    {
      throw UsageError("--zoom must be in [0.01, 100]");
    }
  }
  else if (key == "--camera")
  {
    o.CameraFile = next();
  }
  else
  {
    return false;
  }
  return true;
}

void ValidateLook(const Options& o, const std::vector<std::string>& args)
{
  const bool level = std::find(args.begin(), args.end(), "--level") != args.end();
  if ((o.Window > 0.0) != level)
  {
    throw UsageError("--window and --level go together");
  }
  if (o.Window > 0.0 && o.TransferFunction.empty())
  {
    throw UsageError("--window/--level set the range of a --tf preset; give --tf too");
  }
  if (!o.CameraFile.empty() &&
    (!o.View.empty() || o.Azimuth != 0.0 || o.Elevation != 0.0 || o.Roll != 0.0 || o.Zoom != 1.0))
  {
    throw UsageError("--camera sets the whole camera; leave out --view, --azimuth, "
                     "--elevation, --roll and --zoom");
  }
}

std::string LookUsage()
{
  return R"(  --tf NAME|FILE          the transfer function: a preset (see `deepshadow presets`: CT-Bone,
                          CT-Skin, CT-Muscle, CT-Soft-Tissue, CT-Lung, MR-Default, MR-Angio)
                          or a ParaView JSON preset file (RGBPoints, Points). Default: the
                          scene's, or a grey ramp over a file's range
  --window W --level L    map the preset's range onto [L - W/2, L + W/2] (data units)
  --opacity-unit-distance D  world distance the opacities are for (default: the preset's,
                          or the smallest voxel edge)
  --shade on|off          gradient shading (default on; a preset may turn it off)
  --isosurface V[,V...]   isosurface blending at these contour values (data units, at most
                          16): the surfaces are drawn, lit, and cast the shadows
  --gradient-opacity G    opacity times 0 below G/10 of gradient magnitude, rising to 1 at G
                          (data units per mean voxel edge, as VTK's gradient opacity)
  --ambient A, --diffuse D, --specular S   lighting coefficients in [0, 1]
  --view )" + ViewNames() + R"(
                          look at the volume from that patient side (world axes as DICOM's:
                          x to the patient's left, y posterior, z superior), the whole
                          volume in view
  --azimuth A, --elevation E, --roll R   then turn the camera (degrees, VTK's vtkCamera)
  --zoom Z                then zoom (above 1 closer; 0.01 to 100)
  --camera FILE           the whole camera from JSON (position, focal_point, view_up,
                          view_angle), e.g. the "camera" render --json wrote
)";
}

void ApplyAppearance(const Options& options, vtkImageData* data, vtkVolumeProperty* property)
{
  if (!options.TransferFunction.empty())
  {
    vtkNew<vtkDeepShadowVolumePresets> presets;
    if (options.Window > 0.0)
    {
      presets->SetWindowLevel(options.Window, options.Level);
      if (!presets->GetLastError().empty())
      {
        throw UsageError("--window/--level: " + presets->GetLastError());
      }
    }
    if (!presets->Apply(options.TransferFunction, property))
    {
      throw UsageError(presets->GetLastError());
    }
    const std::string warning = vtkDeepShadowVolumePresets::DataWarning(options.TransferFunction, data);
    if (!warning.empty())
    {
      vtkWarningWithObjectMacro(presets, << warning);
    }
    property->SetScalarOpacityUnitDistance(SmallestSpacing(data));
  }
  if (options.ShadeGiven || options.TransferFunction.empty())
  {
    property->SetShade(options.Shade ? 1 : 0);
  }
  if (options.OpacityUnitDistance > 0.0)
  {
    property->SetScalarOpacityUnitDistance(options.OpacityUnitDistance);
  }
  if (options.Ambient >= 0.0)
  {
    property->SetAmbient(options.Ambient);
  }
  if (options.Diffuse >= 0.0)
  {
    property->SetDiffuse(options.Diffuse);
  }
  if (options.Specular >= 0.0)
  {
    property->SetSpecular(options.Specular);
  }
  for (size_t i = 0; i < options.IsoValues.size(); ++i)
  {
    property->GetIsoSurfaceValues()->SetValue(static_cast<int>(i), options.IsoValues[i]);
  }
  if (options.GradientOpacityFull > 0.0)
  {
    vtkNew<vtkPiecewiseFunction> gradient;
    gradient->AddPoint(0.0, 0.0);
    gradient->AddPoint(0.1 * options.GradientOpacityFull, 0.0);
    gradient->AddPoint(options.GradientOpacityFull, 1.0);
    property->SetGradientOpacity(gradient);
  }
}

void ApplyView(const Options& options, vtkRenderer* renderer, vtkVolume* volume)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  if (!options.CameraFile.empty())
  {
    ReadCamera(options.CameraFile, camera);
    return;
  }
  if (!options.View.empty())
  {
    const auto view = std::find_if(std::begin(PatientViews), std::end(PatientViews),
      [&](const PatientView& v) { return options.View == v.Name; });
    const double* centre = volume->GetCenter();
    camera->SetFocalPoint(centre);
    camera->SetPosition(centre[0] + view->ToCamera[0], centre[1] + view->ToCamera[1],
      centre[2] + view->ToCamera[2]);
    camera->SetViewUp(view->Up.data());
    renderer->ResetCamera(volume->GetBounds());
  }
  camera->Azimuth(options.Azimuth);
  camera->Elevation(options.Elevation);
  camera->Roll(options.Roll);
  camera->OrthogonalizeViewUp();
  camera->Zoom(options.Zoom);
}

void RequireInView(vtkRenderer* renderer, int width, int height)
{
  double bounds[6];
  renderer->ComputeVisiblePropBounds(bounds);
  if (!(bounds[0] <= bounds[1]))
  {
    return;
  }
  // Clip coordinates of the box's corners: outside the view when all lie beyond one plane.
  vtkCamera* camera = renderer->GetActiveCamera();
  vtkMatrix4x4* toClip =
    camera->GetCompositeProjectionTransformMatrix(static_cast<double>(width) / height, -1.0, 1.0);
  int outside[6] = { 0, 0, 0, 0, 0, 0 };
  for (int corner = 0; corner < 8; ++corner)
  {
    const double p[4] = { bounds[corner & 1], bounds[2 + ((corner >> 1) & 1)], bounds[4 + (corner >> 2)], 1.0 };
    double c[4];
    toClip->MultiplyPoint(p, c);
    for (int axis = 0; axis < 3; ++axis)
    {
      outside[2 * axis] += c[axis] < -c[3] ? 1 : 0;
      outside[2 * axis + 1] += c[axis] > c[3] ? 1 : 0;
    }
  }
  if (std::find(std::begin(outside), std::end(outside), 8) != std::end(outside))
  {
    const double* position = camera->GetPosition();
    const double* focal = camera->GetFocalPoint();
    std::ostringstream message;
    message << "the camera sees nothing of the scene: from (" << position[0] << ", " << position[1]
            << ", " << position[2] << ") towards (" << focal[0] << ", " << focal[1] << ", "
            << focal[2] << ") it looks away from the volume, whose box is [" << bounds[0] << ", "
            << bounds[1] << "] x [" << bounds[2] << ", " << bounds[3] << "] x [" << bounds[4]
            << ", " << bounds[5] << "]";
    throw UsageError(message.str());
  }
}

Json CameraJson(vtkCamera* camera)
{
  auto vector = [](const double* v) { return std::vector<double>(v, v + 3); };
  Json json;
  json.SetExact("position", vector(camera->GetPosition()))
    .SetExact("focal_point", vector(camera->GetFocalPoint()))
    .SetExact("view_up", vector(camera->GetViewUp()))
    .SetExact("view_angle", camera->GetViewAngle());
  return json;
}

}
}
