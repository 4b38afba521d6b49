#include "vtkDeepShadowTechniqueInternals.h"

#include "Core/OpticalModel.h"
#include "GL/UniformSink.h"
#include "Sampling/SamplingFeatures.h"
#include "Sampling/ShadowContext.h"
#include "Volume/TransferTableTexture.h"
#include "ShadowSlots.h"
#include "Core/Shadows/ShadowGrid.h"
#include "Core/Shadows.h"
#include "Core/ShadowTechniques.h"
#include "vtkDeepShadowCachedShadow.h"
#include "vtkDeepShadowCachedShadowCS.h"
#include "vtkDeepShadowShadow.h"
#include "vtkDeepShadowTechniqueFactory.h"

#include "CoreAdapter.h"
#include "GL/ComputeProgram.h"
#include "LightingUniforms.h"
#include "ShaderComposer.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtkVolumeProperty.h"
#include "vtk_glew.h"

#include <algorithm>
#include <chrono>
#include <set>

namespace
{
double NowMilliseconds()
{
  return std::chrono::duration<double, std::milli>(
    std::chrono::steady_clock::now().time_since_epoch()).count();
}

// The cache's lights are stacked along z; 8 is the ray caster's light limit.
constexpr int MaxCachedLights = 8;
}

using Internals = vtkDeepShadowTechnique::Internals;

vtkDeepShadowTechnique::vtkDeepShadowTechnique()
  : Impl(new Internals)
{
}

void Internals::SetHooks(vtkDeepShadowTechnique* self, std::unique_ptr<Hooks> hooks)
{
  self->Impl->TechniqueHooks = std::move(hooks);
}

vtkDeepShadowTechnique::~vtkDeepShadowTechnique()
{
  this->SetShadowProperty(nullptr);
}

vtkCxxSetObjectMacro(vtkDeepShadowTechnique, ShadowProperty, vtkVolumeProperty);

void vtkDeepShadowTechnique::SetStepFactor(double factor)
{
  this->SetClamped("StepFactor", "shadow-step-factor", this->StepFactor, factor);
}

void vtkDeepShadowTechnique::SetThreshold(double threshold)
{
  this->SetClamped("Threshold", "shadow-threshold", this->Threshold, threshold);
}

void vtkDeepShadowTechnique::SetShadowVolumeSize(int size)
{
  this->SetClamped("ShadowVolumeSize", "shadow-volume-size", this->ShadowVolumeSize, size);
}

vtkDeepShadowTechnique* vtkDeepShadowTechnique::NewFromName(const char* name)
{
  vtkSmartPointer<vtkDeepShadowTechnique> technique =
    vtkDeepShadowTechniqueFactory::New(std::string(name ? name : ""));
  if (!technique)
  {
    vtkGenericWarningMacro("vtkDeepShadowTechnique::NewFromName: no technique is called \""
      << (name ? name : "(null)") << "\"");
    return nullptr;
  }
  technique->Register(nullptr);
  return technique;
}

void vtkDeepShadowTechnique::RegistryRange(const char* key, double& low, double& high)
{
  const deepshadow::ShadowParameterInfo* parameter = deepshadow::FindShadowParameter(key);
  low = parameter->Low;
  high = parameter->High;
}

void vtkDeepShadowTechnique::SetAllowed(const char* key, int& member, int value)
{
  const std::string problem = deepshadow::FindShadowParameter(key)->Check({ static_cast<double>(value) });
  if (!problem.empty())
  {
    vtkErrorMacro(<< problem << ", not " << value << "; keeping " << member);
    return;
  }
  if (value != member)
  {
    member = value;
    this->Modified();
  }
}

void vtkDeepShadowTechnique::SetParameters(const deepshadow::ShadowParameters& parameters)
{
  this->SetStepFactor(parameters.StepFactor);
  this->SetThreshold(parameters.Threshold);
  this->SetThresholdMode(parameters.Mode == deepshadow::ThresholdMode::Scalar ? ScalarThreshold
      : parameters.Mode == deepshadow::ThresholdMode::Opacity                 ? OpacityThreshold
                                                                              : AccumulatedThreshold);
  this->SetCached(parameters.Cached);
  this->SetShadowVolumeSize(parameters.VolumeSize);
}

