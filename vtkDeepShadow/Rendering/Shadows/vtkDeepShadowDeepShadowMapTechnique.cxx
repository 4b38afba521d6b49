#include "vtkDeepShadowDeepShadowMapTechnique.h"
#include "vtkDeepShadowTechniqueInternals.h"

#include "Volume/ShadowContext.h"
#include "Core/Shadows.h"
#include "vtkDeepShadowDeepShadowMap.h"
#include "vtkDeepShadowDeepShadowMapBuild.h"

#include "vtkDeepShadowTechniqueFactory.h"
#include "vtkObjectFactory.h"
#include "vtk_glew.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

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
    return this->Technique->Layers;
  }

  void SetBuildUniforms(deepshadow::UniformSink& sink, const deepshadow::ShadowContext&) override
  {
    sink.Set("u_epsilon", static_cast<float>(this->Technique->Epsilon));
  }

private:
  vtkDeepShadowDeepShadowMapTechnique* Technique;
};

// The GPU class of the registry's DeepShadowMap techniques (deepshadow::ShadowTechniques()).
static const bool Registered = vtkDeepShadowTechniqueFactory::Register(deepshadow::ShadowKind::DeepShadowMap,
  []() -> vtkDeepShadowTechnique* { return vtkDeepShadowDeepShadowMapTechnique::New(); });

// The build's counters: a shader storage buffer the build adds to atomically, read back
// after it (DeepShadowMapBuild.glsl's DeepShadowStatistics).
class vtkDeepShadowDeepShadowMapTechnique::Statistics
{
public:
  unsigned int Buffer = 0;
  std::array<unsigned int, 5> Last{ { 0, 0, 0, 0, 0 } }; // hit, total, max, overflowed, epsilon bits

  void Release()
  {
    if (this->Buffer)
    {
      glDeleteBuffers(1, &this->Buffer);
      this->Buffer = 0;
    }
  }
};

vtkDeepShadowDeepShadowMapTechnique::vtkDeepShadowDeepShadowMapTechnique()
  : Stats(new Statistics)
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

deepshadow::ShadowParameters vtkDeepShadowDeepShadowMapTechnique::GetParameters() const
{
  deepshadow::ShadowParameters parameters;
  this->FillParameters(parameters);
  parameters.Kind = deepshadow::ShadowKind::DeepShadowMap;
  this->FillMapParameters(parameters);
  parameters.Epsilon = this->Epsilon;
  parameters.Layers = this->Layers;
  parameters.Colored = this->Colored;
  return parameters;
}

void vtkDeepShadowDeepShadowMapTechnique::SetParameters(const deepshadow::ShadowParameters& parameters)
{
  this->Superclass::SetParameters(parameters);
  this->SetEpsilon(parameters.Epsilon);
  this->SetLayers(parameters.Layers);
  this->SetColored(parameters.Colored);
}

std::vector<double> vtkDeepShadowDeepShadowMapTechnique::GetStructureKey() const
{
  return { static_cast<double>(this->MapSize), this->Epsilon, static_cast<double>(this->Layers) };
}

unsigned int vtkDeepShadowDeepShadowMapTechnique::GetTexelFormat() const
{
  return this->Colored ? GL_RGBA32F : GL_RG32F;
}

std::string vtkDeepShadowDeepShadowMapTechnique::GetBuildSource() const
{
  return vtkDeepShadowDeepShadowMapBuild;
}

int vtkDeepShadowDeepShadowMapTechnique::LookupLoopIterations() const
{
  // A binary search over the nodes in each of the four bilinear texels.
  int steps = 1;
  for (int remaining = this->Layers; remaining > 1; remaining /= 2)
  {
    ++steps;
  }
  return 4 * steps;
}

std::string vtkDeepShadowDeepShadowMapTechnique::GetMapLookupSource() const
{
  return std::string("//@Dec\nconst bool DsmColored = ") + (this->Colored ? "true" : "false") +
    ";\n" + vtkDeepShadowDeepShadowMap;
}

void vtkDeepShadowDeepShadowMapTechnique::BeginMapBuild()
{
  Statistics& stats = *this->Stats;
  if (!stats.Buffer)
  {
    glGenBuffers(1, &stats.Buffer);
  }
  const std::array<unsigned int, 5> zero{ { 0, 0, 0, 0, 0 } };
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, stats.Buffer);
  glBufferData(GL_SHADER_STORAGE_BUFFER, sizeof(zero), zero.data(), GL_DYNAMIC_READ);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, stats.Buffer);
}

void vtkDeepShadowDeepShadowMapTechnique::EndMapBuild()
{
  Statistics& stats = *this->Stats;
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, stats.Buffer);
  glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(stats.Last), stats.Last.data());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, 0);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
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
}

void vtkDeepShadowDeepShadowMapTechnique::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Epsilon: " << this->Epsilon << "\n";
  os << indent << "Layers: " << this->Layers << "\n";
  os << indent << "Colored: " << this->Colored << "\n";
  os << indent << "Nodes (last build): " << this->GetNodesAverage() << " average, "
     << this->GetNodesMax() << " maximum, " << this->GetTexelsOverflowed() << " texels overflowed\n";
}
