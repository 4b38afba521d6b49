#include "LightingUniforms.h"

#include "vtkRenderer.h"

#include <glm/geometric.hpp>

namespace deepshadow
{

void SetLightingUniforms(UniformSink& sink, const std::vector<Light>& lights, vtkRenderer* renderer,
  const Material& material)
{
  std::vector<int> positional;
  std::vector<glm::vec3> positions, directions, diffuse, specular, attenuation;
  std::vector<float> coneCos, exponent;
  for (const Light& light : lights)
  {
    // Directional: towards the light. Positional: the spot axis, from the light.
    directions.emplace_back(light.Positional ? glm::normalize(light.FocalPoint - light.Position)
                                             : glm::normalize(light.Position - light.FocalPoint));
    positions.emplace_back(light.Position);
    diffuse.emplace_back(light.Diffuse);
    specular.emplace_back(light.Specular);
    attenuation.emplace_back(light.Attenuation);
    positional.push_back(light.Positional ? 1 : 0);
    coneCos.push_back(static_cast<float>(light.ConeCosine())); // < -1: no cone
    exponent.push_back(static_cast<float>(light.Exponent));
  }
  sink.Set("u_lightCount", static_cast<int>(lights.size()));
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
