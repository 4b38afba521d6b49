#include "UnsupportedSettings.h"

#include "vtkPiecewiseFunction.h"
#include "vtkPlaneCollection.h"
#include "vtkVolumeMapper.h"
#include "vtkVolumeProperty.h"

namespace deepshadow
{
namespace
{
const char* BlendModeName(int mode)
{
  switch (mode)
  {
    case vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND:
      return "maximum intensity projection";
    case vtkVolumeMapper::MINIMUM_INTENSITY_BLEND:
      return "minimum intensity projection";
    case vtkVolumeMapper::AVERAGE_INTENSITY_BLEND:
      return "average intensity projection";
    case vtkVolumeMapper::ADDITIVE_BLEND:
      return "additive";
    case vtkVolumeMapper::ISOSURFACE_BLEND:
      return "isosurface";
    case vtkVolumeMapper::SLICE_BLEND:
      return "slice";
    default:
      return "unknown";
  }
}

// A gradient opacity that changes something: any node below 1.
bool ChangesOpacity(vtkPiecewiseFunction* function)
{
  for (int i = 0; function && i < function->GetSize(); ++i)
  {
    double node[4];
    function->GetNodeValue(i, node);
    if (node[1] != 1.0)
    {
      return true;
    }
  }
  return false;
}
}

std::vector<std::string> UnsupportedSettings(vtkVolumeMapper* mapper, vtkVolumeProperty* property)
{
  std::vector<std::string> said;
  const int blend = mapper->GetBlendMode();
  if (blend != vtkVolumeMapper::COMPOSITE_BLEND)
  {
    said.push_back(std::string("blend mode ") + BlendModeName(blend) +
      " is not supported: the volume is drawn with composite blending");
  }
  if (mapper->GetCropping())
  {
    said.push_back("cropping (SetCropping) is not supported: the whole volume is drawn");
  }
  if (mapper->GetClippingPlanes() && mapper->GetClippingPlanes()->GetNumberOfItems() > 0)
  {
    said.push_back("clipping planes are not supported: the whole volume is drawn (a polyhedral "
                   "bound, AddBound, cuts the volume and its shadows)");
  }
  if (property && !property->GetDisableGradientOpacity(0) &&
    ChangesOpacity(property->GetStoredGradientOpacity(0)))
  {
    said.push_back("gradient opacity is not supported: opacity follows the scalar value only");
  }
  if (property && property->GetTransferFunctionMode() == vtkVolumeProperty::TF_2D)
  {
    said.push_back("2D transfer functions (TF_2D) are not supported: the 1D functions are used");
  }
  return said;
}

}
