#include "vtkDeepShadowFourierOpacityMapTechnique.h"
#include "vtkDeepShadowTechniqueInternals.h"

#include "Core/ShadowTechniques.h"
#include "Core/Shadows/FourierOpacityMap.h"
#include "Sampling/ShadowContext.h"
#include "vtkDeepShadowFourierOpacityMap.h"
#include "vtkDeepShadowFourierOpacityMapBuild.h"
#include "vtkDeepShadowSeriesEnd.h"
#include "vtkDeepShadowSurfaceSteps.h"
#include "vtkDeepShadowSurfaceStepsBuild.h"
#include "vtkDeepShadowTechniqueFactory.h"

#include "vtkObjectFactory.h"
#include "vtk_glew.h"

vtkStandardNewMacro(vtkDeepShadowFourierOpacityMapTechnique);

// The hooks with internal types: its layers per face.
class vtkDeepShadowFourierOpacityMapTechnique::Hooks : public vtkDeepShadowLightSpaceTechnique::Hooks
{
public:
  explicit Hooks(vtkDeepShadowFourierOpacityMapTechnique& self)
    : vtkDeepShadowLightSpaceTechnique::Hooks(self)
    , Technique(&self)
  {
  }

  /** The series, and with casting meshes their steps in one more layer. */
  int GetLayersPerFace(const deepshadow::ShadowContext& context) const override
  {
    return deepshadow::FourierLayers(this->Technique->Terms) + (context.Surfaces ? 1 : 0);
  }

private:
  vtkDeepShadowFourierOpacityMapTechnique* Technique;
};

vtkDeepShadowFourierOpacityMapTechnique::vtkDeepShadowFourierOpacityMapTechnique()
{
  Internals::SetHooks(this, std::make_unique<Hooks>(*this));
}

// The GPU class of the registry's "fom" (deepshadow::ShadowTechniques()).
static const bool Registered = vtkDeepShadowTechniqueFactory::Register(deepshadow::FourierOpacityKind,
  []() -> vtkDeepShadowTechnique* { return vtkDeepShadowFourierOpacityMapTechnique::New(); });

void vtkDeepShadowFourierOpacityMapTechnique::SetTerms(int terms)
{
  const std::string problem = deepshadow::FindShadowParameter("fom-terms")->Check({ static_cast<double>(terms) });
  if (!problem.empty())
  {
    vtkErrorMacro(<< problem << "; got " << terms);
    return;
  }
  if (terms != this->Terms)
  {
    this->Terms = terms;
    this->Modified();
  }
}

deepshadow::ShadowParameters vtkDeepShadowFourierOpacityMapTechnique::GetParameters() const
{
  deepshadow::ShadowParameters parameters;
  this->FillParameters(parameters);
  parameters.Kind = deepshadow::FourierOpacityKind;
  this->FillMapParameters(parameters);
  deepshadow::FindShadowParameter("fom-terms")->Set(parameters, { static_cast<double>(this->Terms) });
  return parameters;
}

void vtkDeepShadowFourierOpacityMapTechnique::SetParameters(const deepshadow::ShadowParameters& parameters)
{
  this->Superclass::SetParameters(parameters);
  this->SetTerms(deepshadow::FourierTerms(parameters));
}

std::vector<double> vtkDeepShadowFourierOpacityMapTechnique::GetStructureKey() const
{
  return { static_cast<double>(this->MapSize), static_cast<double>(this->Terms) };
}

unsigned int vtkDeepShadowFourierOpacityMapTechnique::GetTexelFormat() const
{
  return GL_RGBA32F;
}

std::string vtkDeepShadowFourierOpacityMapTechnique::GetBuildSource() const
{
  return "//@Dec\n#define FOM_LAYERS " + std::to_string(deepshadow::FourierLayers(this->Terms)) + "\n" +
    vtkDeepShadowSurfaceStepsBuild + vtkDeepShadowSeriesEnd + vtkDeepShadowFourierOpacityMapBuild;
}

std::string vtkDeepShadowFourierOpacityMapTechnique::GetMapLookupSource() const
{
  return "//@Dec\n#define FOM_LAYERS " + std::to_string(deepshadow::FourierLayers(this->Terms)) + "\n" +
    vtkDeepShadowSurfaceSteps + vtkDeepShadowSeriesEnd + vtkDeepShadowFourierOpacityMap;
}

void vtkDeepShadowFourierOpacityMapTechnique::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Terms: " << this->Terms << "\n";
}
