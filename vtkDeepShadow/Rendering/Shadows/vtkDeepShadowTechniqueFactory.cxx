#include "vtkDeepShadowTechniqueFactory.h"

#include "Core/ShadowTechniques.h"
#include "vtkDeepShadowTechnique.h"

#include <map>

namespace
{
// Function-local, so that it exists before the first Register() of any file's initializers.
std::map<deepshadow::ShadowKind, vtkDeepShadowTechniqueFactory::Maker>& Makers()
{
  static std::map<deepshadow::ShadowKind, vtkDeepShadowTechniqueFactory::Maker> makers;
  return makers;
}
}

bool vtkDeepShadowTechniqueFactory::Register(deepshadow::ShadowKind kind, Maker maker)
{
  Makers()[kind] = maker;
  return true;
}

vtkSmartPointer<vtkDeepShadowTechnique> vtkDeepShadowTechniqueFactory::New(
  const deepshadow::ShadowParameters& parameters)
{
  const auto found = Makers().find(parameters.Kind);
  if (parameters.Kind == deepshadow::ShadowKind::None || found == Makers().end())
  {
    return nullptr;
  }
  vtkSmartPointer<vtkDeepShadowTechnique> technique;
  technique.TakeReference(found->second());
  technique->SetParameters(parameters);
  return technique;
}

vtkSmartPointer<vtkDeepShadowTechnique> vtkDeepShadowTechniqueFactory::New(const std::string& name)
{
  bool cached = false;
  const deepshadow::ShadowTechniqueInfo* info = deepshadow::FindShadowTechnique(name, &cached);
  return info ? New(info->DefaultParameters(cached)) : nullptr;
}
