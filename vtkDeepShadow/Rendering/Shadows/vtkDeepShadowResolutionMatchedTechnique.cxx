#include "vtkDeepShadowResolutionMatchedTechnique.h"
#include "vtkDeepShadowShadowMapTechnique.h"
#include "vtkDeepShadowTechniqueInternals.h"

#include "Core/ShadowTechniques.h"
#include "Core/Shadows/ResolutionMatched.h"
#include "Core/Shadows/ShadowMap.h"
#include "GL/ComputeProgram.h"
#include "GL/GLObjects.h"
#include "LightSpaceFaces.h"
#include "PageAnalysis.h"
#include "GL/UniformSink.h"
#include "Sampling/ShadowContext.h"
#include "vtkDeepShadowLightSpaceCS.h"
#include "vtkDeepShadowResolutionMatched.h"
#include "vtkDeepShadowShadowMapBuild.h"

#include "vtkDeepShadowTechniqueFactory.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkTextureUnitManager.h"
#include "vtk_glew.h"

#include <algorithm>
#include <map>

vtkStandardNewMacro(vtkDeepShadowResolutionMatchedTechnique);

namespace
{
// Superpages are 1024^2 texels (section 3.3.3): pages of one face and level within one.
constexpr int SuperpageTexels = 1024;
}

// The pages, the atlas and page table they live in, and the passes that fill them.
class vtkDeepShadowResolutionMatchedTechnique::Pages
{
public:
  vtkOpenGLRenderWindow* Window = nullptr;
  deepshadow::SlotFaces Faces;
  int FacesPerLight = 1;
  deepshadow::PageLayout Layout;
  unsigned int Atlas = 0; // AtlasSize^2 R32F, one layer
  unsigned int Table = 0; // TableSize^2 R32UI per face layer
  int TableLayers = 0;
  deepshadow::PageAnalysis Requests; // the analysis
  unsigned int PageList = 0;          // the pages to build: (key, slot) each
  long long PageListBytes = 0;
  deepshadow::ComputeProgram PageBuild;
  std::map<std::uint32_t, int> Resident; // page -> slot
  std::vector<std::uint32_t> TablePages; // what the table was built from
  std::vector<int> TableSlots;
  int AtlasUnit = -1, TableUnit = -1;
  double Version = 0.0; // what the lookup reads changed
  // What the last analysis saw (camera, viewport, analysis and keeping); Dirty: the lights,
  // casters or atlas changed since. The mapper prepares twice in a frame drawn by a pass.
  std::vector<double> AnalysisKey;
  bool Dirty = true;
  int Analyses = 0;

  long long Requested = 0, AfterComponents = 0;
  int UniqueCount = 0, Rendered = 0, Superpages = 0, Finest = 0;

  void Release()
  {
    deepshadow::DeleteTexture(this->Atlas);
    deepshadow::DeleteTexture(this->Table);
    deepshadow::DeleteBuffer(this->PageList, this->PageListBytes);
    this->TableLayers = 0;
    this->Requests.Release();
    this->PageBuild.Release();
    this->Resident.clear();
    this->TablePages.clear();
    this->TableSlots.clear();
  }

  /** Face layer of face `face` of slot `slot`. */
  int Layer(int slot, int face) const { return slot * this->FacesPerLight + face; }
};

class vtkDeepShadowResolutionMatchedTechnique::Hooks : public vtkDeepShadowTechnique::Hooks
{
public:
  explicit Hooks(vtkDeepShadowResolutionMatchedTechnique& self)
    : Self(&self)
  {
  }

  bool AllocateStructures(deepshadow::ShadowContext& context, deepshadow::ShadowSlots& slots) override;
  bool BuildStructures(deepshadow::ShadowContext& context, const deepshadow::ShadowSlots& slots,
    const std::vector<int>& stale) override;
  bool FollowView(deepshadow::ShadowContext& context, const deepshadow::ShadowSlots& slots,
    std::set<int>& rebuilt, std::vector<double>& cacheKey) override;
  void BindLookup(deepshadow::UniformSink& sink, const deepshadow::ShadowContext& context) override;

private:
  /** Builds `pages` (key, slot pairs, sorted by key) superpage by superpage. */
  bool BuildPages(deepshadow::ShadowContext& context, const std::vector<std::pair<std::uint32_t, int>>& pages);

  vtkDeepShadowResolutionMatchedTechnique* Self;
};

