#include "FramebufferCopy.h"

#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

namespace deepshadow
{
namespace
{
// vtkTextureObject depth format of the read framebuffer's depth attachment, or
// DepthStencilFormat when it also has stencil bits.
constexpr int DepthStencilFormat = -2;
int ReadFramebufferDepthFormat()
{
  GLint depthBits = 0, stencilBits = 0, componentType = 0;
  glGetFramebufferAttachmentParameteriv(
    GL_READ_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, &depthBits);
  glGetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, GL_DEPTH_ATTACHMENT,
    GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, &componentType);
  glGetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, GL_STENCIL_ATTACHMENT,
    GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE, &stencilBits);
  glGetError(); // a framebuffer without stencil attachment may flag the last query
  if (stencilBits > 0)
  {
    return DepthStencilFormat;
  }
  if (componentType == GL_FLOAT)
  {
    return vtkTextureObject::Float32;
  }
  return depthBits <= 16 ? vtkTextureObject::Fixed16
                         : depthBits <= 24 ? vtkTextureObject::Fixed24 : vtkTextureObject::Fixed32;
}
}

vtkSmartPointer<vtkTextureObject> NewNearestTexture(vtkOpenGLRenderWindow* window)
{
  auto texture = vtkSmartPointer<vtkTextureObject>::New();
  texture->SetContext(window);
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  texture->SetMinificationFilter(vtkTextureObject::Nearest);
  texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  return texture;
}

void FramebufferCopy::AllocateMatchingDepth(vtkTextureObject* texture, int width, int height) const
{
  if (this->DepthFormat == DepthStencilFormat)
  {
    texture->AllocateDepthStencil(width, height);
  }
  else
  {
    texture->AllocateDepth(width, height, this->DepthFormat);
  }
}

void FramebufferCopy::Capture(vtkOpenGLRenderWindow* window, int x0, int y0, int width, int height, bool color)
{
  vtkOpenGLState* state = window->GetState();
  if (!this->Depth)
  {
    this->Depth = NewNearestTexture(window);
    this->Color = NewNearestTexture(window);
    this->Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    this->Framebuffer->SetContext(window);
  }
  // A depth blit needs identical formats: match whatever the current framebuffer has.
  const int depthFormat = ReadFramebufferDepthFormat();
  if (!this->Depth->GetHandle() || depthFormat != this->DepthFormat)
  {
    this->Release(window);
    this->DepthFormat = depthFormat;
    this->AllocateMatchingDepth(this->Depth, width, height);
    this->Color->Allocate2D(width, height, 4, VTK_UNSIGNED_CHAR);
    state->PushDrawFramebufferBinding();
    this->Framebuffer->Bind(GL_DRAW_FRAMEBUFFER);
    this->Framebuffer->AddDepthAttachment(this->Depth);
    this->Framebuffer->AddColorAttachment(0, this->Color);
    state->PopDrawFramebufferBinding();
  }
  this->Depth->Resize(width, height);
  this->Color->Resize(width, height);
  this->Width = width;
  this->Height = height;
  state->PushDrawFramebufferBinding();
  this->Framebuffer->Bind(GL_DRAW_FRAMEBUFFER);
  state->vtkglBlitFramebuffer(x0, y0, x0 + width, y0 + height, 0, 0, width, height,
    GL_DEPTH_BUFFER_BIT | (color ? GL_COLOR_BUFFER_BIT : 0), GL_NEAREST);
  state->PopDrawFramebufferBinding();
}

long long FramebufferCopy::GetBytes() const
{
  return this->Depth && this->Depth->GetHandle() ? 8LL * this->Width * this->Height : 0;
}

void FramebufferCopy::Release(vtkWindow* window)
{
  if (this->Depth)
  {
    this->Depth->ReleaseGraphicsResources(window);
    this->Color->ReleaseGraphicsResources(window);
    this->Framebuffer->ReleaseGraphicsResources(window);
  }
  this->DepthFormat = -1;
}

}
