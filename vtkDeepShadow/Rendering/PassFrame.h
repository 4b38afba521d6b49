// Internal: what vtkDeepShadowPass hands its mappers for one frame, in one object, instead of
// a setter per item on each mapper. The pass gives it to every mapper it gathered when the
// frame starts and takes it back when the frame ends; each mapper reads what concerns it when
// it draws. The pass fills it as it learns: the casting surfaces first, then the prepared
// volumes' contexts and the shadow source, the other volumes' grids, and the layers and
// segments before the volumes that use them are drawn.
#ifndef deepshadow_PassFrame_h
#define deepshadow_PassFrame_h

#include "Sampling/ShadowContext.h"

#include <map>
#include <memory>

class vtkDeepShadowTechnique;
class vtkObject;
class vtkVolume;

namespace deepshadow
{
class OtherVolumeShadows;
class SurfaceSet;
class TranslucentLayers;
class VolumeSegments;

struct PassFrame
{
  // The casting meshes in world coordinates, held by one volume mapper only: the shadow
  // source's, so that they count once.
  std::shared_ptr<const SurfaceSet> Surfaces;
  const vtkObject* SurfaceHolder = nullptr;

  // Each shadowing volume's context as its mapper's PrepareShadows left it, by mapper.
  std::map<const vtkObject*, ShadowContext> Prepared;
  // The scene's shadow source, which meshes look up directly: the first shadowing volume's
  // context and technique (null: meshes are lit without shadows).
  const ShadowContext* Source = nullptr;
  vtkDeepShadowTechnique* SourceTechnique = nullptr;

  // What the other shadowing volumes cast onto each receiver (a volume or a mesh mapper).
  std::map<const vtkObject*, const OtherVolumeShadows*> Others;

  // The translucent layers the merging volume's mapper composites into its march.
  const vtkObject* Merging = nullptr;
  const TranslucentLayers* Layers = nullptr;

  // The segments the volumes after the first (the guests) are drawn into, and each one's
  // slice of them.
  VolumeSegments* Segments = nullptr;
  std::map<const vtkVolume*, int> Guests;

  std::shared_ptr<const SurfaceSet> SurfacesFor(const vtkObject* mapper) const
  {
    return mapper == this->SurfaceHolder ? this->Surfaces : nullptr;
  }
  const OtherVolumeShadows* OthersOnto(const vtkObject* receiver) const
  {
    const auto found = this->Others.find(receiver);
    return found != this->Others.end() ? found->second : nullptr;
  }
  const TranslucentLayers* LayersFor(const vtkObject* mapper) const
  {
    return mapper == this->Merging ? this->Layers : nullptr;
  }
  /** The segments `volume` is drawn into and its slice (`guest`); null: onto the screen. */
  VolumeSegments* SegmentsFor(const vtkVolume* volume, int& guest) const
  {
    const auto found = this->Guests.find(volume);
    if (!this->Segments || found == this->Guests.end())
    {
      return nullptr;
    }
    guest = found->second;
    return this->Segments;
  }
};

}
#endif
