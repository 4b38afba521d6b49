// Internal: the empty-space block map: one texel per block of the volume, 255 where some
// scalar in the block is visible under the opacity function, 0 where the ray may skip it.
#ifndef vtkDeepShadowOccupancyTexture_h
#define vtkDeepShadowOccupancyTexture_h

#include "Core/EmptySpace.h"

#include "vtkSmartPointer.h"
#include "vtkType.h"

class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

namespace deepshadow
{

class OccupancyTexture
{
public:
  /**
   * Whether the map held was built for another opacity function (its MTime) or another
   * upload of the volume (the mapper's count of uploads).
   */
  bool NeedsUpdate(vtkMTimeType opacityTime, int volumeVersion) const
  {
    return !this->Texture || this->OpacityTime != opacityTime || this->VolumeVersion != volumeVersion;
  }
  void Update(vtkOpenGLRenderWindow* window, const BlockRanges& blocks, const PiecewiseLinear& opacity,
    vtkMTimeType opacityTime, int volumeVersion);
  void Release(vtkWindow* window);

  vtkTextureObject* GetTexture() const { return this->Texture; }
  bool AnyEmptyBlock() const { return this->EmptyBlocks > 0; }
  /** Fraction of the blocks that are empty. */
  double GetEmptyFraction() const { return this->EmptyFraction; }
  /** Bytes on the GPU: one a block. */
  long long GetBytes() const { return this->Blocks; }
  /** The same map on the CPU (clustered light-space maps find the volume's objects in it). */
  const EmptySpaceMap& GetMap() const { return this->Map; }

private:
  vtkSmartPointer<vtkTextureObject> Texture;
  vtkMTimeType OpacityTime = 0;
  int VolumeVersion = -1;
  long long Blocks = 0;
  long long EmptyBlocks = 0;
  double EmptyFraction = 0.0;
  EmptySpaceMap Map;
};

}
#endif
