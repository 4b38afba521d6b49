// VTK objects -> Core: the renderer's lights, the key light a lone headlight becomes, and how
// they shade a volume (VTK's shading or Blinn-Phong, Core/VolumeShading.h).
#include "CoreAdapter.h"

#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkRenderer.h"
#include "vtkVersionMacros.h"
#include "vtkVolume.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace deepshadow
{
namespace adapter
{
namespace
{
glm::dmat3 Diagonal(const glm::dvec3& d)
{
  glm::dmat3 m(1.0);
  m[0][0] = d.x;
  m[1][1] = d.y;
  m[2][2] = d.z;
  return m;
}
}

std::string CheckLights(const std::vector<Light>& lights)
{
  for (size_t i = 0; i < lights.size(); ++i)
  {
    const Light& light = lights[i];
    const glm::dvec3 p = light.Position, f = light.FocalPoint;
    const std::string name = "light " + std::to_string(i);
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z) || !std::isfinite(f.x) ||
      !std::isfinite(f.y) || !std::isfinite(f.z))
    {
      return name + "'s position or focal point is not finite";
    }
    const glm::dvec3 d = p - f;
    if (!light.Positional &&
      (p == f || !std::isfinite(d.x) || !std::isfinite(d.y) || !std::isfinite(d.z)))
    {
      return name + " is directional and its position minus its focal point is " +
        (p == f ? "zero" : "not finite") + ": it has no direction";
    }
    const double farthest = std::max({ std::abs(p.x), std::abs(p.y), std::abs(p.z) });
    if (light.Positional && farthest > MaxLightCoordinate)
    {
      std::ostringstream why;
      why << name << " is positional at " << farthest << " world units; single-precision GPU "
          << "lighting needs at most " << MaxLightCoordinate << " (make it directional)";
      return why.str();
    }
  }
  return std::string();
}

std::vector<Light> MakeLights(vtkRenderer* renderer, bool* truncated)
{
  std::vector<Light> lights;
  if (truncated)
  {
    *truncated = false;
  }
  vtkLightCollection* collection = renderer->GetLights();
  vtkCollectionSimpleIterator it;
  collection->InitTraversal(it);
  while (vtkLight* light = collection->GetNextLight(it))
  {
    if (!light->GetSwitch() || light->GetIntensity() <= 0.0)
    {
      continue;
    }
    if (static_cast<int>(lights.size()) == MaxLights)
    {
      if (truncated)
      {
        *truncated = true;
      }
      break;
    }
    Light l;
    l.Positional = light->GetPositional() != 0;
    double position[3], focal[3];
    light->GetTransformedPosition(position);
    light->GetTransformedFocalPoint(focal);
    l.Position = ToGlm3(position);
    l.FocalPoint = ToGlm3(focal);
    if (!l.Positional)
    {
      // Only the direction matters: one unit from the focal point, normalised after scaling
      // by the largest component, so that 1e308 does not overflow to an infinite length.
      const glm::dvec3 d = l.Position - l.FocalPoint;
      const double largest = std::max({ std::abs(d.x), std::abs(d.y), std::abs(d.z) });
      if (std::isfinite(largest) && largest > 0.0)
      {
        l.Position = l.FocalPoint + glm::normalize(d / largest);
      }
    }
    l.Diffuse = ToGlm3(light->GetDiffuseColor()) * light->GetIntensity();
    l.Specular = ToGlm3(light->GetSpecularColor()) * light->GetIntensity();
    l.Attenuation = ToGlm3(light->GetAttenuationValues());
    l.ConeAngle = light->GetConeAngle();
    l.Exponent = light->GetExponent();
    l.ShadowAttenuation = light->GetShadowAttenuation();
    l.Eye = ToGlm3(position);
    l.ShadedFromEye = light->LightTypeIsHeadlight() && light->GetIntensity() == 1.0;
    l.LoneHeadlight = light->LightTypeIsHeadlight() && !l.Positional;
    lights.push_back(l);
  }
  // VTK's mappers treat a lone headlight of intensity 1 as their simplest lighting; the
  // volume mapper then shades it from the eye (Light::ShadedFromEye).
  int switchedOn = 0;
  collection->InitTraversal(it);
  while (vtkLight* light = collection->GetNextLight(it))
  {
    switchedOn += light->GetSwitch() ? 1 : 0;
  }
  if (switchedOn != 1 || lights.size() != 1)
  {
    for (Light& light : lights)
    {
      light.ShadedFromEye = false;
      light.LoneHeadlight = false;
    }
  }
  return lights;
}

