// How the lights shade a volume sample of gradient normal (vtkVolumeProperty::ShadeOn), in one
// of two models; Features/VTKShading.glsl and Features/Phong.glsl are the GLSL twins.
//
// - Blinn-Phong: the normal is the world-space gradient's, the halfway vector normalize(L + V),
//   the ambient term Ka x colour x the renderer's ambient light. What the CPU reference calls
//   exact; the deepshadow tool draws it.
// - VTK: VTK's GPU volume mapper as it is (vtkVolumeShaderComposer.h,
//   ComputeLightingDeclaration), so that a swapped-in mapper draws VTK's unshadowed picture.
//   VTK rewrote its lighting in 9.2; VolumeShading::Revision says which one (the build's VTK
//   picks it). It has three paths, picked from the renderer's lights as VTK picks its
//   "lighting complexity" (VTKLightingPath):
//   1 Headlight (one light on, a headlight of intensity 1): light and viewer are the eye,
//     compared with the normal in the volume's dataset space; ambient Ka x colour.
//     VTK 9.1 takes the normal inwards, so with one-sided lighting a surface facing the eye
//     takes pow() of a negative N.H, NaN, which Mesa's clamp turns black (GLSL leaves it
//     undefined): black, and its back lit. VTK 9.2 onwards takes it outwards.
//   2 Directional (any other set of directional lights): the gradient is multiplied by the
//     transpose of the volume's texture-to-eye matrix (VTK uploads it untransposed), not by
//     the inverse transpose, so the normal leans towards the box's long axes as the camera
//     sees them (only a cube keeps the true normal); a sample is lit up to half a voxel from
//     where it is (LightingTransform); ambient Ka x the lights' ambient colours (black by
//     default: no ambient term at all). VTK 9.1 only: the specular half vector looks from the
//     eye at that point mirrored through the volume's first voxel (2 P0 - p), and only the
//     last light whose N.H > 0 gives specular light.
//   3 Positional (any positional light): the normal and the lit point as in 2; distance and
//     cone attenuation (cones of 90 degrees or less); ambient as in 2. VTK 9.1's half vector
//     is normalize(L - V).
//   VTK 9.2 onwards, on every path: Phong's reflection, R.V with R the light reflected about
//   the normal, and only where N.L > 0 (after the two-sided flip); R is reflected with the
//   flipped N.L, but the headlight's with the unflipped one; two-sided lighting flips R.V for
//   positional lights only. VTKShadingRevision::Reflection.
//   Colour is clamped to [0, 1] after the lights are summed, as VTK clamps computeLighting.
//
// Shadows multiply each light's diffuse and specular part by its visibility; ambient light is
// never shadowed. Without shadows both models are what their names say.
#ifndef deepshadow_VolumeShading_h
#define deepshadow_VolumeShading_h

