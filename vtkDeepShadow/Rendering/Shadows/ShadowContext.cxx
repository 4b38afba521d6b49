#include "ShadowContext.h"

#include "GL/ComputeProgram.h"

#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

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
  if (this->Raster)
  {
    this->Raster->SetUniform4f(name, glm::value_ptr(value));
  }
}

void UniformSink::Set(const char* name, const glm::mat3& value)
{
  glm::mat3 copy = value;
  if (this->Raster)
  {
    this->Raster->SetUniformMatrix3x3(name, glm::value_ptr(copy));
  }
}

void UniformSink::Set(const char* name, const glm::mat4& value)
{
  glm::mat4 copy = value;
  this->Raster ? void(this->Raster->SetUniformMatrix4x4(name, glm::value_ptr(copy)))
               : this->Compute->Set(name, value);
}

void UniformSink::Set(const char* name, const std::vector<int>& values)
{
  if (this->Raster && !values.empty())
  {
    this->Raster->SetUniform1iv(name, static_cast<int>(values.size()), values.data());
  }
}

void UniformSink::Set(const char* name, const std::vector<float>& values)
{
  if (this->Raster && !values.empty())
  {
    this->Raster->SetUniform1fv(name, static_cast<int>(values.size()), values.data());
  }
}

void UniformSink::Set(const char* name, const std::vector<glm::vec3>& values)
{
  if (this->Raster && !values.empty())
  {
    this->Raster->SetUniform3fv(
      name, static_cast<int>(values.size()), glm::value_ptr(values.front()));
  }
}

void ShadowContext::SetVolumeUniforms(UniformSink& sink) const
{
  sink.Set("u_volume", this->Volume->GetTextureUnit());
  sink.Set("u_scalarMap", glm::vec2(this->ScalarMap));
  sink.Set("u_tableMap", glm::vec2(this->TableMap));
  sink.Set("u_dims", glm::vec3(this->Dims));
  sink.Set("u_worldToIndex", glm::mat4(this->WorldToIndex));
  if (this->Occupancy)
  {
    sink.Set("u_occupancy", this->Occupancy->GetTextureUnit());
    sink.Set("u_blockSize", this->BlockSize);
  }
}

}
