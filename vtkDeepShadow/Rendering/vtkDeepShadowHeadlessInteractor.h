/**
 * @class   vtkDeepShadowHeadlessInteractor
 * @brief   A render window interactor for a process with no display: Start() renders once
 *          and returns.
 *
 * What `vtkRenderWindowInteractor::New()` makes when vtkDeepShadowRenderingObjectFactory
 * makes the headless window (no DISPLAY and no WAYLAND_DISPLAY, or VTK_DEEPSHADOW_HEADLESS=1;
 * in Python once `vtkdeepshadow` is imported), so that VTK's example scripts, which end with
 * `iren.Start()`, run unchanged in CI instead of failing on the X server (VTK 9.1's X11
 * interactor crashes with no display). Start() initialises (one render), saves the picture to
 * the file VTK_DEEPSHADOW_SCREENSHOT names (PNG), if set, and returns at once: there is no
 * event loop, so timers never fire and TerminateApp() has nothing to stop.
 */
#ifndef vtkDeepShadowHeadlessInteractor_h
#define vtkDeepShadowHeadlessInteractor_h

#include "vtkDeepShadowRenderingModule.h" // For export macro
#include "vtkRenderWindowInteractor.h"

class VTKDEEPSHADOWRENDERING_EXPORT vtkDeepShadowHeadlessInteractor : public vtkRenderWindowInteractor
{
public:
  static vtkDeepShadowHeadlessInteractor* New();
  vtkTypeMacro(vtkDeepShadowHeadlessInteractor, vtkRenderWindowInteractor);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** Renders (initialising first), saves the screenshot if asked, returns. */
  void Start() override;

  /** How many times Start() was called. */
  vtkGetMacro(Starts, int);

protected:
  vtkDeepShadowHeadlessInteractor() = default;
  ~vtkDeepShadowHeadlessInteractor() override = default;

private:
  int Starts = 0;

  vtkDeepShadowHeadlessInteractor(const vtkDeepShadowHeadlessInteractor&) = delete;
  void operator=(const vtkDeepShadowHeadlessInteractor&) = delete;
};

#endif
