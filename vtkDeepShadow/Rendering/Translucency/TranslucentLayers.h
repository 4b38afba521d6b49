// Internal: translucent meshes composited in depth order with the volume along each view ray.
//
// VTK blends translucent polygons before volumes, so a volume drawn later covers the glass in
// front of it. vtkDeepShadowPass instead peels the translucent meshes into layers (depth
// peeling: each layer keeps the nearest fragment behind the previous one), and the ray caster
// merges the layers into its march at their depths (Features/TranslucentLayers.glsl), as the
// CPU reference (deepshadow::ReferenceRenderer) merges mesh crossings and volume samples.
// Pixels no volume covers get the layers by a full-screen pass. Memory is bounded (8 bytes a
// pixel a layer); fragments beyond the last layer are left out, and GetOverflowed says so.
// The other volumes' segments (VolumeSegments) are merged the same way, sorted in among the
// layers by depth.
#ifndef vtkDeepShadowTranslucentLayers_h
#define vtkDeepShadowTranslucentLayers_h

#include "GL/FramebufferCopy.h"
#include "ShaderComposer.h"
#include "VolumeSegments.h"

#include "vtkSmartPointer.h"

#include <functional>
#include <memory>
#include <vector>

class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkWindow;

namespace deepshadow
{
class UniformSink;

/** What a mesh drawing one layer needs (Features/Peel.glsl). */
struct PeelStep
{
  vtkTextureObject* Previous = nullptr; // the layer in front (a texel texture for the first)
  bool First = false;                   // nothing in front: Previous is not read
};

class TranslucentLayers
{
public:
  static constexpr int MaxLayers = 8;
  using DrawMeshes = std::function<void(const PeelStep&)>;

  TranslucentLayers();
  ~TranslucentLayers();

  /**
   * Peels what `draw` draws into `layers` layers over the viewport (x0, y0, width, height).
   * Call after the opaque geometry, with the renderer's framebuffer bound: its colour and
   * depth are copied first (the layers stop at the opaque depth).
   */
  void Peel(vtkOpenGLRenderWindow* window, int x0, int y0, int width, int height, int layers,
    const DrawMeshes& draw);

  /** Instead of Peel when there is nothing to peel: the opaque image only, no layers. */
  void CaptureOpaque(vtkOpenGLRenderWindow* window, int x0, int y0, int width, int height);

  /** The other volumes' segments, merged with the layers (none unless allocated). */
  VolumeSegments& GetSegments() { return this->Segments; }

  /** Blends all layers (and segments) over the bound framebuffer's viewport (premultiplied "over"). */
  void Composite(vtkOpenGLRenderWindow* window, int x0, int y0, int width, int height);

  /** The ray caster's feature: the layers, the segments and their loader. */
  ShaderFeature GetShaderFeature() const;
  /** Binds the layers and the opaque colour for a program with the feature. */
  void Activate(UniformSink& sink) const;
  void Deactivate() const;

  int GetLayerCount() const { return this->LayerCount; }
  /** Whether fragments were left behind the last layer in the last Peel. */
  bool GetOverflowed() const { return this->Overflowed; }
  long long GetBytes() const;
  void Release(vtkWindow* window);

private:
  FramebufferCopy Opaque;
  std::vector<vtkSmartPointer<vtkTextureObject>> Layers;
  // Bound as "previous" for the first layer: a sampler must have a texture of its type.
  vtkSmartPointer<vtkTextureObject> Nothing;
  vtkSmartPointer<vtkTextureObject> DepthTest;
  int DepthTestFormat = -1;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  std::unique_ptr<vtkOpenGLQuadHelper> Quad;
  int QuadLayers = 0;
  int QuadSlices = 0;
  VolumeSegments Segments;
  int LayerCount = 0;
  int Width = 0;
  int Height = 0;
  bool Overflowed = false;
  unsigned int Query = 0;
};

}
#endif
