#include "TranslucentLayers.h"

#include "GL/UniformSink.h"
#include "Sampling/ShadowContext.h"
#include "vtkDeepShadowLayersFS.h"

#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <glm/vec4.hpp>

#include <algorithm>
#include <string>

namespace deepshadow
{
namespace
{
// A layer texel is (window depth as float bits, premultiplied RGBA8); "empty" is depth 1.
constexpr GLuint EmptyLayerTexel[4] = { 0x3f800000u, 0u, 0u, 0u };

vtkSmartPointer<vtkTextureObject> NewLayerTexture(vtkOpenGLRenderWindow* window, int width, int height)
{
  auto texture = NewNearestTexture(window);
  texture->SetInternalFormat(GL_RG32UI);
  texture->SetFormat(GL_RG_INTEGER);
  texture->SetDataType(GL_UNSIGNED_INT);
  texture->Allocate2D(width, height, 2, VTK_UNSIGNED_INT);
  return texture;
}
}

TranslucentLayers::TranslucentLayers() = default;
TranslucentLayers::~TranslucentLayers() = default;

void TranslucentLayers::Peel(vtkOpenGLRenderWindow* window, int x0, int y0, int width, int height,
  int layers, const DrawMeshes& draw)
{
  vtkOpenGLState* state = window->GetState();
  layers = std::clamp(layers, 1, MaxLayers);
  if (width != this->Width || height != this->Height || !this->Framebuffer)
  {
    this->Release(window);
    this->Width = width;
    this->Height = height;
    this->Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    this->Framebuffer->SetContext(window);
    this->DepthTest = vtkSmartPointer<vtkTextureObject>::New();
    this->DepthTest->SetContext(window);
    this->Nothing = NewLayerTexture(window, 1, 1);
  }
  this->Opaque.Capture(window, x0, y0, width, height, true);
  // The depth test buffer takes the opaque depth before every layer, so a layer ends there.
  if (!this->DepthTest->GetHandle() || this->DepthTestFormat != this->Opaque.GetDepthFormat())
  {
    this->DepthTest->ReleaseGraphicsResources(window);
    this->Opaque.AllocateMatchingDepth(this->DepthTest, width, height);
    this->DepthTestFormat = this->Opaque.GetDepthFormat();
  }
  while (static_cast<int>(this->Layers.size()) < layers)
  {
    this->Layers.push_back(NewLayerTexture(window, width, height));
  }
  this->LayerCount = layers;

  state->PushFramebufferBindings();
  vtkOpenGLState::ScopedglViewport viewport(state);
  vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthTest(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglDepthMask depthMask(state);
  vtkOpenGLState::ScopedglDepthFunc depthFunc(state);
  this->Framebuffer->Bind(GL_DRAW_FRAMEBUFFER);
  this->Framebuffer->AddDepthAttachment(this->DepthTest);
  state->vtkglViewport(0, 0, width, height);
  state->vtkglDepthFunc(GL_LESS);
  // The meshes write their layer texel at location 1 (Features/Peel.glsl).
  const GLenum drawBuffers[2] = { GL_NONE, GL_COLOR_ATTACHMENT1 };
  auto resetDepth = [&]() {
    this->Opaque.GetFramebuffer()->Bind(GL_READ_FRAMEBUFFER);
    state->vtkglBlitFramebuffer(
      0, 0, width, height, 0, 0, width, height, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  };
  for (int k = 0; k < layers; ++k)
  {
    this->Framebuffer->AddColorAttachment(1, this->Layers[k]);
    glDrawBuffers(2, drawBuffers);
    resetDepth();
    glClearBufferuiv(GL_COLOR, 1, EmptyLayerTexel);
    draw(k > 0 ? PeelStep{ this->Layers[k - 1].Get(), false } : PeelStep{ this->Nothing.Get(), true });
  }
  // Is anything left behind the last layer? One more peel that only counts.
  this->Framebuffer->RemoveColorAttachment(1);
  glDrawBuffer(GL_NONE);
  resetDepth();
  if (!this->Query)
  {
    glGenQueries(1, &this->Query);
  }
  glBeginQuery(GL_ANY_SAMPLES_PASSED, this->Query);
  draw(PeelStep{ this->Layers[layers - 1].Get(), false });
  glEndQuery(GL_ANY_SAMPLES_PASSED);
  GLuint anyLeft = 0;
  glGetQueryObjectuiv(this->Query, GL_QUERY_RESULT, &anyLeft);
  this->Overflowed = anyLeft != 0;
  state->PopFramebufferBindings();
}

void TranslucentLayers::CaptureOpaque(vtkOpenGLRenderWindow* window, int x0, int y0, int width, int height)
{
  this->Opaque.Capture(window, x0, y0, width, height, true);
  this->LayerCount = 0;
  this->Overflowed = false;
}

ShaderFeature TranslucentLayers::GetShaderFeature() const
{
  return TranslucentLayersShaderFeature(this->LayerCount, this->Segments.GetSlices());
}

void TranslucentLayers::Activate(UniformSink& sink) const
{
  std::vector<int> units;
  for (int k = 0; k < this->LayerCount; ++k)
  {
    this->Layers[k]->Activate();
    units.push_back(this->Layers[k]->GetTextureUnit());
  }
  if (!units.empty())
  {
    sink.Set("u_layers", units);
  }
  if (this->Segments.GetSlices() > 0)
  {
    this->Segments.Activate(sink);
  }
  this->Opaque.GetColor()->Activate();
  sink.Set("u_opaqueColor", this->Opaque.GetColor()->GetTextureUnit());
}

void TranslucentLayers::Deactivate() const
{
  for (int k = 0; k < this->LayerCount; ++k)
  {
    this->Layers[k]->Deactivate();
  }
  if (this->Segments.GetSlices() > 0)
  {
    this->Segments.Deactivate();
  }
  this->Opaque.GetColor()->Deactivate();
}

void TranslucentLayers::Composite(vtkOpenGLRenderWindow* window, int x0, int y0, int width, int height)
{
  if (!this->Quad || this->QuadLayers != this->LayerCount || this->QuadSlices != this->Segments.GetSlices())
  {
    const std::string source = ComposeShader(
      vtkDeepShadowLayersFS, {}, { { "TranslucentLayers", this->GetShaderFeature() } });
    this->Quad.reset(new vtkOpenGLQuadHelper(window, nullptr, source.c_str(), ""));
    this->QuadLayers = this->LayerCount;
    this->QuadSlices = this->Segments.GetSlices();
  }
  if (!this->Quad->Program)
  {
    return; // the shader cache said why
  }
  window->GetShaderCache()->ReadyShaderProgram(this->Quad->Program);
  UniformSink sink(this->Quad->Program);
  this->Activate(sink);
  sink.Set("u_viewport", glm::vec4(x0, y0, width, height));
  vtkOpenGLState* state = window->GetState();
  vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthTest(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglDepthMask depthMask(state);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFunc(state);
  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDepthMask(GL_FALSE);
  this->Quad->Render();
  this->Deactivate();
}

long long TranslucentLayers::GetBytes() const
{
  const long long pixels = static_cast<long long>(this->Width) * this->Height;
  return pixels * (8 * static_cast<long long>(this->Layers.size()) + 4) + this->Opaque.GetBytes();
}

void TranslucentLayers::Release(vtkWindow* window)
{
  for (auto& layer : this->Layers)
  {
    layer->ReleaseGraphicsResources(window);
  }
  this->Layers.clear();
  for (vtkTextureObject* texture : { this->DepthTest.Get(), this->Nothing.Get() })
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
  if (this->Quad)
  {
    this->Quad->ReleaseGraphicsResources(window);
    this->Quad.reset();
  }
  this->Opaque.Release(window);
  this->Segments.Release(window);
  if (this->Query)
  {
    glDeleteQueries(1, &this->Query);
    this->Query = 0;
  }
  this->LayerCount = 0;
  this->Width = this->Height = 0;
}

}
