#include "vtkDeepShadowShadowMapTechnique.h"
#include "vtkDeepShadowTechniqueInternals.h"

#include "ShaderComposer.h"
#include "GL/UniformSink.h"
#include "Sampling/ShadowContext.h"
#include "Core/Shadows/ShadowMap.h"
#include "vtkDeepShadowShadowMap.h"
#include "vtkDeepShadowShadowMapBuild.h"

#include "vtkDeepShadowTechniqueFactory.h"
#include "vtkObjectFactory.h"
#include "vtk_glew.h"

#include <algorithm>

vtkStandardNewMacro(vtkDeepShadowShadowMapTechnique);

// The hooks with internal types: what it binds and builds with.
class vtkDeepShadowShadowMapTechnique::Hooks : public vtkDeepShadowLightSpaceTechnique::Hooks
{
public:
  explicit Hooks(vtkDeepShadowShadowMapTechnique& self)
    : vtkDeepShadowLightSpaceTechnique::Hooks(self)
    , Technique(&self)
  {
  }

  void SetMapLookupUniforms(
    deepshadow::UniformSink& sink, const deepshadow::ShadowContext& context) override
  {
    const double step = Internals::FeelerStep(this->Technique, context);
    sink.Set("u_shadowBias", static_cast<float>(this->Technique->Bias * step));
  }

private:
  vtkDeepShadowShadowMapTechnique* Technique;
};

vtkDeepShadowShadowMapTechnique::vtkDeepShadowShadowMapTechnique()
{
  Internals::SetHooks(this, std::make_unique<Hooks>(*this));
}

// The GPU class of the registry's ShadowMap techniques (deepshadow::ShadowTechniques()).
static const bool Registered = vtkDeepShadowTechniqueFactory::Register(deepshadow::ShadowKind::ShadowMap,
  []() -> vtkDeepShadowTechnique* { return vtkDeepShadowShadowMapTechnique::New(); });

void vtkDeepShadowShadowMapTechnique::SetBias(double bias)
{
  this->SetClamped("Bias", "bias", this->Bias, bias);
}

deepshadow::ShadowParameters vtkDeepShadowShadowMapTechnique::GetParameters() const
{
  deepshadow::ShadowParameters parameters;
  this->FillParameters(parameters);
  parameters.Kind = deepshadow::ShadowKind::ShadowMap;
  this->FillMapParameters(parameters);
  parameters.Bias = this->Bias;
  parameters.Filter = static_cast<deepshadow::ShadowFilter>(this->Filter);
  return parameters;
}

void vtkDeepShadowShadowMapTechnique::SetParameters(const deepshadow::ShadowParameters& parameters)
{
  this->Superclass::SetParameters(parameters);
  this->SetBias(parameters.Bias);
  this->SetFilter(static_cast<int>(parameters.Filter));
}

std::vector<double> vtkDeepShadowShadowMapTechnique::GetStructureKey() const
{
  // Bias and filter apply at lookup: they change no map.
  return { static_cast<double>(this->MapSize) };
}

std::vector<double> vtkDeepShadowShadowMapTechnique::GetLookupKey() const
{
  return { this->Bias, static_cast<double>(this->Filter) };
}

unsigned int vtkDeepShadowShadowMapTechnique::GetTexelFormat() const
{
  return GL_R32F;
}

std::string vtkDeepShadowShadowMapTechnique::GetBuildSource() const
{
  return vtkDeepShadowShadowMapBuild;
}

int vtkDeepShadowShadowMapTechnique::LookupLoopIterations() const
{
  // 3x3: three rows of three (Shadows/ShadowMap.glsl); Poisson: one loop over its taps.
  return this->Filter == PCF3x3 ? 12 : this->Filter == PoissonDisc ? static_cast<int>(deepshadow::PoissonDisc().size()) : 0;
}

std::string vtkDeepShadowShadowMapTechnique::GetFilterSource(int filter, bool pages)
{
  // The filter and the Poisson disc come from Core, the CPU twin's tables.
  std::vector<std::string> disc;
  for (const glm::dvec2& tap : deepshadow::PoissonDisc())
  {
    disc.push_back("vec2(" + std::to_string(tap.x) + ", " + std::to_string(tap.y) + ")");
  }
  return "//@Dec\n#define SHADOW_FILTER " + std::to_string(filter) + "\n" +
    (pages ? "#define SHADOW_MAP_PAGES\n" : "") +
    deepshadow::GlslConstantArray("vec2", "POISSON_DISC", "POISSON_TAPS", disc) + vtkDeepShadowShadowMap;
}

std::string vtkDeepShadowShadowMapTechnique::GetMapLookupSource() const
{
  return GetFilterSource(this->Filter);
}

void vtkDeepShadowShadowMapTechnique::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Bias: " << this->Bias << " feeler steps\n";
  os << indent << "Filter: " << this->Filter << "\n";
}
