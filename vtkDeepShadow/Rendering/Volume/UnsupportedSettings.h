// Internal: the settings of vtkVolumeMapper and vtkVolumeProperty that VTK's GPU mapper honours
// and ours does not draw yet, each as one line naming the setting and what is drawn instead,
// so that the mapper says them (once each) instead of drawing something else silently.
#ifndef vtkDeepShadowUnsupportedSettings_h
#define vtkDeepShadowUnsupportedSettings_h

#include <string>
#include <vector>

class vtkVolumeMapper;
class vtkVolumeProperty;

namespace deepshadow
{

/** Blend modes other than composite, cropping, clipping planes, gradient opacity, 2D transfer
 * functions: what `mapper` and `property` ask for that is not drawn. */
std::vector<std::string> UnsupportedSettings(vtkVolumeMapper* mapper, vtkVolumeProperty* property);

}
#endif
