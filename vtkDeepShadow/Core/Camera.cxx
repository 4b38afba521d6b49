#include "Core/Camera.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <limits>
#include <utility>

namespace deepshadow
{

Camera::Camera(const glm::dmat4& viewProjection, int width, int height)
  : ViewProjection(viewProjection)
  , InverseViewProjection(glm::inverse(viewProjection))
  , Width(width)
  , Height(height)
{
}

glm::dvec3 Camera::Unproject(double x, double y, double z) const
{
  const glm::dvec4 ndc(2.0 * x / this->Width - 1.0, 2.0 * y / this->Height - 1.0, 2.0 * z - 1.0, 1.0);
  const glm::dvec4 world = this->InverseViewProjection * ndc;
  return glm::dvec3(world) / world.w;
}

bool Camera::Project(const glm::dvec3& p, double& x, double& y) const
{
  const glm::dvec4 clip = this->ViewProjection * glm::dvec4(p, 1.0);
  if (!(clip.w > 0.0))
  {
    return false;
  }
  x = 0.5 * (clip.x / clip.w + 1.0) * this->Width;
  y = 0.5 * (clip.y / clip.w + 1.0) * this->Height;
  return true;
}

Ray Camera::RayThrough(double x, double y) const
{
  const glm::dvec3 nearPoint = this->Unproject(x, y, 0.0);
  const glm::dvec3 farPoint = this->Unproject(x, y, 1.0);
  return Ray{ nearPoint, glm::normalize(farPoint - nearPoint) };
}

bool IntersectBox(const Ray& ray, const glm::dmat4& worldToBox, const glm::dvec3& lo,
  const glm::dvec3& hi, double& tEnter, double& tExit)
{
  const glm::dvec3 origin = glm::dvec3(worldToBox * glm::dvec4(ray.Origin, 1.0));
  const glm::dvec3 direction = glm::dvec3(worldToBox * glm::dvec4(ray.Direction, 0.0));
  tEnter = -std::numeric_limits<double>::infinity();
  tExit = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < 3; ++axis)
  {
    if (direction[axis] == 0.0)
    {
      if (origin[axis] < lo[axis] || origin[axis] > hi[axis])
      {
        return false;
      }
      continue;
    }
    double t0 = (lo[axis] - origin[axis]) / direction[axis];
    double t1 = (hi[axis] - origin[axis]) / direction[axis];
    if (t0 > t1)
    {
      std::swap(t0, t1);
    }
    tEnter = std::max(tEnter, t0);
    tExit = std::min(tExit, t1);
  }
  return tEnter <= tExit;
}

}
