#include "Volume/VolumeTexture.h"

#include "CoreAdapter.h"
#include "GL/ClampedTexture.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace deepshadow
{

bool VolumeTexture::NeedsUpdate(vtkImageData* input, bool replaceNonFinite) const
{
  return input != this->Source || !input || input->GetMTime() != this->SourceTime || !this->Texture ||
    this->ReplaceNonFinite != replaceNonFinite;
}

bool VolumeTexture::Update(
  vtkOpenGLRenderWindow* window, vtkImageData* input, bool replaceNonFinite, std::string& warning)
{
  this->Release(window);
  this->Source = input;
  this->SourceTime = input ? input->GetMTime() : 0;
  this->ReplaceNonFinite = replaceNonFinite;

  size_t replaced = 0;
  auto grid = adapter::MakeVolumeGrid(input, nullptr, replaceNonFinite, this->Error, &replaced);
  if (grid)
  {
    GLint max3D = 0;
    glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &max3D);
    const glm::ivec3 dims = grid->GetDims();
    if (std::max({ dims.x, dims.y, dims.z }) > max3D)
    {
      this->Error = "the volume (" + std::to_string(dims.x) + "x" + std::to_string(dims.y) + "x" +
        std::to_string(dims.z) + ") exceeds this GL's 3D texture limit of " + std::to_string(max3D) +
        " per axis";
      grid.reset();
    }
  }
  if (!grid)
  {
    return false;
  }
  vtkDataArray* scalars = input->GetPointData()->GetScalars();
  if (replaced > 0)
  {
    warning = std::to_string(replaced) +
      " non-finite samples replaced (NaN by the smallest finite value, +-Inf by the largest/smallest)";
  }
  this->Error.clear();
  this->Dims = grid->GetDims();
  this->Range = grid->GetRange();
  this->Blocks = BlockRanges::Compute(*grid, BlockSize);

  this->Texture = NewClampedTexture(window);
  std::vector<uint16_t> shifted;
  std::vector<float> normalized;
  const void* texels = scalars->GetVoidPointer(0);
  int vtkType = scalars->GetDataType();
  this->ShaderScalar = { 1.0, 0.0 };
  switch (vtkType)
  {
    case VTK_UNSIGNED_CHAR:
      this->Texture->SetInternalFormat(GL_R8);
      this->ScalarMap = { 255.0, 0.0 };
      break;
    case VTK_UNSIGNED_SHORT:
      this->Texture->SetInternalFormat(GL_R16);
      this->ScalarMap = { 65535.0, 0.0 };
      break;
    case VTK_SHORT:
    {
      // Shifted into unsigned range so every value is exact in a 16-bit unorm texture.
      const auto* values = static_cast<const int16_t*>(texels);
      shifted.resize(grid->GetScalars().size());
      for (size_t i = 0; i < shifted.size(); ++i)
      {
        shifted[i] = static_cast<uint16_t>(static_cast<int>(values[i]) + 32768);
      }
      texels = shifted.data();
      vtkType = VTK_UNSIGNED_SHORT;
      this->Texture->SetInternalFormat(GL_R16);
      this->ScalarMap = { 65535.0, -32768.0 };
      break;
    }
    default:
    {
      // Float and the other types: the grid's checked (and, if asked, repaired) single
      // precision copy, normalized to [0, 1] in double,
      // so that a denormal range or one spanning +-FLT_MAX is mapped without overflow or
      // flushing (the shaders' scalar is the normalized one: ShadowContext::ShaderScalar).
      const double low = this->Range.x;
      const double width = this->Range.y > this->Range.x ? this->Range.y - this->Range.x : 1.0;
      const std::vector<float>& values = grid->GetScalars();
      normalized.resize(values.size());
      for (size_t i = 0; i < values.size(); ++i)
      {
        normalized[i] = static_cast<float>((static_cast<double>(values[i]) - low) / width);
      }
      texels = normalized.data();
      vtkType = VTK_FLOAT; // every other type arrives here as the grid's floats
      this->Texture->SetInternalFormat(GL_R32F);
      this->ScalarMap = { 1.0, 0.0 };
      this->ShaderScalar = { 1.0 / width, -low / width };
      break;
    }
  }
  this->Texture->Create3DFromRaw(static_cast<unsigned int>(this->Dims.x), static_cast<unsigned int>(this->Dims.y),
    static_cast<unsigned int>(this->Dims.z), 1, vtkType, const_cast<void*>(texels));
  return true;
}

void VolumeTexture::Release(vtkWindow* window)
{
  if (this->Texture)
  {
    this->Texture->ReleaseGraphicsResources(window);
  }
  *this = VolumeTexture();
}

long long VolumeTexture::GetBytes() const
{
  const int texelBytes = this->ScalarMap.x == 255.0 ? 1 : this->ScalarMap.x == 1.0 ? 4 : 2;
  return static_cast<long long>(this->Dims.x) * this->Dims.y * this->Dims.z * texelBytes;
}

}