vtkDeepShadowResolutionMatchedTechnique::vtkDeepShadowResolutionMatchedTechnique()
  : State(new Pages)
{
  Internals::SetHooks(this, std::make_unique<Hooks>(*this));
  this->ShadowVolumeSize = 64;
}

vtkDeepShadowResolutionMatchedTechnique::~vtkDeepShadowResolutionMatchedTechnique() = default;

// The GPU class of the registry's ResolutionMatched technique (deepshadow::ShadowTechniques()).
static const bool Registered = vtkDeepShadowTechniqueFactory::Register(deepshadow::ShadowKind::ResolutionMatched,
  []() -> vtkDeepShadowTechnique* { return vtkDeepShadowResolutionMatchedTechnique::New(); });

void vtkDeepShadowResolutionMatchedTechnique::SetBias(double bias)
{
  this->SetClamped("Bias", "bias", this->Bias, bias);
}

void vtkDeepShadowResolutionMatchedTechnique::SetFilter(int filter)
{
  this->SetClamped("Filter", this->Filter, filter, 0, 3);
}

void vtkDeepShadowResolutionMatchedTechnique::SetPageSize(int size)
{
  this->SetAllowed("page-size", this->PageSize, size);
}

void vtkDeepShadowResolutionMatchedTechnique::SetAtlasSize(int size)
{
  this->SetClamped("AtlasSize", "atlas-size", this->AtlasSize, size);
}

void vtkDeepShadowResolutionMatchedTechnique::SetMaxResolution(int size)
{
  this->SetAllowed("max-resolution", this->MaxResolution, size);
}

void vtkDeepShadowResolutionMatchedTechnique::SetAnalysisDownsample(int n)
{
  this->SetAllowed("analysis-downsample", this->AnalysisDownsample, n);
}

deepshadow::ShadowParameters vtkDeepShadowResolutionMatchedTechnique::GetParameters() const
{
  deepshadow::ShadowParameters parameters;
  this->FillParameters(parameters);
  parameters.Kind = deepshadow::ShadowKind::ResolutionMatched;
  parameters.Bias = this->Bias;
  parameters.Filter = static_cast<deepshadow::ShadowFilter>(this->Filter);
  parameters.PageSize = this->PageSize;
  parameters.AtlasSize = this->AtlasSize;
  parameters.MaxResolution = this->MaxResolution;
  parameters.AnalysisDownsample = this->AnalysisDownsample;
  parameters.KeepPages = this->KeepPages;
  return parameters;
}

void vtkDeepShadowResolutionMatchedTechnique::SetParameters(const deepshadow::ShadowParameters& parameters)
{
  this->Superclass::SetParameters(parameters);
  this->SetBias(parameters.Bias);
  this->SetFilter(static_cast<int>(parameters.Filter));
  this->SetPageSize(parameters.PageSize);
  this->SetAtlasSize(parameters.AtlasSize);
  this->SetMaxResolution(parameters.MaxResolution);
  this->SetAnalysisDownsample(parameters.AnalysisDownsample);
  this->SetKeepPages(parameters.KeepPages);
}

std::vector<double> vtkDeepShadowResolutionMatchedTechnique::GetStructureKey() const
{
  // What a built page holds: its size, the virtual size, and the apron the filter needs. The
  // atlas size, the analysis and keeping pages change which pages exist, not what they hold.
  return { static_cast<double>(this->PageSize), static_cast<double>(this->MaxResolution),
    static_cast<double>(deepshadow::PageLayout::Of(this->GetParameters()).Apron) };
}

std::vector<double> vtkDeepShadowResolutionMatchedTechnique::GetLookupKey() const
{
  return { this->Bias, static_cast<double>(this->Filter) };
}

long long vtkDeepShadowResolutionMatchedTechnique::GetAtlasBytes() const
{
  return this->State->Atlas ? 4LL * this->State->Layout.AtlasSize * this->State->Layout.AtlasSize : 0;
}

long long vtkDeepShadowResolutionMatchedTechnique::GetStructureBytes() const
{
  const Pages& pages = *this->State;
  const long long cells = static_cast<long long>(pages.Layout.TableSize()) * pages.Layout.TableSize();
  return this->GetAtlasBytes() + (pages.Table ? 4LL * cells * pages.TableLayers : 0);
}

