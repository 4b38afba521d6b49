// Pixel rays, built the way the GPU builds them: through the inverse of the view-projection
// matrix (OpenGL conventions), from the near plane, through pixel centres.
#ifndef deepshadow_Camera_h
#define deepshadow_Camera_h

#include "vtkDeepShadowCoreModule.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace deepshadow
{

struct Ray
{
  glm::dvec3 Origin{ 0.0 };    // on the near plane
  glm::dvec3 Direction{ 0.0, 0.0, -1.0 }; // unit length; t is world distance from Origin
};

class VTKDEEPSHADOWCORE_EXPORT Camera
{
public:
  Camera() = default;
  /** `viewProjection` maps world to OpenGL clip space; the viewport is width x height. */
  Camera(const glm::dmat4& viewProjection, int width, int height);

  int GetWidth() const { return this->Width; }
  int GetHeight() const { return this->Height; }
  const glm::dmat4& GetViewProjection() const { return this->ViewProjection; }
  const glm::dmat4& GetInverseViewProjection() const { return this->InverseViewProjection; }

  /** Ray through window position (x, y), in pixels from the lower-left corner. */
  Ray RayThrough(double x, double y) const;
  /** Ray through the centre of pixel (px, py). */
  Ray PixelRay(int px, int py) const { return this->RayThrough(px + 0.5, py + 0.5); }

  /** World point of window position (x, y) at window depth z in [0, 1]. */
  glm::dvec3 Unproject(double x, double y, double z) const;
  /** Window position (x, y) of world point p; false if p is not in front of the camera. */
  bool Project(const glm::dvec3& p, double& x, double& y) const;

private:
  glm::dmat4 ViewProjection{ 1.0 };
  glm::dmat4 InverseViewProjection{ 1.0 };
  int Width = 1;
  int Height = 1;
};

/**
 * Parametric interval [tEnter, tExit] where `ray` is inside the box [lo, hi] of the space
 * that `worldToBox` maps to (t stays world distance). Returns false if the ray misses it.
 */
VTKDEEPSHADOWCORE_EXPORT bool IntersectBox(const Ray& ray, const glm::dmat4& worldToBox,
  const glm::dvec3& lo, const glm::dvec3& hi, double& tEnter, double& tExit);

}
#endif
