#include "vtkDeepShadowCompositeSurfaceMapper.h"

#include "vtkDeepShadowPolyDataMapper.h"

#include "vtkAppendPolyData.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkInformation.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <vector>

vtkStandardNewMacro(vtkDeepShadowCompositeSurfaceMapper);

vtkDeepShadowCompositeSurfaceMapper::vtkDeepShadowCompositeSurfaceMapper()
{
  this->Inner->SetInputData(this->Joined);
}

vtkDeepShadowCompositeSurfaceMapper::~vtkDeepShadowCompositeSurfaceMapper() = default;

int vtkDeepShadowCompositeSurfaceMapper::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  return 1;
}

namespace
{
// The input and its polydata leaves (the input itself when it is polydata).
std::vector<vtkPolyData*> Leaves(vtkDataObject* input, vtkMTimeType& time)
{
  std::vector<vtkPolyData*> leaves;
  time = input ? input->GetMTime() : 0;
  if (auto* mesh = vtkPolyData::SafeDownCast(input))
  {
    leaves.push_back(mesh);
  }
  else if (auto* composite = vtkCompositeDataSet::SafeDownCast(input))
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(composite->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      if (auto* mesh = vtkPolyData::SafeDownCast(it->GetCurrentDataObject()))
      {
        time = std::max(time, mesh->GetMTime());
        if (mesh->GetNumberOfPoints() > 0)
        {
          leaves.push_back(mesh);
        }
      }
    }
  }
  return leaves;
}
}

void vtkDeepShadowCompositeSurfaceMapper::Join()
{
  if (this->GetNumberOfInputConnections(0) > 0 && !this->Static)
  {
    this->GetInputAlgorithm()->Update();
  }
  vtkDataObject* input = this->GetInputDataObject(0, 0);
  vtkMTimeType time = 0;
  const std::vector<vtkPolyData*> leaves = Leaves(input, time);
  if (input == this->JoinedInput && time == this->JoinedTime)
  {
    return;
  }
  this->JoinedInput = input;
  this->JoinedTime = time;
  ++this->Joins;
  if (leaves.size() == 1)
  {
    this->Joined->ShallowCopy(leaves.front());
  }
  else if (leaves.empty())
  {
    this->Joined->Initialize();
  }
  else
  {
    vtkNew<vtkAppendPolyData> append;
    for (vtkPolyData* leaf : leaves)
    {
      append->AddInputData(leaf);
    }
    append->Update();
    this->Joined->ShallowCopy(append->GetOutput());
  }
  this->Joined->Modified(); // a shallow copy of the same arrays is still a new mesh
}

void vtkDeepShadowCompositeSurfaceMapper::PassSettings()
{
  vtkDeepShadowPolyDataMapper* inner = this->Inner;
  // Each setter is a no-op when the value is the same, so the mesh is not re-uploaded.
  inner->SetLookupTable(this->GetLookupTable());
  inner->SetScalarVisibility(this->GetScalarVisibility());
  inner->SetScalarRange(this->GetScalarRange());
  inner->SetUseLookupTableScalarRange(this->GetUseLookupTableScalarRange());
  inner->SetColorMode(this->GetColorMode());
  inner->SetScalarMode(this->GetScalarMode());
  inner->SetInterpolateScalarsBeforeMapping(this->GetInterpolateScalarsBeforeMapping());
  inner->SetFieldDataTupleId(this->GetFieldDataTupleId());
  inner->SetArrayName(this->GetArrayName());
  inner->SetArrayId(this->GetArrayId());
  inner->SetArrayAccessMode(this->GetArrayAccessMode());
  inner->SetArrayComponent(this->GetArrayComponent());
  inner->SetStatic(1); // Joined is no pipeline output: nothing to update
}

void vtkDeepShadowCompositeSurfaceMapper::Render(vtkRenderer* renderer, vtkActor* actor)
{
  this->Join();
  this->PassSettings();
  if (this->Joined->GetNumberOfPoints() > 0)
  {
    this->Inner->Render(renderer, actor);
  }
}

double* vtkDeepShadowCompositeSurfaceMapper::GetBounds()
{
  this->Join();
  if (this->Joined->GetNumberOfPoints() == 0)
  {
    vtkMath::UninitializeBounds(this->Bounds);
    return this->Bounds;
  }
  this->Joined->GetBounds(this->Bounds);
  return this->Bounds;
}

bool vtkDeepShadowCompositeSurfaceMapper::HasOpaqueGeometry()
{
  this->Join();
  this->PassSettings();
  return this->Inner->HasOpaqueGeometry();
}

bool vtkDeepShadowCompositeSurfaceMapper::HasTranslucentPolygonalGeometry()
{
  this->Join();
  this->PassSettings();
  return this->Inner->HasTranslucentPolygonalGeometry();
}

void vtkDeepShadowCompositeSurfaceMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Inner->ReleaseGraphicsResources(window);
  this->Superclass::ReleaseGraphicsResources(window);
}

void vtkDeepShadowCompositeSurfaceMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Joins: " << this->Joins << "\n";
  os << indent << "SurfaceMapper:\n";
  this->Inner->PrintSelf(os, indent.GetNextIndent());
}
