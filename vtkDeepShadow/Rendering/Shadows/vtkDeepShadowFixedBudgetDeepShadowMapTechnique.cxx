#include "vtkDeepShadowFixedBudgetDeepShadowMapTechnique.h"
#include "vtkDeepShadowTechniqueInternals.h"

#include "Core/ShadowTechniques.h"
#include "GL/UniformSink.h"
#include "Core/Shadows/FixedBudgetDeepShadowMap.h"
#include "vtkDeepShadowFixedBudgetDeepShadowMap.h"
#include "vtkDeepShadowFixedBudgetDeepShadowMapBuild.h"
#include "vtkDeepShadowTechniqueFactory.h"

#include "vtkObjectFactory.h"
#include "vtk_glew.h"

#include <cstring>
#include <set>

vtkStandardNewMacro(vtkDeepShadowFixedBudgetDeepShadowMapTechnique);

namespace
{
// Bins of the node counts: 0 to MaxFixedNodes nodes, and one for more.
constexpr int CountBins = deepshadow::MaxFixedNodes + 2;
}

// With an error: the counts the build adds to (FixedBudgetDeepShadowMapBuild.glsl's
// FixedNodeCounts, a slot's bins after another's), the last ones read per slot, and the nodes
// they ask for (0 before the first build: the budget's).
class vtkDeepShadowFixedBudgetDeepShadowMapTechnique::Counts
{
public:
  unsigned int Buffer = 0;
  std::vector<std::vector<long long>> PerSlot;
  int Nodes = 0;
  double Beyond = 0.0; // share of the counted texels that need more than Nodes

  void Release()
  {
    if (this->Buffer)
    {
      glDeleteBuffers(1, &this->Buffer);
      this->Buffer = 0;
    }
  }
};

// The hooks with internal types: its layers per face, the count's uniforms and reading.
class vtkDeepShadowFixedBudgetDeepShadowMapTechnique::Hooks : public vtkDeepShadowLightSpaceTechnique::Hooks
{
public:
  explicit Hooks(vtkDeepShadowFixedBudgetDeepShadowMapTechnique& self)
    : vtkDeepShadowLightSpaceTechnique::Hooks(self)
    , Technique(&self)
  {
  }

  /** Two nodes a layer (RGBA16). */
  int GetLayersPerFace(const deepshadow::ShadowContext&) const override { return this->Technique->GetNodes() / 2; }

  void SetBuildUniforms(deepshadow::UniformSink& sink, const deepshadow::ShadowContext&) override
  {
    if (this->Technique->Error > 0.0)
    {
      sink.Set("u_countBound", static_cast<float>(this->Technique->Error));
    }
  }

  void SetSlotBuildUniforms(deepshadow::UniformSink& sink, int slot) override
  {
    if (this->Technique->Error > 0.0)
    {
      sink.Set("u_countSlot", slot);
    }
  }

  /** With an error: the nodes the slots' texels ask for now (all slots' last counts). */
  std::vector<int> AfterBuild(const std::vector<int>& built, int slotCount) override
  {
    vtkDeepShadowFixedBudgetDeepShadowMapTechnique* self = this->Technique;
    Counts& counts = *self->NodeCounts;
    if (self->Error <= 0.0)
    {
      return {};
    }
    std::vector<GLuint> read(static_cast<size_t>(slotCount) * CountBins, 0);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, counts.Buffer);
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(read.size() * sizeof(GLuint)), read.data());
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    counts.PerSlot.resize(static_cast<size_t>(slotCount), std::vector<long long>(CountBins, 0));
    for (int slot : built)
    {
      for (int bin = 0; bin < CountBins; ++bin)
      {
        counts.PerSlot[static_cast<size_t>(slot)][static_cast<size_t>(bin)] = read[static_cast<size_t>(slot * CountBins + bin)];
      }
    }
    std::vector<long long> total(CountBins, 0);
    for (int slot = 0; slot < slotCount; ++slot)
    {
      for (int bin = 0; bin < CountBins; ++bin)
      {
        total[static_cast<size_t>(bin)] += counts.PerSlot[static_cast<size_t>(slot)][static_cast<size_t>(bin)];
      }
    }
    const int nodes = deepshadow::FixedNodesForError(total);
    long long all = 0, beyond = 0;
    for (int bin = 0; bin < CountBins; ++bin)
    {
      all += total[static_cast<size_t>(bin)];
      beyond += bin > nodes ? total[static_cast<size_t>(bin)] : 0;
    }
    counts.Beyond = all > 0 ? static_cast<double>(beyond) / static_cast<double>(all) : 0.0;
    if (nodes == self->GetNodes())
    {
      return {};
    }
    // Other layers per face: the base lays the maps out again and builds every slot.
    counts.Nodes = nodes;
    return built;
  }

private:
  vtkDeepShadowFixedBudgetDeepShadowMapTechnique* Technique;
};

vtkDeepShadowFixedBudgetDeepShadowMapTechnique::vtkDeepShadowFixedBudgetDeepShadowMapTechnique()
  : NodeCounts(new Counts)
{
  Internals::SetHooks(this, std::make_unique<Hooks>(*this));
}

vtkDeepShadowFixedBudgetDeepShadowMapTechnique::~vtkDeepShadowFixedBudgetDeepShadowMapTechnique() = default;

// The GPU class of the registry's "dsm-fixed" (deepshadow::ShadowTechniques()).
static const bool Registered = vtkDeepShadowTechniqueFactory::Register(deepshadow::FixedBudgetKind,
  []() -> vtkDeepShadowTechnique* { return vtkDeepShadowFixedBudgetDeepShadowMapTechnique::New(); });

