#include "vtkDeepShadowAdaptiveVolumetricShadowMapTechnique.h"
#include "vtkDeepShadowTechniqueInternals.h"

#include "Core/ShadowTechniques.h"
#include "Core/Shadows/AdaptiveVolumetricShadowMap.h"
#include "Sampling/ShadowContext.h"
#include "vtkDeepShadowAdaptiveVolumetricShadowMap.h"
#include "vtkDeepShadowAdaptiveVolumetricShadowMapBuild.h"
#include "vtkDeepShadowSurfaceSteps.h"
#include "vtkDeepShadowSurfaceStepsBuild.h"
#include "vtkDeepShadowTechniqueFactory.h"

#include "vtkObjectFactory.h"
#include "vtk_glew.h"

vtkStandardNewMacro(vtkDeepShadowAdaptiveVolumetricShadowMapTechnique);

// The hooks with internal types: its layers per face.
class vtkDeepShadowAdaptiveVolumetricShadowMapTechnique::Hooks : public vtkDeepShadowLightSpaceTechnique::Hooks
{
public:
  explicit Hooks(vtkDeepShadowAdaptiveVolumetricShadowMapTechnique& self)
    : vtkDeepShadowLightSpaceTechnique::Hooks(self)
    , Technique(&self)
  {
  }

  /** Two nodes a layer, and with casting meshes their steps in one more layer. */
  int GetLayersPerFace(const deepshadow::ShadowContext& context) const override
  {
    return this->Technique->Nodes / 2 + (context.Surfaces ? 1 : 0);
  }

private:
  vtkDeepShadowAdaptiveVolumetricShadowMapTechnique* Technique;
};

vtkDeepShadowAdaptiveVolumetricShadowMapTechnique::vtkDeepShadowAdaptiveVolumetricShadowMapTechnique()
{
  Internals::SetHooks(this, std::make_unique<Hooks>(*this));
}

// The GPU class of the registry's "avsm" (deepshadow::ShadowTechniques()).
static const bool Registered = vtkDeepShadowTechniqueFactory::Register(deepshadow::AdaptiveVolumetricKind,
  []() -> vtkDeepShadowTechnique* { return vtkDeepShadowAdaptiveVolumetricShadowMapTechnique::New(); });

void vtkDeepShadowAdaptiveVolumetricShadowMapTechnique::SetNodes(int nodes)
{
  const std::string problem = deepshadow::FindShadowParameter("avsm-nodes")->Check({ static_cast<double>(nodes) });
  if (!problem.empty())
  {
    vtkErrorMacro(<< problem << "; got " << nodes);
    return;
  }
  if (nodes != this->Nodes)
  {
    this->Nodes = nodes;
    this->Modified();
  }
}

deepshadow::ShadowParameters vtkDeepShadowAdaptiveVolumetricShadowMapTechnique::GetParameters() const
{
  deepshadow::ShadowParameters parameters;
  this->FillParameters(parameters);
  parameters.Kind = deepshadow::AdaptiveVolumetricKind;
  this->FillMapParameters(parameters);
  deepshadow::FindShadowParameter("avsm-nodes")->Set(parameters, { static_cast<double>(this->Nodes) });
  return parameters;
}

void vtkDeepShadowAdaptiveVolumetricShadowMapTechnique::SetParameters(const deepshadow::ShadowParameters& parameters)
{
  this->Superclass::SetParameters(parameters);
  this->SetNodes(deepshadow::AdaptiveNodes(parameters));
}

std::vector<double> vtkDeepShadowAdaptiveVolumetricShadowMapTechnique::GetStructureKey() const
{
  return { static_cast<double>(this->MapSize), static_cast<double>(this->Nodes) };
}

unsigned int vtkDeepShadowAdaptiveVolumetricShadowMapTechnique::GetTexelFormat() const
{
  return GL_RGBA32F;
}

std::string vtkDeepShadowAdaptiveVolumetricShadowMapTechnique::GetBuildSource() const
{
  return "//@Dec\n#define AVSM_NODES " + std::to_string(this->Nodes) + "\n" + vtkDeepShadowSurfaceStepsBuild +
    vtkDeepShadowAdaptiveVolumetricShadowMapBuild;
}

std::string vtkDeepShadowAdaptiveVolumetricShadowMapTechnique::GetMapLookupSource() const
{
  return "//@Dec\n#define AVSM_NODES " + std::to_string(this->Nodes) + "\n" + vtkDeepShadowSurfaceSteps +
    vtkDeepShadowAdaptiveVolumetricShadowMap;
}

void vtkDeepShadowAdaptiveVolumetricShadowMapTechnique::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Nodes: " << this->Nodes << "\n";
}
