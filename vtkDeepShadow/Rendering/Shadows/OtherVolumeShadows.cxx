#include "OtherVolumeShadows.h"

#include "GL/UniformSink.h"
#include "Sampling/ShadowContext.h"
#include "vtkDeepShadowTechniqueInternals.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cstdint>

namespace deepshadow
{

bool OtherVolumeShadows::Update(vtkOpenGLRenderWindow* window, const GridFrame& frame,
  const std::vector<VolumeCaster>& casters, std::string& error)
{
  // What the grid depends on. A caster that ran any pass this frame (its table, structure or
  // cache was rebuilt) changed what it casts; the key holds what can change without a pass
  // (lookup parameters, a feeler's volume moving).
  std::vector<double> key(glm::value_ptr(frame.NodeToWorld), glm::value_ptr(frame.NodeToWorld) + 16);
  key.insert(key.end(), { double(frame.Dims.x), double(frame.Dims.y), double(frame.Dims.z) });
  bool casterChanged = false;
  size_t lightCount = 0;
  for (const VolumeCaster& caster : casters)
  {
    const ShadowContext& context = *caster.Context;
    casterChanged = casterChanged || !caster.Technique->GetLastPasses().empty();
    key.insert(key.end(), { static_cast<double>(reinterpret_cast<uintptr_t>(caster.Technique)),
      static_cast<double>(caster.Technique->GetMTime()),
      static_cast<double>(context.DataVersion), static_cast<double>(context.BoundVersion),
      static_cast<double>(context.SurfacesVersion), context.ShadowStep });
    key.insert(key.end(), glm::value_ptr(context.IndexToWorld), glm::value_ptr(context.IndexToWorld) + 16);
    for (const Light& light : context.Lights)
    {
      key.insert(key.end(), { light.Positional ? 1.0 : 0.0, light.Position.x, light.Position.y,
        light.Position.z, light.FocalPoint.x, light.FocalPoint.y, light.FocalPoint.z,
        light.ShadowAttenuation > 0.0 ? 1.0 : 0.0 });
    }
    lightCount = std::max(lightCount, context.Lights.size());
  }
  if (!casterChanged && key == this->Key && this->Grid)
  {
    return true;
  }
  this->Key.clear();
  this->WrittenSlabs = 0;
  if (casters.empty() || lightCount == 0)
  {
    return true;
  }

  const int slabs = static_cast<int>(lightCount);
  GLint max3D = 0;
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &max3D);
  if (std::max({ frame.Dims.x, frame.Dims.y, frame.Dims.z * slabs }) > max3D)
  {
    error = "the other volumes' shadow grid (" + std::to_string(frame.Dims.x) + "x" +
      std::to_string(frame.Dims.y) + "x" + std::to_string(frame.Dims.z) + " per light) exceeds "
      "this GL's 3D texture limit of " + std::to_string(max3D);
    return false;
  }
  if (!this->Grid || frame.Dims != this->Frame.Dims || slabs != this->Slabs)
  {
    this->Release(window);
    this->Grid = vtkSmartPointer<vtkTextureObject>::New();
    this->Grid->SetContext(window);
    this->Grid->SetInternalFormat(GL_RGBA16F);
    this->Grid->SetFormat(GL_RGBA);
    this->Grid->SetDataType(GL_FLOAT);
    this->Grid->SetWrapS(vtkTextureObject::ClampToEdge);
    this->Grid->SetWrapT(vtkTextureObject::ClampToEdge);
    this->Grid->SetWrapR(vtkTextureObject::ClampToEdge);
    this->Grid->SetMinificationFilter(vtkTextureObject::Linear);
    this->Grid->SetMagnificationFilter(vtkTextureObject::Linear);
    this->Grid->Allocate3D(static_cast<unsigned int>(frame.Dims.x), static_cast<unsigned int>(frame.Dims.y),
      static_cast<unsigned int>(frame.Dims.z * slabs), 4, VTK_FLOAT);
    this->Slabs = slabs;
  }
  this->Frame = frame;
  int written = 0;
  for (const VolumeCaster& caster : casters)
  {
    written = vtkDeepShadowTechnique::Internals::EvaluateOnGrid(
      caster.Technique, *caster.Context, this->Grid, frame, written);
    if (written < 0)
    {
      error = "a volume casts no shadow onto the others: " + caster.Technique->GetLastError();
      this->WrittenSlabs = 0;
      return false;
    }
  }
  this->WrittenSlabs = written;
  this->Key = key;
  ++this->Builds;
  return true;
}

long long OtherVolumeShadows::GetBytes() const
{
  return this->Grid ? 8LL * this->Frame.Dims.x * this->Frame.Dims.y * this->Frame.Dims.z * this->Slabs : 0;
}

void OtherVolumeShadows::Activate(UniformSink& sink, int lightCount) const
{
  this->Grid->Activate();
  sink.Set("u_otherShadows", this->Grid->GetTextureUnit());
  sink.Set("u_otherDims", glm::vec3(this->Frame.Dims));
  sink.Set("u_otherSlabs", static_cast<float>(this->Slabs));
  sink.Set("u_otherWorldToNode", glm::mat4(this->Frame.WorldToNode));
  std::vector<int> slabOfLight;
  for (int l = 0; l < lightCount; ++l)
  {
    slabOfLight.push_back(l < this->Slabs && ((this->WrittenSlabs >> l) & 1) ? l : -1);
  }
  sink.Set("u_otherSlab", slabOfLight);
}

void OtherVolumeShadows::Deactivate() const
{
  if (this->Grid)
  {
    this->Grid->Deactivate();
  }
}

void OtherVolumeShadows::Release(vtkWindow* window)
{
  if (this->Grid)
  {
    this->Grid->ReleaseGraphicsResources(window);
    this->Grid = nullptr;
  }
  this->Key.clear();
  this->WrittenSlabs = 0;
  this->Slabs = 0;
}

}
