// EGL backend: a context with no surface. On Mesa it uses the surfaceless platform
// (llvmpipe); on a GPU driver without it (NVIDIA) the device platform; else the default display.
#include "HeadlessContext.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdlib>
#include <cstring>
#include <dlfcn.h>
#include <string>

namespace deepshadow
{
namespace headless
{
namespace
{
bool HasExtension(const char* extensions, const char* name)
{
  if (!extensions)
  {
    return false;
  }
  const size_t length = std::strlen(name);
  for (const char* p = std::strstr(extensions, name); p; p = std::strstr(p + length, name))
  {
    if ((p == extensions || p[-1] == ' ') && (p[length] == ' ' || p[length] == '\0'))
    {
      return true;
    }
  }
  return false;
}

// Opens a display: surfaceless platform, else device `VTK_DEEPSHADOW_EGL_DEVICE` (default 0),
// else the default display. `description` says which.
EGLDisplay OpenDisplay(std::string& description)
{
  const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
    eglGetProcAddress("eglGetPlatformDisplayEXT"));
  EGLint major = 0, minor = 0;
  if (getPlatformDisplay && HasExtension(clientExtensions, "EGL_MESA_platform_surfaceless"))
  {
    EGLDisplay display =
      getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display != EGL_NO_DISPLAY && eglInitialize(display, &major, &minor))
    {
      description = "EGL surfaceless platform";
      return display;
    }
  }
  auto queryDevices =
    reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  if (getPlatformDisplay && queryDevices && HasExtension(clientExtensions, "EGL_EXT_platform_device"))
  {
    EGLDeviceEXT devices[16];
    EGLint count = 0;
    if (queryDevices(16, devices, &count) && count > 0)
    {
      const char* requested = std::getenv("VTK_DEEPSHADOW_EGL_DEVICE");
      int index = requested ? std::atoi(requested) : 0;
      index = index < 0 || index >= count ? 0 : index;
      EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[index], nullptr);
      if (display != EGL_NO_DISPLAY && eglInitialize(display, &major, &minor))
      {
        description = "EGL device " + std::to_string(index) + " of " + std::to_string(count);
        return display;
      }
    }
  }
  EGLDisplay display = eglGetDisplay(EGL_DEFAULT_DISPLAY);
  if (display != EGL_NO_DISPLAY && eglInitialize(display, &major, &minor))
  {
    description = "EGL default display";
    return display;
  }
  return EGL_NO_DISPLAY;
}

class EGLHeadlessContext final : public HeadlessContext
{
public:
  EGLHeadlessContext(EGLDisplay display, EGLContext context, std::string description)
    : Display(display)
    , Context(context)
    , Description(std::move(description))
  {
  }
  ~EGLHeadlessContext() override
  {
    if (eglGetCurrentContext() == this->Context)
    {
      eglMakeCurrent(this->Display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    }
    eglDestroyContext(this->Display, this->Context);
  }

  Backend GetBackend() const override { return Backend::EGL; }
  bool MakeCurrent() override
  {
    return eglMakeCurrent(this->Display, EGL_NO_SURFACE, EGL_NO_SURFACE, this->Context) ==
      EGL_TRUE;
  }
  bool IsCurrent() const override { return eglGetCurrentContext() == this->Context; }
  void ReleaseCurrent() override
  {
    eglMakeCurrent(this->Display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  }
  std::string Describe() const override { return this->Description; }

private:
  EGLDisplay Display;
  EGLContext Context;
  std::string Description;
};

// GL 1.0/1.1 functions of libglvnd's libOpenGL, which dispatch to the current EGL context.
void* OpenGLLibrary()
{
  static void* library = []() -> void* {
    for (const char* soname : { "libOpenGL.so.0", "libGL.so.1" })
    {
      if (void* handle = dlopen(soname, RTLD_NOW | RTLD_LOCAL))
      {
        return handle;
      }
    }
    return nullptr;
  }();
  return library;
}
}

GLProc EGLLookup(const char* name)
{
  if (void* library = OpenGLLibrary())
  {
    if (void* symbol = dlsym(library, name))
    {
      return reinterpret_cast<GLProc>(symbol);
    }
  }
  return reinterpret_cast<GLProc>(eglGetProcAddress(name));
}

std::unique_ptr<HeadlessContext> CreateEGLContext(std::string& error)
{
  std::string description;
  EGLDisplay display = OpenDisplay(description);
  if (display == EGL_NO_DISPLAY)
  {
    error = "no EGL display could be initialized (surfaceless, device or default)";
    return nullptr;
  }
  if (!eglBindAPI(EGL_OPENGL_API))
  {
    error = "the EGL display does not offer desktop OpenGL";
    return nullptr;
  }
  const EGLint configAttributes[] = { EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE };
  EGLConfig config = nullptr;
  EGLint configCount = 0;
  eglChooseConfig(display, configAttributes, &config, 1, &configCount);
  for (int minor : { 5, 2 })
  {
    const EGLint major = minor == 5 ? 4 : 3;
    const EGLint contextAttributes[] = { EGL_CONTEXT_MAJOR_VERSION, major,
      EGL_CONTEXT_MINOR_VERSION, minor, EGL_CONTEXT_OPENGL_PROFILE_MASK,
      EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE };
    EGLContext context = eglCreateContext(
      display, configCount > 0 ? config : EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, contextAttributes);
    if (context != EGL_NO_CONTEXT)
    {
      return std::unique_ptr<HeadlessContext>(
        new EGLHeadlessContext(display, context, description));
    }
  }
  error = "EGL could not create an OpenGL 3.2 core context on the " + description;
  return nullptr;
}

}
}
