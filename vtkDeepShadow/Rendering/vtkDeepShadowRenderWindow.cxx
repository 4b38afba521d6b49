#include "vtkDeepShadowRenderWindow.h"

#include "Headless/GLEntryPoints.h"
#include "Headless/HeadlessContext.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLState.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <set>
#include <sstream>
#include <vtksys/SystemTools.hxx>

namespace headless = deepshadow::headless;

vtkStandardNewMacro(vtkDeepShadowRenderWindow);

vtkDeepShadowRenderWindow::vtkDeepShadowRenderWindow()
  : Backend(GetDefaultBackend())
{
  this->ShowWindow = false;
  this->UseOffScreenBuffers = true;
  // Nothing to blit to: VTK's own framebuffer objects are the image.
  this->FrameBlitMode = NoBlit;
  // Multisampling makes images depend on the rasterizer's sample pattern; off by default.
  this->MultiSamples = 0;
  this->SetWindowName("vtkDeepShadow (headless)");
}

namespace
{
// The window whose context was made current last (MakeCurrent), for PushContext, and the
// windows alive (a window destroyed between a push and its pop is not made current again).
// Plain pointers: a weak pointer to a window made in its own destructor (Finalize releases
// through Push/PopContext) corrupts the heap.
vtkDeepShadowRenderWindow* CurrentWindow = nullptr;
std::set<vtkDeepShadowRenderWindow*>& LiveWindows()
{
  static std::set<vtkDeepShadowRenderWindow*> windows;
  return windows;
}
}

vtkDeepShadowRenderWindow::~vtkDeepShadowRenderWindow()
{
  this->Finalize();
  vtkRenderer* renderer;
  vtkCollectionSimpleIterator it;
  this->Renderers->InitTraversal(it);
  while ((renderer = this->Renderers->GetNextRenderer(it)))
  {
    renderer->SetRenderWindow(nullptr);
  }
  LiveWindows().erase(this);
  if (CurrentWindow == this)
  {
    CurrentWindow = nullptr;
  }
}

int vtkDeepShadowRenderWindow::BackendFromString(const char* name)
{
  if (!name)
  {
    return 0;
  }
  const std::string lower = vtksys::SystemTools::LowerCase(name);
  if (lower == "osmesa")
  {
    return OSMesa;
  }
  if (lower == "egl")
  {
    return EGL;
  }
  return 0;
}

int vtkDeepShadowRenderWindow::GetDefaultBackend()
{
  const int fromEnvironment = BackendFromString(std::getenv("VTK_DEEPSHADOW_BACKEND"));
  return fromEnvironment ? fromEnvironment : OSMesa;
}

const char* vtkDeepShadowRenderWindow::GetBackendAsString() const
{
  return this->Backend == EGL ? "egl" : "osmesa";
}

int vtkDeepShadowRenderWindow::GetRewrittenGLImports()
{
  return headless::RewrittenImportCount();
}

bool vtkDeepShadowRenderWindow::HasContext() const
{
  return this->Context != nullptr;
}

std::string vtkDeepShadowRenderWindow::GetContextDescription() const
{
  return this->Context ? this->Context->Describe() : std::string();
}

std::string vtkDeepShadowRenderWindow::GetOpenGLRenderer()
{
  if (!this->CanDraw())
  {
    return std::string();
  }
  this->MakeCurrent();
  const GLubyte* renderer = glGetString(GL_RENDERER);
  return renderer ? reinterpret_cast<const char*>(renderer) : std::string();
}