std::string vtkDeepShadowTechnique::GetName() const
{
  return this->GetParameters().Name();
}

vtkDeepShadowTechnique::Statistics vtkDeepShadowTechnique::GetStatistics() const
{
  Statistics statistics;
  this->AddStatistics(statistics);
  return statistics;
}

std::vector<std::string> vtkDeepShadowTechnique::GetStatisticNames() const
{
  std::vector<std::string> names;
  for (const auto& statistic : this->GetStatistics())
  {
    names.push_back(statistic.first);
  }
  return names;
}

double vtkDeepShadowTechnique::GetStatistic(const std::string& name) const
{
  return FindStatistic(this->GetStatistics(), name);
}

double vtkDeepShadowTechnique::FindStatistic(const Statistics& statistics, const std::string& name)
{
  for (const auto& statistic : statistics)
  {
    if (statistic.first == name)
    {
      return statistic.second;
    }
  }
  return 0.0;
}

long long vtkDeepShadowTechnique::GetShadowBytes() const
{
  const Internals& impl = *this->Impl;
  long long bytes = this->GetStructureBytes();
  if (impl.FeelerTable.GetTexture())
  {
    bytes += impl.FeelerTable.GetBytes();
  }
  for (int c = 0; c < impl.ComponentFeelerCount; ++c)
  {
    bytes += impl.ComponentFeelerTables[static_cast<size_t>(c)].GetBytes();
  }
  if (this->Cached && impl.Cache)
  {
    bytes += static_cast<long long>(impl.CacheDims.x) * impl.CacheDims.y * impl.CacheDims.z *
      impl.CacheSlabs * (impl.CacheColored ? 8 : 2);
  }
  return bytes;
}

void vtkDeepShadowTechnique::FillParameters(deepshadow::ShadowParameters& parameters) const
{
  parameters.StepFactor = this->StepFactor;
  parameters.Threshold = this->Threshold;
  parameters.Mode = this->ThresholdMode == ScalarThreshold ? deepshadow::ThresholdMode::Scalar
    : this->ThresholdMode == OpacityThreshold              ? deepshadow::ThresholdMode::Opacity
                                                           : deepshadow::ThresholdMode::Accumulated;
  parameters.Cached = this->Cached;
  parameters.VolumeSize = this->ShadowVolumeSize;
}

int vtkDeepShadowTechnique::GetBuildCoarsening() const
{
  return this->Impl->Coarsening;
}

double Internals::FeelerStep(
  const vtkDeepShadowTechnique* self, const deepshadow::ShadowContext& context)
{
  return self->StepFactor * context.ShadowStep;
}

