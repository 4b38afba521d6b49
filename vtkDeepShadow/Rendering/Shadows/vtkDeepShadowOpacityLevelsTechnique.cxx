#include "vtkDeepShadowOpacityLevelsTechnique.h"
#include "vtkDeepShadowTechniqueInternals.h"

#include "GL/UniformSink.h"
#include "Sampling/ShadowContext.h"
#include "Core/Shadows.h"
#include "vtkDeepShadowOpacityLevels.h"
#include "vtkDeepShadowOpacityLevelsBuild.h"
#include "vtkDeepShadowSurfaceSteps.h"
#include "vtkDeepShadowSurfaceStepsBuild.h"

#include "Core/ShadowTechniques.h"
#include "vtkDeepShadowTechniqueFactory.h"
#include "vtkObjectFactory.h"
#include "vtk_glew.h"

vtkStandardNewMacro(vtkDeepShadowOpacityLevelsTechnique);

// The hooks with internal types: what it binds and builds with.
class vtkDeepShadowOpacityLevelsTechnique::Hooks : public vtkDeepShadowLightSpaceTechnique::Hooks
{
public:
  explicit Hooks(vtkDeepShadowOpacityLevelsTechnique& self)
    : vtkDeepShadowLightSpaceTechnique::Hooks(self)
    , Technique(&self)
  {
  }

  /** The levels, and with casting meshes their steps in a second texel. */
  int GetLayersPerFace(const deepshadow::ShadowContext& context) const override
  {
    return context.Surfaces ? 2 : 1;
  }

  void SetBuildUniforms(deepshadow::UniformSink& sink, const deepshadow::ShadowContext&) override
  {
    const double* levels = this->Technique->Levels;
    sink.Set("u_levels", glm::vec3(levels[0], levels[1], levels[2]));
  }

  void SetMapLookupUniforms(
    deepshadow::UniformSink& sink, const deepshadow::ShadowContext& context) override
  {
    this->SetBuildUniforms(sink, context);
  }

private:
  vtkDeepShadowOpacityLevelsTechnique* Technique;
};

vtkDeepShadowOpacityLevelsTechnique::vtkDeepShadowOpacityLevelsTechnique()
{
  Internals::SetHooks(this, std::make_unique<Hooks>(*this));
}

// The GPU class of the registry's OpacityLevels techniques (deepshadow::ShadowTechniques()).
static const bool Registered = vtkDeepShadowTechniqueFactory::Register(deepshadow::ShadowKind::OpacityLevels,
  []() -> vtkDeepShadowTechnique* { return vtkDeepShadowOpacityLevelsTechnique::New(); });

void vtkDeepShadowOpacityLevelsTechnique::SetLevels(double first, double second, double third)
{
  const std::string problem =
    deepshadow::FindShadowParameter("opacity-levels")->Check({ first, second, third });
  if (!problem.empty())
  {
    vtkErrorMacro(<< problem << "; got " << first << ", " << second << ", " << third);
    return;
  }
  if (first != this->Levels[0] || second != this->Levels[1] || third != this->Levels[2])
  {
    this->Levels[0] = first;
    this->Levels[1] = second;
    this->Levels[2] = third;
    this->Modified();
  }
}

deepshadow::ShadowParameters vtkDeepShadowOpacityLevelsTechnique::GetParameters() const
{
  deepshadow::ShadowParameters parameters;
  this->FillParameters(parameters);
  parameters.Kind = deepshadow::ShadowKind::OpacityLevels;
  this->FillMapParameters(parameters);
  parameters.Levels = { { this->Levels[0], this->Levels[1], this->Levels[2] } };
  return parameters;
}

void vtkDeepShadowOpacityLevelsTechnique::SetParameters(const deepshadow::ShadowParameters& parameters)
{
  this->Superclass::SetParameters(parameters);
  this->SetLevels(parameters.Levels[0], parameters.Levels[1], parameters.Levels[2]);
}

std::vector<double> vtkDeepShadowOpacityLevelsTechnique::GetStructureKey() const
{
  return { static_cast<double>(this->MapSize), this->Levels[0], this->Levels[1], this->Levels[2] };
}

unsigned int vtkDeepShadowOpacityLevelsTechnique::GetTexelFormat() const
{
  return GL_RGBA32F;
}

std::string vtkDeepShadowOpacityLevelsTechnique::GetBuildSource() const
{
  return std::string(vtkDeepShadowSurfaceStepsBuild) + vtkDeepShadowOpacityLevelsBuild;
}

std::string vtkDeepShadowOpacityLevelsTechnique::GetMapLookupSource() const
{
  return std::string(vtkDeepShadowSurfaceSteps) + vtkDeepShadowOpacityLevels;
}

void vtkDeepShadowOpacityLevelsTechnique::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Levels: " << this->Levels[0] << ", " << this->Levels[1] << ", " << this->Levels[2] << "\n";
}
