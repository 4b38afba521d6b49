#include "Core/VolumeShading.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace deepshadow
{

bool VolumeShading::AmbientTimesColour() const
{
  return this->Path == ShadingPath::BlinnPhong || this->Path == ShadingPath::VTKHeadlight;
}

glm::dvec3 VolumeShading::Normal(const glm::dvec3& indexGradient) const
{
  const glm::dvec3 inward = this->IndexGradientToNormal * indexGradient;
  const double length = glm::length(inward);
  if (!(length > 0.0))
  {
    return glm::dvec3(0.0);
  }
  const bool inwards = this->Path == ShadingPath::VTKHeadlight && this->Revision == VTKShadingRevision::HalfVector;
  return inwards ? inward / length : -inward / length;
}

glm::dvec3 VolumeShading::Halfway(glm::dvec3& toLight, const glm::dvec3& toViewer, const glm::dvec3& position) const
{
  switch (this->Path)
  {
    case ShadingPath::VTKHeadlight:
      // Light and viewer both at the eye: the half vector is the light's direction.
      toLight = glm::normalize(this->WorldToShading * toLight);
      return toLight;
    case ShadingPath::VTKDirectional:
      // VTK views the point mirrored through the first voxel: eye - (2 P0 - p).
      return glm::normalize(toLight + glm::normalize(this->Eye - this->MirrorCentre + position));
    case ShadingPath::VTKPositional:
      return glm::normalize(toLight - glm::normalize(this->Eye - position));
    case ShadingPath::BlinnPhong:
      break;
  }
  return glm::normalize(toLight + toViewer);
}

PhongParts VolumeShading::LightTerms(const glm::dvec3& color, const glm::dvec3& normal, const LightSample& sample,
  bool positional, const glm::dvec3& toViewer, const glm::dvec3& litPosition, const Material& material,
  bool twoSided) const
{
  glm::dvec3 toLight = sample.ToLight;
  if (this->Path == ShadingPath::BlinnPhong || this->Revision == VTKShadingRevision::HalfVector)
  {
    const glm::dvec3 halfway = this->Halfway(toLight, toViewer, litPosition);
    return PhongTerms(color, normal, toLight, halfway, sample, material, twoSided);
  }
  // VTK 9.2 onwards. The headlight's light and viewer are the eye, in dataset space (the
  // half vector Halfway gives it is that direction).
  glm::dvec3 viewer;
  if (this->Path == ShadingPath::VTKHeadlight)
  {
    viewer = this->Halfway(toLight, toViewer, litPosition);
  }
  else
  {
    viewer = glm::normalize(this->Eye - litPosition);
  }
  PhongParts parts;
  const double facing = glm::dot(normal, toLight);
  parts.NDotL = twoSided ? std::abs(facing) : facing;
  if (!(parts.NDotL > 0.0))
  {
    return parts; // no diffuse light, and VTK gives no specular light then either
  }
  const double scale = this->Path == ShadingPath::VTKHeadlight ? facing : parts.NDotL;
  double rDotV = -glm::dot(viewer, glm::normalize(toLight - 2.0 * scale * normal));
  if (twoSided && positional && this->Path != ShadingPath::VTKHeadlight)
  {
    rDotV = std::abs(rDotV);
  }
  parts.NDotH = std::max(rDotV, 0.0);
  parts.Diffuse = material.Diffuse * parts.NDotL * sample.Diffuse * color;
  if (parts.NDotH > 0.0)
  {
    parts.Specular = material.Specular * std::pow(parts.NDotH, material.SpecularPower) * sample.Specular;
  }
  return parts;
}

}
