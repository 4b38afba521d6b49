#include "NodePool.h"

#include "Core/Shadows/NodeChunks.h"
#include "GL/UniformSink.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkTextureUnitManager.h"
#include "vtk_glew.h"

#include <algorithm>

namespace deepshadow
{

bool NodePool::Reserve(vtkOpenGLRenderWindow* window, std::vector<long long> limits, long long start,
  int chunkNodes, bool colored, bool& remade, std::string& problem)
{
  remade = false;
  this->Window = window;
  GLint maxEntries = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &maxEntries);
  const long long slots = std::max<long long>(1, static_cast<long long>(limits.size()));
  // Chunk numbers are stored as floats (MaxPoolChunks says why).
  const long long allowed =
    std::min(MaxPoolChunks, static_cast<long long>(maxEntries) / (chunkNodes + 1)) / slots;
  for (long long& limit : limits)
  {
    if (limit > allowed)
    {
      problem = "this GL holds at most " + std::to_string(allowed) + " chunks per light, not " +
        std::to_string(limit) + ": a smaller pool than node-pool-mb asks";
      limit = allowed;
    }
  }
  const long long largest = limits.empty() ? 0 : *std::max_element(limits.begin(), limits.end());
  const bool sameLayout = this->Buffer && this->Nodes == chunkNodes && this->Colored == colored &&
    this->Limits.size() == limits.size() && this->Region <= largest;
  this->Limits = limits;
  if (sameLayout || largest == 0)
  {
    return true;
  }
  this->Nodes = chunkNodes;
  this->Colored = colored;
  this->Region = std::min(largest, std::max<long long>(64, start));
  remade = true;
  return this->Allocate(problem);
}

bool NodePool::Allocate(std::string& problem)
{
  while (glGetError() != GL_NO_ERROR)
  {
    // errors of earlier GL calls are not ours to report
  }
  if (!this->Buffer)
  {
    glGenBuffers(1, &this->Buffer);
    glGenTextures(1, &this->Texture);
  }
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Buffer);
  glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(this->AllocatedBytes()), nullptr, GL_DYNAMIC_COPY);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  // The buffer texture follows the buffer's new storage once attached again.
  vtkTextureUnitManager* units = this->Window->GetTextureUnitManager();
  const int unit = units->Allocate();
  this->Window->GetState()->vtkglActiveTexture(GL_TEXTURE0 + unit);
  glBindTexture(GL_TEXTURE_BUFFER, this->Texture);
  glTexBuffer(GL_TEXTURE_BUFFER, this->Colored ? GL_RGBA32F : GL_RG32F, this->Buffer);
  glBindTexture(GL_TEXTURE_BUFFER, 0);
  units->Free(unit);
  if (glGetError() != GL_NO_ERROR)
  {
    problem = "the GL could not allocate " + std::to_string(this->AllocatedBytes()) + " bytes of deep shadow map nodes";
    this->Release();
    return false;
  }
  return true;
}

long long NodePool::Base(int slot) const
{
  return static_cast<long long>(slot) * this->Region;
}

long long NodePool::Capacity(int slot) const
{
  return std::min(this->Region, this->Limit(slot));
}

bool NodePool::Grow(long long requested, int slot, std::string& problem)
{
  const long long wanted = std::min(this->Limit(slot), requested + requested / 4);
  if (requested <= this->Capacity(slot) || wanted <= this->Region)
  {
    return false;
  }
  this->Region = wanted;
  return this->Allocate(problem);
}

void NodePool::BindBuild() const
{
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, this->Buffer);
}

void NodePool::UnbindBuild() const
{
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, 0);
}

void NodePool::BindLookup(UniformSink& sink, vtkOpenGLRenderWindow* window)
{
  this->Window = window;
  this->Unit = window->GetTextureUnitManager()->Allocate();
  window->GetState()->vtkglActiveTexture(GL_TEXTURE0 + this->Unit);
  glBindTexture(GL_TEXTURE_BUFFER, this->Texture);
  sink.Set("u_shadowNodes", this->Unit);
}

void NodePool::UnbindLookup()
{
  if (this->Unit >= 0)
  {
    this->Window->GetState()->vtkglActiveTexture(GL_TEXTURE0 + this->Unit);
    glBindTexture(GL_TEXTURE_BUFFER, 0);
    this->Window->GetTextureUnitManager()->Free(this->Unit);
    this->Unit = -1;
  }
}

long long NodePool::ChunkBytes() const
{
  return deepshadow::ChunkBytes(this->Nodes, this->Colored);
}

long long NodePool::AllocatedBytes() const
{
  return this->Buffer ? this->Region * static_cast<long long>(this->Limits.size()) * this->ChunkBytes() : 0;
}

void NodePool::Release()
{
  this->UnbindLookup();
  if (this->Buffer)
  {
    glDeleteBuffers(1, &this->Buffer);
    glDeleteTextures(1, &this->Texture);
  }
  this->Buffer = 0;
  this->Texture = 0;
  this->Region = 0;
}
}
