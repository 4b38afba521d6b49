#include "vtkDeepShadowRenderWindow.h"

#include "Headless/GLEntryPoints.h"
#include "Headless/HeadlessContext.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLState.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtk_glew.h"

#include <cstdlib>
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

void vtkDeepShadowRenderWindow::Initialize()
{
  if (this->Context)
  {
    return;
  }
  this->LastError.clear();
  const auto backend = static_cast<headless::Backend>(this->Backend);

  std::string error;
  if (!headless::InterpositionIsEffective(error) || !headless::AcquireBackend(backend, error))
  {
    this->LastError = error;
    vtkErrorMacro("Cannot render headless: " << error);
    return;
  }
  this->Context = headless::HeadlessContext::Create(backend, error);
  if (!this->Context || !this->Context->MakeCurrent())
  {
    headless::ReleaseBackend(backend);
    this->Context.reset();
    this->LastError = error.empty() ? "the new context could not be made current" : error;
    vtkErrorMacro("Cannot create a headless " << this->GetBackendAsString()
                                              << " context: " << this->LastError);
    return;
  }
  this->ContextBackend = this->Backend;

  // Renderers hold per-context resources: reattach them to the new context.
  vtkRenderer* renderer;
  vtkCollectionSimpleIterator it;
  for (this->Renderers->InitTraversal(it); (renderer = this->Renderers->GetNextRenderer(it));)
  {
    renderer->SetRenderWindow(nullptr);
    renderer->SetRenderWindow(this);
  }
  this->OpenGLInit();
  if (!this->Initialized)
  {
    this->LastError = "VTK could not initialize OpenGL on the headless context";
  }
  this->Mapped = 1;
}

void vtkDeepShadowRenderWindow::Finalize()
{
  if (!this->Context)
  {
    return;
  }
  this->Context->MakeCurrent();
  this->ReleaseGraphicsResources(this);
  this->Context.reset();
  headless::ReleaseBackend(static_cast<headless::Backend>(this->ContextBackend));
  this->ContextBackend = 0;
  this->Initialized = false;
  this->Mapped = 0;
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
         << "OpenGL renderer string:  " << text(GL_RENDERER) << "\n"
         << "OpenGL version string:  " << text(GL_VERSION) << "\n";
  delete[] this->Capabilities;
  const std::string str = report.str();
  this->Capabilities = new char[str.size() + 1];
  std::copy(str.c_str(), str.c_str() + str.size() + 1, this->Capabilities);
  return this->Capabilities;
}

void vtkDeepShadowRenderWindow::SetSize(int width, int height)
{
  // Framebuffers follow Size at the next Start(); nothing else to resize.
  this->Superclass::SetSize(width, height);
}

int* vtkDeepShadowRenderWindow::GetScreenSize()
{
  // No screen: report the largest framebuffer we would let a user ask for.
  this->ScreenSize[0] = 16384;
  this->ScreenSize[1] = 16384;
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
