#include "Volume/OccupancyTexture.h"

#include "GL/ClampedTexture.h"

#include "vtkTextureObject.h"

#include <algorithm>

namespace deepshadow
{

void OccupancyTexture::Update(vtkOpenGLRenderWindow* window, const BlockRanges& blocks,
  const PiecewiseLinear& opacity, vtkMTimeType opacityTime, int volumeVersion)
{
  this->Release(window);
  std::vector<uint8_t> occupancy = blocks.Occupancy(opacity);
  this->Blocks = static_cast<long long>(blocks.Min.size());
  this->EmptyBlocks = std::count(occupancy.begin(), occupancy.end(), uint8_t(0));
  this->EmptyFraction = occupancy.empty() ? 0.0 : double(this->EmptyBlocks) / occupancy.size();
  // The layout and occupancy (what clustering reads), not the ranges again.
  this->Map.Blocks.BlockSize = blocks.BlockSize;
  this->Map.Blocks.BlockCount = blocks.BlockCount;
  this->Map.Occupied = occupancy;
  for (uint8_t& v : occupancy)
  {
    v = v ? 255 : 0;
  }
  this->Texture = NewClampedTexture(window);
  this->Texture->SetMinificationFilter(vtkTextureObject::Nearest);
  this->Texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  this->Texture->Create3DFromRaw(static_cast<unsigned int>(blocks.BlockCount.x),
    static_cast<unsigned int>(blocks.BlockCount.y), static_cast<unsigned int>(blocks.BlockCount.z), 1,
    VTK_UNSIGNED_CHAR, occupancy.data());
  this->OpacityTime = opacityTime;
  this->VolumeVersion = volumeVersion;
}

void OccupancyTexture::Release(vtkWindow* window)
{
  if (this->Texture)
  {
    this->Texture->ReleaseGraphicsResources(window);
  }
  *this = OccupancyTexture();
}

}
