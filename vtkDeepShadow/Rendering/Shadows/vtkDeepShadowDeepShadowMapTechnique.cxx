#include "vtkDeepShadowDeepShadowMapTechnique.h"
#include "vtkDeepShadowTechniqueInternals.h"

#include "GL/UniformSink.h"
#include "Sampling/ShadowContext.h"
#include "Core/Shadows.h"
#include "Core/Shadows/NodeChunks.h"
#include "NodePool.h"
#include "ShadowSlots.h"
#include "vtkDeepShadowDeepShadowMap.h"
#include "vtkDeepShadowDeepShadowMapBuild.h"

#include "vtkDeepShadowTechniqueFactory.h"
#include "vtkObjectFactory.h"
#include "vtk_glew.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <numeric>
#include <sstream>

vtkStandardNewMacro(vtkDeepShadowDeepShadowMapTechnique);

// The hooks with internal types: what it binds and builds with.
class vtkDeepShadowDeepShadowMapTechnique::Hooks : public vtkDeepShadowLightSpaceTechnique::Hooks
{
public:
  explicit Hooks(vtkDeepShadowDeepShadowMapTechnique& self)
    : vtkDeepShadowLightSpaceTechnique::Hooks(self)
    , Technique(&self)
  {
  }

  int GetLayersPerFace(const deepshadow::ShadowContext&) const override
  {
    // Chunked: one layer of first chunks per face, the nodes in the pool.
    return this->Technique->ChunkNodes > 0 ? 1 : this->Technique->Layers;
  }

  bool AllocateStructures(deepshadow::ShadowContext& context, deepshadow::ShadowSlots& slots) override;

  void SetBuildUniforms(deepshadow::UniformSink& sink, const deepshadow::ShadowContext&) override
  {
    sink.Set("u_epsilon", static_cast<float>(this->Technique->Epsilon));
  }

  void SetSlotBuildUniforms(deepshadow::UniformSink& sink, int slot) override;
  std::vector<int> AfterBuild(const std::vector<int>& built, int slotCount) override;
  void SetMapLookupUniforms(deepshadow::UniformSink& sink, const deepshadow::ShadowContext& context) override;

private:
  vtkDeepShadowDeepShadowMapTechnique* Technique;
};

// The GPU class of the registry's DeepShadowMap techniques (deepshadow::ShadowTechniques()).
static const bool Registered = vtkDeepShadowTechniqueFactory::Register(deepshadow::ShadowKind::DeepShadowMap,
  []() -> vtkDeepShadowTechnique* { return vtkDeepShadowDeepShadowMapTechnique::New(); });

// The build's counters: a shader storage buffer the build adds to atomically, read back
// after it (DeepShadowMapBuild.glsl's DeepShadowStatistics).
class vtkDeepShadowDeepShadowMapTechnique::NodeCounter
{
public:
  unsigned int Buffer = 0;
  // hit, total, max, overflowed, epsilon bits, then chunks asked for per slot (chunked)
  std::array<unsigned int, 9> Last{};
  // Per slot, the most nodes a texel of its last build holds (fixed layers): the lookup's
  // binary search covers no more, as the layers beyond hold only the last value far away.
  std::vector<int> SearchNodes;
  bool SaidLost = false; // a bound of 1 or more was said, while it lasts

  void Release()
  {
    if (this->Buffer)
    {
      glDeleteBuffers(1, &this->Buffer);
      this->Buffer = 0;
    }
  }
};

// Chunked node memory: the pool, and per slot the bound of its build (doubled while the
// pool cannot hold its nodes) and the chunks it took.
class vtkDeepShadowDeepShadowMapTechnique::Chunks
{
public:
  deepshadow::NodePool Pool;
  std::vector<double> Bound;
  std::vector<long long> Used;
  std::vector<bool> Cut; // the pool ran out even at a bound of 1
  std::string SaidLimit; // what the GL allows of the pool, said once while it lasts
  std::string SaidShort; // the same for a pool too small for the nodes
};

