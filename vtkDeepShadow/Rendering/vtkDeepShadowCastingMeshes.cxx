#include "vtkDeepShadowCastingMeshes.h"

#include "Core/Geometry/SurfaceSet.h"
#include "vtkDeepShadowPolyDataMapper.h"

#include "vtkActor.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"

#include <cstdint>
#include <stdexcept>

vtkStandardNewMacro(vtkDeepShadowCastingMeshes);

vtkDeepShadowCastingMeshes::vtkDeepShadowCastingMeshes() = default;
vtkDeepShadowCastingMeshes::~vtkDeepShadowCastingMeshes() = default;

bool vtkDeepShadowCastingMeshes::Update(
  const std::vector<std::pair<vtkActor*, vtkDeepShadowPolyDataMapper*>>& meshes)
{
  std::vector<double> key;
  for (const auto& [actor, mapper] : meshes)
  {
    if (!mapper->GetCastShadows())
    {
      continue;
    }
    vtkPolyData* input = mapper->GetInput();
    key.insert(key.end(), { static_cast<double>(reinterpret_cast<uintptr_t>(actor)),
      static_cast<double>(mapper->GetMTime()), static_cast<double>(input ? input->GetMTime() : 0),
      static_cast<double>(actor->GetProperty()->GetMTime()) });
    const double* m = actor->GetMatrix()->GetData();
    key.insert(key.end(), m, m + 16);
  }
  if (key == this->Key && (this->Surfaces == nullptr) == key.empty())
  {
    return false;
  }
  this->Key = key;
  this->Surfaces.reset();
  this->LastError.clear();
  std::vector<deepshadow::SurfaceMesh> casting;
  for (const auto& [actor, mapper] : meshes)
  {
    deepshadow::SurfaceMesh mesh;
    std::string error;
    if (!mapper->GetCastShadows())
    {
      continue;
    }
    if (mapper->GetSurfaceMesh(actor, mesh, error))
    {
      casting.push_back(std::move(mesh));
    }
    else
    {
      vtkWarningMacro("a mesh casts no shadow: " << error);
    }
  }
  this->Count = 0;
  try
  {
    if (!casting.empty())
    {
      this->Surfaces = std::make_shared<const deepshadow::SurfaceSet>(std::move(casting));
      this->Count = this->Surfaces->GetSurfaceCount();
    }
  }
  catch (const std::invalid_argument& e)
  {
    this->LastError = std::string("meshes cast no shadows: ") + e.what();
    vtkErrorMacro(<< this->LastError);
  }
  ++this->Builds;
  return true;
}

void vtkDeepShadowCastingMeshes::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Builds: " << this->Builds << "\n";
  os << indent << "Count: " << this->Count << "\n";
}