bool Internals::Prepare(vtkDeepShadowTechnique* self, deepshadow::ShadowContext& context)
{
  Internals& impl = *self->Impl;
  self->LastError.clear();
  self->LastPasses.clear();
  impl.PassMilliseconds = 0.0;
  impl.Passes = 0;
  if (!impl.TechniqueHooks)
  {
    // Every hook call comes after a successful Prepare: one check here keeps a technique
    // written outside the tree that forgot its hooks from crashing later.
    self->LastError = std::string(self->GetClassName()) +
      " installed no hooks (call Internals::SetHooks in its constructor)";
    return false;
  }
  const deepshadow::ShadowParameters parameters = self->GetParameters();
  const bool colored = parameters.IsColored();
  // The drawn opacity decides which blocks view rays sample (a cache may skip the others).
  const std::vector<double> drawnOpacityKey = context.TransferKey(false);
  if (self->ShadowProperty)
  {
    context.Transfer = deepshadow::adapter::MakeTransferFunction(self->ShadowProperty, context.OpacityUnitScale);
  }
  impl.SkipEmpty = self->ShadowProperty == nullptr;

  UpdateFeelerTable(self, context, colored);

  // Which lights get a shadow, and which of their structures are stale.
  const int maxLights = self->Cached ? std::min(self->GetMaxShadowLights(), MaxCachedLights)
                                     : self->GetMaxShadowLights();
  const int dropped = impl.Slots.Assign(context.Lights, maxLights);
  if (dropped > 0 && dropped != impl.DroppedSaid)
  {
    vtkWarningWithObjectMacro(self, << dropped << " shadow-casting lights beyond " << maxLights
                                    << " cast no shadow (" << self->GetName() << ")");
  }
  impl.DroppedSaid = dropped;
  std::vector<double> key = self->GetStructureKey();
  key.insert(key.end(), { self->StepFactor, self->Threshold, static_cast<double>(self->ThresholdMode),
    colored ? 1.0 : 0.0, impl.SkipEmpty ? 1.0 : 0.0 });
  const std::vector<double> transferKey = context.TransferKey(colored);
  key.insert(key.end(), transferKey.begin(), transferKey.end());
  // Coarser structures while interacting: built so when one must be rebuilt, kept so while the
  // frames last; a frame without them builds in full (the allocation changes, so every slot).
  bool coarse = false;
  if (context.RebuildCoarsening > 1 && self->CoarsensWhileInteracting())
  {
    coarse = impl.Coarsening > 1;
    for (int slot = 0; slot < impl.Slots.Count() && !coarse; ++slot)
    {
      coarse = impl.Slots.WouldRebuild(slot, context, key);
    }
  }
  impl.Coarsening = coarse ? context.RebuildCoarsening : 1;
  if (!impl.TechniqueHooks->AllocateStructures(context, impl.Slots))
  {
    impl.Slots.Invalidate();
    return false;
  }
  std::set<int> rebuilt;
  std::vector<int> stale;
  for (int slot = 0; slot < impl.Slots.Count(); ++slot)
  {
    if (impl.Slots.Stale(slot, context, key))
    {
      stale.push_back(slot);
    }
  }
  if (!stale.empty())
  {
    if (!impl.TechniqueHooks->BuildStructures(context, impl.Slots, stale))
    {
      impl.Slots.Invalidate();
      return false;
    }
    if (impl.Passes > 0) // techniques without a structure of their own build nothing
    {
      rebuilt.insert(stale.begin(), stale.end());
    }
  }

  if (!impl.TechniqueHooks->FollowView(context, impl.Slots, rebuilt, key))
  {
    impl.Slots.Invalidate();
    return false;
  }

  if (!impl.TechniqueHooks->ExchangeStructures(context, impl.Slots, rebuilt, key))
  {
    return false;
  }

  if (self->Cached)
  {
    if (!PrepareCache(self, context, key, drawnOpacityKey, rebuilt))
    {
      return false;
    }
  }
  else if (impl.Cache)
  {
    impl.ReleaseCache(context.Window);
  }

  if (!rebuilt.empty())
  {
    self->BuildCount += static_cast<int>(rebuilt.size());
    self->LastBuildMilliseconds = impl.PassMilliseconds;
  }
  return true;
}

void Internals::UpdateFeelerTable(
  vtkDeepShadowTechnique* self, const deepshadow::ShadowContext& context, bool colored)
{
  Internals& impl = *self->Impl;
  // An isosurface's opacity is the function's own: the table is sampled for a unit step.
  const double step =
    context.IsoValues.empty() ? FeelerStep(self, context) : context.Transfer.OpacityUnitDistance;
  std::vector<double> tableKey = context.TransferKey(colored);
  tableKey.insert(tableKey.end(), { static_cast<double>(context.DataVersion), step,
    static_cast<double>(context.TableSize), context.Range.x, context.Range.y });
  if (impl.FeelerTable.NeedsUpdate(tableKey))
  {
    impl.FeelerTable.Update(
      context.Window, context.Transfer, context.Range, context.TableSize, step, tableKey);
    self->LastPasses.emplace_back("feeler-table");
  }
  // Components 1..: each its own function over its own range (the key covers them all).
  impl.ComponentFeelerCount = static_cast<int>(context.OtherComponents.size());
  for (int c = 0; c < impl.ComponentFeelerCount; ++c)
  {
    const deepshadow::ShadowContext::Component& component = context.OtherComponents[static_cast<size_t>(c)];
    deepshadow::TransferTableTexture& table = impl.ComponentFeelerTables[static_cast<size_t>(c)];
    std::vector<double> key = tableKey;
    key.insert(key.end(), { static_cast<double>(c), component.Range.x, component.Range.y });
    if (table.NeedsUpdate(key))
    {
      table.Update(context.Window, component.Transfer, component.Range, context.TableSize, step, std::move(key));
    }
  }
}