vtkDeepShadowDeepShadowMapTechnique::vtkDeepShadowDeepShadowMapTechnique()
  : Stats(new NodeCounter)
  , Pool(new Chunks)
{
  Internals::SetHooks(this, std::make_unique<Hooks>(*this));
}

vtkDeepShadowDeepShadowMapTechnique::~vtkDeepShadowDeepShadowMapTechnique() = default;

void vtkDeepShadowDeepShadowMapTechnique::SetEpsilon(double epsilon)
{
  this->SetClamped("Epsilon", "epsilon", this->Epsilon, epsilon);
}

void vtkDeepShadowDeepShadowMapTechnique::SetLayers(int layers)
{
  this->SetClamped("Layers", "layers", this->Layers, layers);
}

void vtkDeepShadowDeepShadowMapTechnique::SetChunkNodes(int nodes)
{
  this->SetClamped("ChunkNodes", "chunk-nodes", this->ChunkNodes, nodes);
}

void vtkDeepShadowDeepShadowMapTechnique::SetPoolMegabytes(double megabytes)
{
  this->SetClamped("PoolMegabytes", "node-pool-mb", this->PoolMegabytes, megabytes);
}

bool vtkDeepShadowDeepShadowMapTechnique::Hooks::AllocateStructures(
  deepshadow::ShadowContext& context, deepshadow::ShadowSlots& slots)
{
  if (!this->vtkDeepShadowLightSpaceTechnique::Hooks::AllocateStructures(context, slots))
  {
    return false;
  }
  vtkDeepShadowDeepShadowMapTechnique* self = this->Technique;
  Chunks& chunks = *self->Pool;
  if (self->ChunkNodes == 0)
  {
    chunks.Pool.Release();
    return true;
  }
  // Each light's limit, as the twin's (ChunkPoolCapacity over its faces' texels). A new pool
  // starts at an eighth of the automatic limit (a node per texel's worth), whatever the limit.
  std::vector<long long> limits;
  long long start = 0;
  for (int slot = 0; slot < slots.Count(); ++slot)
  {
    const size_t texels = static_cast<size_t>(self->GetFaceCount(slot)) * self->GetBuiltMapSize() * self->GetBuiltMapSize();
    limits.push_back(deepshadow::ChunkPoolCapacity(texels, self->ChunkNodes, self->Colored, self->Layers, self->PoolMegabytes));
    start = std::max(start, deepshadow::ChunkPoolCapacity(texels, self->ChunkNodes, self->Colored, self->Layers, 0.0) / 8);
  }
  bool remade = false;
  std::string problem;
  const bool made =
    chunks.Pool.Reserve(context.Window, limits, start, self->ChunkNodes, self->Colored, remade, problem);
  if (!made)
  {
    self->LastError = problem;
    return false;
  }
  if (!problem.empty() && problem != chunks.SaidLimit)
  {
    vtkWarningWithObjectMacro(self, << problem);
  }
  chunks.SaidLimit = problem;
  // Every build starts from the bound asked for.
  chunks.Bound.assign(static_cast<size_t>(slots.Count()), self->Epsilon);
  chunks.Used.resize(static_cast<size_t>(slots.Count()), 0);
  chunks.Cut.assign(static_cast<size_t>(slots.Count()), false);
  if (remade)
  {
    slots.Invalidate();
  }
  return true;
}

void vtkDeepShadowDeepShadowMapTechnique::Hooks::SetSlotBuildUniforms(deepshadow::UniformSink& sink, int slot)
{
  vtkDeepShadowDeepShadowMapTechnique* self = this->Technique;
  if (self->ChunkNodes == 0)
  {
    return;
  }
  const Chunks& chunks = *self->Pool;
  sink.Set("u_epsilon", static_cast<float>(chunks.Bound[static_cast<size_t>(slot)]));
  // Unsigned in the shader; the pool keeps chunk numbers below MaxPoolChunks.
  sink.Set("u_chunkBase", static_cast<int>(chunks.Pool.Base(slot)));
  sink.Set("u_chunkCapacity", static_cast<int>(chunks.Pool.Capacity(slot)));
  sink.Set("u_poolSlot", slot);
}

