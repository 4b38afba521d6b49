#include "ComputeProgram.h"

#include "vtk_glew.h"

#include <glm/gtc/type_ptr.hpp>

#include <vector>

namespace deepshadow
{

ComputeProgram::~ComputeProgram() = default; // GL objects need a context: Release() frees them

bool ComputeProgram::Build(const std::string& source)
{
  if (this->Program && source == this->Source)
  {
    return true;
  }
  this->Release();
  this->Source = source;
  const GLuint shader = glCreateShader(GL_COMPUTE_SHADER);
  if (!shader)
  {
    this->LastError = "this OpenGL context has no compute shaders (OpenGL 4.3 is needed)";
    return false;
  }
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  auto log = [](GLuint object, bool isProgram) {
    GLint length = 0;
    isProgram ? glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length)
              : glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> text(static_cast<size_t>(length) + 1, '\0');
    isProgram ? glGetProgramInfoLog(object, length, nullptr, text.data())
              : glGetShaderInfoLog(object, length, nullptr, text.data());
    return std::string(text.data());
  };
  if (!ok)
  {
    this->LastError = "compute shader failed to compile: " + log(shader, false);
    glDeleteShader(shader);
    return false;
  }
  const GLuint program = glCreateProgram();
  glAttachShader(program, shader);
  glLinkProgram(program);
  glDeleteShader(shader);
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok)
  {
    this->LastError = "compute program failed to link: " + log(program, true);
    glDeleteProgram(program);
    return false;
  }
  this->Program = program;
  this->LastError.clear();
  ++this->CompileCount;
  return true;
}

void ComputeProgram::Use()
{
  glUseProgram(this->Program);
}

int ComputeProgram::Location(const char* name)
{
  return glGetUniformLocation(this->Program, name);
}

void ComputeProgram::Set(const char* name, int value)
{
  glUniform1i(this->Location(name), value);
}

void ComputeProgram::Set(const char* name, float value)
{
  glUniform1f(this->Location(name), value);
}

void ComputeProgram::Set(const char* name, const glm::vec2& value)
{
  glUniform2fv(this->Location(name), 1, glm::value_ptr(value));
}

void ComputeProgram::Set(const char* name, const glm::ivec2& value)
{
  glUniform2iv(this->Location(name), 1, glm::value_ptr(value));
}

void ComputeProgram::Set(const char* name, const glm::ivec3& value)
{
  glUniform3iv(this->Location(name), 1, glm::value_ptr(value));
}

void ComputeProgram::Set(const char* name, const glm::vec3& value)
{
  glUniform3fv(this->Location(name), 1, glm::value_ptr(value));
}

void ComputeProgram::Set(const char* name, const glm::vec4& value)
{
  glUniform4fv(this->Location(name), 1, glm::value_ptr(value));
}

void ComputeProgram::Set(const char* name, const glm::mat3& value)
{
  glUniformMatrix3fv(this->Location(name), 1, GL_FALSE, glm::value_ptr(value));
}

void ComputeProgram::Set(const char* name, const glm::mat4& value)
{
  glUniformMatrix4fv(this->Location(name), 1, GL_FALSE, glm::value_ptr(value));
}

void ComputeProgram::Set(const char* name, const std::vector<int>& values)
{
  if (!values.empty())
  {
    glUniform1iv(this->Location(name), static_cast<GLsizei>(values.size()), values.data());
  }
}

void ComputeProgram::Set(const char* name, const std::vector<float>& values)
{
  if (!values.empty())
  {
    glUniform1fv(this->Location(name), static_cast<GLsizei>(values.size()), values.data());
  }
}

void ComputeProgram::Set(const char* name, const std::vector<glm::vec3>& values)
{
  if (!values.empty())
  {
    glUniform3fv(this->Location(name), static_cast<GLsizei>(values.size()), glm::value_ptr(values.front()));
  }
}

void ComputeProgram::Set(const char* name, const std::vector<glm::vec4>& values)
{
  if (!values.empty())
  {
    glUniform4fv(this->Location(name), static_cast<GLsizei>(values.size()), glm::value_ptr(values.front()));
  }
}

void ComputeProgram::Dispatch(const glm::ivec3& size, const glm::ivec3& local)
{
  const glm::ivec3 groups = (size + local - 1) / local;
  glDispatchCompute(static_cast<GLuint>(groups.x), static_cast<GLuint>(groups.y),
    static_cast<GLuint>(groups.z));
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
    GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

void ComputeProgram::Release()
{
  if (this->Program)
  {
    glDeleteProgram(this->Program);
    this->Program = 0;
  }
  this->Source.clear();
}

}
