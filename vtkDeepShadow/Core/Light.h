// Lights in world space, with VTK's semantics (vtkLight): directional unless positional;
// positional lights attenuate by 1 / (c + l d + q d^2); a cone angle of 90 degrees or less
// makes a spot light (VTK's shaders: "per OpenGL standard cone angle is 90 or less") whose
// intensity falls off as cos^exponent inside the cone and is 0 outside.
#ifndef deepshadow_Light_h
#define deepshadow_Light_h

#include "Core/OpticalModel.h"
#include "vtkDeepShadowCoreModule.h"

#include <glm/vec3.hpp>

#include <vector>

namespace deepshadow
{

struct VTKDEEPSHADOWCORE_EXPORT Light
{
  bool Positional = false;
  glm::dvec3 Position{ 0.0, 0.0, 1.0 };
  glm::dvec3 FocalPoint{ 0.0 };
  glm::dvec3 Diffuse{ 1.0 };  // colour x intensity
  glm::dvec3 Specular{ 1.0 }; // colour x intensity
  glm::dvec3 Attenuation{ 1.0, 0.0, 0.0 };
  double ConeAngle = 180.0; // degrees; < 90 makes a spot light
  double Exponent = 1.0;
  /** vtkLight::ShadowAttenuation: 0 casts no shadow, 1 full shadows (the default). */
  double ShadowAttenuation = 1.0;
  /**
   * VTK's volume mapper shades a lone headlight (the only light, a headlight of intensity 1)
   * from the eye at every sample, not as a directional light: true for that light, with Eye
   * the camera's position. It still casts shadows, and lights meshes, as the directional
   * light it is (VolumeSampleAt).
   */
  bool ShadedFromEye = false;
  glm::dvec3 Eye{ 0.0 };
  /**
   * The scene's only light is this directional headlight (any intensity): VTK's polygon mapper
   * then takes its simplest path, a specular (N.L)^p (SurfaceLight).
   */
  bool LoneHeadlight = false;

  /** The spot's cone cosine, cos(ConeAngle <= 90); -2 (below any cosine) when it is no spot. */
  double ConeCosine() const;

  /** Direction and colour of this light as seen from world point `p`. */
  LightSample At(const glm::dvec3& p) const;
  /** The same for shading a volume's sample at `p` (ShadedFromEye: towards the eye). */
  LightSample VolumeSampleAt(const glm::dvec3& p) const;
};

/**
 * An unshaded volume with a shadow technique is lit without a normal (isotropically); each
 * light gives it (1 - Ka A) * Ld * scale of its colour, scale = 1 / (the lights' summed
 * nominal diffuse, its largest channel), so that where every light reaches it the volume keeps
 * the colour it has unshaded and unshadowed, and shadows only darken it, whatever the number
 * of lights (vtkLightKit's five sum to 1.66 in red). 0 when no light is lit.
 */
VTKDEEPSHADOWCORE_EXPORT double IsotropicLightScale(const std::vector<Light>& lights);

}
#endif
