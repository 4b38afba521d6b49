#include "VolumeSegments.h"

#include "GL/FramebufferCopy.h"
#include "GL/UniformSink.h"
#include "Sampling/ShadowContext.h"

#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <vector>

namespace deepshadow
{
namespace
{
// Depth 1 (float bits): nothing in this piece (Features/VolumeSegments.glsl).
constexpr GLuint EmptySegmentTexel[4] = { 0x3f800000u, 0u, 0u, 0u };
}

VolumeSegments::VolumeSegments() = default;
VolumeSegments::~VolumeSegments() = default;

bool VolumeSegments::Allocate(vtkOpenGLRenderWindow* window, int width, int height, int guests,
  int segments, std::string& error)
{
  if (this->Texture && width == this->Width && height == this->Height && guests == this->Guests &&
    segments == this->Segments)
  {
    return true;
  }
  this->Release(window);
  GLint max3D = 0;
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &max3D);
  if (width > max3D || height > max3D || guests * segments > max3D)
  {
    error = "the volumes' segments (" + std::to_string(width) + "x" + std::to_string(height) + "x" +
      std::to_string(guests * segments) + ") exceed this GL's 3D texture limit of " +
      std::to_string(max3D) + "; volumes are blended in the renderer's order";
    return false;
  }
  this->Texture = NewNearestTexture(window);
  this->Texture->SetWrapR(vtkTextureObject::ClampToEdge);
  this->Texture->SetInternalFormat(GL_RGBA32UI);
  this->Texture->SetFormat(GL_RGBA_INTEGER);
  this->Texture->SetDataType(GL_UNSIGNED_INT);
  if (!this->Texture->Allocate3D(static_cast<unsigned int>(width), static_cast<unsigned int>(height),
        static_cast<unsigned int>(guests * segments), 4, VTK_UNSIGNED_INT))
  {
    error = "the volumes' segments could not be allocated";
    this->Texture = nullptr;
    return false;
  }
  this->Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
  this->Framebuffer->SetContext(window);
  this->Width = width;
  this->Height = height;
  this->Guests = guests;
  this->Segments = segments;
  return true;
}

void VolumeSegments::Begin(vtkOpenGLRenderWindow* window, int guest)
{
  vtkOpenGLState* state = window->GetState();
  state->PushFramebufferBindings();
  state->vtkglGetIntegerv(GL_VIEWPORT, this->SavedViewport);
  this->Framebuffer->Bind(GL_DRAW_FRAMEBUFFER);
  std::vector<GLenum> buffers;
  for (int k = 0; k < this->Segments; ++k)
  {
    this->Framebuffer->AddColorAttachment(
      static_cast<unsigned int>(k), this->Texture, static_cast<unsigned int>(guest * this->Segments + k));
    buffers.push_back(GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(k));
  }
  glDrawBuffers(static_cast<GLsizei>(buffers.size()), buffers.data());
  state->vtkglViewport(0, 0, this->Width, this->Height);
}

void VolumeSegments::End(vtkOpenGLRenderWindow* window)
{
  vtkOpenGLState* state = window->GetState();
  this->Framebuffer->RemoveColorAttachments(static_cast<unsigned int>(this->Segments));
  state->vtkglViewport(this->SavedViewport[0], this->SavedViewport[1], this->SavedViewport[2], this->SavedViewport[3]);
  state->PopFramebufferBindings();
}

void VolumeSegments::Clear(vtkOpenGLRenderWindow* window)
{
  for (int g = 0; g < this->Guests; ++g)
  {
    this->Begin(window, g);
    for (int k = 0; k < this->Segments; ++k)
    {
      glClearBufferuiv(GL_COLOR, k, EmptySegmentTexel);
    }
    this->End(window);
  }
}

void VolumeSegments::Activate(UniformSink& sink) const
{
  this->Texture->Activate();
  sink.Set("u_segments", this->Texture->GetTextureUnit());
}

void VolumeSegments::Deactivate() const
{
  this->Texture->Deactivate();
}

long long VolumeSegments::GetBytes() const
{
  return this->Texture ? 16LL * this->Width * this->Height * this->Guests * this->Segments : 0;
}

void VolumeSegments::Release(vtkWindow* window)
{
  if (this->Texture)
  {
    this->Texture->ReleaseGraphicsResources(window);
  }
  if (this->Framebuffer)
  {
    this->Framebuffer->ReleaseGraphicsResources(window);
  }
  this->Texture = nullptr;
  this->Framebuffer = nullptr;
  this->Width = this->Height = this->Guests = this->Segments = 0;
}

}
