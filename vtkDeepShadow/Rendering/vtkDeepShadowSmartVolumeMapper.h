/**
 * @class   vtkDeepShadowSmartVolumeMapper
 * @brief   vtkSmartVolumeMapper whose GPU path is vtkDeepShadowVolumeMapper.
 *
 * The whole API of VTK's smart mapper (SetRequestedRenderMode..., interactive adjustment,
 * independent components as it combines them, FinalColorWindow/Level...), so a script that
 * uses vtkSmartVolumeMapper keeps working when only the class name changes. Its GPU mappers
 * (full and low resolution) are deep-shadow mappers: under the GPU and default render modes
 * the volume is drawn by ours, with shadows once SetShadowTechnique gives one; the ray-cast
 * mode draws with VTK's CPU mapper, as the smart mapper does, without shadows.
 *
 * vtkDeepShadowVolumeMapperFactory::Override() serves scripts that cannot be edited instead:
 * it makes vtkGPUVolumeRayCastMapper::New(), and so every vtkSmartVolumeMapper, ours.
 */
#ifndef vtkDeepShadowSmartVolumeMapper_h
#define vtkDeepShadowSmartVolumeMapper_h

#include "vtkDeepShadowRenderingModule.h" // For export macro
#include "vtkSmartVolumeMapper.h"

class vtkDeepShadowTechnique;
class vtkDeepShadowVolumeMapper;

class VTKDEEPSHADOWRENDERING_EXPORT vtkDeepShadowSmartVolumeMapper : public vtkSmartVolumeMapper
{
public:
  static vtkDeepShadowSmartVolumeMapper* New();
  vtkTypeMacro(vtkDeepShadowSmartVolumeMapper, vtkSmartVolumeMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The shadow technique of both GPU mappers (null, the default: no shadows). See
   * vtkDeepShadowVolumeMapper::SetShadowTechnique.
   */
  void SetShadowTechnique(vtkDeepShadowTechnique* technique);
  vtkDeepShadowTechnique* GetShadowTechnique();
  ///@}

  /** The full-resolution GPU mapper, for its other settings (shading model, key light, ...). */
  vtkDeepShadowVolumeMapper* GetDeepShadowMapper();

protected:
  vtkDeepShadowSmartVolumeMapper();
  ~vtkDeepShadowSmartVolumeMapper() override = default;

private:
  vtkDeepShadowSmartVolumeMapper(const vtkDeepShadowSmartVolumeMapper&) = delete;
  void operator=(const vtkDeepShadowSmartVolumeMapper&) = delete;
};

#endif