std::vector<int> vtkDeepShadowDeepShadowMapTechnique::Hooks::AfterBuild(const std::vector<int>& built, int slotCount)
{
  vtkDeepShadowDeepShadowMapTechnique* self = this->Technique;
  if (self->ChunkNodes == 0)
  {
    // Fixed layers build no light again. The lookup searches, of these lights' layers, the
    // most nodes a texel holds (the build's counters are for all of them together).
    std::vector<int>& searched = self->Stats->SearchNodes;
    searched.resize(static_cast<size_t>(slotCount), self->Layers);
    const int most = std::clamp(static_cast<int>(self->Stats->Last[2]), 1, self->Layers);
    for (int slot : built)
    {
      searched[static_cast<size_t>(slot)] = most;
    }
    self->SayShadowLost();
    return {};
  }
  Chunks& chunks = *self->Pool;
  std::vector<int> doubled;
  bool grew = false;
  std::string problem;
  for (int slot : built)
  {
    const long long requested = self->Stats->Last[5 + static_cast<size_t>(slot)];
    // A pool short of its limit grows (moving every light's chunks); one at its limit gets a
    // doubled bound, as the twin (DeepShadowMap::BuildChunked).
    if (chunks.Pool.Grow(requested, slot, problem))
    {
      grew = true;
      continue;
    }
    if (!problem.empty())
    {
      self->LastError = problem;
      return {};
    }
    chunks.Used[static_cast<size_t>(slot)] = std::min(requested, chunks.Pool.Capacity(slot));
    chunks.Cut[static_cast<size_t>(slot)] = requested > chunks.Pool.Capacity(slot);
    double& bound = chunks.Bound[static_cast<size_t>(slot)];
    const double next = deepshadow::ChunkedBuildBound(bound, requested, chunks.Pool.Limit(slot));
    if (next >= 0.0)
    {
      bound = next;
      doubled.push_back(slot);
    }
  }
  if (grew)
  {
    std::vector<int> all(static_cast<size_t>(slotCount));
    std::iota(all.begin(), all.end(), 0);
    return all;
  }
  if (doubled.empty())
  {
    self->SayPoolShort();
  }
  return doubled;
}

void vtkDeepShadowDeepShadowMapTechnique::SayShadowLost()
{
  // Fixed layers double an overflowing texel's bound until its nodes fit; from a bound of 1
  // on, one node of 1 fits any visibility, so those texels keep no shadow at all.
  const double bound = this->GetEpsilonMax();
  const bool lost = bound >= 1.0 && bound > this->Epsilon;
  if (lost && !this->Stats->SaidLost)
  {
    vtkWarningMacro(<< "the deep shadow map's " << this->Layers << " layers cannot hold the shadow at epsilon "
                    << this->Epsilon << ": texels that need more nodes were built with a bound of up to "
                    << bound << ", and a bound of 1 or more keeps no shadow there (raise Layers, or use chunk-nodes)");
  }
  this->Stats->SaidLost = lost;
}

void vtkDeepShadowDeepShadowMapTechnique::SayPoolShort()
{
  // Once the build is done: which lights' nodes did not fit at the bound asked for, said once
  // while the same happens again.
  Chunks& chunks = *this->Pool;
  std::ostringstream say;
  for (size_t slot = 0; slot < chunks.Bound.size(); ++slot)
  {
    if (chunks.Bound[slot] > this->Epsilon || chunks.Cut[slot])
    {
      say << (say.tellp() > 0 ? "; " : "") << "the deep shadow map's node pool of "
          << chunks.Pool.Limit(static_cast<int>(slot)) * chunks.Pool.ChunkBytes() / 1048576.0
          << " MB cannot hold light " << slot << "'s nodes at epsilon " << this->Epsilon << ": "
          << (chunks.Cut[slot] ? "texels keep the chunks they got at a bound of " : "built with a bound of ")
          << chunks.Bound[slot] << (chunks.Bound[slot] >= 1.0 ? ", which keeps no shadow" : "")
          << " (node-pool-mb raises it)";
    }
  }
  if (!say.str().empty() && say.str() != chunks.SaidShort)
  {
    vtkWarningMacro(<< say.str());
  }
  chunks.SaidShort = say.str();
}

