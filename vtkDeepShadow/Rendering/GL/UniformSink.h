// Internal: a uniform setter shared by the ray caster's program and the techniques' compute
// programs, so that one function sets a feature's uniforms on either.
#ifndef vtkDeepShadowUniformSink_h
#define vtkDeepShadowUniformSink_h

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <vector>

class vtkShaderProgram;

namespace deepshadow
{
class ComputeProgram;

/** Sets uniforms by name on either kind of program. */
class UniformSink
{
public:
  explicit UniformSink(vtkShaderProgram* program)
    : Raster(program)
  {
  }
  explicit UniformSink(ComputeProgram* program)
    : Compute(program)
  {
  }
  void Set(const char* name, int value);
  void Set(const char* name, float value);
  void Set(const char* name, const glm::vec2& value);
  void Set(const char* name, const glm::vec3& value);
  void Set(const char* name, const glm::vec4& value);
  void Set(const char* name, const glm::mat3& value);
  void Set(const char* name, const glm::mat4& value);
  // Arrays (the ray caster's per-light uniforms).
  void Set(const char* name, const std::vector<int>& values);
  void Set(const char* name, const std::vector<float>& values);
  void Set(const char* name, const std::vector<glm::vec3>& values);
  void Set(const char* name, const std::vector<glm::vec4>& values);

private:
  vtkShaderProgram* Raster = nullptr;
  ComputeProgram* Compute = nullptr;
};

}
#endif