void vtkDeepShadowFixedBudgetDeepShadowMapTechnique::SetBits(int bits)
{
  const std::string problem = deepshadow::FindShadowParameter("dsm-bits")->Check({ static_cast<double>(bits) });
  if (!problem.empty())
  {
    vtkErrorMacro(<< problem << "; got " << bits);
    return;
  }
  if (bits != this->Bits)
  {
    this->Bits = bits;
    this->Modified();
  }
}

void vtkDeepShadowFixedBudgetDeepShadowMapTechnique::SetError(double error)
{
  const std::string problem = deepshadow::FindShadowParameter("dsm-fixed-error")->Check({ error });
  if (!problem.empty())
  {
    vtkErrorMacro(<< problem << "; got " << error);
    return;
  }
  if (error != this->Error)
  {
    this->Error = error;
    this->NodeCounts->Nodes = 0;
    this->NodeCounts->PerSlot.clear();
    this->Modified();
  }
}

int vtkDeepShadowFixedBudgetDeepShadowMapTechnique::GetNodes() const
{
  return this->Error > 0.0 && this->NodeCounts->Nodes > 0 ? this->NodeCounts->Nodes : this->Bits / 32;
}

deepshadow::ShadowParameters vtkDeepShadowFixedBudgetDeepShadowMapTechnique::GetParameters() const
{
  deepshadow::ShadowParameters parameters;
  this->FillParameters(parameters);
  parameters.Kind = deepshadow::FixedBudgetKind;
  this->FillMapParameters(parameters);
  deepshadow::FindShadowParameter("dsm-bits")->Set(parameters, { static_cast<double>(this->Bits) });
  deepshadow::FindShadowParameter("dsm-fixed-error")->Set(parameters, { this->Error });
  return parameters;
}

void vtkDeepShadowFixedBudgetDeepShadowMapTechnique::SetParameters(const deepshadow::ShadowParameters& parameters)
{
  this->Superclass::SetParameters(parameters);
  this->SetBits(deepshadow::FixedBudgetBits(parameters));
  this->SetError(deepshadow::FixedBudgetError(parameters));
}

std::vector<double> vtkDeepShadowFixedBudgetDeepShadowMapTechnique::GetStructureKey() const
{
  // With an error the nodes follow from the build; the error is what the structure depends on.
  return { static_cast<double>(this->MapSize), this->Error > 0.0 ? 0.0 : static_cast<double>(this->Bits), this->Error };
}

unsigned int vtkDeepShadowFixedBudgetDeepShadowMapTechnique::GetTexelFormat() const
{
  return GL_RGBA16;
}

std::string vtkDeepShadowFixedBudgetDeepShadowMapTechnique::NodesDefine() const
{
  return "//@Dec\n#define FIXED_NODES " + std::to_string(this->GetNodes()) + "\n";
}

std::string vtkDeepShadowFixedBudgetDeepShadowMapTechnique::GetBuildSource() const
{
  const std::string count = this->Error > 0.0 ? "#define FIXED_COUNT_BINS " + std::to_string(CountBins) + "\n" : "";
  return this->NodesDefine() + count + "#define FIXED_BOUND_LOG2_MIN " + std::to_string(deepshadow::FixedBoundLog2Min) +
    "\n#define FIXED_BISECTION_STEPS " + std::to_string(deepshadow::FixedBisectionSteps) + "\n" +
    vtkDeepShadowFixedBudgetDeepShadowMapBuild;
}

void vtkDeepShadowFixedBudgetDeepShadowMapTechnique::BeginMapBuild()
{
  if (this->Error <= 0.0)
  {
    return;
  }
  // Room for every slot's bins, zeroed.
  Counts& counts = *this->NodeCounts;
  if (!counts.Buffer)
  {
    glGenBuffers(1, &counts.Buffer);
  }
  const std::vector<GLuint> zero(static_cast<size_t>(this->GetMaxShadowLights()) * CountBins, 0);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, counts.Buffer);
  glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(zero.size() * sizeof(GLuint)), zero.data(), GL_DYNAMIC_READ);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, counts.Buffer);
}

void vtkDeepShadowFixedBudgetDeepShadowMapTechnique::EndMapBuild()
{
  if (this->Error > 0.0)
  {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, 0);
  }
}

std::string vtkDeepShadowFixedBudgetDeepShadowMapTechnique::GetMapLookupSource() const
{
  // A CPU rasterizer pays per fetch and a GPU for fetches that wait on each other: the loop
  // stops early on the first only (the lookup's comment has the figures).
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const bool software = renderer && (std::strstr(renderer, "llvmpipe") || std::strstr(renderer, "softpipe"));
  return this->NodesDefine() + (software ? "#define FIXED_LOOKUP_STOPS\n" : "") +
    vtkDeepShadowFixedBudgetDeepShadowMap;
}

void vtkDeepShadowFixedBudgetDeepShadowMapTechnique::AddStatistics(Statistics& statistics) const
{
  this->Superclass::AddStatistics(statistics);
  statistics.emplace_back("fixed_nodes", this->GetNodes());
  statistics.emplace_back("texel_bits", 32.0 * this->GetNodes()); // as built (the bench charts it)
  if (this->Error > 0.0)
  {
    statistics.emplace_back("fixed_nodes_beyond", this->NodeCounts->Beyond);
  }
}

void vtkDeepShadowFixedBudgetDeepShadowMapTechnique::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Superclass::ReleaseGraphicsResources(window);
  this->NodeCounts->Release();
}

void vtkDeepShadowFixedBudgetDeepShadowMapTechnique::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Bits: " << this->Bits << "\n";
  os << indent << "Error: " << this->Error << " (nodes " << this->GetNodes() << ")\n";
}
