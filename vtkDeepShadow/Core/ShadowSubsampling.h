// Shadows while interacting, looked up on a coarser grid of rays
// (vtkDeepShadowVolumeMapper::InteractiveShadowSubsampling); the CPU twin of the two passes
// (Shaders/Features/ShadowRatio.glsl and ShadowRatioApply.glsl).
//
// On a CPU rasterizer a shadow lookup per sample costs as much as the sample itself (or more),
// however the lookup is structured. While the view moves, the shadows are instead found on
// one ray per N x N block of pixels: a coarse pass marches those rays shadowed and keeps, per
// ray, its shadowed composite over its unshadowed one (a ratio per colour channel), its
// opacity and the unshadowed composite itself; the full pass marches every pixel without any
// shadow lookup, and multiplies its colour by the ratio interpolated from the four nearest
// coarse rays (joint bilateral upsampling, Kopf et al. 2007, guided by the unshadowed
// picture): each weighted by its bilinear weight, its opacity (a coarse ray that meets
// nothing says nothing) and how near its unshadowed composite is to the pixel's own (a ray
// past a rod's edge, on the floor behind it, does not darken the rod). The guide is the full
// pass's own colour, so it costs the march nothing. The picture keeps the full resolution of
// the volume; only the shadows' own detail is coarser.
//
// An unshaded volume (ParaView's default) is lit isotropically with a technique and emits its
// colour without one; since the lights add linearly, its shadowed colour along a ray is its
// emitted colour times the weighted mean of (A + B V) over the samples, which the ratio is,
// exactly, where neighbouring rays see the same shadows. A shaded volume's ratio is of its
// shadowed lighting over the same lighting without shadows, which the full pass draws.
#ifndef deepshadow_ShadowSubsampling_h
#define deepshadow_ShadowSubsampling_h

#include "Core/Image.h"
#include "Core/ReferenceRenderer.h"
#include "vtkDeepShadowCoreModule.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <vector>

namespace deepshadow
{

/** The largest subsampling factor (pixels per coarse ray along each axis). */
constexpr int MaxShadowSubsampling = 16;

/** The coarse grid of a width x height view at `scale` pixels a ray: ceil(width / scale), ... */
VTKDEEPSHADOWCORE_EXPORT glm::ivec2 ShadowRatioSize(int width, int height, int scale);

/** Where coarse ray (i, j) crosses the view, in pixels: the centre of its block. */
inline glm::dvec2 ShadowRatioRayPosition(int i, int j, int scale)
{
  return { (i + 0.5) * scale, (j + 0.5) * scale };
}

/** What a coarse ray keeps. */
struct ShadowRatioTexel
{
  glm::dvec3 Ratio{ 1.0 }; // shadowed / unshadowed composite, per channel
  double Alpha = 0.0;      // its opacity
  glm::dvec3 Unshadowed{ 0.0 }; // the unshadowed composite (premultiplied), the upsampling's guide
};

/**
 * A coarse ray's texel from its premultiplied shadowed composite and its unshadowed colour
 * composite: per channel shadowed / unshadowed (1 where the unshadowed channel is below 1e-6).
 */
VTKDEEPSHADOWCORE_EXPORT ShadowRatioTexel MakeShadowRatioTexel(const glm::dvec4& shadowed, const glm::dvec3& unshadowed);

/**
 * The distance between unshadowed composites (premultiplied RGB) at which a coarse ray counts
 * half as much as one that saw the pixel's own colour.
 */
constexpr double ShadowRatioGuideScale = 0.1;

/** The coarse texels, row by row from the bottom (as the GPU's textures). */
struct ShadowRatioImage
{
  glm::ivec2 Size{ 0 };
  int Scale = 1;
  std::vector<ShadowRatioTexel> Texels;

  const ShadowRatioTexel& At(int i, int j) const { return this->Texels[static_cast<size_t>(j) * this->Size.x + i]; }
};

/**
 * The ratio at full-resolution pixel (x, y) whose unshadowed composite is `unshadowed`: the four
 * coarse texels around its centre, clamped to the grid, each weighted by its bilinear weight,
 * its opacity and 1 / (1 + (|its Unshadowed - unshadowed| / ShadowRatioGuideScale)^2); 1 where those
 * weights sum to 1e-6 or less.
 */
VTKDEEPSHADOWCORE_EXPORT glm::dvec3 UpsampleShadowRatio(const ShadowRatioImage& ratio, int x, int y, const glm::dvec3& unshadowed);

/**
 * The mapper's interactive frame of a scene of one volume and no meshes: the coarse pass of
 * `scale` pixels a ray (the volume as given, shadowed), then every pixel marched without its
 * technique, its colour times UpsampleShadowRatio. `coarse`, if given, receives the coarse
 * pass's texels. Throws std::invalid_argument for another kind of scene.
 */
VTKDEEPSHADOWCORE_EXPORT Image RenderShadowSubsampled(const Scene& scene, const MarchSettings& settings, int scale,
  int threads = 0, ShadowRatioImage* coarse = nullptr);

}
#endif