void vtkDeepShadowRenderWindow::Initialize()
{
  if (this->Context || this->FailedBackend == this->Backend)
  {
    return;
  }
  this->LastError.clear();
  const auto backend = static_cast<headless::Backend>(this->Backend);

  std::string error;
  if (!headless::InterpositionIsEffective(error) || !headless::AcquireBackend(backend, error))
  {
    this->LastError = error;
    this->FailedBackend = this->Backend;
    vtkErrorMacro("Cannot render headless: " << error);
    return;
  }
  this->Context = headless::HeadlessContext::Create(backend, error);
  if (!this->Context || !this->Context->MakeCurrent())
  {
    headless::ReleaseBackend(backend);
    this->Context.reset();
    this->FailedBackend = this->Backend;
    this->LastError = error.empty() ? "the new context could not be made current" : error;
    vtkErrorMacro("Cannot create a headless " << this->GetBackendAsString()
                                              << " context: " << this->LastError);
    return;
  }
  this->ContextBackend = this->Backend;
  this->FailedBackend = 0;
  CurrentWindow = this; // as MakeCurrent() does: Push/PopContext restore by it
  LiveWindows().insert(this);

  // Renderers hold per-context resources: reattach them to the new context.
  vtkRenderer* renderer;
  vtkCollectionSimpleIterator it;
  for (this->Renderers->InitTraversal(it); (renderer = this->Renderers->GetNextRenderer(it));)
  {
    renderer->SetRenderWindow(nullptr);
    renderer->SetRenderWindow(this);
  }
  // Releasing a prop's objects made in another window (a mapper shared with one) made that
  // window's context current for a while: VTK's initialization must reach this one.
  this->MakeCurrent();
  this->OpenGLInit();
  if (!this->Initialized)
  {
    this->LastError = "VTK could not initialize OpenGL on the headless context";
  }
  else
  {
    // The largest framebuffer side this context can make (16384 on llvmpipe).
    GLint renderbuffer = 0, viewport[2] = { 0, 0 }, texture = 0;
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &renderbuffer);
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &texture);
    for (const GLint limit : { renderbuffer, viewport[0], viewport[1], texture })
    {
      this->MaximumSize = limit > 0 ? std::min(this->MaximumSize, static_cast<int>(limit)) : this->MaximumSize;
    }
  }
  this->Mapped = 1;
}

void vtkDeepShadowRenderWindow::Finalize()
{
  if (!this->Context)
  {
    return;
  }
  this->MakeCurrent();
  this->ReleaseGraphicsResources(this);
  this->Context.reset();
  headless::ReleaseBackend(static_cast<headless::Backend>(this->ContextBackend));
  this->ContextBackend = 0;
  this->Initialized = false;
  this->Mapped = 0;
}

void vtkDeepShadowRenderWindow::Render()
{
  // Without a context VTK's End() calls GL through an empty dispatch table and aborts (EGL
  // with no vendor library, a machine without libOSMesa): the error is the answer instead.
  this->Initialize();
  if (!this->CanDraw())
  {
    return;
  }
  this->Superclass::Render();
}

int vtkDeepShadowRenderWindow::ReadPixels(
  const vtkRecti& rect, int front, int glFormat, int glType, void* data, int right)
{
  if (this->CanDraw())
  {
    return this->Superclass::ReadPixels(rect, front, glFormat, glType, data, right);
  }
  // vtkWindowToImageFilter and the Get*PixelData methods read the picture of a window whose
  // context could not be made (its error was said): black, and VTK_ERROR.
  const size_t components = glFormat == GL_RGBA ? 4 : glFormat == GL_RGB ? 3 : 1;
  const size_t bytes = glType == GL_FLOAT || glType == GL_UNSIGNED_INT ? 4 : 1;
  if (data && rect.GetWidth() > 0 && rect.GetHeight() > 0)
  {
    std::memset(data, 0, components * bytes * static_cast<size_t>(rect.GetWidth()) * rect.GetHeight());
  }
  return VTK_ERROR;
}

int vtkDeepShadowRenderWindow::GetZbufferData(int x1, int y1, int x2, int y2, float* z)
{
  if (this->CanDraw())
  {
    return this->Superclass::GetZbufferData(x1, y1, x2, y2, z);
  }
  const size_t count = static_cast<size_t>(std::abs(x2 - x1) + 1) * (std::abs(y2 - y1) + 1);
  std::fill(z, z + count, 1.0f);
  return VTK_ERROR;
}

int vtkDeepShadowRenderWindow::SetZbufferData(int x1, int y1, int x2, int y2, float* buffer)
{
  return this->CanDraw()
    ? this->Superclass::SetZbufferData(x1, y1, x2, y2, buffer)
    : VTK_ERROR;
}

int vtkDeepShadowRenderWindow::SetPixelData(
  int x, int y, int x2, int y2, unsigned char* data, int front, int right)
{
  return this->CanDraw()
    ? this->Superclass::SetPixelData(x, y, x2, y2, data, front, right)
    : VTK_ERROR;
}

int vtkDeepShadowRenderWindow::SetRGBAPixelData(
  int x, int y, int x2, int y2, float* data, int front, int blend, int right)
{
  return this->CanDraw()
    ? this->Superclass::SetRGBAPixelData(x, y, x2, y2, data, front, blend, right)
    : VTK_ERROR;
}

int vtkDeepShadowRenderWindow::SetRGBACharPixelData(
  int x, int y, int x2, int y2, unsigned char* data, int front, int blend, int right)
{
  return this->CanDraw()
    ? this->Superclass::SetRGBACharPixelData(x, y, x2, y2, data, front, blend, right)
    : VTK_ERROR;
}