void vtkDeepShadowDeepShadowMapTechnique::Hooks::SetMapLookupUniforms(
  deepshadow::UniformSink& sink, const deepshadow::ShadowContext& context)
{
  vtkDeepShadowDeepShadowMapTechnique* self = this->Technique;
  if (self->ChunkNodes > 0)
  {
    self->Pool->Pool.BindLookup(sink, context.Window);
    return;
  }
  // One count for every light: a computed index costs llvmpipe more than the nodes it saves.
  const std::vector<int>& searched = self->Stats->SearchNodes;
  const int most = searched.empty() ? self->Layers : *std::max_element(searched.begin(), searched.end());
  sink.Set("u_dsmSearchNodes", std::min(most, self->Layers));
}

void vtkDeepShadowDeepShadowMapTechnique::UnbindLookup()
{
  this->Superclass::UnbindLookup();
  this->Pool->Pool.UnbindLookup();
}

long long vtkDeepShadowDeepShadowMapTechnique::GetStructureBytes() const
{
  return this->Superclass::GetStructureBytes() + this->Pool->Pool.AllocatedBytes();
}

long long vtkDeepShadowDeepShadowMapTechnique::GetChunksUsed() const
{
  const auto& used = this->Pool->Used;
  return this->ChunkNodes > 0 ? std::accumulate(used.begin(), used.end(), 0LL) : 0;
}

long long vtkDeepShadowDeepShadowMapTechnique::GetChunkBytes() const
{
  return this->ChunkNodes > 0 ? deepshadow::ChunkBytes(this->ChunkNodes, this->Colored) : 0;
}

long long vtkDeepShadowDeepShadowMapTechnique::GetPoolBytes() const
{
  return this->Pool->Pool.AllocatedBytes();
}

deepshadow::ShadowParameters vtkDeepShadowDeepShadowMapTechnique::GetParameters() const
{
  deepshadow::ShadowParameters parameters;
  this->FillParameters(parameters);
  parameters.Kind = deepshadow::ShadowKind::DeepShadowMap;
  this->FillMapParameters(parameters);
  parameters.Epsilon = this->Epsilon;
  parameters.Layers = this->Layers;
  parameters.ChunkNodes = this->ChunkNodes;
  parameters.PoolMegabytes = this->PoolMegabytes;
  parameters.Colored = this->Colored;
  return parameters;
}

void vtkDeepShadowDeepShadowMapTechnique::SetParameters(const deepshadow::ShadowParameters& parameters)
{
  this->Superclass::SetParameters(parameters);
  this->SetEpsilon(parameters.Epsilon);
  this->SetLayers(parameters.Layers);
  this->SetChunkNodes(parameters.ChunkNodes);
  this->SetPoolMegabytes(parameters.PoolMegabytes);
  this->SetColored(parameters.Colored);
}

std::vector<double> vtkDeepShadowDeepShadowMapTechnique::GetStructureKey() const
{
  return { static_cast<double>(this->MapSize), this->Epsilon, static_cast<double>(this->Layers),
    static_cast<double>(this->ChunkNodes), this->PoolMegabytes };
}

unsigned int vtkDeepShadowDeepShadowMapTechnique::GetTexelFormat() const
{
  // Chunked: each texel's first chunk (the nodes are in the pool).
  return this->ChunkNodes > 0 ? GL_R32F : (this->Colored ? GL_RGBA32F : GL_RG32F);
}

std::string vtkDeepShadowDeepShadowMapTechnique::ChunkDefines() const
{
  return this->ChunkNodes > 0
    ? "//@Dec\n#define DSM_CHUNKED\n#define DSM_CHUNK_NODES " + std::to_string(this->ChunkNodes) + "\n"
    : std::string();
}

std::string vtkDeepShadowDeepShadowMapTechnique::GetBuildSource() const
{
  return this->ChunkDefines() + vtkDeepShadowDeepShadowMapBuild;
}

