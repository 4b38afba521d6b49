#include "Core/Light.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace deepshadow
{

double Light::ConeCosine() const
{
  return this->ConeAngle <= 90.0 ? std::cos(this->ConeAngle * 3.14159265358979323846 / 180.0) : -2.0;
}

LightSample Light::At(const glm::dvec3& p) const
{
  LightSample sample;
  if (!this->Positional)
  {
    sample.ToLight = glm::normalize(this->Position - this->FocalPoint);
    sample.Diffuse = this->Diffuse;
    sample.Specular = this->Specular;
    return sample;
  }
  const glm::dvec3 fromLight = p - this->Position;
  const double distance = glm::length(fromLight);
  sample.ToLight = distance > 0.0 ? -fromLight / distance : glm::dvec3(0.0, 0.0, 1.0);
  double attenuation = 1.0 /
    (this->Attenuation.x + this->Attenuation.y * distance +
      this->Attenuation.z * distance * distance);
  const double coneCos = this->ConeCosine();
  if (coneCos >= -1.0)
  {
    const glm::dvec3 axis = glm::normalize(this->FocalPoint - this->Position);
    const double coneDot = glm::dot(-sample.ToLight, axis);
    attenuation = coneDot >= coneCos ? attenuation * std::pow(coneDot, this->Exponent) : 0.0;
  }
  sample.Reach = attenuation;
  sample.Diffuse = attenuation * this->Diffuse;
  sample.Specular = attenuation * this->Specular;
  return sample;
}

LightSample Light::VolumeSampleAt(const glm::dvec3& p) const
{
  LightSample sample = this->At(p);
  if (this->ShadedFromEye && p != this->Eye)
  {
    sample.ToLight = glm::normalize(this->Eye - p);
  }
  return sample;
}

double IsotropicLightScale(const std::vector<Light>& lights)
{
  glm::dvec3 sum(0.0);
  for (const Light& light : lights)
  {
    sum += light.Diffuse;
  }
  const double largest = std::max({ sum.r, sum.g, sum.b });
  return largest > 0.0 ? 1.0 / largest : 0.0;
}

}
