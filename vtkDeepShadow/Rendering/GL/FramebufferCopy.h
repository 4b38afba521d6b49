// Internal: a copy of what opaque geometry left in the current framebuffer's viewport (its
// depth, and its colour when asked), for passes that read it while drawing into it.
#ifndef vtkDeepShadowFramebufferCopy_h
#define vtkDeepShadowFramebufferCopy_h

#include "vtkOpenGLFramebufferObject.h" // For vtkSmartPointer
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h" // For vtkSmartPointer

class vtkOpenGLRenderWindow;
class vtkWindow;

namespace deepshadow
{

/** A 2D texture for texelFetch-style reads: clamped, nearest, of `window`'s context. */
vtkSmartPointer<vtkTextureObject> NewNearestTexture(vtkOpenGLRenderWindow* window);

class FramebufferCopy
{
public:
  /**
   * Copies the viewport (x0, y0, width, height) of the bound read framebuffer into textures
   * of the viewport's size: depth always (in the framebuffer's own depth format, as a depth
   * blit needs), colour (RGBA8) when `color`.
   */
  void Capture(vtkOpenGLRenderWindow* window, int x0, int y0, int width, int height, bool color);

  vtkTextureObject* GetDepth() const { return this->Depth; }
  vtkTextureObject* GetColor() const { return this->Color; }
  /** The framebuffer holding both textures (a blit source for the depth). */
  vtkOpenGLFramebufferObject* GetFramebuffer() const { return this->Framebuffer; }

  /**
   * Allocates `texture` as a depth texture of the captured depth's format, so the captured
   * depth can be blitted into it.
   */
  void AllocateMatchingDepth(vtkTextureObject* texture, int width, int height) const;

  /** The captured depth's format (changes when the framebuffer's does). */
  int GetDepthFormat() const { return this->DepthFormat; }

  long long GetBytes() const;
  void Release(vtkWindow* window);

private:
  vtkSmartPointer<vtkTextureObject> Depth;
  vtkSmartPointer<vtkTextureObject> Color;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  int DepthFormat = -1;
  int Width = 0;
  int Height = 0;
};

}
#endif
