#include "vtkDeepShadowFixedBudgetDeepShadowMapTechnique.h"
#include "vtkDeepShadowTechniqueInternals.h"

#include "Core/ShadowTechniques.h"
#include "Core/Shadows/FixedBudgetDeepShadowMap.h"
#include "vtkDeepShadowFixedBudgetDeepShadowMap.h"
#include "vtkDeepShadowFixedBudgetDeepShadowMapBuild.h"
#include "vtkDeepShadowTechniqueFactory.h"

#include "vtkObjectFactory.h"
#include "vtk_glew.h"

#include <cstring>

vtkStandardNewMacro(vtkDeepShadowFixedBudgetDeepShadowMapTechnique);

// The hooks with internal types: its layers per face.
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

private:
  vtkDeepShadowFixedBudgetDeepShadowMapTechnique* Technique;
};

vtkDeepShadowFixedBudgetDeepShadowMapTechnique::vtkDeepShadowFixedBudgetDeepShadowMapTechnique()
{
  Internals::SetHooks(this, std::make_unique<Hooks>(*this));
}

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

deepshadow::ShadowParameters vtkDeepShadowFixedBudgetDeepShadowMapTechnique::GetParameters() const
{
  deepshadow::ShadowParameters parameters;
  this->FillParameters(parameters);
  parameters.Kind = deepshadow::FixedBudgetKind;
  this->FillMapParameters(parameters);
  deepshadow::FindShadowParameter("dsm-bits")->Set(parameters, { static_cast<double>(this->Bits) });
  return parameters;
}

void vtkDeepShadowFixedBudgetDeepShadowMapTechnique::SetParameters(const deepshadow::ShadowParameters& parameters)
{
  this->Superclass::SetParameters(parameters);
  this->SetBits(deepshadow::FixedBudgetBits(parameters));
}

std::vector<double> vtkDeepShadowFixedBudgetDeepShadowMapTechnique::GetStructureKey() const
{
  return { static_cast<double>(this->MapSize), static_cast<double>(this->Bits) };
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
  return this->NodesDefine() + "#define FIXED_BOUND_LOG2_MIN " + std::to_string(deepshadow::FixedBoundLog2Min) +
    "\n#define FIXED_BISECTION_STEPS " + std::to_string(deepshadow::FixedBisectionSteps) + "\n" +
    vtkDeepShadowFixedBudgetDeepShadowMapBuild;
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

void vtkDeepShadowFixedBudgetDeepShadowMapTechnique::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Bits: " << this->Bits << "\n";
}
