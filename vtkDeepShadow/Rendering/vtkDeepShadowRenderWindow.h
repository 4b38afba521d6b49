/**
 * @class   vtkDeepShadowRenderWindow
 * @brief   Render window with no X server and no display: OSMesa or EGL, llvmpipe or GPU.
 *
 * A drop-in vtkRenderWindow for machines with no display. It renders VTK 9.1 (as Debian
 * builds it, for GLX) into an OSMesa context (the default) or an EGL context with no surface
 * (Mesa's surfaceless platform, or a GPU's device platform). Read the pixels the usual way
 * (vtkWindowToImageFilter, GetPixelData, vtkRegressionTestImage).
 *
 * When this module is linked and the process has no display (neither DISPLAY nor
 * WAYLAND_DISPLAY is set), `vtkRenderWindow::New()` returns this class, so an ordinary VTK
 * pipeline renders headless unchanged. `VTK_DEEPSHADOW_HEADLESS=1` forces that override,
 * `=0` turns it off. `VTK_DEEPSHADOW_BACKEND=osmesa|egl` picks the default backend.
 *
 * Only one backend can be in use in a process at a time (GLEW's entry points are global);
 * asking for the other while a context of the first exists is an error.
 */
#ifndef vtkDeepShadowRenderWindow_h
#define vtkDeepShadowRenderWindow_h

#include "vtkDeepShadowRenderingModule.h" // For export macro
#include "vtkOpenGLRenderWindow.h"

#include <memory> // For std::unique_ptr
#include <string> // For std::string
#include <vector> // For the context stack

namespace deepshadow
{
namespace headless
{
class HeadlessContext;
}
}

class VTKDEEPSHADOWRENDERING_EXPORT vtkDeepShadowRenderWindow : public vtkOpenGLRenderWindow
{
public:
  static vtkDeepShadowRenderWindow* New();
  vtkTypeMacro(vtkDeepShadowRenderWindow, vtkOpenGLRenderWindow);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum BackendType
  {
    OSMesa = 1,
    EGL = 2
  };

  ///@{
  /**
   * Which context to create. Takes effect at the next context creation (first render, or
   * after Finalize()). Default: VTK_DEEPSHADOW_BACKEND, else OSMesa.
   */
  vtkSetClampMacro(Backend, int, OSMesa, EGL);
  vtkGetMacro(Backend, int);
  void SetBackendToOSMesa() { this->SetBackend(OSMesa); }
  void SetBackendToEGL() { this->SetBackend(EGL); }
  const char* GetBackendAsString() const;
  ///@}

  /** Parses "osmesa" / "egl" (case-insensitive); returns 0 for anything else. */
  static int BackendFromString(const char* name);
  /** The backend a new window starts with (VTK_DEEPSHADOW_BACKEND, else OSMesa). */
  static int GetDefaultBackend();

  /** True once a context exists. */
  bool HasContext() const;
  /** Where the context came from ("OSMesa ...", "EGL surfaceless platform", ...). */
  std::string GetContextDescription() const;
  /** GL_RENDERER of the context ("llvmpipe (LLVM 15.0.6, 256 bits)", "NVIDIA H100 ..."); "" without one. */
  std::string GetOpenGLRenderer();
  /**
   * How many GL imports of other libraries this process had to point at the headless
   * window's entry points (0 when the program links this module before VTK's OpenGL
   * libraries; more when VTK's were bound first, as after `import vtk` in Python).
   */
  static int GetRewrittenGLImports();

  /** Why the last context creation failed; empty when it did not. */
  const std::string& GetLastError() const { return this->LastError; }

  // vtkRenderWindow / vtkOpenGLRenderWindow API.
  void Initialize() override;
  void Finalize() override;
  /** Draws nothing (and says why once) when no context could be created. */
  void Render() override;
  void Start() override;
  void Frame() override;
  void MakeCurrent() override;
  void ReleaseCurrent() override;
  bool IsCurrent() override;
  /**
   * Makes this window's context current for a while, and gives back the one that was: VTK's
   * mappers release their GL objects in the window that made them between the two, in the
   * middle of another window's frame. Without the pop, the rest of that frame ran in this
   * window's context, and the first of two windows showing one prop went blank.
   */
  void PushContext() override;
  void PopContext() override;
  int SupportsOpenGL() override;
  vtkTypeBool IsDirect() override { return 1; }
  const char* ReportCapabilities() override;