std::vector<Light> KeyForLoneHeadlight(vtkRenderer* renderer, std::vector<Light> lights, const KeyLight& key, bool* replaced)
{
  if (replaced)
  {
    *replaced = false;
  }
  int switchedOn = 0, headlights = 0;
  vtkCollectionSimpleIterator it;
  vtkLightCollection* collection = renderer->GetLights();
  collection->InitTraversal(it);
  while (vtkLight* light = collection->GetNextLight(it))
  {
    switchedOn += light->GetSwitch() ? 1 : 0;
    headlights += light->GetSwitch() && light->LightTypeIsHeadlight() ? 1 : 0;
  }
  if (switchedOn != 1 || headlights != 1 || lights.size() != 1)
  {
    return lights;
  }
  // The camera's frame: forward (camera to focal point), up, right.
  vtkCamera* camera = renderer->GetActiveCamera();
  double position[3], focal[3], up[3];
  camera->GetPosition(position);
  camera->GetFocalPoint(focal);
  camera->GetViewUp(up);
  const glm::dvec3 forward = glm::normalize(ToGlm3(focal) - ToGlm3(position));
  const glm::dvec3 right = glm::normalize(glm::cross(forward, ToGlm3(up)));
  const glm::dvec3 upward = glm::cross(right, forward);
  const double e = glm::radians(key.Elevation), a = glm::radians(key.Azimuth);
  const glm::dvec3 towardsLight =
    std::cos(e) * std::sin(a) * right + std::sin(e) * upward - std::cos(e) * std::cos(a) * forward;
  const Light head = lights.front();
  Light keyLight = head;
  keyLight.Positional = false;
  keyLight.FocalPoint = ToGlm3(focal);
  keyLight.Position = keyLight.FocalPoint + towardsLight;
  keyLight.Diffuse = head.Diffuse * key.KeyIntensity;
  keyLight.Specular = head.Specular * key.KeyIntensity;
  keyLight.ConeAngle = 180.0;
  keyLight.ShadedFromEye = false;
  keyLight.LoneHeadlight = false;
  Light fill = head;
  fill.Diffuse = head.Diffuse * key.FillIntensity;
  fill.Specular = head.Specular * key.FillIntensity;
  fill.ShadowAttenuation = 0.0;
  fill.ShadedFromEye = false;
  fill.LoneHeadlight = false;
  if (replaced)
  {
    *replaced = true;
  }
  return { keyLight, fill };
}

VTKShadingRevision BuiltVTKShadingRevision()
{
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 2, 0)
  return VTKShadingRevision::Reflection;
#else
  return VTKShadingRevision::HalfVector;
#endif
}

ShadingPath VTKLightingPath(vtkRenderer* renderer)
{
  // vtkOpenGLGPUVolumeRayCastMapper's loop, as it is: every light of the collection is
  // looked at, so a light switched off after the headlight still leaves the headlight path
  // (and, in VTK 9.1, a positional one switched off still picks the positional path).
  const bool reflection = BuiltVTKShadingRevision() == VTKShadingRevision::Reflection;
  int complexity = 0, switchedOn = 0, positionalOn = 0;
  vtkCollectionSimpleIterator it;
  vtkLightCollection* collection = renderer->GetLights();
  collection->InitTraversal(it);
  while (vtkLight* light = collection->GetNextLight(it))
  {
    if (light->GetSwitch() > 0)
    {
      ++switchedOn;
      positionalOn += light->GetPositional() ? 1 : 0;
      complexity = std::max(complexity, 1);
    }
    if (complexity == 1 &&
      (switchedOn > 1 || light->GetIntensity() != 1.0 || !light->LightTypeIsHeadlight()))
    {
      complexity = 2;
    }
    if (!reflection && complexity < 3 && light->GetPositional())
    {
      complexity = 3;
      break;
    }
  }
  if (reflection && complexity == 2 && positionalOn > 0)
  {
    complexity = 3; // VTK 9.2's default lighting is the headlight's, whatever it is
  }
  return static_cast<ShadingPath>(complexity);
}

ShadingPath NextVTKLightingPath(ShadingPath previous, vtkRenderer* renderer)
{
  const ShadingPath now = VTKLightingPath(renderer);
  if (BuiltVTKShadingRevision() == VTKShadingRevision::Reflection)
  {
    return now;
  }
  return std::max(previous, now);
}

