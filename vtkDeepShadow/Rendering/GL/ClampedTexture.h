// Internal: a texture object that clamps to its edges, as every lookup table and volume of the
// ray caster wants.
#ifndef vtkDeepShadowClampedTexture_h
#define vtkDeepShadowClampedTexture_h

#include "vtkOpenGLRenderWindow.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"

namespace deepshadow
{

inline vtkSmartPointer<vtkTextureObject> NewClampedTexture(vtkOpenGLRenderWindow* window)
{
  auto texture = vtkSmartPointer<vtkTextureObject>::New();
  texture->SetContext(window);
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  texture->SetWrapR(vtkTextureObject::ClampToEdge);
  return texture;
}

}
#endif
