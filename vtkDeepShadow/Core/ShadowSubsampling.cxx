#include "Core/ShadowSubsampling.h"

#include "Core/Jitter.h"
#include "Core/Parallel.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace deepshadow
{

glm::ivec2 ShadowRatioSize(int width, int height, int scale)
{
  return { (width + scale - 1) / scale, (height + scale - 1) / scale };
}

ShadowRatioTexel MakeShadowRatioTexel(const glm::dvec4& shadowed, const glm::dvec3& unshadowed)
{
  ShadowRatioTexel texel;
  for (int c = 0; c < 3; ++c)
  {
    if (unshadowed[c] > 1e-6)
    {
      texel.Ratio[c] = shadowed[c] / unshadowed[c];
    }
  }
  texel.Alpha = shadowed.a;
  texel.Unshadowed = unshadowed;
  return texel;
}

glm::dvec3 UpsampleShadowRatio(const ShadowRatioImage& ratio, int x, int y, const glm::dvec3& unshadowed)
{
  // The pixel's centre in coarse texels, whose centres sit at integers.
  const glm::dvec2 u = (glm::dvec2(x, y) + 0.5) / static_cast<double>(ratio.Scale) - 0.5;
  const glm::dvec2 base = glm::floor(u);
  const glm::dvec2 f = u - base;
  glm::dvec3 sum(0.0);
  double weight = 0.0;
  for (int corner = 0; corner < 4; ++corner)
  {
    const glm::ivec2 offset(corner & 1, corner >> 1);
    const glm::ivec2 texel = glm::clamp(glm::ivec2(base) + offset, glm::ivec2(0), ratio.Size - 1);
    const ShadowRatioTexel& r = ratio.At(texel.x, texel.y);
    const double apart = glm::distance(r.Unshadowed, unshadowed) / ShadowRatioGuideScale;
    const double w = (offset.x ? f.x : 1.0 - f.x) * (offset.y ? f.y : 1.0 - f.y) * r.Alpha / (1.0 + apart * apart);
    sum += w * r.Ratio;
    weight += w;
  }
  return weight > 1e-6 ? sum / weight : glm::dvec3(1.0);
}

Image RenderShadowSubsampled(const Scene& scene, const MarchSettings& settings, int scale, int threads,
  ShadowRatioImage* coarse)
{
  if (scene.Volumes.size() != 1 || (scene.Surfaces && !scene.Surfaces->Empty()))
  {
    throw std::invalid_argument("subsampled shadows are drawn for one volume without meshes");
  }
  if (scale < 1 || scale > MaxShadowSubsampling)
  {
    throw std::invalid_argument("the shadow subsampling must be 1 to " + std::to_string(MaxShadowSubsampling));
  }
  const VolumeInstance& shadowed = scene.Volumes[0];
  VolumeInstance unshadowed = shadowed;
  unshadowed.Shadows = ShadowParameters();
  const ReferenceRenderer::PreparedVolume withShadows = ReferenceRenderer::Prepare(scene, shadowed, settings, threads);
  const ReferenceRenderer::PreparedVolume without = ReferenceRenderer::Prepare(scene, unshadowed, settings, threads);
  const double unlimited = std::numeric_limits<double>::infinity();
  auto offsetAt = [&](uint32_t x, uint32_t y) {
    return settings.Jitter ? JitterOffset(x, y, settings.JitterSeed) : UnjitteredOffset;
  };

  // The coarse pass: one ray through each block's centre, its jitter that of the pixel there.
  ShadowRatioImage ratio;
  ratio.Scale = scale;
  ratio.Size = ShadowRatioSize(scene.View.GetWidth(), scene.View.GetHeight(), scale);
  ratio.Texels.assign(static_cast<size_t>(ratio.Size.x) * ratio.Size.y, ShadowRatioTexel());
  ParallelFor(
    ratio.Size.y,
    [&](int j) {
      for (int i = 0; i < ratio.Size.x; ++i)
      {
        const glm::dvec2 at = ShadowRatioRayPosition(i, j, scale);
        const Ray ray = scene.View.RayThrough(at.x, at.y);
        const double offset = offsetAt(static_cast<uint32_t>(at.x), static_cast<uint32_t>(at.y));
        const glm::dvec4 shadowedComposite =
          ReferenceRenderer::MarchRay(scene, shadowed, withShadows, ray, unlimited, offset, settings);
        const glm::dvec4 unshadowedComposite =
          ReferenceRenderer::MarchRay(scene, unshadowed, without, ray, unlimited, offset, settings);
        ratio.Texels[static_cast<size_t>(j) * ratio.Size.x + i] =
          MakeShadowRatioTexel(shadowedComposite, glm::dvec3(unshadowedComposite));
      }
    },
    threads);

  // The full pass: every pixel without its technique, times the ratio.
  const int width = scene.View.GetWidth();
  Image image(width, scene.View.GetHeight());
  ParallelFor(
    image.Height,
    [&](int y) {
      for (int x = 0; x < width; ++x)
      {
        const Ray ray = scene.View.PixelRay(x, y);
        const glm::dvec4 rgba = ReferenceRenderer::MarchRay(scene, unshadowed, without, ray, unlimited,
          offsetAt(static_cast<uint32_t>(x), static_cast<uint32_t>(y)), settings);
        const glm::dvec3 colour = glm::dvec3(rgba) * UpsampleShadowRatio(ratio, x, y, glm::dvec3(rgba));
        // As the GPU's 8-bit target: clamped, then blended over the background.
        image.Set(x, y, glm::clamp(colour, 0.0, 1.0) + (1.0 - rgba.a) * scene.Background);
      }
    },
    threads);
  if (coarse)
  {
    *coarse = std::move(ratio);
  }
  return image;
}

}
