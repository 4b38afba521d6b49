#include "vtkDeepShadowPowerMomentMapTechnique.h"
#include "vtkDeepShadowTechniqueInternals.h"

#include "Core/ShadowTechniques.h"
#include "Core/Shadows/PowerMomentMap.h"
#include "Sampling/ShadowContext.h"
#include "vtkDeepShadowPowerMomentMap.h"
#include "vtkDeepShadowPowerMomentMapBuild.h"
#include "vtkDeepShadowSeriesEnd.h"
#include "vtkDeepShadowSurfaceSteps.h"
#include "vtkDeepShadowSurfaceStepsBuild.h"
#include "vtkDeepShadowTechniqueFactory.h"

#include "vtkObjectFactory.h"
#include "vtk_glew.h"

#include <sstream>

vtkStandardNewMacro(vtkDeepShadowPowerMomentMapTechnique);

// The hooks with internal types: its layers per face.
class vtkDeepShadowPowerMomentMapTechnique::Hooks : public vtkDeepShadowLightSpaceTechnique::Hooks
{
public:
  explicit Hooks(vtkDeepShadowPowerMomentMapTechnique& self)
    : vtkDeepShadowLightSpaceTechnique::Hooks(self)
    , Technique(&self)
  {
  }

  /** The moments, and with casting meshes their steps in one more layer. */
  int GetLayersPerFace(const deepshadow::ShadowContext& context) const override
  {
    return deepshadow::PowerMomentLayers(this->Technique->Moments) + (context.Surfaces ? 1 : 0);
  }

private:
  vtkDeepShadowPowerMomentMapTechnique* Technique;
};

vtkDeepShadowPowerMomentMapTechnique::vtkDeepShadowPowerMomentMapTechnique()
{
  Internals::SetHooks(this, std::make_unique<Hooks>(*this));
}

// The GPU class of the registry's "moments" (deepshadow::ShadowTechniques()).
static const bool Registered = vtkDeepShadowTechniqueFactory::Register(deepshadow::PowerMomentKind,
  []() -> vtkDeepShadowTechnique* { return vtkDeepShadowPowerMomentMapTechnique::New(); });

void vtkDeepShadowPowerMomentMapTechnique::SetMoments(int moments)
{
  const std::string problem = deepshadow::FindShadowParameter("moments")->Check({ static_cast<double>(moments) });
  if (!problem.empty())
  {
    vtkErrorMacro(<< problem << "; got " << moments);
    return;
  }
  if (moments != this->Moments)
  {
    this->Moments = moments;
    this->Modified();
  }
}

deepshadow::ShadowParameters vtkDeepShadowPowerMomentMapTechnique::GetParameters() const
{
  deepshadow::ShadowParameters parameters;
  this->FillParameters(parameters);
  parameters.Kind = deepshadow::PowerMomentKind;
  this->FillMapParameters(parameters);
  deepshadow::FindShadowParameter("moments")->Set(parameters, { static_cast<double>(this->Moments) });
  return parameters;
}

void vtkDeepShadowPowerMomentMapTechnique::SetParameters(const deepshadow::ShadowParameters& parameters)
{
  this->Superclass::SetParameters(parameters);
  this->SetMoments(deepshadow::PowerMomentCount(parameters));
}

std::vector<double> vtkDeepShadowPowerMomentMapTechnique::GetStructureKey() const
{
  return { static_cast<double>(this->MapSize), static_cast<double>(this->Moments) };
}

unsigned int vtkDeepShadowPowerMomentMapTechnique::GetTexelFormat() const
{
  return GL_RGBA32F;
}

std::string vtkDeepShadowPowerMomentMapTechnique::GetDefines() const
{
  // The bias and the overestimation as the CPU twin's, to the last digit.
  std::ostringstream defines;
  defines.precision(9);
  defines << std::scientific << "//@Dec\n#define POWER_MOMENTS " << this->Moments << "\n#define MOMENTS_LAYERS "
          << deepshadow::PowerMomentLayers(this->Moments) << "\n#define MOMENTS_BIAS "
          << deepshadow::PowerMomentBias(this->Moments) << "\n#define MOMENTS_OVERESTIMATION "
          << deepshadow::PowerMomentOverestimation << "\n";
  return defines.str();
}

std::string vtkDeepShadowPowerMomentMapTechnique::GetBuildSource() const
{
  return this->GetDefines() + vtkDeepShadowSurfaceStepsBuild + vtkDeepShadowSeriesEnd + vtkDeepShadowPowerMomentMapBuild;
}

std::string vtkDeepShadowPowerMomentMapTechnique::GetMapLookupSource() const
{
  return this->GetDefines() + vtkDeepShadowSurfaceSteps + vtkDeepShadowSeriesEnd + vtkDeepShadowPowerMomentMap;
}

void vtkDeepShadowPowerMomentMapTechnique::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Moments: " << this->Moments << "\n";
}