bool Internals::PrepareCache(vtkDeepShadowTechnique* self, deepshadow::ShadowContext& context,
  std::vector<double> key, const std::vector<double>& drawnOpacityKey, std::set<int>& rebuilt)
{
  Internals& impl = *self->Impl;
  const bool colored = self->GetParameters().IsColored();
  const int maxLights = std::min(self->GetMaxShadowLights(), MaxCachedLights);
  // The cache depends on everything the structure and the lookup do, on its own size, and
  // (where it skips nodes no view sample reads) on the blocks the drawn opacity leaves.
  const deepshadow::GridFrame frame =
    deepshadow::GridFrame::OverVolume(context.Dims, context.IndexToWorld, self->ShadowVolumeSize);
  const glm::ivec3 dims = frame.Dims;
  const glm::vec3 reach = glm::vec3(context.Dims - 1) / glm::vec3(dims - 1);
  const bool skipEmpty = context.Occupancy &&
    std::max({ reach.x, reach.y, reach.z }) <= context.BlockSize;
  const std::vector<double> lookupKey = self->GetLookupKey();
  key.insert(key.end(), lookupKey.begin(), lookupKey.end());
  key.insert(key.end(), { static_cast<double>(self->ShadowVolumeSize), skipEmpty ? 1.0 : 0.0 });
  if (skipEmpty)
  {
    key.insert(key.end(), drawnOpacityKey.begin(), drawnOpacityKey.end());
  }
  GLint max3D = 0;
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &max3D);
  // Grow only: fewer shadow-casting lights keep the others' slabs.
  const int slabs = std::max(impl.Cache && dims == impl.CacheDims ? impl.CacheSlabs : 1, impl.Slots.Count());
  if (std::max({ dims.x, dims.y, dims.z * slabs }) > max3D)
  {
    self->LastError = "the shadow volume (" + std::to_string(dims.x) + "x" +
      std::to_string(dims.y) + "x" + std::to_string(dims.z) + " per light) exceeds this GL's 3D "
      "texture limit of " + std::to_string(max3D);
    return false;
  }
  if (!impl.Cache || dims != impl.CacheDims || slabs != impl.CacheSlabs || colored != impl.CacheColored)
  {
    impl.ReleaseCache(context.Window);
    impl.Cache = vtkSmartPointer<vtkTextureObject>::New();
    impl.Cache->SetContext(context.Window);
    impl.Cache->SetInternalFormat(colored ? GL_RGBA16F : GL_R16F);
    impl.Cache->SetFormat(colored ? GL_RGBA : GL_RED);
    impl.Cache->SetDataType(GL_FLOAT);
    impl.Cache->SetWrapS(vtkTextureObject::ClampToEdge);
    impl.Cache->SetWrapT(vtkTextureObject::ClampToEdge);
    impl.Cache->SetWrapR(vtkTextureObject::ClampToEdge);
    impl.Cache->SetMinificationFilter(vtkTextureObject::Linear);
    impl.Cache->SetMagnificationFilter(vtkTextureObject::Linear);
    impl.Cache->Allocate3D(static_cast<unsigned int>(dims.x), static_cast<unsigned int>(dims.y),
      static_cast<unsigned int>(dims.z * slabs), colored ? 4 : 1, VTK_FLOAT);
    impl.CacheDims = dims;
    impl.CacheSlabs = slabs;
    impl.CacheColored = colored;
  }
  impl.CacheFrame = frame; // stale slots below are rebuilt for it
  impl.CacheSlots.Assign(context.Lights, maxLights);
  std::vector<int> staleCache;
  for (int slot = 0; slot < impl.CacheSlots.Count(); ++slot)
  {
    if (impl.CacheSlots.Stale(slot, context, key))
    {
      staleCache.push_back(slot);
    }
  }
  if (!staleCache.empty())
  {
    std::vector<std::pair<int, int>> slotsAndSlabs;
    for (int slot : staleCache)
    {
      slotsAndSlabs.emplace_back(slot, slot);
    }
    if (!RunGridPass(self, impl.CacheBuild, colored ? "#define CACHE_COLORED\n" : "", context,
          impl.Cache, colored, frame, slotsAndSlabs, impl.CacheSlots, skipEmpty, reach, -1))
    {
      impl.CacheSlots.Invalidate();
      return false;
    }
    self->LastPasses.insert(self->LastPasses.end(), staleCache.size(), "shadow-cache");
    rebuilt.insert(staleCache.begin(), staleCache.end());
  }
  return true;
}

