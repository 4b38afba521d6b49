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

std::vector<double> ShadowContext::TransferKey(bool colors) const
{
  std::vector<double> key{ this->Transfer.OpacityUnitDistance };
  auto add = [&key](const PiecewiseLinear& function) {
    key.push_back(static_cast<double>(function.GetNodes().size()));
    for (const auto& [x, y] : function.GetNodes())
    {
      key.insert(key.end(), { x, y });
    }
  };
  add(this->Transfer.Opacity);
  if (colors)
  {
    add(this->Transfer.Red);
    add(this->Transfer.Green);
    add(this->Transfer.Blue);
  }
  return key;
}

void ShadowContext::AddVolumeFeatures(std::set<std::string>& enabled,
  std::map<std::string, ShaderFeature>& runtime, bool surfaces) const
{
  enabled.insert("VolumeSampling");
  if (this->Occupancy)
  {
    enabled.insert("EmptySpace");
  }
  if (this->Bound)
  {
    enabled.insert("TriangleHierarchy");
    runtime["Bound"] = BoundShaderFeature(static_cast<int>(this->Bound->LeafRoots.size()));
  }
  if (surfaces && this->Surfaces)
  {
    enabled.insert("TriangleHierarchy");
    enabled.insert("Surfaces");
  }
}

glm::dvec2 ShadowContext::ShaderTableMap() const
{
  // coordinate = scalar * TableMap.x + TableMap.y, scalar = (s - ShaderScalar.y) / ShaderScalar.x
  const double scale = this->TableMap.x / this->ShaderScalar.x;
  return { scale, this->TableMap.y - this->ShaderScalar.y * scale };
}

glm::dvec2 ShadowContext::ShaderRange() const
{
  return this->Range * this->ShaderScalar.x + this->ShaderScalar.y;
}

void ShadowContext::SetVolumeUniforms(UniformSink& sink) const
{
  sink.Set("u_volume", this->Volume->GetTextureUnit());
  sink.Set("u_scalarMap", glm::vec2(this->ScalarMap));
  sink.Set("u_tableMap", glm::vec2(this->ShaderTableMap()));
  sink.Set("u_dims", glm::vec3(this->Dims));
  sink.Set("u_worldToIndex", glm::mat4(this->WorldToIndex));
  if (this->Occupancy)
  {
    sink.Set("u_occupancy", this->Occupancy->GetTextureUnit());
    sink.Set("u_blockSize", this->BlockSize);
  }
  if (this->Bound)
  {
    sink.Set("u_boundNodes", this->Bound->Nodes->GetTextureUnit());
    sink.Set("u_boundTriangles", this->Bound->Triangles->GetTextureUnit());
    sink.Set("u_boundLeafRoot", this->Bound->LeafRoots);
    sink.Set("u_boundTruth", this->Bound->TruthTable);
  }
  if (this->Surfaces)
  {
    sink.Set("u_surfaceNodes", this->Surfaces->Nodes->GetTextureUnit());
    sink.Set("u_surfaceTriangles", this->Surfaces->Triangles->GetTextureUnit());
    sink.Set("u_surfaceRoot", this->Surfaces->Root);
    sink.Set("u_surfaceTransmission", this->Surfaces->Transmission);
  }
}

void ShadowContext::ActivateVolumeTextures() const
{
  this->Volume->Activate();
  if (this->Occupancy)
  {
    this->Occupancy->Activate();
  }
  if (this->Bound)
  {
    this->Bound->Nodes->Activate();
    this->Bound->Triangles->Activate();
  }
  if (this->Surfaces)
  {
    this->Surfaces->Nodes->Activate();
    this->Surfaces->Triangles->Activate();
  }
}

void ShadowContext::DeactivateVolumeTextures() const
{
  this->Volume->Deactivate();
  if (this->Occupancy)
  {
    this->Occupancy->Deactivate();
  }
  if (this->Bound)
  {
    this->Bound->Nodes->Deactivate();
    this->Bound->Triangles->Deactivate();
  }
  if (this->Surfaces)
  {
    this->Surfaces->Nodes->Deactivate();
    this->Surfaces->Triangles->Deactivate();
  }
}

}
