#include "vtkDeepShadowTechniqueInternals.h"

#include "GL/ComputeProgram.h"
#include "GL/GLObjects.h"
#include "Core/Shadows/LightSpace.h"
#include "GL/UniformSink.h"
#include "Sampling/ShadowContext.h"
#include "LightSpaceBricks.h"
#include "LightSpaceClusters.h"
#include "LightSpaceFaces.h"
#include "ShadowSlots.h"
#include "vtkDeepShadowBrickTotalsCS.h"
#include "vtkDeepShadowLightSpaceCS.h"

#include "vtkDeepShadowBrickExchange.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkTextureUnitManager.h"
#include "vtk_glew.h"

#include <algorithm>

// The texels of every face of every shadow-casting light: one 2D array texture, layer
// ((slot * FacesPerLight) + face) * LayersPerFace + k, and the pass that fills it.
class vtkDeepShadowLightSpaceTechnique::Maps
{
public:
  unsigned int Texture = 0;
  unsigned int Format = 0;
  int Size = 0;
  int Slabs = 0;
  int FacesPerLight = 1; // 6 once some light needs a cube of faces
  int LayersPerFace = 1;
  double CasterRadius = 0.0; // the casters' bounding sphere, as the faces see it
  int Unit = -1;
  vtkOpenGLRenderWindow* Window = nullptr;
  std::vector<std::vector<deepshadow::ShadowMapFace>> Faces; // per slot
  deepshadow::LightSpaceClusters Clusters; // clustered faces (SetClusters)
  deepshadow::ComputeProgram Build;
  unsigned int Deferred = 0; // the build's deferred texels: a count, then one uint each
  // Other processes' bricks of the volume (vtkDeepShadowBrickExchange), and the pass that
  // reads this brick's total transmittance per texel into Totals (RGBA32F, one layer per face).
  deepshadow::LightSpaceBricks Bricks;
  deepshadow::ComputeProgram TotalsPass;
  unsigned int Totals = 0;
  int TotalsLayers = 0;
  int TotalsSize = 0;
  std::string BrickProblem; // said once while it lasts
  bool SaidOverlap = false;  // the same

  void Release()
  {
    if (this->Totals)
    {
      glDeleteTextures(1, &this->Totals);
      this->Totals = 0;
      this->TotalsLayers = 0;
      this->TotalsSize = 0;
    }
    this->TotalsPass.Release();
    this->Bricks.Release();
    this->Clusters.Release(this->Window);
    if (this->Texture)
    {
      glDeleteTextures(1, &this->Texture);
      this->Texture = 0;
    }
    if (this->Deferred)
    {
      glDeleteBuffers(1, &this->Deferred);
      this->Deferred = 0;
    }
    this->Build.Release();
  }
};

namespace
{
int BytesPerTexel(unsigned int format)
{
  switch (format)
  {
    case GL_R32F:
    case GL_RGBA8:
      return 4;
    case GL_RG32F:
    case GL_RGBA16:
      return 8;
    default:
      return 16;
  }
}

// The lights of the technique's slots, in slot order.
std::vector<deepshadow::Light> SlotLights(const deepshadow::ShadowContext& context, const deepshadow::ShadowSlots& slots)
{
  std::vector<deepshadow::Light> lights;
  for (int slot = 0; slot < slots.Count(); ++slot)
  {
    lights.push_back(context.Lights[static_cast<size_t>(slots.Light(slot))]);
  }
  return lights;
}
}

vtkDeepShadowLightSpaceTechnique::vtkDeepShadowLightSpaceTechnique()
  : LightMaps(new Maps)
{
  // A cache only has to follow the map's detail: 64 nodes lose nothing measurable on the
  // standard scenes (Documentation/Measured.md) and cost an eighth of 128 to fill.
  this->ShadowVolumeSize = 64;
}

vtkDeepShadowLightSpaceTechnique::~vtkDeepShadowLightSpaceTechnique() = default;

void vtkDeepShadowLightSpaceTechnique::SetMapSize(int size)
{
  this->SetClamped("MapSize", "shadow-map-size", this->MapSize, size);
}

