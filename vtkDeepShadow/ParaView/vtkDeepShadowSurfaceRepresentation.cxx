#include "vtkDeepShadowSurfaceRepresentation.h"

#include "vtkDeepShadowCompositeSurfaceMapper.h"
#include "vtkDeepShadowPolyDataMapper.h"
#include "vtkDeepShadowVolumeMapper.h"

#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkPVRenderView.h"
#include "vtkPVView.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeCollection.h"

vtkStandardNewMacro(vtkDeepShadowSurfaceRepresentation);

vtkDeepShadowSurfaceRepresentation::vtkDeepShadowSurfaceRepresentation()
{
  // As ParaView's Surface LIC does: the superclass's mappers make way for ours, for the full
  // and the level-of-detail geometry alike (interactive frames keep their shadows), and
  // SetupDefaults connects them again.
  this->Mapper->Delete();
  this->LODMapper->Delete();
  this->Mapper = vtkDeepShadowCompositeSurfaceMapper::New();
  this->LODMapper = vtkDeepShadowCompositeSurfaceMapper::New();
  this->SetupDefaults();
}

vtkDeepShadowSurfaceRepresentation::~vtkDeepShadowSurfaceRepresentation() = default;

bool vtkDeepShadowSurfaceRepresentation::AddToView(vtkView* view)
{
  if (auto* renderView = vtkPVRenderView::SafeDownCast(view))
  {
    this->Renderer = renderView->GetRenderer();
  }
  return this->Superclass::AddToView(view);
}

bool vtkDeepShadowSurfaceRepresentation::RemoveFromView(vtkView* view)
{
  this->Renderer = nullptr;
  this->ShadowingVolume = nullptr;
  for (vtkMapper* mapper : { this->Mapper, this->LODMapper })
  {
    vtkDeepShadowCompositeSurfaceMapper::SafeDownCast(mapper)->GetSurfaceMapper()->SetShadowingVolume(nullptr);
  }
  return this->Superclass::RemoveFromView(view);
}

int vtkDeepShadowSurfaceRepresentation::ProcessViewRequest(
  vtkInformationRequestKey* request, vtkInformation* in, vtkInformation* out)
{
  const int result = this->Superclass::ProcessViewRequest(request, in, out);
  if (result && request == vtkPVView::REQUEST_RENDER())
  {
    this->FindShadowingVolume();
  }
  return result;
}

void vtkDeepShadowSurfaceRepresentation::FindShadowingVolume()
{
  vtkVolume* found = nullptr;
  if (this->Renderer)
  {
    vtkVolumeCollection* volumes = this->Renderer->GetVolumes();
    vtkCollectionSimpleIterator it;
    volumes->InitTraversal(it);
    while (vtkVolume* volume = volumes->GetNextVolume(it))
    {
      auto* mapper = vtkDeepShadowVolumeMapper::SafeDownCast(volume->GetMapper());
      if (volume->GetVisibility() && mapper && mapper->GetShadowTechnique())
      {
        found = volume;
        break;
      }
    }
  }
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (found && controller && controller->GetNumberOfProcesses() > 1)
  {
    if (!this->SaidRanks && controller->GetLocalProcessId() == 0)
    {
      vtkWarningMacro(<< "Shadowed Surface under MPI is drawn without the volumes' shadows and casts none: a rank's "
                         "lookups see its own brick and those in front of it, not every brick between the light and "
                         "the surface");
    }
    this->SaidRanks = true;
    found = nullptr;
  }
  this->ShadowingVolume = found;
  for (vtkMapper* mapper : { this->Mapper, this->LODMapper })
  {
    vtkDeepShadowCompositeSurfaceMapper::SafeDownCast(mapper)->GetSurfaceMapper()->SetShadowingVolume(found);
  }
}

void vtkDeepShadowSurfaceRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ShadowingVolume: " << this->ShadowingVolume << "\n";
}