bool Internals::RunGridPass(vtkDeepShadowTechnique* self, deepshadow::ComputeProgram& program,
  const std::string& defines, const deepshadow::ShadowContext& context, vtkTextureObject* grid, bool colored,
  const deepshadow::GridFrame& frame, const std::vector<std::pair<int, int>>& slotsAndSlabs,
  const deepshadow::ShadowSlots& slots, bool skipEmpty, const glm::vec3& reach, int storeMask)
{
  const std::string lookup = "//@Dec\n" + defines + self->GetLookupSource();
  if (!BeginBuildPass(self, program, vtkDeepShadowCachedShadowCS, context, "Lookup", lookup))
  {
    return false;
  }
  deepshadow::UniformSink sink(&program);
  self->Impl->TechniqueHooks->BindLookup(sink, context);
  program.Set("u_shadowDims", frame.Dims);
  program.Set("u_cacheSkipEmpty", skipEmpty ? 1 : 0);
  program.Set("u_cacheReach", reach);
  program.Set("u_nodeToWorld", glm::mat4(frame.NodeToWorld));
  const GLenum format = colored ? GL_RGBA16F : GL_R16F;
  const bool multiply = storeMask >= 0;
  glBindImageTexture(0, grid->GetHandle(), 0, GL_TRUE, 0, multiply ? GL_READ_WRITE : GL_WRITE_ONLY, format);
  for (const auto& [slot, slab] : slotsAndSlabs)
  {
    const deepshadow::Light& light = context.Lights[static_cast<size_t>(slots.Light(slot))];
    program.Set("u_slot", slot);
    program.Set("u_slab", slab);
    if (multiply)
    {
      program.Set("u_firstCaster", (storeMask >> slab) & 1);
    }
    // The shader reads u_lightToward for directional lights only (towards the light);
    // positional ones aim from u_lightPosition.
    const deepshadow::PackedLight packed = deepshadow::PackLight(light);
    program.Set("u_lightPositional", packed.Positional);
    program.Set("u_lightPosition", packed.Position);
    program.Set("u_lightToward", packed.Direction);
    program.Dispatch(frame.Dims, glm::ivec3(4));
  }
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_READ_WRITE, format);
  self->UnbindLookup();
  EndBuildPass(self, context);
  return true;
}

int Internals::EvaluateOnGrid(vtkDeepShadowTechnique* self, const deepshadow::ShadowContext& context,
  vtkTextureObject* grid, const deepshadow::GridFrame& frame, int writtenSlabs)
{
  Internals& impl = *self->Impl;
  // Slab l holds light l of the context; each light with a structure of ours.
  std::vector<std::pair<int, int>> slotsAndSlabs;
  for (int slot = 0; slot < impl.Slots.Count(); ++slot)
  {
    slotsAndSlabs.emplace_back(slot, impl.Slots.Light(slot));
  }
  if (slotsAndSlabs.empty())
  {
    return writtenSlabs;
  }
  if (!RunGridPass(self, impl.OtherBuild, "#define OTHER_VOLUMES\n", context, grid, true, frame,
        slotsAndSlabs, impl.Slots, false, glm::vec3(0.0), ~writtenSlabs & 0xff))
  {
    return -1;
  }
  for (const auto& entry : slotsAndSlabs)
  {
    writtenSlabs |= 1 << entry.second;
  }
  return writtenSlabs;
}

std::vector<std::string> vtkDeepShadowTechnique::GetLookupFeatures(bool direct) const
{
  if (this->Cached && !direct)
  {
    return { "ShadowGrid" };
  }
  if (this->NeedsFeeler(direct) && this->GetParameters().IsColored())
  {
    return { "FeelerColored" };
  }
  return {};
}

std::vector<std::string> vtkDeepShadowTechnique::GetBuildFeatures() const
{
  if (this->GetParameters().IsColored())
  {
    return { "FeelerColored" };
  }
  return {};
}

