// vtkDeepShadowVolumeMapper as a vtkGPUVolumeRayCastMapper: the sample distance as VTK
// sets and locks it, and what VTK's own callers ask of a GPU mapper (vtkSmartVolumeMapper:
// the reduction ratio and whether it can render; vtkAMRVolumeMapper: refused).
#include "vtkDeepShadowVolumeMapper.h"

#include "Core/VolumeGrid.h"

#include "vtkImageData.h"
#include "vtkOpenGLRenderWindow.h"

#include <cmath>

void vtkDeepShadowVolumeMapper::SetSampleDistance(float distance)
{
  if (!(distance >= 0.0f) || !std::isfinite(distance))
  {
    vtkErrorMacro("SetSampleDistance(" << distance << "): the sample distance must be finite "
                  "and >= 0 (0: the default); it stays " << this->SampleDistance);
    return;
  }
  if (distance != this->SampleDistance)
  {
    this->SampleDistance = distance;
    this->Modified();
  }
}

double vtkDeepShadowVolumeMapper::SampleStep(vtkImageData* input, const glm::dmat4& indexToWorld)
{
  if (this->LockSampleDistanceToInputSpacing)
  {
    double spacing[3];
    int extent[6];
    input->GetSpacing(spacing);
    input->GetExtent(extent);
    return this->SpacingAdjustedSampleDistance(spacing, extent);
  }
  return this->SampleDistance > 0.0f ? static_cast<double>(this->SampleDistance)
                                     : deepshadow::DefaultSampleDistance(indexToWorld);
}

void vtkDeepShadowVolumeMapper::GetReductionRatio(double ratio[3])
{
  ratio[0] = ratio[1] = ratio[2] = 1.0;
}

int vtkDeepShadowVolumeMapper::IsRenderSupported(vtkRenderWindow* window, vtkVolumeProperty*)
{
  return vtkOpenGLRenderWindow::SafeDownCast(window) ? 1 : 0;
}

void vtkDeepShadowVolumeMapper::PreRender(
  vtkRenderer*, vtkVolume*, double[6], double[2], int, unsigned int)
{
  this->ReportError("AMR volumes (vtkAMRVolumeMapper) are not supported: nothing is drawn");
}

void vtkDeepShadowVolumeMapper::RenderBlock(vtkRenderer*, vtkVolume*, unsigned int) {}

void vtkDeepShadowVolumeMapper::PostRender(vtkRenderer*, int) {}
