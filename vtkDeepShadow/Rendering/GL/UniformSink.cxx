#include "GL/UniformSink.h"

#include "GL/ComputeProgram.h"

#include "vtkShaderProgram.h"

#include <glm/gtc/type_ptr.hpp>

namespace deepshadow
{

void UniformSink::Set(const char* name, int value)
{
  this->Raster ? void(this->Raster->SetUniformi(name, value)) : this->Compute->Set(name, value);
}

void UniformSink::Set(const char* name, float value)
{
  this->Raster ? void(this->Raster->SetUniformf(name, value)) : this->Compute->Set(name, value);
}

void UniformSink::Set(const char* name, const glm::vec2& value)
{
  this->Raster ? void(this->Raster->SetUniform2f(name, glm::value_ptr(value)))
               : this->Compute->Set(name, value);
}

void UniformSink::Set(const char* name, const glm::vec3& value)
{
  this->Raster ? void(this->Raster->SetUniform3f(name, glm::value_ptr(value)))
               : this->Compute->Set(name, value);
}

void UniformSink::Set(const char* name, const glm::vec4& value)
{
  this->Raster ? void(this->Raster->SetUniform4f(name, glm::value_ptr(value)))
               : this->Compute->Set(name, value);
}

void UniformSink::Set(const char* name, const glm::mat3& value)
{
  glm::mat3 copy = value;
  this->Raster ? void(this->Raster->SetUniformMatrix3x3(name, glm::value_ptr(copy)))
               : this->Compute->Set(name, value);
}

void UniformSink::Set(const char* name, const glm::mat4& value)
{
  glm::mat4 copy = value;
  this->Raster ? void(this->Raster->SetUniformMatrix4x4(name, glm::value_ptr(copy)))
               : this->Compute->Set(name, value);
}

void UniformSink::Set(const char* name, const std::vector<int>& values)
{
  if (values.empty())
  {
    return;
  }
  this->Raster
    ? void(this->Raster->SetUniform1iv(name, static_cast<int>(values.size()), values.data()))
    : this->Compute->Set(name, values);
}

void UniformSink::Set(const char* name, const std::vector<float>& values)
{
  if (values.empty())
  {
    return;
  }
  this->Raster
    ? void(this->Raster->SetUniform1fv(name, static_cast<int>(values.size()), values.data()))
    : this->Compute->Set(name, values);
}

void UniformSink::Set(const char* name, const std::vector<glm::vec3>& values)
{
  if (values.empty())
  {
    return;
  }
  this->Raster ? void(this->Raster->SetUniform3fv(name, static_cast<int>(values.size()),
                   glm::value_ptr(values.front())))
               : this->Compute->Set(name, values);
}

void UniformSink::Set(const char* name, const std::vector<glm::vec4>& values)
{
  if (values.empty())
  {
    return;
  }
  this->Raster ? void(this->Raster->SetUniform4fv(name, static_cast<int>(values.size()),
                   reinterpret_cast<const float(*)[4]>(glm::value_ptr(values.front()))))
               : this->Compute->Set(name, values);
}

}