std::string vtkDeepShadowTechnique::GetShaderFeatureSource(bool direct) const
{
  if (!this->Cached || direct)
  {
    return vtkDeepShadowShadow + this->GetLookupSource();
  }
  const bool colored = this->GetParameters().IsColored();
  return std::string(vtkDeepShadowShadow) + "//@Dec\nconst bool ShadowCacheColored = " +
    (colored ? "true" : "false") + ";\n" + vtkDeepShadowCachedShadow;
}

void vtkDeepShadowTechnique::ActivateFeelerTable()
{
  this->Impl->FeelerTable.GetTexture()->Activate();
  for (int c = 0; c < this->Impl->ComponentFeelerCount; ++c)
  {
    this->Impl->ComponentFeelerTables[static_cast<size_t>(c)].GetTexture()->Activate();
  }
}

void vtkDeepShadowTechnique::DeactivateFeelerTable()
{
  if (this->Impl->FeelerTable.GetTexture())
  {
    this->Impl->FeelerTable.GetTexture()->Deactivate();
  }
  for (int c = 0; c < this->Impl->ComponentFeelerCount; ++c)
  {
    if (vtkTextureObject* table = this->Impl->ComponentFeelerTables[static_cast<size_t>(c)].GetTexture())
    {
      table->Deactivate();
    }
  }
}

void Internals::SetFeelerUniforms(const vtkDeepShadowTechnique* self,
  deepshadow::UniformSink& sink, const deepshadow::ShadowContext& context)
{
  const double step = FeelerStep(self, context);
  const deepshadow::ShadowParameters parameters = self->GetParameters();
  sink.Set("u_feelerTable", self->Impl->FeelerTable.GetTexture()->GetTextureUnit());
  for (int c = 0; c < self->Impl->ComponentFeelerCount; ++c)
  {
    sink.Set(("u_componentFeelerTable" + std::to_string(c + 1)).c_str(),
      self->Impl->ComponentFeelerTables[static_cast<size_t>(c)].GetTexture()->GetTextureUnit());
  }
  sink.Set("u_feelerStep", static_cast<float>(step));
  // Per-sample opacity thresholds are compared with the table's step-corrected opacity (an
  // isosurface's is uncorrected).
  sink.Set("u_feelerThreshold",
    static_cast<float>(parameters.Mode == deepshadow::ThresholdMode::Opacity && context.IsoValues.empty()
        ? deepshadow::CorrectOpacity(self->Threshold, step, context.Transfer.OpacityUnitDistance)
        : self->Threshold));
  sink.Set("u_feelerThresholdMode", static_cast<int>(parameters.Mode));
  sink.Set("u_scalarRange", glm::vec2(context.ShaderRange()));
  sink.Set("u_feelerTermination",
    parameters.EarlyTermination ? static_cast<float>(deepshadow::ShadowTerminationTransmittance) : 0.0f);
  if (context.Surfaces)
  {
    sink.Set("u_surfaceThreshold", static_cast<float>(self->Threshold));
  }
  // Zero-opacity blocks cannot stop a feeler, unless the threshold is on the scalar or the
  // shadows are cast by another transfer function than the one the blocks were found for.
  const bool opaqueOnScalar = parameters.Mode == deepshadow::ThresholdMode::Scalar &&
    deepshadow::ShadowTechniqueOf(parameters).Binary;
  sink.Set("u_feelerSkipEmpty", context.Occupancy && self->Impl->SkipEmpty && !opaqueOnScalar ? 1 : 0);
}

bool Internals::BeginBuildPass(vtkDeepShadowTechnique* self, deepshadow::ComputeProgram& program,
  const std::string& shaderTemplate, const deepshadow::ShadowContext& context,
  const std::string& runtimeName, const std::string& runtimeSource)
{
  // Builds march through the casting surfaces too.
  const deepshadow::SamplingUse use{ context, true };
  deepshadow::ComposedFeatures features;
  features.Enabled.insert("Feeler");
  deepshadow::ComposeSamplingFeatures(use, features);
  for (const std::string& feature : self->GetBuildFeatures())
  {
    features.Enabled.insert(feature);
  }
  if (!runtimeName.empty())
  {
    features.Runtime[runtimeName] = deepshadow::ShaderFeature(runtimeName, runtimeSource);
  }
  if (!program.Build(deepshadow::ComposeShader(shaderTemplate, features.Enabled, features.Runtime)))
  {
    self->LastError = program.Error();
    return false;
  }
  self->Impl->PassStart = NowMilliseconds();
  self->ActivateFeelerTable();
  program.Use();
  deepshadow::UniformSink sink(&program);
  deepshadow::BindSamplingFeatures(use, sink);
  SetFeelerUniforms(self, sink, context);
  return true;
}

