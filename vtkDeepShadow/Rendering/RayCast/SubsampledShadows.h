// Internal: shadows while interacting, looked up on a coarser grid of rays
// (vtkDeepShadowVolumeMapper::InteractiveShadowSubsampling; Core/ShadowSubsampling.h says how
// and is the CPU twin). Which frames can be drawn that way, and the coarse pass's target.
#ifndef vtkDeepShadowSubsampledShadows_h
#define vtkDeepShadowSubsampledShadows_h

#include "RayCast/RayCastFrame.h"

#include "vtkOpenGLFramebufferObject.h" // For vtkSmartPointer
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h" // For vtkSmartPointer

#include <glm/vec2.hpp>


class vtkOpenGLRenderWindow;
class vtkWindow;

namespace deepshadow
{

/**
 * Whether `frame` (interactive, with a technique) can take its shadows from the coarse grid:
 * a volume of one component composited alone (no translucent meshes, no other volume
 * interleaved, no shader code of the user's, no label map or isosurface, the colour not the
 * shadow term). The others keep a lookup per sample.
 */
bool CanSubsampleShadows(const RayCastFrame& frame);

/**
 * Pixels a coarse ray for `frame` with a technique at the mapper's `requested` subsampling:
 * `requested` on an interactive frame that can take its shadows from the coarse grid, else 1.
 */
int ShadowSubsampling(const RayCastFrame& frame, int requested);

class ShadowRatioTarget;

/** `frame` as its coarse pass draws it, one ray per `scale` x `scale` pixels (feature ShadowRatio). */
RayCastFrame CoarsePassOf(const RayCastFrame& frame, int scale);
/**
 * `frame` as its full pass draws it: without the technique (shaded, lit by the same lights;
 * unshaded, its colour), times the ratio `target` holds (feature ShadowRatioApply).
 */
RayCastFrame FullPassOf(const RayCastFrame& frame, int scale, const ShadowRatioTarget& target);

/**
 * The coarse pass's render targets: per coarse ray, two RGBA16F texels (the ratio and the
 * opacity; the unshadowed composite).
 */
class ShadowRatioTarget
{
public:
  /** (Re)allocates it for a width x height view at `scale` pixels a ray; false if the GL cannot. */
  bool Allocate(vtkOpenGLRenderWindow* window, int width, int height, int scale);
  /** Binds them for drawing, the viewport the whole target, cleared to "no ray" (ratio 1, opacity 0). */
  void Begin(vtkOpenGLRenderWindow* window);
  /** Restores the framebuffer and viewport Begin found. */
  void End(vtkOpenGLRenderWindow* window);

  vtkTextureObject* GetTexels() const { return this->Texels; }
  vtkTextureObject* GetGuides() const { return this->Guides; }
  long long GetBytes() const;
  void Release(vtkWindow* window);

private:
  vtkSmartPointer<vtkTextureObject> Texels;
  vtkSmartPointer<vtkTextureObject> Guides;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  glm::ivec2 Size{ 0 };
  int SavedViewport[4] = { 0, 0, 0, 0 };
  bool SavedScissor = false;
};

}
#endif
