// The optical model shared by the GPU ray caster and the CPU reference: emission and
// absorption, front-to-back, with the opacity corrected for the step length, and Phong
// shading of gradient normals. Every function here has a GLSL twin in
// Shaders/vtkDeepShadowVolumeFS.glsl with the same name; tests compare them.
#ifndef deepshadow_OpticalModel_h
#define deepshadow_OpticalModel_h

#include "vtkDeepShadowCoreModule.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>

namespace deepshadow
{

/**
 * Opacity of a step of `stepLength` for a material whose opacity over `unitDistance` is
 * `alpha`: 1 - (1 - alpha)^(stepLength / unitDistance). Exact for homogeneous media;
 * alpha = 1 stays 1, alpha = 0 stays 0; clamped to [0, 1].
 */
inline double CorrectOpacity(double alpha, double stepLength, double unitDistance)
{
  alpha = std::clamp(alpha, 0.0, 1.0);
  if (alpha <= 0.0 || alpha >= 1.0)
  {
    return alpha;
  }
  return 1.0 - std::pow(1.0 - alpha, stepLength / unitDistance);
}

/** Front-to-back "over" of a sample (straight colour, opacity) under what is accumulated. */
inline void CompositeFrontToBack(glm::dvec4& accumulated, const glm::dvec3& color, double alpha)
{
  const double weight = (1.0 - accumulated.a) * alpha;
  accumulated.r += weight * color.r;
  accumulated.g += weight * color.g;
  accumulated.b += weight * color.b;
  accumulated.a += weight;
}

/** Front-to-back "over" of something already premultiplied (colour x alpha, alpha). */
inline void CompositeFrontToBack(glm::dvec4& accumulated, const glm::dvec4& premultiplied)
{
  accumulated += (1.0 - accumulated.a) * premultiplied;
}

/** Surface-like material of a volume (vtkVolumeProperty's ambient/diffuse/specular). */
struct Material
{
  double Ambient = 0.1;
  double Diffuse = 0.7;
  double Specular = 0.2;
  double SpecularPower = 10.0;
};

/** What one light delivers at a point: direction to it and its colours after attenuation. */
struct LightSample
{
  glm::dvec3 ToLight{ 0.0, 0.0, 1.0 }; // unit vector from the point towards the light
  glm::dvec3 Diffuse{ 1.0 };
  glm::dvec3 Specular{ 1.0 };
  /** Distance and cone attenuation alone (0: the light does not reach the point). */
  double Reach = 1.0;
};

/** One light's Phong parts at a point (no ambient): N.L, N.H and the light they give. */
struct PhongParts
{
  double NDotL = 0.0; // |N.L| with two-sided lighting
  double NDotH = 0.0; // |N.H| with two-sided lighting
  glm::dvec3 Diffuse{ 0.0 };  // kd C Ld N.L where N.L > 0
  glm::dvec3 Specular{ 0.0 }; // ks Ls (N.H)^p where N.H > 0
};

/**
 * The Phong parts of light `light` reaching unit normal `normal` from `toLight`, with the half
 * vector `halfway` (Blinn-Phong's, or VTK's: VolumeShading::Halfway).
 */
inline PhongParts PhongTerms(const glm::dvec3& color, const glm::dvec3& normal, const glm::dvec3& toLight,
  const glm::dvec3& halfway, const LightSample& light, const Material& material, bool twoSided)
{
  PhongParts parts;
  parts.NDotL = glm::dot(normal, toLight);
  parts.NDotH = glm::dot(normal, halfway);
  if (twoSided)
  {
    parts.NDotL = std::abs(parts.NDotL);
    parts.NDotH = std::abs(parts.NDotH);
  }
  if (parts.NDotL > 0.0)
  {
    parts.Diffuse = material.Diffuse * parts.NDotL * light.Diffuse * color;
  }
  if (parts.NDotH > 0.0)
  {
    parts.Specular = material.Specular * std::pow(parts.NDotH, material.SpecularPower) * light.Specular;
  }
  return parts;
}

/**
 * A surface's light from one light (no ambient), as VTK's polygon mapper lights it:
 * kd C Ld max(N.L, 0) + ks Ls max(R.V, 0)^p where N.L > 0, with R the light's direction
 * mirrored about the normal (Phong's reflection; VTK's volumes use a half vector instead).
 * The normal is on the viewer's side already (two-sided lighting turned a back face's): each
 * light is one-sided, so a sphere's far side stays dark. A zero normal gives no light.
 * `loneHeadlight`: the light is Light::LoneHeadlight; `specularColor`, the highlights' colour.
 */
inline glm::dvec3 SurfaceLight(const glm::dvec3& color, const glm::dvec3& normal, const glm::dvec3& toViewer,
  const LightSample& light, const Material& material, bool loneHeadlight, const glm::dvec3& specularColor)
{
  const double nDotL = glm::dot(normal, light.ToLight);
  if (glm::dot(normal, normal) == 0.0 || nDotL <= 0.0)
  {
    return glm::dvec3(0.0);
  }
  const glm::dvec3 reflected = 2.0 * nDotL * normal - light.ToLight;
  // VTK's lone headlight (Light::LoneHeadlight): (N.L)^p, the viewer taken along the light.
  const double rDotV = loneHeadlight ? nDotL : std::max(glm::dot(reflected, toViewer), 0.0);
  const double specular = rDotV > 0.0 ? std::pow(rDotV, material.SpecularPower) : 0.0;
  return material.Diffuse * nDotL * light.Diffuse * color +
    material.Specular * specular * light.Specular * specularColor;
}

/** Rays stop once accumulated opacity exceeds this (VTK's value: 1 - 1/255). */
constexpr double DefaultTerminationOpacity = 1.0 - 1.0 / 255.0;

}
#endif