long long vtkDeepShadowResolutionMatchedTechnique::GetPagesRequested() const
{
  return this->State->Requested;
}

long long vtkDeepShadowResolutionMatchedTechnique::GetRequestsAfterComponents() const
{
  return this->State->AfterComponents;
}

int vtkDeepShadowResolutionMatchedTechnique::GetPagesUnique() const
{
  return this->State->UniqueCount;
}

int vtkDeepShadowResolutionMatchedTechnique::GetPagesRendered() const
{
  return this->State->Rendered;
}

int vtkDeepShadowResolutionMatchedTechnique::GetSuperpages() const
{
  return this->State->Superpages;
}

int vtkDeepShadowResolutionMatchedTechnique::GetPagesResident() const
{
  return static_cast<int>(this->State->Resident.size());
}

int vtkDeepShadowResolutionMatchedTechnique::GetAnalyses() const
{
  return this->State->Analyses;
}

int vtkDeepShadowResolutionMatchedTechnique::GetFinestLevelUsed() const
{
  return this->State->Finest;
}

int vtkDeepShadowResolutionMatchedTechnique::LookupLoopIterations() const
{
  // The shadow map's filter (Shadows/ShadowMap.glsl).
  return this->Filter == 2 ? 12 : this->Filter == 3 ? static_cast<int>(deepshadow::PoissonDisc().size()) : 0;
}

std::string vtkDeepShadowResolutionMatchedTechnique::GetLookupSource() const
{
  return deepshadow::LightSpaceSource(this->State->Faces) +
    vtkDeepShadowShadowMapTechnique::GetFilterSource(this->Filter, true) + vtkDeepShadowResolutionMatched;
}

bool vtkDeepShadowResolutionMatchedTechnique::Hooks::AllocateStructures(
  deepshadow::ShadowContext& context, deepshadow::ShadowSlots& slots)
{
  vtkDeepShadowResolutionMatchedTechnique* self = this->Self;
  Pages& state = *self->State;
  state.Window = context.Window;
  const deepshadow::PageLayout layout = deepshadow::PageLayout::Of(self->GetParameters());
  GLint maxSize = 0, maxLayers = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &maxLayers);
  if (layout.AtlasSize > maxSize || layout.TableSize() > maxSize)
  {
    self->LastError = "page atlas size " + std::to_string(layout.AtlasSize) + " exceeds this GL's texture limit of " +
      std::to_string(maxSize);
    return false;
  }
  const deepshadow::CasterBounds bounds =
    deepshadow::CasterBoundsOf(context.IndexToWorld, context.Dims, context.CastingSurfaces);
  state.Faces.assign(static_cast<size_t>(slots.Count()), {});
  int facesPerLight = 1, faces = 0;
  for (int slot = 0; slot < slots.Count(); ++slot)
  {
    state.Faces[static_cast<size_t>(slot)] =
      deepshadow::ShadowMapFaces(context.Lights[static_cast<size_t>(slots.Light(slot))], bounds);
    facesPerLight = std::max(facesPerLight, static_cast<int>(state.Faces[static_cast<size_t>(slot)].size()));
    faces += static_cast<int>(state.Faces[static_cast<size_t>(slot)].size());
  }
  if (layout.BasePages(faces) > layout.Capacity())
  {
    self->LastError = "the page atlas holds " + std::to_string(layout.Capacity()) + " pages, fewer than the " +
      std::to_string(layout.BasePages(faces)) + " of the base level; raise the atlas size";
    return false;
  }
  const int tableLayers = std::max(1, slots.Count() * facesPerLight);
  if (tableLayers > maxLayers)
  {
    self->LastError = std::to_string(tableLayers) + " page table layers exceed this GL's limit of " + std::to_string(maxLayers);
    return false;
  }
  const bool sameAtlas = state.Atlas && layout.AtlasSize == state.Layout.AtlasSize &&
    layout.SlotSize() == state.Layout.SlotSize() && layout.MaxResolution == state.Layout.MaxResolution &&
    layout.PageSize == state.Layout.PageSize;
  const bool sameTable = sameAtlas && state.Table && state.TableLayers == tableLayers && state.FacesPerLight == facesPerLight;
  if (sameTable)
  {
    return true;
  }
  while (glGetError() != GL_NO_ERROR)
  {
    // errors of earlier GL calls are not ours to report
  }
  deepshadow::DeleteTexture(state.Atlas);
  deepshadow::DeleteTexture(state.Table);
  state.Atlas = deepshadow::NewArrayTexture(context.Window, GL_R32F, layout.AtlasSize, layout.AtlasSize, 1);
  state.Table = deepshadow::NewArrayTexture(context.Window, GL_R32UI, layout.TableSize(), layout.TableSize(), tableLayers);
  if (glGetError() != GL_NO_ERROR)
  {
    self->LastError = "the GL could not allocate the page atlas (" + std::to_string(layout.AtlasSize) + "^2) and table";
    deepshadow::DeleteTexture(state.Atlas);
    deepshadow::DeleteTexture(state.Table);
    return false;
  }
  state.Layout = layout;
  state.TableLayers = tableLayers;
  state.FacesPerLight = facesPerLight;
  state.Resident.clear();
  state.TablePages.clear();
  state.Dirty = true;
  slots.Invalidate();
  return true;
}

