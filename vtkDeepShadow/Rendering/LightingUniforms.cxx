#include "LightingUniforms.h"

#include "vtkRenderer.h"

#include <glm/geometric.hpp>

namespace deepshadow
{

PackedLight PackLight(const Light& light)
{
  PackedLight packed;
  packed.Positional = light.Positional ? 1 : 0;
  packed.Position = glm::vec3(light.Position);
  packed.Direction = glm::vec3(light.Positional ? glm::normalize(light.FocalPoint - light.Position)
                                                : glm::normalize(light.Position - light.FocalPoint));
  packed.Diffuse = glm::vec3(light.Diffuse);
  packed.Specular = glm::vec3(light.Specular);
  packed.Attenuation = glm::vec3(light.Attenuation);
  packed.ConeCos = static_cast<float>(light.ConeCosine());
  packed.Exponent = static_cast<float>(light.Exponent);
  return packed;
}

namespace
{
bool Looped(const Light& light, bool isotropic)
{
  return !isotropic || light.Positional || light.ShadowAttenuation != 0.0;
}
}

std::vector<int> LoopedLights(const std::vector<Light>& lights, bool isotropic)
{
  std::vector<int> looped;
  for (size_t i = 0; i < lights.size(); ++i)
  {
    if (Looped(lights[i], isotropic))
    {
      looped.push_back(static_cast<int>(i));
    }
  }
  return looped;
}

glm::vec3 UnloopedDiffuse(const std::vector<Light>& lights)
{
  glm::dvec3 sum(0.0);
  for (const Light& light : lights)
  {
    if (!Looped(light, true))
    {
      sum += light.Diffuse;
    }
  }
  return glm::vec3(sum);
}

void SetLightingUniforms(UniformSink& sink, const std::vector<Light>& lights, vtkRenderer* renderer,
  const Material& material, bool volume, bool isotropic)
{
  int fromEye = -1;
  for (size_t i = 0; volume && i < lights.size(); ++i)
  {
    if (lights[i].ShadedFromEye)
    {
      fromEye = static_cast<int>(i);
      sink.Set("u_lightEye", glm::vec3(lights[i].Eye));
    }
  }
  sink.Set("u_lightFromEye", fromEye);
  // Meshes: VTK's polygon mapper lights a lone headlight by its simplest path.
  sink.Set("u_loneHeadlight", !volume && lights.size() == 1 && lights[0].LoneHeadlight ? 1 : 0);
  std::vector<int> positional;
  std::vector<glm::vec3> positions, directions, diffuse, specular, attenuation;
  std::vector<float> coneCos, exponent;
  for (const Light& light : lights)
  {
    const PackedLight packed = PackLight(light);
    positional.push_back(packed.Positional);
    positions.push_back(packed.Position);
    directions.push_back(packed.Direction);
    diffuse.push_back(packed.Diffuse);
    specular.push_back(packed.Specular);
    attenuation.push_back(packed.Attenuation);
    coneCos.push_back(packed.ConeCos);
    exponent.push_back(packed.Exponent);
  }
  const std::vector<int> looped = LoopedLights(lights, isotropic);
  sink.Set("u_lightLoopCount", static_cast<int>(looped.size()));
  sink.Set("u_lightLoop", looped);
  sink.Set("u_lightPositional", positional);
  sink.Set("u_lightPosition", positions);
  sink.Set("u_lightDirection", directions);
  sink.Set("u_lightDiffuse", diffuse);
  sink.Set("u_lightSpecular", specular);
  sink.Set("u_lightAttenuation", attenuation);
  sink.Set("u_lightConeCos", coneCos);
  sink.Set("u_lightExponent", exponent);
  double ambient[3];
  renderer->GetAmbient(ambient);
  sink.Set("u_ambientLight", glm::vec3(ambient[0], ambient[1], ambient[2]));
  sink.Set("u_material",
    glm::vec4(material.Ambient, material.Diffuse, material.Specular, material.SpecularPower));
  sink.Set("u_twoSidedLighting", renderer->GetTwoSidedLighting() ? 1 : 0);
}

}