void vtkDeepShadowLightSpaceTechnique::SetClusters(int clusters)
{
  this->SetClamped("Clusters", "clusters", this->Clusters, clusters);
}

void vtkDeepShadowLightSpaceTechnique::SetClusterDistance(double distance)
{
  this->SetClamped("ClusterDistance", "cluster-distance", this->ClusterDistance, distance);
}

void vtkDeepShadowLightSpaceTechnique::SetParameters(const deepshadow::ShadowParameters& parameters)
{
  this->Superclass::SetParameters(parameters);
  this->SetMapSize(parameters.MapSize);
  this->SetClusters(parameters.Clusters);
  this->SetClusterDistance(parameters.ClusterDistance);
}

void vtkDeepShadowLightSpaceTechnique::FillMapParameters(deepshadow::ShadowParameters& parameters) const
{
  parameters.MapSize = this->MapSize;
  parameters.Clusters = this->Clusters;
  parameters.ClusterDistance = this->ClusterDistance;
}

bool vtkDeepShadowLightSpaceTechnique::Hooks::AllocateStructures(
  deepshadow::ShadowContext& context, deepshadow::ShadowSlots& slots)
{
  vtkDeepShadowLightSpaceTechnique* self = this->Self;
  Maps& maps = *self->LightMaps;
  maps.Window = context.Window;
  // Coarser while interacting (GetBuildCoarsening): N times smaller a side, down to 64 texels.
  const int coarsening = self->GetBuildCoarsening();
  const int size = coarsening > 1 ? std::max(std::min(self->MapSize, 64), self->MapSize / coarsening) : self->MapSize;
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  if (self->MapSize > maxSize)
  {
    self->LastError = "shadow map size " + std::to_string(self->MapSize) +
      " exceeds this GL's texture limit of " + std::to_string(maxSize);
    return false;
  }
  deepshadow::CasterBounds bounds =
    deepshadow::CasterBoundsOf(context.IndexToWorld, context.Dims, context.CastingSurfaces);
  // With other bricks, every brick's faces see the union of their boxes (collective).
  std::string problem;
  const bool exchanging = maps.Bricks.BeginFrame(
    bounds, size, SlotLights(context, slots), self->GetParameters().IsColored() ? 3 : 1, problem);
  if (problem != maps.BrickProblem && !problem.empty())
  {
    vtkWarningWithObjectMacro(self, << "shadows are not shared between bricks: " << problem);
  }
  maps.BrickProblem = problem;
  maps.CasterRadius = bounds.Radius;
  if (maps.Bricks.UnionChanged())
  {
    slots.Invalidate();
  }
  maps.Faces.resize(static_cast<size_t>(slots.Count()));
  // Clusters come from the drawn opacity's empty blocks (as the CPU twin's): not with a
  // separate shadow property, nor between bricks (whose faces see their union).
  const bool clusterable =
    self->Clusters > 0 && context.EmptyBlocks && !self->GetShadowProperty() && !exchanging;
  maps.Clusters.BeginFrame(clusterable ? slots.Count() : 0);
  int facesPerLight = 1;
  for (int slot = 0; slot < slots.Count(); ++slot)
  {
    const deepshadow::Light& light = context.Lights[static_cast<size_t>(slots.Light(slot))];
    maps.Faces[slot].clear();
    if (clusterable)
    {
      maps.Clusters.Cluster(slot, light, context.IndexToWorld, context.Dims, *context.EmptyBlocks,
        context.CastingSurfaces, self->Clusters, self->ClusterDistance, context.Eye, maps.Faces[slot]);
    }
    if (maps.Faces[slot].empty())
    {
      maps.Faces[slot] = deepshadow::ShadowMapFaces(light, bounds);
    }
    facesPerLight = std::max(facesPerLight, static_cast<int>(maps.Faces[slot].size()));
  }
  // Other clusters (the occupancy, the parameters or the casting meshes changed) need every
  // map rebuilt; a light's own faces follow it as before.
  if (maps.Clusters.EndFrame(context.Window, context.EmptyBlocks ? context.EmptyBlocks->Blocks.BlockCount : glm::ivec3(0)))
  {
    slots.Invalidate();
  }
  const unsigned int format = self->GetTexelFormat();
  const int layersPerFace = this->GetLayersPerFace(context);
  const bool sameShape = maps.Texture && maps.Size == size && maps.Format == format &&
    maps.LayersPerFace == layersPerFace;
  // Grow only: fewer shadow-casting lights keep the others' maps (not between bricks, whose
  // layers must agree whatever each brick drew before).
  const bool keep = sameShape && !exchanging;
  const int slabs = std::max(keep ? maps.Slabs : 1, slots.Count());
  facesPerLight = std::max(facesPerLight, keep ? maps.FacesPerLight : 1);
  if (!sameShape || maps.Slabs != slabs || maps.FacesPerLight != facesPerLight)
  {
    maps.Format = format;
    maps.Size = size;
    maps.Slabs = slabs;
    maps.FacesPerLight = facesPerLight;
    maps.LayersPerFace = layersPerFace;
    slots.Invalidate();
    return this->AllocateMapTexture(context);
  }
  return true;
}