bool vtkDeepShadowResolutionMatchedTechnique::Hooks::BuildStructures(
  deepshadow::ShadowContext&, const deepshadow::ShadowSlots&, const std::vector<int>& stale)
{
  // The stale lights' pages are built again as the view asks for them (FollowView).
  Pages& state = *this->Self->State;
  for (auto page = state.Resident.begin(); page != state.Resident.end();)
  {
    int face, level, x, y;
    deepshadow::DecodePage(page->first, face, level, x, y);
    const bool staleFace = std::find(stale.begin(), stale.end(), face / state.FacesPerLight) != stale.end();
    page = staleFace ? state.Resident.erase(page) : std::next(page);
  }
  state.TablePages.clear();
  state.Dirty = true;
  return true;
}

bool vtkDeepShadowResolutionMatchedTechnique::Hooks::BuildPages(
  deepshadow::ShadowContext& context, const std::vector<std::pair<std::uint32_t, int>>& pages)
{
  vtkDeepShadowResolutionMatchedTechnique* self = this->Self;
  Pages& state = *self->State;
  const deepshadow::PageLayout& layout = state.Layout;
  // Superpages: pages of one face and level within one SuperpageTexels^2 square, a dispatch each.
  int shift = 0;
  while ((layout.PageSize << (shift + 1)) <= SuperpageTexels)
  {
    ++shift;
  }
  auto superpage = [&](std::uint32_t key) {
    int face, level, x, y;
    deepshadow::DecodePage(key, face, level, x, y);
    return (static_cast<std::uint64_t>(face) << 40) | (static_cast<std::uint64_t>(level) << 32) |
      (static_cast<std::uint64_t>(y >> shift) << 16) | static_cast<std::uint64_t>(x >> shift);
  };
  std::vector<std::pair<std::uint32_t, int>> ordered = pages;
  std::stable_sort(ordered.begin(), ordered.end(),
    [&](const auto& a, const auto& b) { return superpage(a.first) < superpage(b.first); });
  std::vector<GLuint> list;
  for (const auto& [key, slot] : ordered)
  {
    list.push_back(key);
    list.push_back(static_cast<GLuint>(slot));
  }
  deepshadow::EnsureStorageBuffer(state.PageList, state.PageListBytes, 4 * static_cast<long long>(list.size()));
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, state.PageList);
  glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, 4 * static_cast<GLsizeiptr>(list.size()), list.data());

  if (!Internals::BeginBuildPass(self, state.PageBuild, vtkDeepShadowLightSpaceCS, context, "Build",
        "//@Dec\n#define LIGHT_SPACE_PAGES\n" + std::string(vtkDeepShadowShadowMapBuild)))
  {
    return false;
  }
  deepshadow::ComputeProgram& build = state.PageBuild;
  build.Set("u_pageSize", layout.PageSize);
  build.Set("u_apron", layout.Apron);
  build.Set("u_slotsPerSide", layout.SlotsPerSide());
  build.Set("u_layer", 0);
  build.Set("u_deferredPass", 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, state.PageList);
  glBindImageTexture(0, state.Atlas, 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R32F);
  state.Superpages = 0;
  for (size_t first = 0; first < ordered.size();)
  {
    size_t last = first + 1;
    while (last < ordered.size() && superpage(ordered[last].first) == superpage(ordered[first].first))
    {
      ++last;
    }
    int faceIndex, level, x, y;
    deepshadow::DecodePage(ordered[first].first, faceIndex, level, x, y);
    const deepshadow::ShadowMapFace& face =
      state.Faces[static_cast<size_t>(faceIndex / state.FacesPerLight)][static_cast<size_t>(faceIndex % state.FacesPerLight)];
    build.Set("u_size", layout.LevelSize(level));
    build.Set("u_perspective", face.Perspective ? 1 : 0);
    build.Set("u_origin", glm::vec3(face.Origin));
    build.Set("u_forward", glm::vec3(face.Forward));
    build.Set("u_right", glm::vec3(face.Right));
    build.Set("u_up", glm::vec3(face.Up));
    build.Set("u_extent", static_cast<float>(face.Extent));
    build.Set("u_near", static_cast<float>(face.Near));
    build.Set("u_pageOffset", static_cast<int>(first));
    build.Set("u_pageCount", static_cast<int>(last - first));
    const int texels = layout.SlotSize() * layout.SlotSize() * static_cast<int>(last - first);
    build.Dispatch(glm::ivec3(texels, 1, 1), glm::ivec3(64, 1, 1));
    ++state.Superpages;
    first = last;
  }
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, 0);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  Internals::EndBuildPass(self, context);
  self->LastPasses.emplace_back("page-build");
  return true;
}

