// Internal: the settings of vtkGPUVolumeRayCastMapper and vtkVolumeProperty that VTK's GPU mapper honours
// and ours does not draw yet, each as one line naming the setting and what is drawn instead,
// so that the mapper says them (once each) instead of drawing something else silently.
#ifndef vtkDeepShadowUnsupportedSettings_h
#define vtkDeepShadowUnsupportedSettings_h

#include <string>
#include <vector>

class vtkGPUVolumeRayCastMapper;
class vtkImageData;
class vtkMatrix4x4;
class vtkVolumeProperty;

namespace deepshadow
{

/** Isosurface and slice blending, gradient opacity, 2D transfer functions, masks, image
 * sample distance, final colour window/level, render to image, depth
 * pass, more input volumes: what `mapper` and `property` ask for that is not drawn; a prop
 * (`propMatrix`) scaled differently along its axes, whose opacity per dataset unit is
 * approximated; and, when a shadow technique is set (`shadowed`), that projection blend
 * modes have no shadows. `drawn` is the image drawn (DrawnScalars), `fromCells` whether
 * from cell scalars, `components` how many per voxel (several: drawn composite, without
 * gradient opacity or a mask). */
std::vector<std::string> UnsupportedSettings(vtkGPUVolumeRayCastMapper* mapper, vtkImageData* drawn,
  bool fromCells, int components, vtkVolumeProperty* property, const vtkMatrix4x4* propMatrix, bool shadowed);

}
#endif