bool vtkDeepShadowLightSpaceTechnique::Hooks::AllocateMapTexture(const deepshadow::ShadowContext& context)
{
  vtkDeepShadowLightSpaceTechnique* self = this->Self;
  Maps& maps = *self->LightMaps;
  const long long layers = static_cast<long long>(maps.Slabs) * maps.FacesPerLight * maps.LayersPerFace;
  GLint maxLayers = 0;
  glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &maxLayers);
  if (layers > maxLayers)
  {
    self->LastError = std::to_string(layers) + " light-space layers (" + std::to_string(maps.Slabs) +
      " lights x " + std::to_string(maps.FacesPerLight) + " faces x " + std::to_string(maps.LayersPerFace) +
      " per face) exceed this GL's limit of " + std::to_string(maxLayers);
    deepshadow::DeleteTexture(maps.Texture);
    return false;
  }
  deepshadow::DeleteTexture(maps.Texture);
  while (glGetError() != GL_NO_ERROR)
  {
    // errors of earlier GL calls are not ours to report
  }
  // Bound on a unit of our own while it is made, chosen through VTK's state: VTK caches the
  // active unit and what its textures are bound to (ParaView warns every frame when they
  // change behind it).
  maps.Texture = deepshadow::NewArrayTexture(context.Window, maps.Format, maps.Size, maps.Size, static_cast<int>(layers));
  if (glGetError() != GL_NO_ERROR)
  {
    self->LastError = "the GL could not allocate " +
      std::to_string(layers * maps.Size * maps.Size * BytesPerTexel(maps.Format)) + " bytes of light-space maps";
    deepshadow::DeleteTexture(maps.Texture);
    return false;
  }
  return true;
}

long long vtkDeepShadowLightSpaceTechnique::GetStructureBytes() const
{
  const Maps& maps = *this->LightMaps;
  if (!maps.Texture)
  {
    return 0;
  }
  return static_cast<long long>(maps.Size) * maps.Size * maps.Slabs * maps.FacesPerLight *
    maps.LayersPerFace * BytesPerTexel(maps.Format);
}

int vtkDeepShadowLightSpaceTechnique::GetBuiltMapSize() const
{
  return this->LightMaps->Size;
}

double vtkDeepShadowLightSpaceTechnique::GetCasterRadius() const
{
  return this->LightMaps->CasterRadius;
}

int vtkDeepShadowLightSpaceTechnique::GetFaceCount(int slot) const
{
  const auto& faces = this->LightMaps->Faces;
  return slot >= 0 && slot < static_cast<int>(faces.size()) ? static_cast<int>(faces[slot].size()) : 0;
}

