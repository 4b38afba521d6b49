// Binary masks (vtkGPUVolumeRayCastMapper::SetMaskInput with the binary mask type) as VTK's
// mapper reads them: a sample is clear where the mask's nearest voxel is 0 or less, whatever
// the volume's interpolation (measured against VTK's: a mask over voxels 10-21 shows
// [9.5, 21.5)). The CPU twin of Rendering/Shaders/Features/Mask.glsl. Shadows are cast by what
// the mask keeps (ShadowCaster::Mask).
#ifndef deepshadow_Mask_h
#define deepshadow_Mask_h

#include "Core/VolumeGrid.h"

#include <glm/vec3.hpp>

namespace deepshadow
{

/** 1 where `mask` (null: none) keeps the sample at continuous voxel index `index`, else 0. */
inline double MaskFactor(const VolumeGrid* mask, const glm::dvec3& index)
{
  return !mask || mask->Sample(index, Interpolation::Nearest) > 0.0 ? 1.0 : 0.0;
}

}
#endif
