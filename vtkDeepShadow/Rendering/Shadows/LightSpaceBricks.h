// Internal: a light-space technique's side of vtkDeepShadowBrickExchange. It gathers the
// bricks' boxes (the light faces are fitted to their union), reads back the brick's total
// transmittance per texel, and keeps the product of the totals of the bricks in front of this
// one (scanned along each light's order of the bricks, or gathered) in a texture that
// Shaders/Shadows/LightSpace.glsl multiplies into every lookup (LIGHT_SPACE_UPSTREAM).
#ifndef vtkDeepShadowLightSpaceBricks_h
#define vtkDeepShadowLightSpaceBricks_h

#include "Core/Light.h"
#include "Core/Shadows/Bricks.h"
#include "Core/Shadows/LightSpace.h"

#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkDeepShadowBrickExchange;
class vtkOpenGLRenderWindow;

namespace deepshadow
{
class UniformSink;

class LightSpaceBricks
{
public:
  ~LightSpaceBricks();

  /** The exchange in use (none, or one brick: the technique draws its volume alone). */
  void SetExchange(vtkDeepShadowBrickExchange* exchange);
  vtkDeepShadowBrickExchange* GetExchange() const;

  /**
   * Start of a frame (collective): gathers every brick's box with the map's shape (size,
   * lights, channels) and a signature of its lights. True if this frame exchanges: every brick then replaces `bounds`
   * (its own casters) by the union of the bricks' boxes. False: `bounds` is left alone, and
   * `problem` says why if something is wrong (bricks that disagree on the map's shape).
   */
  bool BeginFrame(
    CasterBounds& bounds, int mapSize, const std::vector<Light>& slotLights, int channels, std::string& problem);
  /** Whether the current frame exchanges (the lookup then multiplies the upstream texture). */
  bool Exchanging() const { return this->Active; }
  /** Whether the bricks' union changed at the last BeginFrame (the maps must be rebuilt). */
  bool UnionChanged() const { return this->UnionMoved; }

  /**
   * The brick's totals, `layers` layers (slot x face) of size x size texels, read from the
   * RGBA32F array texture `totals` (channels 1: red only).
   */
  void ReadTotals(vtkOpenGLRenderWindow* window, unsigned int totals, int size, int layers, int channels);
  /**
   * Collective: multiplies per light (slot) the totals of the bricks in front, scanned or
   * gathered, and uploads the product when it changed. False (and `problem`) if the exchange
   * failed.
   */
  bool Exchange(vtkOpenGLRenderWindow* window, const std::vector<Light>& slotLights, int facesPerLight,
    std::string& problem);
  /** Changes whenever the upstream texture does (in the cache's key). */
  double GetVersion() const { return this->Version; }
  /** Whether some brick overlaps this one (it is left out of the product; said once). */
  bool Overlapping() const { return this->Overlap; }

  /** Binds the upstream texture on a unit of its own for the lookup, and its sampler. */
  void BindLookup(UniformSink& sink, vtkOpenGLRenderWindow* window);
  void UnbindLookup();
  void Release();

private:
  /** Each slot's LightOrder of the bricks, again only when the boxes or its light changed. */
  void UpdateOrders(const std::vector<Light>& slotLights, size_t slots, double tolerance);
  // The two ways to the product; `upstream` holds every slot's.
  bool Scan(const std::vector<std::vector<int>>& orders, size_t perSlot, std::vector<float>& upstream);
  bool Gather(const std::vector<Light>& slotLights, size_t slots, size_t perSlot, double tolerance,
    std::vector<float>& upstream);

  vtkSmartPointer<vtkDeepShadowBrickExchange> Exchanger;
  bool Active = false;
  bool UnionMoved = false;
  bool Overlap = false;
  bool LightsAgree = false;
  int LocalBrick = 0;
  std::vector<BrickBox> Boxes;
  std::vector<std::vector<int>> Orders; // per slot (UpdateOrders)
  std::vector<double> OrdersKey;        // the boxes and slot lights they were found for
  BrickBox LastUnion;
  int Size = 0;
  int Layers = 0;
  int Channels = 1;
  std::vector<float> Totals;   // layer, texel, channel
  std::vector<float> Upstream; // the same layout
  unsigned int Texture = 0;    // RGBA32F array, Layers layers
  int TextureSize = 0;
  int TextureLayers = 0;
  int Unit = -1;
  vtkOpenGLRenderWindow* Window = nullptr;
  double Version = 0.0;
};

}
#endif
