#include "RayCast/SubsampledShadows.h"

#include "Core/ShadowSubsampling.h"
#include "GL/FramebufferCopy.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtk_glew.h"

namespace deepshadow
{

bool CanSubsampleShadows(const RayCastFrame& frame)
{
  const ShadowContext& context = frame.Context;
  // Whatever composites other than the volume's samples, or lights them its own way, keeps
  // the lookup per sample: the shadow term, projections and isosurfaces, translucent meshes
  // or another volume along the rays, the user's code, several components, a label map.
  return !frame.ShadowTerm && frame.Projection.Mode == BlendMode::Composite && context.IsoValues.empty() &&
    !frame.Layers && !frame.Segments && !frame.UserCode && context.OtherComponents.empty() &&
    context.MaskFeature() != "LabelMap";
}

int ShadowSubsampling(const RayCastFrame& frame, int requested)
{
  return frame.Interactive && requested > 1 && CanSubsampleShadows(frame) ? requested : 1;
}

RayCastFrame CoarsePassOf(const RayCastFrame& frame, int scale)
{
  RayCastFrame coarse = frame;
  coarse.RatioPass = RayCastFrame::ShadowRatioPass::Coarse;
  coarse.RatioScale = scale;
  return coarse;
}

RayCastFrame FullPassOf(const RayCastFrame& frame, int scale, const ShadowRatioTarget& target)
{
  RayCastFrame full = frame;
  full.RatioPass = RayCastFrame::ShadowRatioPass::Full;
  full.RatioScale = scale;
  full.RatioTexels = target.GetTexels();
  full.RatioGuides = target.GetGuides();
  full.Technique = nullptr;
  full.Others = nullptr;
  full.Lit = frame.Shade; // lit without shadows, or (unshaded) the colour
  return full;
}

bool ShadowRatioTarget::Allocate(vtkOpenGLRenderWindow* window, int width, int height, int scale)
{
  const glm::ivec2 size = ShadowRatioSize(width, height, scale);
  if (this->Texels && size == this->Size)
  {
    return true;
  }
  this->Release(window);
  auto make = [&](int internalFormat, int format, int components) {
    vtkSmartPointer<vtkTextureObject> texture = NewNearestTexture(window);
    texture->SetInternalFormat(internalFormat);
    texture->SetFormat(format);
    texture->SetDataType(GL_FLOAT);
    return texture->Allocate2D(static_cast<unsigned int>(size.x), static_cast<unsigned int>(size.y), components, VTK_FLOAT)
      ? texture
      : nullptr;
  };
  this->Texels = make(GL_RGBA16F, GL_RGBA, 4);
  this->Guides = make(GL_RGBA16F, GL_RGBA, 4);
  if (!this->Texels || !this->Guides)
  {
    this->Release(window);
    return false;
  }
  this->Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
  this->Framebuffer->SetContext(window);
  this->Size = size;
  return true;
}

void ShadowRatioTarget::Begin(vtkOpenGLRenderWindow* window)
{
  vtkOpenGLState* state = window->GetState();
  state->PushFramebufferBindings();
  state->vtkglGetIntegerv(GL_VIEWPORT, this->SavedViewport);
  this->Framebuffer->Bind(GL_DRAW_FRAMEBUFFER);
  this->Framebuffer->AddColorAttachment(0, this->Texels);
  this->Framebuffer->AddColorAttachment(1, this->Guides);
  const GLenum buffers[2] = { GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1 };
  glDrawBuffers(2, buffers);
  state->vtkglViewport(0, 0, this->Size.x, this->Size.y);
  // The renderer's scissor box is its tile of the window, not of this target.
  this->SavedScissor = state->GetEnumState(GL_SCISSOR_TEST);
  state->SetEnumState(GL_SCISSOR_TEST, false);
  const GLfloat noRay[4] = { 1.0f, 1.0f, 1.0f, 0.0f };
  const GLfloat nothing[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
  glClearBufferfv(GL_COLOR, 0, noRay);
  glClearBufferfv(GL_COLOR, 1, nothing);
}

void ShadowRatioTarget::End(vtkOpenGLRenderWindow* window)
{
  vtkOpenGLState* state = window->GetState();
  this->Framebuffer->RemoveColorAttachments(2);
  state->SetEnumState(GL_SCISSOR_TEST, this->SavedScissor);
  state->vtkglViewport(this->SavedViewport[0], this->SavedViewport[1], this->SavedViewport[2], this->SavedViewport[3]);
  state->PopFramebufferBindings();
}

long long ShadowRatioTarget::GetBytes() const
{
  return this->Texels ? 16LL * this->Size.x * this->Size.y : 0;
}

void ShadowRatioTarget::Release(vtkWindow* window)
{
  for (vtkTextureObject* texture : { this->Texels.Get(), this->Guides.Get() })
  {
    if (texture)
    {
      texture->ReleaseGraphicsResources(window);
    }
  }
  if (this->Framebuffer)
  {
    this->Framebuffer->ReleaseGraphicsResources(window);
  }
  this->Texels = nullptr;
  this->Guides = nullptr;
  this->Framebuffer = nullptr;
  this->Size = glm::ivec2(0);
}

}
