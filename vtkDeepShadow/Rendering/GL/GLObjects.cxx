#include "GLObjects.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkTextureUnitManager.h"
#include "vtk_glew.h"

namespace deepshadow
{

unsigned int NewArrayTexture(vtkOpenGLRenderWindow* window, unsigned int format, int width, int height, int layers)
{
  unsigned int texture = 0;
  glGenTextures(1, &texture);
  vtkTextureUnitManager* units = window->GetTextureUnitManager();
  const int unit = units->Allocate();
  window->GetState()->vtkglActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_2D_ARRAY, texture);
  glTexStorage3D(GL_TEXTURE_2D_ARRAY, 1, format, width, height, layers);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
  units->Free(unit);
  return texture;
}

void DeleteTexture(unsigned int& texture)
{
  if (texture)
  {
    glDeleteTextures(1, &texture);
    texture = 0;
  }
}

void EnsureStorageBuffer(unsigned int& buffer, long long& allocated, long long bytes)
{
  if (!buffer)
  {
    glGenBuffers(1, &buffer);
    allocated = 0;
  }
  if (allocated < bytes)
  {
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer);
    glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(bytes), nullptr, GL_DYNAMIC_COPY);
    allocated = bytes;
  }
}

void DeleteBuffer(unsigned int& buffer, long long& allocated)
{
  if (buffer)
  {
    glDeleteBuffers(1, &buffer);
    buffer = 0;
  }
  allocated = 0;
}
}
