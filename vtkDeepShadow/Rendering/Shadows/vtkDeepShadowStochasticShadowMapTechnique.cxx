#include "vtkDeepShadowStochasticShadowMapTechnique.h"
#include "vtkDeepShadowTechniqueInternals.h"

#include "ShaderComposer.h"
#include "GL/UniformSink.h"
#include "Sampling/ShadowContext.h"
#include "Core/Shadows.h"
#include "Core/Shadows/StochasticShadowMap.h"
#include "vtkDeepShadowStochasticShadowMap.h"
#include "vtkDeepShadowStochasticShadowMapBuild.h"

#include "Core/ShadowTechniques.h"
#include "vtkDeepShadowTechniqueFactory.h"
#include "vtkObjectFactory.h"
#include "vtk_glew.h"

#include <algorithm>

vtkStandardNewMacro(vtkDeepShadowStochasticShadowMapTechnique);

// The hooks with internal types: what it binds and builds with.
class vtkDeepShadowStochasticShadowMapTechnique::Hooks : public vtkDeepShadowLightSpaceTechnique::Hooks
{
public:
  explicit Hooks(vtkDeepShadowStochasticShadowMapTechnique& self)
    : vtkDeepShadowLightSpaceTechnique::Hooks(self)
    , Technique(&self)
  {
  }

  int GetLayersPerFace(const deepshadow::ShadowContext&) const override
  {
    return this->Technique->Photons;
  }

  void SetBuildUniforms(deepshadow::UniformSink& sink, const deepshadow::ShadowContext&) override
  {
    sink.Set("u_cssmSeed", static_cast<int>(this->Technique->Seed));
  }

private:
  vtkDeepShadowStochasticShadowMapTechnique* Technique;
};

vtkDeepShadowStochasticShadowMapTechnique::vtkDeepShadowStochasticShadowMapTechnique()
{
  Internals::SetHooks(this, std::make_unique<Hooks>(*this));
}

// The GPU class of the registry's Stochastic techniques (deepshadow::ShadowTechniques()).
static const bool Registered = vtkDeepShadowTechniqueFactory::Register(deepshadow::ShadowKind::Stochastic,
  []() -> vtkDeepShadowTechnique* { return vtkDeepShadowStochasticShadowMapTechnique::New(); });

void vtkDeepShadowStochasticShadowMapTechnique::SetOffsets(int offsets)
{
  this->SetAllowed("cssm-offsets", this->Offsets, offsets);
}

void vtkDeepShadowStochasticShadowMapTechnique::SetPhotons(int photons)
{
  this->SetClamped("Photons", "cssm-photons", this->Photons, photons);
}

deepshadow::ShadowParameters vtkDeepShadowStochasticShadowMapTechnique::GetParameters() const
{
  deepshadow::ShadowParameters parameters;
  this->FillParameters(parameters);
  parameters.Kind = deepshadow::ShadowKind::Stochastic;
  this->FillMapParameters(parameters);
  parameters.Offsets = this->Offsets;
  parameters.Seed = this->Seed;
  parameters.Photons = this->Photons;
  return parameters;
}

void vtkDeepShadowStochasticShadowMapTechnique::SetParameters(const deepshadow::ShadowParameters& parameters)
{
  this->Superclass::SetParameters(parameters);
  this->SetOffsets(parameters.Offsets);
  this->SetSeed(parameters.Seed);
  this->SetPhotons(parameters.Photons);
}

std::vector<std::string> vtkDeepShadowStochasticShadowMapTechnique::GetBuildFeatures() const
{
  std::vector<std::string> features = this->Superclass::GetBuildFeatures();
  features.push_back("Hash"); // the random thresholds
  return features;
}

std::vector<double> vtkDeepShadowStochasticShadowMapTechnique::GetStructureKey() const
{
  return { static_cast<double>(this->MapSize), static_cast<double>(this->Seed),
    static_cast<double>(this->Photons) };
}

std::vector<double> vtkDeepShadowStochasticShadowMapTechnique::GetLookupKey() const
{
  return { static_cast<double>(this->Offsets) };
}

unsigned int vtkDeepShadowStochasticShadowMapTechnique::GetTexelFormat() const
{
  return GL_RGBA32F;
}

std::string vtkDeepShadowStochasticShadowMapTechnique::GetBuildSource() const
{
  return vtkDeepShadowStochasticShadowMapBuild;
}

int vtkDeepShadowStochasticShadowMapTechnique::LookupLoopIterations() const
{
  return this->Offsets * (1 + this->Photons); // offsets, and photons per offset
}

std::string vtkDeepShadowStochasticShadowMapTechnique::GetMapLookupSource() const
{
  // The offsets come from Core, the CPU twin's table.
  std::vector<std::string> offsets;
  for (const glm::ivec2& offset : deepshadow::StochasticOffsets(this->Offsets))
  {
    offsets.push_back("ivec2(" + std::to_string(offset.x) + ", " + std::to_string(offset.y) + ")");
  }
  return deepshadow::GlslConstantArray("ivec2", "CSSM_OFFSET", "CSSM_OFFSETS", offsets) +
    vtkDeepShadowStochasticShadowMap;
}

void vtkDeepShadowStochasticShadowMapTechnique::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Offsets: " << this->Offsets << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
  os << indent << "Photons: " << this->Photons << "\n";
}
