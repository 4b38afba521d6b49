#include "vtkDeepShadowRayTechnique.h"

#include "GL/ComputeProgram.h"
#include "ShadowContext.h"
#include "ShadowSlots.h"
#include "Shadows.h"
#include "vtkDeepShadowCachedRayShadow.h"
#include "vtkDeepShadowCachedShadowCS.h"
#include "vtkDeepShadowRayShadow.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>

vtkStandardNewMacro(vtkDeepShadowRayTechnique);

namespace
{
// Lights stacked along z; 8 is the ray caster's light limit.
constexpr int MaxCachedLights = 8;
}

// The 3D shadow volume of the cached variant and the pass that fills it.
class vtkDeepShadowRayTechnique::Cache
{
public:
  vtkSmartPointer<vtkTextureObject> Texture;
  glm::ivec3 Dims{ 0 };
  int Slabs = 0;
  deepshadow::ShadowSlots Slots;
  deepshadow::ComputeProgram Build;
};

vtkDeepShadowRayTechnique::vtkDeepShadowRayTechnique()
  : ShadowCache(new Cache)
{
}

vtkDeepShadowRayTechnique::~vtkDeepShadowRayTechnique() = default;

void vtkDeepShadowRayTechnique::SetShadowVolumeSize(int size)
{
  const int clamped = std::clamp(size, 2, 2048);
  if (clamped != size)
  {
    vtkWarningMacro("ShadowVolumeSize " << size << " is outside [2, 2048]; using " << clamped);
  }
  if (clamped != this->ShadowVolumeSize)
  {
    this->ShadowVolumeSize = clamped;
    this->Modified();
  }
}

deepshadow::ShadowParameters vtkDeepShadowRayTechnique::GetParameters() const
{
  deepshadow::ShadowParameters parameters;
  this->FillParameters(parameters);
  parameters.Kind = deepshadow::ShadowKind::Rays;
  parameters.Opaque = this->Opaque;
  parameters.Cached = this->Cached;
  parameters.VolumeSize = this->ShadowVolumeSize;
  parameters.EarlyTermination = this->EarlyTermination;
  return parameters;
}

std::string vtkDeepShadowRayTechnique::GetShaderFeatureSource() const
{
  return this->Cached ? vtkDeepShadowCachedRayShadow : vtkDeepShadowRayShadow;
}

