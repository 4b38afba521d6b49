// Internal: float data the shaders read with texelFetch, in RGBA32F 2D textures of
// FloatTexelsWidth columns (the hierarchies of Features/TriangleHierarchy.glsl).
#ifndef vtkDeepShadowFloatTexels_h
#define vtkDeepShadowFloatTexels_h

#include "vtkSmartPointer.h"

#include <glm/vec4.hpp>

#include <string>
#include <vector>

class vtkOpenGLRenderWindow;
class vtkTextureObject;

namespace deepshadow
{

/** HierarchyTextureWidth in Features/TriangleHierarchy.glsl. */
constexpr int FloatTexelsWidth = 4096;

/**
 * Why `texels` texels cannot be held by this GL (rows beyond its texture limit, or more than
 * 2^24 triangles of three texels, whose indices float cannot count exactly); "" if they can.
 */
std::string FloatTexelsLimit(size_t texels, size_t triangles, int hierarchyDepth);

/**
 * Replaces `texture` by a new one holding `texels` (padded to whole rows); returns its bytes.
 */
long long UploadFloatTexels(vtkOpenGLRenderWindow* window, vtkSmartPointer<vtkTextureObject>& texture,
  std::vector<glm::vec4> texels);

}
#endif
