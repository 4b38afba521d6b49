#include "vtkDeepShadowRayTechnique.h"
#include "vtkDeepShadowTechniqueInternals.h"

#include "GL/UniformSink.h"
#include "Sampling/ShadowContext.h"
#include "Core/Shadows.h"
#include "vtkDeepShadowRayShadow.h"

#include "vtkDeepShadowTechniqueFactory.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkDeepShadowRayTechnique);

// The hooks with internal types: what it binds and builds with.
class vtkDeepShadowRayTechnique::Hooks : public vtkDeepShadowTechnique::Hooks
{
public:
  explicit Hooks(vtkDeepShadowRayTechnique& self)
    : Technique(&self)
  {
  }

  void BindLookup(deepshadow::UniformSink& sink, const deepshadow::ShadowContext&) override
  {
    sink.Set("u_shadowOpaque", this->Technique->Opaque ? 1 : 0);
  }

private:
  vtkDeepShadowRayTechnique* Technique;
};

vtkDeepShadowRayTechnique::vtkDeepShadowRayTechnique()
{
  Internals::SetHooks(this, std::make_unique<Hooks>(*this));
}

// The GPU class of the registry's Rays techniques (deepshadow::ShadowTechniques()).
static const bool Registered = vtkDeepShadowTechniqueFactory::Register(deepshadow::ShadowKind::Rays,
  []() -> vtkDeepShadowTechnique* { return vtkDeepShadowRayTechnique::New(); });

deepshadow::ShadowParameters vtkDeepShadowRayTechnique::GetParameters() const
{
  deepshadow::ShadowParameters parameters;
  this->FillParameters(parameters);
  parameters.Kind = deepshadow::ShadowKind::Rays;
  parameters.Opaque = this->Opaque;
  parameters.Colored = this->Colored && !this->Opaque;
  parameters.EarlyTermination = this->EarlyTermination;
  return parameters;
}

void vtkDeepShadowRayTechnique::SetParameters(const deepshadow::ShadowParameters& parameters)
{
  this->Superclass::SetParameters(parameters);
  this->SetOpaque(parameters.Opaque);
  this->SetColored(parameters.Colored);
  this->SetEarlyTermination(parameters.EarlyTermination);
}

std::vector<double> vtkDeepShadowRayTechnique::GetStructureKey() const
{
  return { this->Opaque ? 1.0 : 0.0, this->EarlyTermination ? 1.0 : 0.0 };
}

std::string vtkDeepShadowRayTechnique::GetLookupSource() const
{
  return vtkDeepShadowRayShadow;
}

void vtkDeepShadowRayTechnique::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Opaque: " << this->Opaque << "\n";
  os << indent << "Colored: " << this->Colored << "\n";
  os << indent << "EarlyTermination: " << this->EarlyTermination << "\n";
}