bool vtkDeepShadowLightSpaceTechnique::Hooks::BuildStructures(deepshadow::ShadowContext& context,
  const deepshadow::ShadowSlots& slots, const std::vector<int>& stale)
{
  vtkDeepShadowLightSpaceTechnique* self = this->Self;
  Maps& maps = *self->LightMaps;
  deepshadow::UniformSink sink(&maps.Build);
  // The build program for the current layout. Clustered faces march their cluster's box only.
  auto beginPass = [&] {
    if (!Internals::BeginBuildPass(self, maps.Build, vtkDeepShadowLightSpaceCS, context, "Build",
          maps.Clusters.BuildDefines() + self->GetBuildSource()))
    {
      return false;
    }
    maps.Build.Set("u_size", maps.Size);
    maps.Build.Set("u_layersPerFace", maps.LayersPerFace);
    maps.Build.Set("u_lightDepthRange", static_cast<float>(deepshadow::LightDepthRange(maps.CasterRadius)));
    this->SetBuildUniforms(sink, context);
    glBindImageTexture(0, maps.Texture, 0, GL_TRUE, 0, GL_WRITE_ONLY, maps.Format);
    return true;
  };
  if (!beginPass())
  {
    return false;
  }
  const bool defers = self->DefersTexels();
  if (defers)
  {
    // Room for every texel of a face.
    const GLsizeiptr bytes = sizeof(GLuint) * (1 + static_cast<GLsizeiptr>(maps.Size) * maps.Size);
    GLint64 allocated = 0;
    if (!maps.Deferred)
    {
      glGenBuffers(1, &maps.Deferred);
    }
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, maps.Deferred);
    glGetBufferParameteri64v(GL_SHADER_STORAGE_BUFFER, GL_BUFFER_SIZE, &allocated);
    if (allocated != bytes)
    {
      glBufferData(GL_SHADER_STORAGE_BUFFER, bytes, nullptr, GL_DYNAMIC_COPY);
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, maps.Deferred);
  }
  maps.Clusters.ActivateLabels();
  // One slot's faces: a dispatch each, and one more for a face's deferred texels.
  auto buildSlot = [&](int slot) {
    for (size_t f = 0; f < maps.Faces[slot].size(); ++f)
    {
      const deepshadow::ShadowMapFace& face = maps.Faces[slot][f];
      maps.Build.Set("u_layer", (slot * maps.FacesPerLight + static_cast<int>(f)) * maps.LayersPerFace);
      maps.Build.Set("u_face", static_cast<int>(f));
      maps.Build.Set("u_perspective", face.Perspective ? 1 : 0);
      maps.Build.Set("u_origin", glm::vec3(face.Origin));
      maps.Build.Set("u_forward", glm::vec3(face.Forward));
      maps.Build.Set("u_right", glm::vec3(face.Right));
      maps.Build.Set("u_up", glm::vec3(face.Up));
      maps.Build.Set("u_extent", static_cast<float>(face.Extent));
      maps.Build.Set("u_near", static_cast<float>(face.Near));
      maps.Clusters.SetBuildUniforms(maps.Build, slot, static_cast<int>(f));
      maps.Build.Set("u_deferredPass", 0);
      GLuint deferred = 0;
      if (defers)
      {
        glBindBuffer(GL_SHADER_STORAGE_BUFFER, maps.Deferred);
        glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(deferred), &deferred);
      }
      maps.Build.Dispatch(glm::ivec3(maps.Size, maps.Size, 1), glm::ivec3(8, 8, 1));
      self->LastPasses.emplace_back("light-space-build");
      if (defers)
      {
        glBindBuffer(GL_SHADER_STORAGE_BUFFER, maps.Deferred);
        glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(deferred), &deferred);
      }
      if (deferred > 0)
      {
        // The deferred texels, 64 to a group (the pass's 8 x 8 invocations).
        maps.Build.Set("u_deferredPass", 1);
        maps.Build.Dispatch(glm::ivec3(static_cast<int>(deferred), 1, 1), glm::ivec3(64, 1, 1));
        self->LastPasses.emplace_back("light-space-deferred");
      }
    }
  };
  // A technique may ask for slots again: the deep shadow map's node pool was short, or
  // dsm-fixed's build found that an error asks for other layers per face (then every slot is
  // built again in the new layout).
  for (std::vector<int> building = stale; !building.empty();
       building = this->AfterBuild(building, slots.Count()))
  {
    const int layersPerFace = this->GetLayersPerFace(context);
    if (layersPerFace != maps.LayersPerFace)
    {
      maps.LayersPerFace = layersPerFace;
      Internals::EndBuildPass(self, context);
      if (!this->AllocateMapTexture(context) || !beginPass())
      {
        return false;
      }
      building.clear();
      for (int slot = 0; slot < slots.Count(); ++slot)
      {
        building.push_back(slot);
      }
    }
    self->BeginMapBuild();
    for (int slot : building)
    {
      this->SetSlotBuildUniforms(sink, slot);
      buildSlot(slot);
    }
    self->EndMapBuild();
  }
  if (defers)
  {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, 0);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  }
  maps.Clusters.DeactivateLabels();
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, maps.Format);
  Internals::EndBuildPass(self, context);
  // A build asked for again may fail (the GL could not grow the node pool).
  return self->LastError.empty();
}

