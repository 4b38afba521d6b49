#include "Core/VolumeShading.h"

#include <glm/geometric.hpp>

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
  return this->Path == ShadingPath::VTKHeadlight ? inward / length : -inward / length;
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

}
