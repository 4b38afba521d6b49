// Internal: the ray caster's proxy geometry: the volume's box in index space [0,1]^3 (scaled
// by the vertex shader), whose back faces start one fragment per pixel the box covers.
#ifndef vtkDeepShadowBoxDrawer_h
#define vtkDeepShadowBoxDrawer_h

#include "vtkSmartPointer.h"

#include <functional>

class vtkOpenGLBufferObject;
class vtkOpenGLRenderWindow;
class vtkOpenGLVertexArrayObject;
class vtkShaderProgram;

namespace deepshadow
{

class BoxDrawer
{
public:
  /**
   * Draws the box's back faces with `program` (attribute a_corner): no depth test or write,
   * depth clamped, blended front-to-back premultiplied when `blend`. `mirrored`: the
   * index-to-world transform turns the box inside out. `begin` and `end`, if set, run just
   * before and after the draw call (a render target of the pass).
   */
  void Draw(vtkOpenGLRenderWindow* window, vtkShaderProgram* program, bool blend, bool mirrored,
    const std::function<void()>& begin, const std::function<void()>& end);
  void Release();

private:
  vtkSmartPointer<vtkOpenGLVertexArrayObject> VertexArray;
  vtkSmartPointer<vtkOpenGLBufferObject> Corners;
  vtkSmartPointer<vtkOpenGLBufferObject> Triangles;
  vtkShaderProgram* Program = nullptr; // the program VertexArray's attributes are bound to
};

}
#endif