bool vtkDeepShadowResolutionMatchedTechnique::Hooks::FollowView(deepshadow::ShadowContext& context,
  const deepshadow::ShadowSlots& slots, std::set<int>& rebuilt, std::vector<double>& cacheKey)
{
  vtkDeepShadowResolutionMatchedTechnique* self = this->Self;
  Pages& state = *self->State;
  std::vector<double> analysisKey(&context.View.GetViewProjection()[0][0], &context.View.GetViewProjection()[0][0] + 16);
  analysisKey.insert(analysisKey.end(), { static_cast<double>(context.View.GetWidth()),
    static_cast<double>(context.View.GetHeight()), static_cast<double>(self->AnalysisDownsample),
    self->KeepPages ? 1.0 : 0.0, static_cast<double>(slots.Count()) });
  if (slots.Count() == 0 || (!state.Dirty && analysisKey == state.AnalysisKey))
  {
    // Nothing it depends on changed: the same pages (the counts stay the last analysis's).
    cacheKey.push_back(state.Version);
    return true;
  }
  state.AnalysisKey = analysisKey;
  state.Dirty = false;
  ++state.Analyses;
  state.Rendered = 0;
  state.Superpages = 0;
  std::vector<std::uint32_t> unique;
  std::string error;
  if (!state.Requests.Analyse(self, context, state.Faces, state.FacesPerLight, state.Layout,
        self->AnalysisDownsample, unique, error))
  {
    self->LastError = error;
    state.Dirty = true;
    return false;
  }
  self->LastPasses.insert(self->LastPasses.end(), { "page-analysis", "page-requests" });
  state.Requested = state.Requests.GetCounts().Requested;
  state.AfterComponents = state.Requests.GetCounts().AfterComponents;
  state.UniqueCount = static_cast<int>(unique.size());
  std::vector<int> faces;
  for (int slot = 0; slot < slots.Count(); ++slot)
  {
    for (size_t f = 0; f < state.Faces[static_cast<size_t>(slot)].size(); ++f)
    {
      faces.push_back(state.Layer(slot, static_cast<int>(f)));
    }
  }
  const std::vector<std::uint32_t> pages = deepshadow::FitPages(unique, faces, state.Layout, state.Finest);

  // Kept pages keep their slots; new ones take free slots, then those of pages not needed.
  if (!self->KeepPages)
  {
    state.Resident.clear();
  }
  const deepshadow::SlotAssignment assignment = deepshadow::AssignSlots(pages, state.Resident, state.Layout.Capacity());
  const std::vector<int>& slotOf = assignment.SlotOf;
  const std::vector<std::pair<std::uint32_t, int>>& build = assignment.Build;

  if (!build.empty())
  {
    if (!this->BuildPages(context, build))
    {
      return false;
    }
    state.Rendered = static_cast<int>(build.size());
    for (const auto& entry : build)
    {
      rebuilt.insert(static_cast<int>(entry.first >> 26) / state.FacesPerLight);
    }
  }
  if (!build.empty() || pages != state.TablePages || slotOf != state.TableSlots)
  {
    const std::vector<std::uint32_t> table = deepshadow::BuildPageTable(pages, slotOf, state.TableLayers, state.Layout);
    vtkTextureUnitManager* units = context.Window->GetTextureUnitManager();
    const int unit = units->Allocate();
    context.Window->GetState()->vtkglActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_2D_ARRAY, state.Table);
    glTexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, 0, 0, state.Layout.TableSize(), state.Layout.TableSize(),
      state.TableLayers, GL_RED_INTEGER, GL_UNSIGNED_INT, table.data());
    glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
    units->Free(unit);
    state.TablePages = pages;
    state.TableSlots = slotOf;
    state.Version += 1.0;
  }
  cacheKey.push_back(state.Version);
  return true;
}