bool vtkDeepShadowRayTechnique::Prepare(deepshadow::ShadowContext& context)
{
  if (!this->Superclass::Prepare(context))
  {
    return false;
  }
  Cache& cache = *this->ShadowCache;
  if (!this->Cached)
  {
    this->StructureBytes = 0;
    return true;
  }

  const int dropped = cache.Slots.Assign(context.Lights, MaxCachedLights);
  if (dropped > 0)
  {
    vtkWarningMacro(<< dropped << " shadow-casting lights beyond " << MaxCachedLights
                    << " cast no shadow");
  }
  const glm::ivec3 dims = deepshadow::ShadowVolumeDims(context.Dims, this->ShadowVolumeSize);
  GLint max3D = 0;
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &max3D);
  if (std::max({ dims.x, dims.y, dims.z * std::max(cache.Slabs, cache.Slots.Count()) }) > max3D)
  {
    this->LastError = "the shadow volume (" + std::to_string(dims.x) + "x" +
      std::to_string(dims.y) + "x" + std::to_string(dims.z) + " per light) exceeds this GL's 3D "
      "texture limit of " + std::to_string(max3D);
    return false;
  }
  // Grow only: fewer shadow-casting lights keep the others' slabs.
  const int slabs = std::max(cache.Texture && dims == cache.Dims ? cache.Slabs : 1,
    cache.Slots.Count());
  if (!cache.Texture || dims != cache.Dims || slabs != cache.Slabs)
  {
    if (cache.Texture)
    {
      cache.Texture->ReleaseGraphicsResources(context.Window);
    }
    cache.Texture = vtkSmartPointer<vtkTextureObject>::New();
    cache.Texture->SetContext(context.Window);
    cache.Texture->SetInternalFormat(GL_R16F);
    cache.Texture->SetFormat(GL_RED);
    cache.Texture->SetDataType(GL_FLOAT);
    cache.Texture->SetWrapS(vtkTextureObject::ClampToEdge);
    cache.Texture->SetWrapT(vtkTextureObject::ClampToEdge);
    cache.Texture->SetWrapR(vtkTextureObject::ClampToEdge);
    cache.Texture->SetMinificationFilter(vtkTextureObject::Linear);
    cache.Texture->SetMagnificationFilter(vtkTextureObject::Linear);
    cache.Texture->Allocate3D(static_cast<unsigned int>(dims.x),
      static_cast<unsigned int>(dims.y), static_cast<unsigned int>(dims.z * slabs), 1, VTK_FLOAT);
    cache.Dims = dims;
    cache.Slabs = slabs;
    cache.Slots.Invalidate();
  }
  this->StructureBytes = static_cast<long long>(dims.x) * dims.y * dims.z * slabs * 2;

  const std::vector<double> parameters{ this->Opaque ? 1.0 : 0.0, this->Threshold,
    static_cast<double>(this->ThresholdMode), this->StepFactor,
    static_cast<double>(this->ShadowVolumeSize), this->EarlyTermination ? 1.0 : 0.0 };
  std::vector<int> stale;
  for (int slot = 0; slot < cache.Slots.Count(); ++slot)
  {
    if (cache.Slots.Stale(slot, context, parameters))
    {
      stale.push_back(slot);
    }
  }
  if (stale.empty())
  {
    return true;
  }

  if (!this->BeginBuildPass(cache.Build, vtkDeepShadowCachedShadowCS, context))
  {
    return false;
  }
  cache.Build.Set("u_shadowDims", dims);
  cache.Build.Set("u_indexToWorld", glm::mat4(context.IndexToWorld));
  cache.Build.Set("u_opaque", this->Opaque ? 1 : 0);
  glBindImageTexture(0, cache.Texture->GetHandle(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R16F);
  for (int slot : stale)
  {
    const deepshadow::Light& light = context.Lights[static_cast<size_t>(cache.Slots.Light(slot))];
    cache.Build.Set("u_slot", slot);
    cache.Build.Set("u_lightPositional", light.Positional ? 1 : 0);
    cache.Build.Set("u_lightPosition", glm::vec3(light.Position));
    cache.Build.Set("u_lightToward", glm::vec3(glm::normalize(light.Position - light.FocalPoint)));
    cache.Build.Dispatch(dims, glm::ivec3(4));
  }
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R16F);
  this->EndBuildPass(context, static_cast<int>(stale.size()));
  return true;
}

void vtkDeepShadowRayTechnique::Bind(
  deepshadow::UniformSink& sink, const deepshadow::ShadowContext& context)
{
  const int lightCount = static_cast<int>(context.Lights.size());
  std::vector<float> attenuation;
  for (const deepshadow::Light& light : context.Lights)
  {
    attenuation.push_back(static_cast<float>(light.ShadowAttenuation));
  }
  if (!this->Cached)
  {
    this->ActivateFeelerTable();
    this->SetFeelerUniforms(sink, context, true);
    sink.Set("u_shadowAttenuation", attenuation);
    sink.Set("u_shadowOpaque", this->Opaque ? 1 : 0);
    return;
  }
  Cache& cache = *this->ShadowCache;
  cache.Texture->Activate();
  sink.Set("u_shadowVolume", cache.Texture->GetTextureUnit());
  sink.Set("u_shadowDims", glm::vec3(cache.Dims));
  sink.Set("u_shadowSlabs", static_cast<float>(cache.Slabs));
  sink.Set("u_shadowSlot", cache.Slots.SlotOfEachLight(lightCount));
  sink.Set("u_shadowAttenuation", attenuation);
}

void vtkDeepShadowRayTechnique::Unbind()
{
  this->Superclass::Unbind();
  if (this->Cached && this->ShadowCache->Texture)
  {
    this->ShadowCache->Texture->Deactivate();
  }
}

void vtkDeepShadowRayTechnique::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Superclass::ReleaseGraphicsResources(window);
  Cache& cache = *this->ShadowCache;
  if (cache.Texture)
  {
    cache.Texture->ReleaseGraphicsResources(window);
    cache.Texture = nullptr;
  }
  cache.Build.Release();
  cache.Slots.Invalidate();
}

void vtkDeepShadowRayTechnique::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Opaque: " << this->Opaque << "\n";
  os << indent << "Cached: " << this->Cached << " (" << this->ShadowVolumeSize << " nodes)\n";
  os << indent << "EarlyTermination: " << this->EarlyTermination << "\n";
}
