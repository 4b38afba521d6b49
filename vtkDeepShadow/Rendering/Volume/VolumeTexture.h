// Internal: the volume's scalars as a 3D texture (vtkDeepShadowVolumeMapper's first holder),
// with what the shaders need to read them back as data scalars.
#ifndef vtkDeepShadowVolumeTexture_h
#define vtkDeepShadowVolumeTexture_h

#include "Core/EmptySpace.h"

#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <string>

class vtkImageData;
class vtkObject;
class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

namespace deepshadow
{

class VolumeTexture
{
public:
  /** Edge of the empty-space blocks (Features/EmptySpace.glsl reads u_blockSize). */
  static constexpr int BlockSize = 8;

  /** Whether `input` (with non-finite samples replaced or not) is not what is uploaded. */
  bool NeedsUpdate(vtkImageData* input, bool replaceNonFinite) const;
  /**
   * Checks and uploads `input`: native formats where exact (8/16 bit normalized), float
   * otherwise. `warning` receives what is worth one (replaced samples). False on bad input
   * (GetError() says why; nothing is held then).
   */
  bool Update(vtkOpenGLRenderWindow* window, vtkImageData* input, bool replaceNonFinite, std::string& warning);
  void Release(vtkWindow* window);

  vtkTextureObject* GetTexture() const { return this->Texture; }
  const std::string& GetError() const { return this->Error; }
  const glm::ivec3& GetDims() const { return this->Dims; }
  const glm::dvec2& GetRange() const { return this->Range; }
  /** Texel value -> the shaders' scalar (ShadowContext::ScalarMap). */
  const glm::dvec2& GetScalarMap() const { return this->ScalarMap; }
  /** Data scalar -> the shaders' scalar (ShadowContext::ShaderScalar). */
  const glm::dvec2& GetShaderScalar() const { return this->ShaderScalar; }
  /** Each block's scalar range, for the occupancy map. */
  const BlockRanges& GetBlocks() const { return this->Blocks; }
  /** Bytes on the GPU: one texel per voxel of 1 (8 bit), 2 (16 bit) or 4 (float) bytes. */
  long long GetBytes() const;

private:
  vtkSmartPointer<vtkTextureObject> Texture;
  vtkImageData* Source = nullptr;
  vtkMTimeType SourceTime = 0;
  bool ReplaceNonFinite = false;
  std::string Error;
  glm::ivec3 Dims{ 0 };
  glm::dvec2 Range{ 0.0 };
  glm::dvec2 ScalarMap{ 1.0, 0.0 };
  glm::dvec2 ShaderScalar{ 1.0, 0.0 };
  BlockRanges Blocks;
};

}
#endif
