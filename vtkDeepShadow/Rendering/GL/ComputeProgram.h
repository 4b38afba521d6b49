// Internal: a GLSL compute program (VTK 9.1's vtkShaderProgram has no compute stage).
// Compiles once per source; uniforms by name; dispatch over a grid with a memory barrier so
// that later passes see what it wrote.
#ifndef vtkDeepShadowComputeProgram_h
#define vtkDeepShadowComputeProgram_h

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <string>
#include <vector>

namespace deepshadow
{

class ComputeProgram
{
public:
  ComputeProgram() = default;
  ~ComputeProgram();
  ComputeProgram(const ComputeProgram&) = delete;
  ComputeProgram& operator=(const ComputeProgram&) = delete;

  /** Compiles and links `source` unless it is the one already built. False: see Error(). */
  bool Build(const std::string& source);
  bool IsReady() const { return this->Program != 0; }
  const std::string& Error() const { return this->LastError; }
  /** How many times a program was compiled (observability). */
  int Compilations() const { return this->CompileCount; }

  void Use();
  void Set(const char* name, int value);
  void Set(const char* name, float value);
  void Set(const char* name, const glm::vec2& value);
  void Set(const char* name, const glm::ivec2& value);
  void Set(const char* name, const glm::ivec3& value);
  void Set(const char* name, const glm::vec3& value);
  void Set(const char* name, const glm::vec4& value);
  void Set(const char* name, const glm::mat3& value);
  void Set(const char* name, const glm::mat4& value);
  void Set(const char* name, const std::vector<int>& values);
  void Set(const char* name, const std::vector<float>& values);
  void Set(const char* name, const std::vector<glm::vec3>& values);
  void Set(const char* name, const std::vector<glm::vec4>& values);

  /** Dispatches enough groups of `local` invocations to cover `size`, then a barrier. */
  void Dispatch(const glm::ivec3& size, const glm::ivec3& local);

  /** Frees the GL program (the context must be current). */
  void Release();

private:
  int Location(const char* name);

  unsigned int Program = 0;
  std::string Source;
  std::string LastError;
  int CompileCount = 0;
};

}
#endif
