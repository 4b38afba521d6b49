#include "Volume/BoxDrawer.h"

#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkShaderProgram.h"
#include "vtk_glew.h"

#include <vector>

namespace deepshadow
{

void BoxDrawer::Draw(vtkOpenGLRenderWindow* window, vtkShaderProgram* program, bool blend, bool mirrored,
  const std::function<void()>& begin, const std::function<void()>& end)
{
  if (!this->VertexArray)
  {
    this->VertexArray = vtkSmartPointer<vtkOpenGLVertexArrayObject>::New();
    this->Corners = vtkSmartPointer<vtkOpenGLBufferObject>::New();
    this->Triangles = vtkSmartPointer<vtkOpenGLBufferObject>::New();
    std::vector<float> corners;
    for (int i = 0; i < 8; ++i)
    {
      corners.insert(corners.end(), { float(i & 1), float((i >> 1) & 1), float((i >> 2) & 1) });
    }
    // Counter-clockwise seen from outside (outward normals).
    const std::vector<unsigned int> triangles = { 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5, 0, 1, 5, 0, 5, 4, 2,
      6, 7, 2, 7, 3, 0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6 };
    this->Corners->Upload(corners, vtkOpenGLBufferObject::ArrayBuffer);
    this->Triangles->Upload(triangles, vtkOpenGLBufferObject::ElementArrayBuffer);
  }
  const bool programChanged = this->Program != program;
  if (programChanged)
  {
    this->VertexArray->ShaderProgramChanged(); // drops the VAO: rebind before adding arrays
  }
  this->VertexArray->Bind();
  if (programChanged)
  {
    this->VertexArray->AddAttributeArray(
      program, this->Corners, "a_corner", 0, 3 * sizeof(float), VTK_FLOAT, 3, false);
    this->Program = program;
  }
  this->Triangles->Bind();
  {
    vtkOpenGLState* state = window->GetState();
    vtkOpenGLState::ScopedglEnableDisable blendScope(state, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable depthTest(state, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglEnableDisable cull(state, GL_CULL_FACE);
    vtkOpenGLState::ScopedglDepthMask depthMask(state);
    vtkOpenGLState::ScopedglBlendFuncSeparate blendFunc(state);
    if (blend)
    {
      state->vtkglEnable(GL_BLEND);
      state->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    }
    else
    {
      state->vtkglDisable(GL_BLEND);
    }
    state->vtkglDisable(GL_DEPTH_TEST);
    state->vtkglDepthMask(GL_FALSE);
    state->vtkglEnable(GL_CULL_FACE);
    state->vtkglCullFace(GL_FRONT);
    glFrontFace(mirrored ? GL_CW : GL_CCW);
    glEnable(GL_DEPTH_CLAMP);
    if (begin)
    {
      begin();
    }
    glDrawElements(GL_TRIANGLES, 36, GL_UNSIGNED_INT, nullptr);
    if (end)
    {
      end();
    }
    glDisable(GL_DEPTH_CLAMP);
    glFrontFace(GL_CCW);
    state->vtkglCullFace(GL_BACK);
  }
  this->Triangles->Release();
  this->VertexArray->Release();
}

void BoxDrawer::Release()
{
  if (this->VertexArray)
  {
    this->VertexArray->ReleaseGraphicsResources();
  }
  if (this->Corners)
  {
    this->Corners->ReleaseGraphicsResources();
  }
  if (this->Triangles)
  {
    this->Triangles->ReleaseGraphicsResources();
  }
  *this = BoxDrawer();
}

}