void Internals::EndBuildPass(vtkDeepShadowTechnique* self, const deepshadow::ShadowContext& context)
{
  glFinish(); // the build time includes the GPU's work
  self->DeactivateFeelerTable();
  deepshadow::UnbindSamplingFeatures({ context, true });
  // VTK tracks the bound program; ours replaced it.
  context.Window->GetShaderCache()->ReleaseCurrentShader();
  self->Impl->PassMilliseconds += NowMilliseconds() - self->Impl->PassStart;
  ++self->Impl->Passes;
}

int Internals::SlotCount(const vtkDeepShadowTechnique* self)
{
  return self->Impl->Slots.Count();
}

void Internals::Bind(vtkDeepShadowTechnique* self, deepshadow::UniformSink& sink,
  const deepshadow::ShadowContext& context, bool direct)
{
  Internals& impl = *self->Impl;
  std::vector<float> attenuation;
  for (const deepshadow::Light& light : context.Lights)
  {
    attenuation.push_back(static_cast<float>(light.ShadowAttenuation));
  }
  sink.Set("u_shadowSlot", impl.Slots.SlotOfEachLight(static_cast<int>(context.Lights.size())));
  std::vector<int> slotLights;
  for (int slot = 0; slot < impl.Slots.Count(); ++slot)
  {
    slotLights.push_back(impl.Slots.Light(slot));
  }
  sink.Set("u_shadowSlotCount", impl.Slots.Count());
  sink.Set("u_shadowSlotLight", slotLights);
  sink.Set("u_shadowAttenuation", attenuation);
  if (self->Cached && !direct)
  {
    impl.Cache->Activate();
    sink.Set("u_shadowVolume", impl.Cache->GetTextureUnit());
    sink.Set("u_shadowDims", glm::vec3(impl.CacheDims));
    sink.Set("u_shadowWorldToNode", glm::mat4(impl.CacheFrame.WorldToNode));
    sink.Set("u_shadowSlabs", static_cast<float>(impl.CacheSlabs));
    return;
  }
  if (self->LookupNeedsFeeler())
  {
    self->ActivateFeelerTable();
    SetFeelerUniforms(self, sink, context);
  }
  self->Impl->TechniqueHooks->BindLookup(sink, context);
}

void vtkDeepShadowTechnique::Unbind(bool direct)
{
  if (this->Cached && !direct)
  {
    if (this->Impl->Cache)
    {
      this->Impl->Cache->Deactivate();
    }
    return;
  }
  this->UnbindLookup();
  this->DeactivateFeelerTable();
}

void vtkDeepShadowTechnique::ReleaseGraphicsResources(vtkWindow* window)
{
  Internals& impl = *this->Impl;
  impl.FeelerTable.Release(window);
  for (auto& table : impl.ComponentFeelerTables)
  {
    table.Release(window);
  }
  impl.ReleaseCache(window);
  impl.OtherBuild.Release();
  impl.Slots.Invalidate();
}

void vtkDeepShadowTechnique::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Technique: " << this->GetName() << "\n";
  os << indent << "StepFactor: " << this->StepFactor << "\n";
  os << indent << "Threshold: " << this->Threshold
     << (this->ThresholdMode == ScalarThreshold ? " (scalar)"
          : this->ThresholdMode == OpacityThreshold ? " (opacity)"
                                                    : " (accumulated opacity)")
     << "\n";
  os << indent << "Cached: " << this->Cached << " (" << this->ShadowVolumeSize << " nodes)\n";
  os << indent << "ShadowProperty: " << this->ShadowProperty << "\n";
  os << indent << "BuildCount: " << this->BuildCount << "\n";
  os << indent << "ShadowBytes: " << this->GetShadowBytes() << "\n";
  for (const auto& statistic : this->GetStatistics())
  {
    os << indent << statistic.first << ": " << statistic.second << "\n";
  }
}