VolumeShading MakeVolumeShading(vtkRenderer* renderer, vtkVolume* volume, vtkImageData* drawn,
  vtkImageData* input, const glm::dmat4& indexToWorld, ShadingModel model, ShadingPath path, bool keyLit,
  std::vector<Light>& lights)
{
  VolumeShading shading;
  const glm::dmat3 indexToWorldLinear(indexToWorld);
  shading.IndexGradientToNormal = glm::transpose(glm::inverse(indexToWorldLinear));
  double ambient[3];
  renderer->GetAmbient(ambient);
  shading.Ambient = ToGlm3(ambient);
  if (model == ShadingModel::BlinnPhong)
  {
    return shading;
  }
  if (path == ShadingPath::BlinnPhong)
  {
    shading.Ambient = glm::dvec3(0.0); // no light on: VTK lights nothing, not even ambient
    return shading;
  }
  if (keyLit)
  {
    // Our key and fill replaced VTK's headlight path: its ambient (Ka x colour), Blinn-Phong.
    shading.Ambient = glm::dvec3(1.0);
    return shading;
  }
  shading.Path = path;
  shading.Revision = BuiltVTKShadingRevision();
  for (Light& light : lights)
  {
    light.ShadedFromEye = path == ShadingPath::VTKHeadlight;
  }
  double position[3];
  renderer->GetActiveCamera()->GetPosition(position);
  shading.Eye = ToGlm3(position);
  const glm::dmat4 volumeMatrix = ToGlm(volume->GetMatrix());
  double spacing[3];
  drawn->GetSpacing(spacing);
  const glm::dvec3 drawnSpacing = glm::max(glm::abs(ToGlm3(spacing)), glm::dvec3(1e-300));
  // VTK's texture holds the input's Dims points as texels, its texture-to-dataset matrix
  // spans the first to the last point ((Dims - 1) x spacing, its "loaded bounds"), and its
  // gradient differences points Dims / (Dims - 1) texels apart (a "cell step"), divided by
  // the spacing.
  int extent[6];
  input->GetExtent(extent);
  const glm::dvec3 dims(extent[1] - extent[0] + 1, extent[3] - extent[2] + 1, extent[5] - extent[4] + 1);
  const glm::dvec3 reach = dims / glm::max(dims - 1.0, glm::dvec3(1.0));
  if (path == ShadingPath::VTKHeadlight)
  {
    // That gradient along the texture's axes, against the eye's direction in dataset space
    // (the volume's matrix undone).
    shading.Ambient = glm::dvec3(1.0);
    shading.IndexGradientToNormal = Diagonal(reach / drawnSpacing);
    shading.WorldToShading = glm::inverse(glm::dmat3(volumeMatrix));
    return shading;
  }
  // That gradient multiplied by VTK's "texture to eye" matrix, which reaches the shader
  // transposed (BindTransformations uploads it without the transpose its other matrices get):
  // eye normal = (View x VolumeMatrix x Direction x box)^T x gradient, the gradient read as an
  // eye-space vector. In world space, with View's rotation R and VolumeMatrix x Direction =
  // indexToWorld / spacing: R^T (box / spacing) indexToWorld^T R. Only a cube-shaped box
  // keeps the true normal.
  input->GetSpacing(spacing);
  const glm::dvec3 box = glm::max(dims - 1.0, glm::dvec3(1.0)) * glm::abs(ToGlm3(spacing));
  const glm::dmat3 view(ToGlm(renderer->GetActiveCamera()->GetModelViewTransformMatrix()));
  shading.IndexGradientToNormal = glm::transpose(view) * Diagonal(box / drawnSpacing) *
    glm::transpose(indexToWorldLinear) * view * Diagonal(reach / drawnSpacing);
  glm::dvec3 ambientSum(0.0);
  vtkCollectionSimpleIterator it;
  renderer->GetLights()->InitTraversal(it);
  while (vtkLight* light = renderer->GetLights()->GetNextLight(it))
  {
    if (light->GetSwitch() > 0)
    {
      ambientSum += ToGlm3(light->GetAmbientColor()) * light->GetIntensity();
    }
  }
  shading.Ambient = ambientSum;
  // The first point, and where VTK lights each index (VolumeShading::LightingTransform).
  shading.MirrorCentre = 2.0 * glm::dvec3(indexToWorld[3]);
  const glm::dvec3 squeeze = glm::max(dims - 1.0, glm::dvec3(1.0)) / dims;
  glm::dmat4 texelCentres(Diagonal(squeeze));
  texelCentres[3] = glm::dvec4(0.5 * squeeze, 1.0);
  shading.LightingTransform = indexToWorld * texelCentres * glm::inverse(indexToWorld);
  return shading;
}

}
}
