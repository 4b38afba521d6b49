#include "FloatTexels.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>

namespace deepshadow
{

std::string FloatTexelsLimit(size_t texels, size_t triangles, int hierarchyDepth)
{
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  if (hierarchyDepth >= 32)
  {
    return "its hierarchy is deeper than the GPU's walk allows (32)";
  }
  const size_t rows = (texels + FloatTexelsWidth - 1) / FloatTexelsWidth;
  if (rows > static_cast<size_t>(maxSize) || triangles >= (1u << 24))
  {
    return "it has too many triangles for this GL (" + std::to_string(triangles) + ")";
  }
  return std::string();
}

long long UploadFloatTexels(vtkOpenGLRenderWindow* window, vtkSmartPointer<vtkTextureObject>& texture,
  std::vector<glm::vec4> texels)
{
  const int columns = static_cast<int>(std::min<size_t>(FloatTexelsWidth, std::max<size_t>(texels.size(), 1)));
  const int rows = static_cast<int>((std::max<size_t>(texels.size(), 1) + columns - 1) / columns);
  texels.resize(static_cast<size_t>(columns) * rows, glm::vec4(0.0f));
  if (texture)
  {
    texture->ReleaseGraphicsResources(window);
  }
  texture = vtkSmartPointer<vtkTextureObject>::New();
  texture->SetContext(window);
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  texture->SetMinificationFilter(vtkTextureObject::Nearest);
  texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  texture->Create2DFromRaw(static_cast<unsigned int>(columns), static_cast<unsigned int>(rows), 4,
    VTK_FLOAT, glm::value_ptr(texels.front()));
  return static_cast<long long>(texels.size()) * 16;
}

}
