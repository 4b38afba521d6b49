#include "vtkDeepShadowSmartVolumeMapper.h"

#include "vtkDeepShadowVolumeMapper.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkDeepShadowSmartVolumeMapper);

vtkDeepShadowSmartVolumeMapper::vtkDeepShadowSmartVolumeMapper()
{
  // vtkSmartVolumeMapper made its GPU mappers with vtkGPUVolumeRayCastMapper::New(): ours
  // replace them, set up as its constructor set up its own.
  this->GPUMapper->Delete();
  this->GPUMapper = vtkDeepShadowVolumeMapper::New();
  this->GPUMapper->LockSampleDistanceToInputSpacingOn();
  this->MaxMemoryInBytes = this->GPUMapper->GetMaxMemoryInBytes();
  this->MaxMemoryFraction = this->GPUMapper->GetMaxMemoryFraction();
  this->GPULowResMapper->Delete();
  this->GPULowResMapper = vtkDeepShadowVolumeMapper::New();
}

vtkDeepShadowVolumeMapper* vtkDeepShadowSmartVolumeMapper::GetDeepShadowMapper()
{
  return static_cast<vtkDeepShadowVolumeMapper*>(this->GPUMapper);
}

void vtkDeepShadowSmartVolumeMapper::SetShadowTechnique(vtkDeepShadowTechnique* technique)
{
  if (technique == this->GetShadowTechnique())
  {
    return;
  }
  this->GetDeepShadowMapper()->SetShadowTechnique(technique);
  static_cast<vtkDeepShadowVolumeMapper*>(this->GPULowResMapper)->SetShadowTechnique(technique);
  this->Modified();
}

vtkDeepShadowTechnique* vtkDeepShadowSmartVolumeMapper::GetShadowTechnique()
{
  return this->GetDeepShadowMapper()->GetShadowTechnique();
}

void vtkDeepShadowSmartVolumeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ShadowTechnique: " << this->GetShadowTechnique() << "\n";
}
