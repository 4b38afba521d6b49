// Internal: the other volumes' marches, cut into segments, for the volume that merges them.
//
// vtkDeepShadowPass draws one volume (the first) with the translucent layers merged into its
// march. Each other volume (a "guest") is drawn first into this structure instead of the
// screen: along each view ray its march is cut into N pieces of equal length, each composited
// on its own and kept at its opacity-weighted mean depth (Features/VolumeSegments.glsl). The
// merging volume sorts them in among the layers and its own samples (Features/
// TranslucentLayers.glsl), so volumes interleave along the view ray: exactly where they do
// not overlap along a ray, at the grain of a piece where they do. The CPU twin is
// deepshadow::ReferenceRenderer with Scene::VolumeSegments = N.
//
// Storage: one RGBA32UI texel per pixel and piece (16 bytes: depth, RGBA in 16-bit fixed point) in a 3D
// texture of guests x N slices, each guest drawing N slices at once (N colour attachments).
#ifndef vtkDeepShadowVolumeSegments_h
#define vtkDeepShadowVolumeSegments_h

#include "vtkSmartPointer.h"

#include <string>

class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

namespace deepshadow
{
class UniformSink;

class VolumeSegments
{
public:
  VolumeSegments();
  ~VolumeSegments();

  /**
   * Storage for `guests` volumes of `segments` pieces over a `width` x `height` viewport.
   * False, with `error`, when this GL cannot hold it.
   */
  bool Allocate(vtkOpenGLRenderWindow* window, int width, int height, int guests, int segments,
    std::string& error);

  /**
   * Makes guest `guest`'s slices the draw target (at most 8 pieces: the colour attachments
   * every GL 3.3 has), over the viewport at (0, 0); End() restores the framebuffer and
   * viewport before.
   */
  void Begin(vtkOpenGLRenderWindow* window, int guest);
  void End(vtkOpenGLRenderWindow* window);
  /** Empties every guest's slices, once a frame (a guest that draws nothing leaves nothing). */
  void Clear(vtkOpenGLRenderWindow* window);

  int GetSegments() const { return this->Segments; }
  /** Slices the merging shader reads: guests x segments (0 when nothing is allocated). */
  int GetSlices() const { return this->Guests * this->Segments; }
  /** Binds the slices as u_segments. */
  void Activate(UniformSink& sink) const;
  void Deactivate() const;
  long long GetBytes() const;
  void Release(vtkWindow* window);

private:
  vtkSmartPointer<vtkTextureObject> Texture;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  int Width = 0;
  int Height = 0;
  int Guests = 0;
  int Segments = 0;
  int SavedViewport[4] = { 0, 0, 0, 0 };
};

}
#endif
