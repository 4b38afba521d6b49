/**
 * @class   vtkDeepShadowRenderingObjectFactory
 * @brief   Makes `vtkRenderWindow::New()` return a vtkDeepShadowRenderWindow when headless,
 *          and `vtkRenderWindowInteractor::New()` a vtkDeepShadowHeadlessInteractor.
 *
 * Registered by VTK's module auto-initialisation when a program links DeepShadow::Rendering.
 * Policy (ShouldOverrideRenderWindow): VTK_DEEPSHADOW_HEADLESS=1 always, =0 never; unset:
 * when neither DISPLAY nor WAYLAND_DISPLAY is set. When it overrides, it also disables the
 * X11 window's and interactor's overrides so that ours win whatever the registration order.
 */
#ifndef vtkDeepShadowRenderingObjectFactory_h
#define vtkDeepShadowRenderingObjectFactory_h

#include "vtkDeepShadowRenderingModule.h" // For export macro
#include "vtkObjectFactory.h"

class VTKDEEPSHADOWRENDERING_EXPORT vtkDeepShadowRenderingObjectFactory : public vtkObjectFactory
{
public:
  static vtkDeepShadowRenderingObjectFactory* New();
  vtkTypeMacro(vtkDeepShadowRenderingObjectFactory, vtkObjectFactory);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  const char* GetVTKSourceVersion() override;
  const char* GetDescription() override;

  /** The policy above, read from the environment now. */
  static bool ShouldOverrideRenderWindow();

  /** Registers the factory once per process if the policy says so. Idempotent. */
  static void RegisterIfHeadless();

protected:
  vtkDeepShadowRenderingObjectFactory();
  ~vtkDeepShadowRenderingObjectFactory() override = default;

private:
  vtkDeepShadowRenderingObjectFactory(const vtkDeepShadowRenderingObjectFactory&) = delete;
  void operator=(const vtkDeepShadowRenderingObjectFactory&) = delete;
};

#endif
