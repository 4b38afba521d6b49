#include "vtkDeepShadowShadowMapTechnique.h"

#include "GL/ComputeProgram.h"
#include "ShadowContext.h"
#include "ShadowSlots.h"
#include "Shadows.h"
#include "vtkDeepShadowMapShadow.h"
#include "vtkDeepShadowShadowMapCS.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkTextureUnitManager.h"
#include "vtk_glew.h"

#include <algorithm>
#include <sstream>

vtkStandardNewMacro(vtkDeepShadowShadowMapTechnique);

namespace
{
constexpr int MaxShadowLights = 4; // MapShadow.glsl's array sizes
}

// The maps (one R32F 2D array texture, six layers per shadow-casting light) and their pass.
class vtkDeepShadowShadowMapTechnique::Maps
{
public:
  unsigned int Texture = 0;
  int Size = 0;
  int Slabs = 0;
  int LayersPerLight = 1; // 6 once some light needs a cube of faces
  int Unit = -1;
  vtkOpenGLRenderWindow* Window = nullptr;
  deepshadow::ShadowSlots Slots;
  std::vector<std::vector<deepshadow::ShadowMapFace>> Faces; // per slot
  deepshadow::ComputeProgram Build;

  void Release()
  {
    if (this->Texture)
    {
      glDeleteTextures(1, &this->Texture);
      this->Texture = 0;
    }
    this->Build.Release();
    this->Slots.Invalidate();
  }
};

vtkDeepShadowShadowMapTechnique::vtkDeepShadowShadowMapTechnique()
  : ShadowMaps(new Maps)
{
}

vtkDeepShadowShadowMapTechnique::~vtkDeepShadowShadowMapTechnique() = default;

void vtkDeepShadowShadowMapTechnique::SetMapSize(int size)
{
  const int clamped = std::max(size, 1);
  if (clamped != size)
  {
    vtkWarningMacro("MapSize " << size << " is below 1; using 1");
  }
  if (clamped != this->MapSize)
  {
    this->MapSize = clamped;
    this->Modified();
  }
}

void vtkDeepShadowShadowMapTechnique::SetBias(double bias)
{
  const double clamped = std::max(bias, 0.0);
  if (clamped != bias)
  {
    vtkWarningMacro("Bias " << bias << " is negative; using 0");
  }
  if (clamped != this->Bias)
  {
    this->Bias = clamped;
    this->Modified();
  }
}

deepshadow::ShadowParameters vtkDeepShadowShadowMapTechnique::GetParameters() const
{
  deepshadow::ShadowParameters parameters;
  this->FillParameters(parameters);
  parameters.Kind = deepshadow::ShadowKind::ShadowMap;
  parameters.MapSize = this->MapSize;
  parameters.Bias = this->Bias;
  parameters.Filter = static_cast<deepshadow::ShadowFilter>(this->Filter);
  return parameters;
}

std::string vtkDeepShadowShadowMapTechnique::GetShaderFeatureSource() const
{
  // The filter and the Poisson disc come from Core, the CPU twin's tables.
  std::ostringstream constants;
  constants << "//@Dec\n#define SHADOW_FILTER " << this->Filter << "\n";
  const auto& disc = deepshadow::PoissonDisc();
  constants << "#define POISSON_TAPS " << disc.size() << "\nconst vec2 POISSON_DISC["
            << disc.size() << "] = vec2[" << disc.size() << "](";
  for (size_t k = 0; k < disc.size(); ++k)
  {
    constants << (k ? ", " : "") << "vec2(" << disc[k].x << ", " << disc[k].y << ")";
  }
  constants << ");\n";
  // The constants go first in the Dec part of the map lookup.
  std::string source = vtkDeepShadowMapShadow;
  const size_t dec = source.find("//@Dec\n");
  return source.replace(dec, 7, constants.str());
}