  ///@{
  /**
   * Pixel and depth I/O. Without a context (its creation failed and said why) reads give
   * black and the far plane, writes do nothing, all return VTK_ERROR: VTK's own would jump
   * through GL pointers that were never loaded.
   */
  using vtkOpenGLRenderWindow::GetZbufferData;
  using vtkOpenGLRenderWindow::SetPixelData;
  using vtkOpenGLRenderWindow::SetRGBACharPixelData;
  using vtkOpenGLRenderWindow::SetRGBAPixelData;
  using vtkOpenGLRenderWindow::SetZbufferData;
  int GetZbufferData(int x1, int y1, int x2, int y2, float* z) override;
  int SetZbufferData(int x1, int y1, int x2, int y2, float* buffer) override;
  int SetPixelData(int x, int y, int x2, int y2, unsigned char* data, int front, int right) override;
  int SetRGBAPixelData(
    int x, int y, int x2, int y2, float* data, int front, int blend = 0, int right = 0) override;
  int SetRGBACharPixelData(int x, int y, int x2, int y2, unsigned char* data, int front,
    int blend = 0, int right = 0) override;
  ///@}

  /**
   * Refuses (vtkErrorMacro, GetLastError(), the size kept) a side above GetMaximumSize():
   * a framebuffer that large cannot be made, and the picture was black with no word.
   */
  void SetSize(int width, int height) override;
  /**
   * The largest side a picture may have: the context's renderbuffer, viewport and texture
   * limits once it exists (16384 on llvmpipe), 16384 before.
   */
  int GetMaximumSize();
  void SetSize(int a[2]) override { this->SetSize(a[0], a[1]); }
  int* GetScreenSize() VTK_SIZEHINT(2) override;
  void SetShowWindow(bool) override;

  // A headless window has no native window, display or cursor.
  void* GetGenericContext() override;
  void* GetGenericWindowId() override { return nullptr; }
  void* GetGenericDisplayId() override { return nullptr; }
  void* GetGenericParentId() override { return nullptr; }
  void* GetGenericDrawable() override { return nullptr; }
  void SetDisplayId(void*) override {}
  void SetWindowId(void*) override {}
  void SetParentId(void*) override {}
  void SetWindowInfo(const char*) override {}
  void SetParentInfo(const char*) override {}
  void SetNextWindowId(void*) override {}
  void SetNextWindowInfo(const char*) override {}
  void SetFullScreen(vtkTypeBool) override {}
  void WindowRemap() override {}
  vtkTypeBool GetEventPending() override { return 0; }
  void HideCursor() override {}
  void ShowCursor() override {}

protected:
  vtkDeepShadowRenderWindow();
  ~vtkDeepShadowRenderWindow() override;

  /** Zeros, not a jump through a GL pointer never loaded, when there is no context. */
  int ReadPixels(const vtkRecti& rect, int front, int glFormat, int glType, void* data,
    int right = 0) override;
  void CreateAWindow() override { this->Initialize(); }
  void DestroyWindow() override { this->Finalize(); }

  int Backend;
  std::string LastError;
  std::unique_ptr<deepshadow::headless::HeadlessContext> Context;
  int ContextBackend = 0; // backend of Context, fixed at its creation
  int FailedBackend = 0;  // backend whose creation failed: not retried (nor said again) every frame
  int MaximumSize = 16384;
  std::vector<vtkDeepShadowRenderWindow*> ContextStack; // PushContext: the window current before

  /** A context exists and VTK initialized OpenGL in it: GL may be called. */
  bool CanDraw() const { return this->Context && this->Initialized; }

private:
  vtkDeepShadowRenderWindow(const vtkDeepShadowRenderWindow&) = delete;
  void operator=(const vtkDeepShadowRenderWindow&) = delete;
};

#endif
