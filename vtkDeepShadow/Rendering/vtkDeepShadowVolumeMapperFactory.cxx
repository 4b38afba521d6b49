#include "vtkDeepShadowVolumeMapperFactory.h"

#include "vtkDeepShadowTechnique.h"
#include "vtkDeepShadowVolumeMapper.h"
#include "vtkSmartPointer.h"
#include "vtkVersion.h"

#include <cstdlib>
#include <cstring>
#include <string>

vtkStandardNewMacro(vtkDeepShadowVolumeMapperFactory);

namespace
{
const char* const Base = "vtkGPUVolumeRayCastMapper";
const char* const Ours = "vtkDeepShadowVolumeMapper";
const char* const VTKs = "vtkOpenGLGPUVolumeRayCastMapper";

// The technique of the mappers made while overriding; empty when not overriding.
std::string& OverridingTechnique()
{
  static std::string technique;
  return technique;
}

vtkObject* CreateMapper()
{
  vtkDeepShadowVolumeMapper* mapper = vtkDeepShadowVolumeMapper::New();
  if (OverridingTechnique() != "none")
  {
    vtkSmartPointer<vtkDeepShadowTechnique> technique;
    technique.TakeReference(vtkDeepShadowTechnique::NewFromName(OverridingTechnique().c_str()));
    mapper->SetShadowTechnique(technique);
  }
  return mapper;
}
}

vtkDeepShadowVolumeMapperFactory::vtkDeepShadowVolumeMapperFactory()
{
  this->RegisterOverride(
    Base, Ours, "vtkDeepShadow volume mapper with shadows", 1, CreateMapper);
}

const char* vtkDeepShadowVolumeMapperFactory::GetVTKSourceVersion()
{
  return VTK_SOURCE_VERSION;
}

const char* vtkDeepShadowVolumeMapperFactory::GetDescription()
{
  return "vtkDeepShadow volume mapper override (opt-in)";
}

bool vtkDeepShadowVolumeMapperFactory::Override(const char* technique)
{
  const std::string name = technique && *technique ? technique : "dsm";
  if (name != "none")
  {
    // Checked now, not at the first New() where an application could not hear it.
    vtkSmartPointer<vtkDeepShadowTechnique> probe;
    probe.TakeReference(vtkDeepShadowTechnique::NewFromName(name.c_str()));
    if (!probe)
    {
      vtkGenericWarningMacro("vtkDeepShadowVolumeMapperFactory::Override: no shadow technique "
                             "is named '" << name << "'; VTK's mapper stays");
      return false;
    }
  }
  static bool registered = false;
  if (!registered)
  {
    registered = true;
    auto* factory = vtkDeepShadowVolumeMapperFactory::New();
    vtkObjectFactory::RegisterFactory(factory);
    factory->Delete();
  }
  OverridingTechnique() = name;
  vtkObjectFactory::SetAllEnableFlags(0, Base);
  vtkObjectFactory::SetAllEnableFlags(1, Base, Ours);
  return true;
}

void vtkDeepShadowVolumeMapperFactory::Restore()
{
  if (!IsOverriding())
  {
    return;
  }
  OverridingTechnique().clear();
  vtkObjectFactory::SetAllEnableFlags(0, Base, Ours);
  vtkObjectFactory::SetAllEnableFlags(1, Base, VTKs);
}

bool vtkDeepShadowVolumeMapperFactory::IsOverriding()
{
  return !OverridingTechnique().empty();
}

const char* vtkDeepShadowVolumeMapperFactory::GetTechnique()
{
  return OverridingTechnique().c_str();
}

void vtkDeepShadowVolumeMapperFactory::OverrideFromEnvironment()
{
  const char* value = std::getenv("VTK_DEEPSHADOW_VOLUME_MAPPER");
  if (!value || !*value || std::strcmp(value, "0") == 0)
  {
    return;
  }
  Override(std::strcmp(value, "1") == 0 ? "dsm" : value);
}

void vtkDeepShadowVolumeMapperFactory::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Overriding vtkGPUVolumeRayCastMapper: "
     << (IsOverriding() ? OverridingTechnique() : std::string("no")) << "\n";
}