bool vtkDeepShadowLightSpaceTechnique::Hooks::ExchangeStructures(deepshadow::ShadowContext& context,
  const deepshadow::ShadowSlots& slots, const std::set<int>& rebuilt, std::vector<double>& cacheKey)
{
  vtkDeepShadowLightSpaceTechnique* self = this->Self;
  Maps& maps = *self->LightMaps;
  if (!maps.Bricks.Exchanging())
  {
    return true;
  }
  const int layers = slots.Count() * maps.FacesPerLight;
  const int channels = self->GetParameters().IsColored() ? 3 : 1;
  if (!rebuilt.empty() || !maps.Totals || maps.TotalsLayers != layers || maps.TotalsSize != maps.Size)
  {
    // This brick's total per texel: the technique's own lookup beyond the texel ray's end.
    const std::string lookup = deepshadow::LightSpaceSource(maps.Faces) + self->GetMapLookupSource();
    if (!Internals::BeginBuildPass(self, maps.TotalsPass, vtkDeepShadowBrickTotalsCS, context, "Lookup", lookup))
    {
      return false;
    }
    if (!maps.Totals || maps.TotalsLayers != layers || maps.TotalsSize != maps.Size)
    {
      if (maps.Totals)
      {
        glDeleteTextures(1, &maps.Totals);
      }
      glGenTextures(1, &maps.Totals);
      vtkTextureUnitManager* units = context.Window->GetTextureUnitManager();
      const int unit = units->Allocate();
      context.Window->GetState()->vtkglActiveTexture(GL_TEXTURE0 + unit);
      glBindTexture(GL_TEXTURE_2D_ARRAY, maps.Totals);
      glTexStorage3D(GL_TEXTURE_2D_ARRAY, 1, GL_RGBA32F, maps.Size, maps.Size, layers);
      glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
      units->Free(unit);
      maps.TotalsLayers = layers;
      maps.TotalsSize = maps.Size;
    }
    deepshadow::UniformSink sink(&maps.TotalsPass);
    this->BindLookup(sink, context);
    maps.TotalsPass.Set("u_slots", slots.Count());
    glBindImageTexture(0, maps.Totals, 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    maps.TotalsPass.Dispatch(glm::ivec3(maps.Size, maps.Size, layers), glm::ivec3(8, 8, 1));
    glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    self->UnbindLookup();
    Internals::EndBuildPass(self, context);
    self->LastPasses.emplace_back("light-space-totals");
    maps.Bricks.ReadTotals(context.Window, maps.Totals, maps.Size, layers, channels);
  }
  std::string problem;
  if (!maps.Bricks.Exchange(context.Window, SlotLights(context, slots), maps.FacesPerLight, problem))
  {
    self->LastError = problem;
    return false;
  }
  if (maps.Bricks.Overlapping() && !maps.SaidOverlap)
  {
    vtkWarningWithObjectMacro(self, << "bricks overlap (ghost cells?): an overlapping brick casts no shadow on this one");
  }
  maps.SaidOverlap = maps.Bricks.Overlapping();
  cacheKey.push_back(maps.Bricks.GetVersion());
  return true;
}

std::string vtkDeepShadowLightSpaceTechnique::GetLookupSource() const
{
  // Between bricks, LightSpace.glsl multiplies the bricks in front into every lookup.
  const std::string upstream =
    this->LightMaps->Bricks.Exchanging() ? "//@Dec\n#define LIGHT_SPACE_UPSTREAM\n" : "";
  // Clustered faces: LightSpace.glsl loops over a light's faces.
  const std::string clusters = this->LightMaps->Clusters.LookupDefines();
  return upstream + clusters + deepshadow::LightSpaceSource(this->LightMaps->Faces) + this->GetMapLookupSource();
}

void vtkDeepShadowLightSpaceTechnique::SetBrickExchange(vtkDeepShadowBrickExchange* exchange)
{
  if (exchange != this->LightMaps->Bricks.GetExchange())
  {
    this->LightMaps->Bricks.SetExchange(exchange);
    this->Modified();
  }
}

std::vector<int> vtkDeepShadowLightSpaceTechnique::GetClusterCounts() const
{
  std::vector<int> counts = this->LightMaps->Clusters.Counts();
  counts.resize(this->LightMaps->Faces.size(), 0);
  return counts;
}

vtkDeepShadowBrickExchange* vtkDeepShadowLightSpaceTechnique::GetBrickExchange()
{
  return this->LightMaps->Bricks.GetExchange();
}

void vtkDeepShadowLightSpaceTechnique::Hooks::BindLookup(
  deepshadow::UniformSink& sink, const deepshadow::ShadowContext& context)
{
  vtkDeepShadowLightSpaceTechnique* self = this->Self;
  Maps& maps = *self->LightMaps;
  maps.Unit = context.Window->GetTextureUnitManager()->Allocate();
  context.Window->GetState()->vtkglActiveTexture(GL_TEXTURE0 + maps.Unit);
  glBindTexture(GL_TEXTURE_2D_ARRAY, maps.Texture);
  sink.Set("u_shadowMap", maps.Unit);
  deepshadow::SetLightSpaceFaceUniforms(
    sink, maps.Faces, static_cast<float>(maps.Size), maps.FacesPerLight, maps.LayersPerFace);
  maps.Clusters.SetLookupUniforms(sink, maps.Faces);
  if (maps.Bricks.Exchanging())
  {
    maps.Bricks.BindLookup(sink, context.Window);
  }
  sink.Set("u_lightDepthRange", static_cast<float>(deepshadow::LightDepthRange(maps.CasterRadius)));
  this->SetMapLookupUniforms(sink, context);
}

void vtkDeepShadowLightSpaceTechnique::UnbindLookup()
{
  Maps& maps = *this->LightMaps;
  if (maps.Unit >= 0)
  {
    maps.Window->GetState()->vtkglActiveTexture(GL_TEXTURE0 + maps.Unit);
    glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
    maps.Window->GetTextureUnitManager()->Free(maps.Unit);
    maps.Unit = -1;
  }
  maps.Bricks.UnbindLookup();
}

void vtkDeepShadowLightSpaceTechnique::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Superclass::ReleaseGraphicsResources(window);
  this->LightMaps->Release();
}

void vtkDeepShadowLightSpaceTechnique::AddStatistics(Statistics& statistics) const
{
  this->Superclass::AddStatistics(statistics);
  double faces = 0.0;
  for (const int count : this->GetClusterCounts())
  {
    faces += count;
  }
  statistics.emplace_back("clusters", faces);
  statistics.emplace_back("cluster_texels", faces * this->LightMaps->Size * this->LightMaps->Size);
  statistics.emplace_back("map_size", this->LightMaps->Size);
}

void vtkDeepShadowLightSpaceTechnique::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MapSize: " << this->MapSize << "\n";
  os << indent << "Clusters: " << this->Clusters << "\n";
  os << indent << "ClusterDistance: " << this->ClusterDistance << "\n";
  os << indent << "BrickExchange: " << this->LightMaps->Bricks.GetExchange() << "\n";
}