void vtkDeepShadowResolutionMatchedTechnique::Hooks::BindLookup(
  deepshadow::UniformSink& sink, const deepshadow::ShadowContext& context)
{
  vtkDeepShadowResolutionMatchedTechnique* self = this->Self;
  Pages& state = *self->State;
  vtkTextureUnitManager* units = context.Window->GetTextureUnitManager();
  state.AtlasUnit = units->Allocate();
  context.Window->GetState()->vtkglActiveTexture(GL_TEXTURE0 + state.AtlasUnit);
  glBindTexture(GL_TEXTURE_2D_ARRAY, state.Atlas);
  state.TableUnit = units->Allocate();
  context.Window->GetState()->vtkglActiveTexture(GL_TEXTURE0 + state.TableUnit);
  glBindTexture(GL_TEXTURE_2D_ARRAY, state.Table);
  sink.Set("u_shadowMap", state.AtlasUnit);
  sink.Set("u_pageTable", state.TableUnit);
  deepshadow::SetLightSpaceFaceUniforms(
    sink, state.Faces, static_cast<float>(state.Layout.MaxResolution), state.FacesPerLight, 1);
  sink.Set("u_pageSize", state.Layout.PageSize);
  sink.Set("u_apron", state.Layout.Apron);
  sink.Set("u_slotsPerSide", state.Layout.SlotsPerSide());
  sink.Set("u_finestLevel", state.Layout.FinestLevel());
  sink.Set("u_atlasSize", static_cast<float>(state.Layout.AtlasSize));
  sink.Set("u_shadowBias", static_cast<float>(self->Bias * Internals::FeelerStep(self, context)));
}

void vtkDeepShadowResolutionMatchedTechnique::UnbindLookup()
{
  Pages& state = *this->State;
  for (int* unit : { &state.AtlasUnit, &state.TableUnit })
  {
    if (*unit >= 0)
    {
      state.Window->GetState()->vtkglActiveTexture(GL_TEXTURE0 + *unit);
      glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
      state.Window->GetTextureUnitManager()->Free(*unit);
      *unit = -1;
    }
  }
}

void vtkDeepShadowResolutionMatchedTechnique::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Superclass::ReleaseGraphicsResources(window);
  this->State->Release();
}

void vtkDeepShadowResolutionMatchedTechnique::AddStatistics(Statistics& statistics) const
{
  this->Superclass::AddStatistics(statistics);
  statistics.emplace_back("pages_requested", static_cast<double>(this->GetPagesRequested()));
  statistics.emplace_back("requests_after_components", static_cast<double>(this->GetRequestsAfterComponents()));
  statistics.emplace_back("pages_unique", this->GetPagesUnique());
  statistics.emplace_back("pages_rendered", this->GetPagesRendered());
  statistics.emplace_back("superpages", this->GetSuperpages());
  statistics.emplace_back("pages_resident", this->GetPagesResident());
  statistics.emplace_back("finest_level_used", this->GetFinestLevelUsed());
  statistics.emplace_back("analyses", this->GetAnalyses());
  statistics.emplace_back("atlas_bytes", static_cast<double>(this->GetAtlasBytes()));
}

void vtkDeepShadowResolutionMatchedTechnique::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Bias: " << this->Bias << " feeler steps\n";
  os << indent << "Filter: " << this->Filter << "\n";
  os << indent << "PageSize: " << this->PageSize << "\n";
  os << indent << "AtlasSize: " << this->AtlasSize << "\n";
  os << indent << "MaxResolution: " << this->MaxResolution << "\n";
  os << indent << "AnalysisDownsample: " << this->AnalysisDownsample << "\n";
  os << indent << "KeepPages: " << this->KeepPages << "\n";
}