int vtkDeepShadowDeepShadowMapTechnique::LookupLoopIterations() const
{
  // One binary search over the nodes, the four bilinear texels in step (at most Layers
  // nodes); chunked, over one chunk's, after the walk past full chunks: one pass, and
  // (mostly) one link.
  int steps = this->ChunkNodes > 0 ? 2 : 0;
  for (int remaining = this->ChunkNodes > 0 ? this->ChunkNodes : this->Layers; remaining > 0; remaining /= 2)
  {
    ++steps;
  }
  return steps;
}

std::string vtkDeepShadowDeepShadowMapTechnique::GetMapLookupSource() const
{
  return this->ChunkDefines() + "//@Dec\nconst bool DsmColored = " + (this->Colored ? "true" : "false") +
    ";\n" + vtkDeepShadowDeepShadowMap;
}

void vtkDeepShadowDeepShadowMapTechnique::BeginMapBuild()
{
  NodeCounter& stats = *this->Stats;
  if (!stats.Buffer)
  {
    glGenBuffers(1, &stats.Buffer);
  }
  const std::array<unsigned int, 9> zero{};
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, stats.Buffer);
  glBufferData(GL_SHADER_STORAGE_BUFFER, sizeof(zero), zero.data(), GL_DYNAMIC_READ);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, stats.Buffer);
  if (this->ChunkNodes > 0)
  {
    this->Pool->Pool.BindBuild();
  }
}

void vtkDeepShadowDeepShadowMapTechnique::EndMapBuild()
{
  NodeCounter& stats = *this->Stats;
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, stats.Buffer);
  glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(stats.Last), stats.Last.data());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, 0);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  if (this->ChunkNodes > 0)
  {
    this->Pool->Pool.UnbindBuild();
  }
}

double vtkDeepShadowDeepShadowMapTechnique::GetNodesAverage() const
{
  const auto& last = this->Stats->Last;
  return last[0] ? static_cast<double>(last[1]) / last[0] : 0.0;
}

int vtkDeepShadowDeepShadowMapTechnique::GetNodesMax() const
{
  return static_cast<int>(this->Stats->Last[2]);
}

long long vtkDeepShadowDeepShadowMapTechnique::GetTexelsOverflowed() const
{
  return static_cast<long long>(this->Stats->Last[3]);
}

double vtkDeepShadowDeepShadowMapTechnique::GetEpsilonMax() const
{
  float epsilon = 0.0f;
  std::memcpy(&epsilon, &this->Stats->Last[4], sizeof(epsilon));
  return epsilon;
}

void vtkDeepShadowDeepShadowMapTechnique::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Superclass::ReleaseGraphicsResources(window);
  this->Stats->Release();
  this->Pool->Pool.Release();
}

void vtkDeepShadowDeepShadowMapTechnique::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Epsilon: " << this->Epsilon << "\n";
  os << indent << "Layers: " << this->Layers << "\n";
  os << indent << "ChunkNodes: " << this->ChunkNodes << "\n";
  os << indent << "PoolMegabytes: " << this->PoolMegabytes << "\n";
  os << indent << "Colored: " << this->Colored << "\n";
}

void vtkDeepShadowDeepShadowMapTechnique::AddStatistics(Statistics& statistics) const
{
  this->Superclass::AddStatistics(statistics);
  statistics.emplace_back("dsm_nodes_avg", this->GetNodesAverage());
  statistics.emplace_back("dsm_nodes_max", this->GetNodesMax());
  statistics.emplace_back("dsm_texels_overflowed", static_cast<double>(this->GetTexelsOverflowed()));
  statistics.emplace_back("dsm_epsilon_max", this->GetEpsilonMax());
  statistics.emplace_back("chunks_used", static_cast<double>(this->GetChunksUsed()));
  statistics.emplace_back("chunk_bytes", static_cast<double>(this->GetChunkBytes()));
  statistics.emplace_back("pool_bytes", static_cast<double>(this->GetPoolBytes()));
}