#include "Core/Light.h"
#include "Core/OpticalModel.h"
#include "vtkDeepShadowCoreModule.h"

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace deepshadow
{

enum class ShadingModel
{
  VTK,
  BlinnPhong
};

enum class ShadingPath
{
  BlinnPhong = 0,
  VTKHeadlight = 1,
  VTKDirectional = 2,
  VTKPositional = 3
};

/** Which VTK's lighting the VTK paths follow. */
enum class VTKShadingRevision
{
  HalfVector, // VTK 9.0 and 9.1: Blinn's half vector, with the quirks listed above
  Reflection  // VTK 9.2 onwards: Phong's reflected light
};

struct VTKDEEPSHADOWCORE_EXPORT VolumeShading
{
  ShadingPath Path = ShadingPath::BlinnPhong;
  VTKShadingRevision Revision = VTKShadingRevision::HalfVector;
  /**
   * BlinnPhong and VTKHeadlight: multiplies Ka x colour (the renderer's ambient light, or 1);
   * VTKDirectional and VTKPositional: the lights' ambient colours x intensities, summed,
   * multiplies Ka alone.
   */
  glm::dvec3 Ambient{ 1.0 };
  /** An index-space gradient to the direction of the inward normal in shading space. */
  glm::dmat3 IndexGradientToNormal{ 1.0 };
  /** World vectors to shading space (VTKHeadlight: the volume's dataset space). */
  glm::dmat3 WorldToShading{ 1.0 };
  /** The camera's position (VTK paths: the viewer of the specular half vector). */
  glm::dvec3 Eye{ 0.0 };
  /** VTKDirectional: twice the world position of the volume's first voxel. */
  glm::dvec3 MirrorCentre{ 0.0 };
  /**
   * VTKDirectional and VTKPositional: where VTK lights a sample at a world point (shadows are
   * looked up where the sample is). VTK maps the texture coordinate of index i, (i + 0.5) / N,
   * to a position as if 0 and 1 were the first and last points: index (i + 0.5) (N - 1) / N,
   * half a voxel up the axis at its start, half a voxel down at its end.
   */
  glm::dmat4 LightingTransform{ 1.0 };
  /** Whether the ambient term is Ka x colour x Ambient (else Ka x Ambient). */
  bool AmbientTimesColour() const;
  /**
   * The unit normal the lights are compared with, in shading space (zero for a zero
   * gradient): outward, but for VTKHeadlight's under HalfVector, which VTK 9.1 takes inward.
   */
  glm::dvec3 Normal(const glm::dvec3& indexGradient) const;
  /**
   * The half vector of light `toLight` (world, unit) at world point `position` seen along
   * `toViewer` (world, unit), in shading space; `toLight` becomes shading space too.
   */
  glm::dvec3 Halfway(glm::dvec3& toLight, const glm::dvec3& toViewer, const glm::dvec3& position) const;
  /**
   * One light's diffuse and specular parts at a sample of shading-space `normal`, lit at world
   * `litPosition` and seen along `toViewer` (world, unit): Blinn-Phong or VTK's, as Path and
   * Revision say. NDotH is R.V under Reflection.
   */
  PhongParts LightTerms(const glm::dvec3& color, const glm::dvec3& normal, const LightSample& sample,
    bool positional, const glm::dvec3& toViewer, const glm::dvec3& litPosition, const Material& material,
    bool twoSided) const;
};

/**
 * The colour of a volume sample of colour `color` and shading-space normal `normal`
 * (VolumeShading::Normal) at world `position`, seen along `toViewer`: ambient plus each
 * light's diffuse and specular part times `visibility(l)` (1 - ShadowAttenuation (1 - V) per
 * channel), clamped to [0, 1]. `visibility` is asked only for lights that give light there.
 */
template <typename Visibility>
glm::dvec3 ShadeVolumeSample(const VolumeShading& shading, const glm::dvec3& color,
  const glm::dvec3& normal, const glm::dvec3& position, const glm::dvec3& toViewer,
  const std::vector<Light>& lights, const Material& material, bool twoSided, Visibility&& visibility)
{
  glm::dvec3 lit = material.Ambient * shading.Ambient * (shading.AmbientTimesColour() ? color : glm::dvec3(1.0));
  if (glm::dot(normal, normal) == 0.0)
  {
    return glm::clamp(lit, 0.0, 1.0); // a zero gradient: ambient only
  }
  glm::dvec3 lastSpecular(0.0); // VTK 9.1's VTKDirectional: only the last light's
  const bool halfVector = shading.Revision == VTKShadingRevision::HalfVector;
  const glm::dvec3 litPosition(shading.LightingTransform * glm::dvec4(position, 1.0));
  for (size_t l = 0; l < lights.size(); ++l)
  {
    const LightSample sample = lights[l].VolumeSampleAt(litPosition);
    if (sample.Reach <= 0.0)
    {
      continue;
    }
    const PhongParts parts =
      shading.LightTerms(color, normal, sample, lights[l].Positional, toViewer, litPosition, material, twoSided);
    if (halfVector && shading.Path == ShadingPath::VTKHeadlight && parts.NDotH < 0.0)
    {
      return glm::dvec3(0.0); // VTK's pow() of a negative N.H: NaN, clamped to black (Mesa)
    }
    if (parts.Diffuse == glm::dvec3(0.0) && parts.Specular == glm::dvec3(0.0) && parts.NDotH <= 0.0)
    {
      continue;
    }
    const glm::dvec3 factor = visibility(l);
    if (halfVector && shading.Path == ShadingPath::VTKDirectional)
    {
      lit += parts.Diffuse * factor;
      if (parts.NDotH > 0.0)
      {
        lastSpecular = parts.Specular * factor;
      }
    }
    else
    {
      lit += (parts.Diffuse + parts.Specular) * factor;
    }
  }
  return glm::clamp(lit + lastSpecular, 0.0, 1.0);
}

}
#endif
