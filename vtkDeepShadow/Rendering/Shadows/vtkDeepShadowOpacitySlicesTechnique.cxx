#include "vtkDeepShadowOpacitySlicesTechnique.h"
#include "vtkDeepShadowTechniqueInternals.h"

#include "Core/ShadowTechniques.h"
#include "Core/Shadows/OpacitySlices.h"
#include "vtkDeepShadowOpacitySlices.h"
#include "vtkDeepShadowOpacitySlicesBuild.h"
#include "vtkDeepShadowTechniqueFactory.h"

#include "vtkObjectFactory.h"
#include "vtk_glew.h"

vtkStandardNewMacro(vtkDeepShadowOpacitySlicesTechnique);

// The hooks with internal types: its layers per face.
class vtkDeepShadowOpacitySlicesTechnique::Hooks : public vtkDeepShadowLightSpaceTechnique::Hooks
{
public:
  explicit Hooks(vtkDeepShadowOpacitySlicesTechnique& self)
    : vtkDeepShadowLightSpaceTechnique::Hooks(self)
    , Technique(&self)
  {
  }

  /** Four slices a layer (RGBA8). */
  int GetLayersPerFace(const deepshadow::ShadowContext&) const override { return this->Technique->Slices / 4; }

private:
  vtkDeepShadowOpacitySlicesTechnique* Technique;
};

vtkDeepShadowOpacitySlicesTechnique::vtkDeepShadowOpacitySlicesTechnique()
{
  Internals::SetHooks(this, std::make_unique<Hooks>(*this));
}

// The GPU class of the registry's "slices" (deepshadow::ShadowTechniques()).
static const bool Registered = vtkDeepShadowTechniqueFactory::Register(deepshadow::OpacitySlicesKind,
  []() -> vtkDeepShadowTechnique* { return vtkDeepShadowOpacitySlicesTechnique::New(); });

void vtkDeepShadowOpacitySlicesTechnique::SetSlices(int slices)
{
  const std::string problem = deepshadow::FindShadowParameter("slices")->Check({ static_cast<double>(slices) });
  if (!problem.empty())
  {
    vtkErrorMacro(<< problem << "; got " << slices);
    return;
  }
  if (slices != this->Slices)
  {
    this->Slices = slices;
    this->Modified();
  }
}

deepshadow::ShadowParameters vtkDeepShadowOpacitySlicesTechnique::GetParameters() const
{
  deepshadow::ShadowParameters parameters;
  this->FillParameters(parameters);
  parameters.Kind = deepshadow::OpacitySlicesKind;
  this->FillMapParameters(parameters);
  deepshadow::FindShadowParameter("slices")->Set(parameters, { static_cast<double>(this->Slices) });
  return parameters;
}

void vtkDeepShadowOpacitySlicesTechnique::SetParameters(const deepshadow::ShadowParameters& parameters)
{
  this->Superclass::SetParameters(parameters);
  this->SetSlices(deepshadow::OpacitySliceCount(parameters));
}

std::vector<double> vtkDeepShadowOpacitySlicesTechnique::GetStructureKey() const
{
  return { static_cast<double>(this->MapSize), static_cast<double>(this->Slices) };
}

unsigned int vtkDeepShadowOpacitySlicesTechnique::GetTexelFormat() const
{
  return GL_RGBA8;
}

std::string vtkDeepShadowOpacitySlicesTechnique::GetBuildSource() const
{
  return "//@Dec\n#define SLICES " + std::to_string(this->Slices) + "\n" + vtkDeepShadowOpacitySlicesBuild;
}

std::string vtkDeepShadowOpacitySlicesTechnique::GetMapLookupSource() const
{
  return "//@Dec\n#define SLICES " + std::to_string(this->Slices) + "\n" + vtkDeepShadowOpacitySlices;
}

void vtkDeepShadowOpacitySlicesTechnique::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Slices: " << this->Slices << "\n";
}
