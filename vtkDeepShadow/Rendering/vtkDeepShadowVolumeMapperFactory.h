/**
 * @class   vtkDeepShadowVolumeMapperFactory
 * @brief   Opt-in: `vtkGPUVolumeRayCastMapper::New()` returns a vtkDeepShadowVolumeMapper.
 *
 * One call, Override("dsm"), or the environment variable VTK_DEEPSHADOW_VOLUME_MAPPER=dsm
 * read when the module initialises, and every later `vtkGPUVolumeRayCastMapper::New()` -
 * those of vtkSmartVolumeMapper, vtkMultiBlockVolumeMapper and the applications built on
 * them included - makes our mapper with that shadow technique (a name
 * vtkDeepShadowTechnique::NewFromName knows; "none" for no shadows; "1" means "dsm").
 * Mappers made before the call stay what they are. Restore() gives VTK's mapper back.
 *
 * VTK's own override (vtkOpenGLGPUVolumeRayCastMapper) is switched off while ours is on,
 * whatever the order the factories were registered in.
 */
#ifndef vtkDeepShadowVolumeMapperFactory_h
#define vtkDeepShadowVolumeMapperFactory_h

#include "vtkDeepShadowRenderingModule.h" // For export macro
#include "vtkObjectFactory.h"

class VTKDEEPSHADOWRENDERING_EXPORT vtkDeepShadowVolumeMapperFactory : public vtkObjectFactory
{
public:
  static vtkDeepShadowVolumeMapperFactory* New();
  vtkTypeMacro(vtkDeepShadowVolumeMapperFactory, vtkObjectFactory);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  const char* GetVTKSourceVersion() override;
  const char* GetDescription() override;

  /**
   * From now on vtkGPUVolumeRayCastMapper::New() returns our mapper with `technique`. False,
   * with an error and nothing changed, for a technique name no class implements.
   */
  static bool Override(const char* technique = "dsm");
  /** vtkGPUVolumeRayCastMapper::New() returns VTK's mapper again. */
  static void Restore();
  /** Whether the override is on. */
  static bool IsOverriding();
  /** The technique overriding mappers get ("" when not overriding). */
  static const char* GetTechnique();
  /** Overrides if VTK_DEEPSHADOW_VOLUME_MAPPER names a technique (or is "1"); "0" or unset: not. */
  static void OverrideFromEnvironment();

protected:
  vtkDeepShadowVolumeMapperFactory();
  ~vtkDeepShadowVolumeMapperFactory() override = default;

private:
  vtkDeepShadowVolumeMapperFactory(const vtkDeepShadowVolumeMapperFactory&) = delete;
  void operator=(const vtkDeepShadowVolumeMapperFactory&) = delete;
};

#endif
