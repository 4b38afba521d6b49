// Internal: the Lighting feature's uniforms (Shaders/Features/Lighting.glsl), shared by the
// volume and poly-data mappers so that volumes and meshes are lit by one formula.
#ifndef vtkDeepShadowLightingUniforms_h
#define vtkDeepShadowLightingUniforms_h

#include "Core/Light.h"
#include "Core/OpticalModel.h"
#include "GL/UniformSink.h"

#include <glm/vec3.hpp>

#include <vector>

class vtkRenderer;

namespace deepshadow
{

/**
 * One light as the shaders take it: Lighting.glsl's u_light* arrays and the cached-shadow
 * pass's u_light* uniforms read the same fields, packed here only.
 */
struct PackedLight
{
  int Positional = 0;
  glm::vec3 Position{ 0.0f };
  // Unit: towards a directional light; a positional light's spot axis, from the light.
  glm::vec3 Direction{ 0.0f };
  glm::vec3 Diffuse{ 0.0f };
  glm::vec3 Specular{ 0.0f };
  glm::vec3 Attenuation{ 0.0f };
  float ConeCos = 0.0f; // < -1: no cone
  float Exponent = 0.0f;
};
PackedLight PackLight(const Light& light);

/**
 * Lights in world space (in the order given), ambient light, two-sided lighting, material.
 * `volume`: a volume's samples are shaded, with a lone headlight from the eye
 * (Light::ShadedFromEye); meshes shade every directional light as one. `isotropic`: lit
 * without a normal (the Isotropic feature), so the loop visits only LoopedLights.
 */
void SetLightingUniforms(UniformSink& sink, const std::vector<Light>& lights, vtkRenderer* renderer,
  const Material& material, bool volume, bool isotropic = false);

/**
 * The lights Lighting.glsl's loop visits (u_lightLoop): all, or, lit isotropically, only those
 * whose share differs between samples (positional, or casting a shadow). A directional light
 * that casts none gives every sample the same share without a normal: the Isotropic feature
 * adds their summed diffuse (UnloopedDiffuse: the isotropic lights LoopedLights leaves out)
 * once, instead of a loop pass per light (with ParaView's light kit, one pass for its key
 * light instead of five).
 */
std::vector<int> LoopedLights(const std::vector<Light>& lights, bool isotropic);
glm::vec3 UnloopedDiffuse(const std::vector<Light>& lights);

}
#endif