void vtkDeepShadowRenderWindow::Start()
{
  this->Initialize();
  if (!this->Context)
  {
    return;
  }
  // A library loaded since the context was made (a later Python import, e.g. VTK's GPU volume
  // mapper) may call GL through libOpenGL: point it here too. Cheap when nothing was loaded.
  std::string error;
  if (!headless::InterpositionIsEffective(error))
  {
    vtkErrorMacro("Cannot render headless: " << error);
    return;
  }
  this->Superclass::Start();
}

void vtkDeepShadowRenderWindow::Frame()
{
  if (this->Context)
  {
    this->Superclass::Frame();
  }
}

void vtkDeepShadowRenderWindow::MakeCurrent()
{
  if (this->Context && !this->Context->IsCurrent() && !this->Context->MakeCurrent())
  {
    vtkErrorMacro("Failed to make the headless context current");
    return;
  }
  if (this->Context)
  {
    CurrentWindow = this;
    LiveWindows().insert(this);
  }
}

void vtkDeepShadowRenderWindow::PushContext()
{
  vtkDeepShadowRenderWindow* before = CurrentWindow && CurrentWindow->IsCurrent() ? CurrentWindow : nullptr;
  this->ContextStack.push_back(before);
  if (before != this)
  {
    this->MakeCurrent();
  }
}

void vtkDeepShadowRenderWindow::PopContext()
{
  if (this->ContextStack.empty())
  {
    return;
  }
  vtkDeepShadowRenderWindow* before = this->ContextStack.back();
  this->ContextStack.pop_back();
  if (before && before != this && LiveWindows().count(before))
  {
    before->MakeCurrent();
  }
}

void vtkDeepShadowRenderWindow::ReleaseCurrent()
{
  if (this->Context)
  {
    this->Context->ReleaseCurrent();
  }
}

bool vtkDeepShadowRenderWindow::IsCurrent()
{
  return this->Context && this->Context->IsCurrent();
}

int vtkDeepShadowRenderWindow::SupportsOpenGL()
{
  this->Initialize();
  return this->Initialized ? 1 : 0;
}

const char* vtkDeepShadowRenderWindow::ReportCapabilities()
{
  this->Initialize();
  if (!this->Initialized)
  {
    return "no headless OpenGL context";
  }
  this->MakeCurrent();
  auto text = [](GLenum name) {
    const GLubyte* value = glGetString(name);
    return value ? reinterpret_cast<const char*>(value) : "?";
  };
  std::ostringstream report;
  report << "Headless context: " << this->GetContextDescription() << "\n"
         << "OpenGL vendor string:  " << text(GL_VENDOR) << "\n"
         << "OpenGL renderer string:  " << this->GetOpenGLRenderer() << "\n"
         << "OpenGL version string:  " << text(GL_VERSION) << "\n";
  delete[] this->Capabilities;
  const std::string str = report.str();
  this->Capabilities = new char[str.size() + 1];
  std::copy(str.c_str(), str.c_str() + str.size() + 1, this->Capabilities);
  return this->Capabilities;
}

void vtkDeepShadowRenderWindow::SetSize(int width, int height)
{
  const int largest = this->GetMaximumSize();
  if (width > largest || height > largest)
  {
    std::ostringstream message;
    message << "SetSize(" << width << ", " << height << "): a side of at most " << largest
            << " pixels can be drawn (this context's framebuffer limit); the size stays "
            << this->Size[0] << "x" << this->Size[1];
    this->LastError = message.str();
    vtkErrorMacro(<< this->LastError);
    return;
  }
  // Framebuffers follow Size at the next Start(); nothing else to resize.
  this->Superclass::SetSize(width, height);
}

int vtkDeepShadowRenderWindow::GetMaximumSize()
{
  return this->MaximumSize;
}

int* vtkDeepShadowRenderWindow::GetScreenSize()
{
  // No screen: report the largest framebuffer we would let a user ask for.
  this->ScreenSize[0] = this->MaximumSize;
  this->ScreenSize[1] = this->MaximumSize;
  return this->ScreenSize;
}

void vtkDeepShadowRenderWindow::SetShowWindow(bool)
{
  // There is nothing to show; stay off screen whatever is asked.
  this->ShowWindow = false;
  this->UseOffScreenBuffers = true;
}

void* vtkDeepShadowRenderWindow::GetGenericContext()
{
  return this->Context.get();
}

void vtkDeepShadowRenderWindow::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Backend: " << this->GetBackendAsString() << "\n";
  os << indent << "Context: " << (this->Context ? this->GetContextDescription() : "(none)")
     << "\n";
  if (!this->LastError.empty())
  {
    os << indent << "LastError: " << this->LastError << "\n";
  }
}
