#include "Volume/TransferTableTexture.h"

#include "GL/ClampedTexture.h"

#include "vtkTextureObject.h"

#include <algorithm>

namespace deepshadow
{

void TransferTableTexture::Update(vtkOpenGLRenderWindow* window, const TransferFunction& function,
  const glm::dvec2& range, int size, double step, std::vector<double> key)
{
  this->Release(window);
  this->Table = TransferTable::Sample(function, range.x, range.y, size, step);
  this->Texture = NewClampedTexture(window);
  this->Texture->SetMinificationFilter(vtkTextureObject::Linear);
  this->Texture->SetMagnificationFilter(vtkTextureObject::Linear);
  this->Texture->Create2DFromRaw(this->Table.Size, 1, 4, VTK_FLOAT, static_cast<void*>(this->Table.RGBA.data()));
  this->Key = std::move(key);
}

void TransferTableTexture::UpdateRows(vtkOpenGLRenderWindow* window, const std::vector<TransferFunction>& functions,
  const glm::dvec2& range, int size, std::vector<double> key)
{
  this->Release(window);
  std::vector<float> texels;
  for (const TransferFunction& function : functions)
  {
    const TransferTable row = TransferTable::Sample(function, range.x, range.y, size, function.OpacityUnitDistance);
    texels.insert(texels.end(), row.RGBA.begin(), row.RGBA.end());
    if (this->Rows == 1 && this->Table.Size == 0)
    {
      this->Table = row;
    }
  }
  this->Rows = std::max(1, static_cast<int>(functions.size()));
  this->Texture = NewClampedTexture(window);
  this->Texture->SetMinificationFilter(vtkTextureObject::Linear);
  this->Texture->SetMagnificationFilter(vtkTextureObject::Linear);
  this->Texture->Create2DFromRaw(this->Table.Size, this->Rows, 4, VTK_FLOAT, static_cast<void*>(texels.data()));
  this->Key = std::move(key);
}

void TransferTableTexture::UpdateImage(
  vtkOpenGLRenderWindow* window, int width, int height, const float* rgba, std::vector<double> key)
{
  this->Release(window);
  this->Table.Size = width;
  this->Rows = height;
  this->Texture = NewClampedTexture(window);
  this->Texture->SetMinificationFilter(vtkTextureObject::Linear);
  this->Texture->SetMagnificationFilter(vtkTextureObject::Linear);
  this->Texture->Create2DFromRaw(width, height, 4, VTK_FLOAT, const_cast<float*>(rgba));
  this->Key = std::move(key);
}

void TransferTableTexture::Release(vtkWindow* window)
{
  if (this->Texture)
  {
    this->Texture->ReleaseGraphicsResources(window);
  }
  *this = TransferTableTexture();
}

}
