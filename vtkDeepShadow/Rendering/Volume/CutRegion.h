// Internal: what vtkVolumeMapper's clipping planes and cropping keep of the volume, as closed
// meshes in the image's (data) coordinates, to be bound leaves beside the user's (feature
// Bound): the view rays, every shadow technique and the CPU reference then see the same cut
// volume, and a volume is drawn and casts shadows only where VTK's mapper draws it.
#ifndef vtkDeepShadowCutRegion_h
#define vtkDeepShadowCutRegion_h

#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkImageData;
class vtkMatrix4x4;
class vtkPolyData;
class vtkVolumeMapper;

namespace deepshadow
{

class CutRegion
{
public:
  /**
   * The meshes (0, 1 or 2: the image's box cut by the clipping planes, the union of the
   * cropping sub-boxes) for `mapper`'s settings, the image's placement and the prop's matrix
   * (clipping planes are in world coordinates). Rebuilt only when one of those changed, so an
   * unchanged cut keeps its meshes (and their MTimes).
   */
  const std::vector<vtkPolyData*>& Update(
    vtkVolumeMapper* mapper, vtkImageData* input, vtkMatrix4x4* propMatrix);

  /**
   * The bound expression over `userLeaves` user bounds combined by `userExpression` ("": their
   * union) and then `cutLeaves` cut meshes: the intersection of all. "" when only one leaf.
   */
  static std::string Combine(int userLeaves, const std::string& userExpression, int cutLeaves);

private:
  std::vector<double> Signature;
  vtkSmartPointer<vtkPolyData> Clipped;
  vtkSmartPointer<vtkPolyData> Cropped;
  std::vector<vtkPolyData*> Meshes;
};

}
#endif