bool vtkDeepShadowShadowMapTechnique::Prepare(deepshadow::ShadowContext& context)
{
  if (!this->Superclass::Prepare(context))
  {
    return false;
  }
  Maps& maps = *this->ShadowMaps;
  maps.Window = context.Window;
  GLint maxSize = 0, maxLayers = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &maxLayers);
  if (this->MapSize > maxSize)
  {
    this->LastError = "shadow map size " + std::to_string(this->MapSize) +
      " exceeds this GL's texture limit of " + std::to_string(maxSize);
    return false;
  }
  const int dropped = maps.Slots.Assign(context.Lights, MaxShadowLights);
  if (dropped > 0)
  {
    vtkWarningMacro(<< dropped << " shadow-casting lights beyond " << MaxShadowLights
                    << " cast no shadow map");
  }
  glm::dvec3 centre;
  double radius = 0.0;
  deepshadow::VolumeBoundingSphere(context.IndexToWorld, context.Dims, centre, radius);
  const std::vector<double> parameters{ this->Threshold, static_cast<double>(this->ThresholdMode),
    this->StepFactor, static_cast<double>(this->MapSize) };
  maps.Faces.resize(static_cast<size_t>(maps.Slots.Count()));
  int layersPerLight = 1;
  for (int slot = 0; slot < maps.Slots.Count(); ++slot)
  {
    maps.Faces[slot] = deepshadow::ShadowMapFaces(
      context.Lights[static_cast<size_t>(maps.Slots.Light(slot))], centre, radius);
    layersPerLight = std::max(layersPerLight, static_cast<int>(maps.Faces[slot].size()));
  }
  // Grow only: fewer shadow-casting lights keep the others' maps.
  const int slabs = std::max(maps.Texture && maps.Size == this->MapSize ? maps.Slabs : 1,
    maps.Slots.Count());
  layersPerLight = std::max(
    layersPerLight, maps.Texture && maps.Size == this->MapSize ? maps.LayersPerLight : 1);
  if (!maps.Texture || maps.Size != this->MapSize || maps.Slabs != slabs ||
    maps.LayersPerLight != layersPerLight)
  {
    if (maps.Texture)
    {
      glDeleteTextures(1, &maps.Texture);
    }
    glGenTextures(1, &maps.Texture);
    glBindTexture(GL_TEXTURE_2D_ARRAY, maps.Texture);
    glTexStorage3D(GL_TEXTURE_2D_ARRAY, 1, GL_R32F, this->MapSize, this->MapSize,
      std::min(slabs * layersPerLight, static_cast<int>(maxLayers)));
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
    maps.Size = this->MapSize;
    maps.Slabs = slabs;
    maps.LayersPerLight = layersPerLight;
    maps.Slots.Invalidate();
  }
  this->StructureBytes =
    static_cast<long long>(this->MapSize) * this->MapSize * slabs * maps.LayersPerLight * 4;

  std::vector<int> stale;
  for (int slot = 0; slot < maps.Slots.Count(); ++slot)
  {
    maps.Faces[slot] = deepshadow::ShadowMapFaces(
      context.Lights[static_cast<size_t>(maps.Slots.Light(slot))], centre, radius);
    if (maps.Slots.Stale(slot, context, parameters))
    {
      stale.push_back(slot);
    }
  }
  if (stale.empty())
  {
    return true;
  }

  if (!this->BeginBuildPass(maps.Build, vtkDeepShadowShadowMapCS, context))
  {
    return false;
  }
  maps.Build.Set("u_size", this->MapSize);
  glBindImageTexture(0, maps.Texture, 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R32F);
  for (int slot : stale)
  {
    for (size_t f = 0; f < maps.Faces[slot].size(); ++f)
    {
      const deepshadow::ShadowMapFace& face = maps.Faces[slot][f];
      maps.Build.Set("u_layer", slot * maps.LayersPerLight + static_cast<int>(f));
      maps.Build.Set("u_perspective", face.Perspective ? 1 : 0);
      maps.Build.Set("u_origin", glm::vec3(face.Origin));
      maps.Build.Set("u_forward", glm::vec3(face.Forward));
      maps.Build.Set("u_right", glm::vec3(face.Right));
      maps.Build.Set("u_up", glm::vec3(face.Up));
      maps.Build.Set("u_extent", static_cast<float>(face.Extent));
      maps.Build.Dispatch(glm::ivec3(this->MapSize, this->MapSize, 1), glm::ivec3(8, 8, 1));
    }
  }
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
  this->EndBuildPass(context, static_cast<int>(stale.size()));
  return true;
}

void vtkDeepShadowShadowMapTechnique::Bind(
  deepshadow::UniformSink& sink, const deepshadow::ShadowContext& context)
{
  Maps& maps = *this->ShadowMaps;
  maps.Unit = context.Window->GetTextureUnitManager()->Allocate();
  glActiveTexture(GL_TEXTURE0 + maps.Unit);
  glBindTexture(GL_TEXTURE_2D_ARRAY, maps.Texture);
  sink.Set("u_shadowMap", maps.Unit);
  std::vector<float> attenuation;
  for (const deepshadow::Light& light : context.Lights)
  {
    attenuation.push_back(static_cast<float>(light.ShadowAttenuation));
  }
  sink.Set("u_shadowSlot", maps.Slots.SlotOfEachLight(static_cast<int>(context.Lights.size())));
  sink.Set("u_shadowAttenuation", attenuation);
  std::vector<int> faceCount, perspective;
  std::vector<glm::vec3> origin, forward, right, up;
  std::vector<float> extent;
  for (const auto& faces : maps.Faces)
  {
    faceCount.push_back(static_cast<int>(faces.size()));
    perspective.push_back(faces.front().Perspective ? 1 : 0);
    origin.emplace_back(faces.front().Origin);
    forward.emplace_back(faces.front().Forward);
    right.emplace_back(faces.front().Right);
    up.emplace_back(faces.front().Up);
    extent.push_back(static_cast<float>(faces.front().Extent));
  }
  sink.Set("u_shadowFaceCount", faceCount);
  sink.Set("u_shadowPerspective", perspective);
  sink.Set("u_shadowOrigin", origin);
  sink.Set("u_shadowForward", forward);
  sink.Set("u_shadowRight", right);
  sink.Set("u_shadowUp", up);
  sink.Set("u_shadowExtent", extent);
  sink.Set("u_shadowSize", static_cast<float>(this->MapSize));
  sink.Set("u_shadowLayersPerLight", maps.LayersPerLight);
  sink.Set("u_shadowBias", static_cast<float>(this->Bias * this->FeelerStep(context)));
}

void vtkDeepShadowShadowMapTechnique::Unbind()
{
  this->Superclass::Unbind();
  Maps& maps = *this->ShadowMaps;
  if (maps.Unit >= 0)
  {
    glActiveTexture(GL_TEXTURE0 + maps.Unit);
    glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
    maps.Window->GetTextureUnitManager()->Free(maps.Unit);
    maps.Unit = -1;
  }
}

void vtkDeepShadowShadowMapTechnique::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Superclass::ReleaseGraphicsResources(window);
  this->ShadowMaps->Release();
}

void vtkDeepShadowShadowMapTechnique::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MapSize: " << this->MapSize << "\n";
  os << indent << "Bias: " << this->Bias << " feeler steps\n";
  os << indent << "Filter: " << this->Filter << "\n";
}
