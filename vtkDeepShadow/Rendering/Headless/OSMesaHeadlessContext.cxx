// OSMesa backend: Mesa's off-screen library, loaded at run time with RTLD_LOCAL so that its
// exported gl* functions never shadow libglvnd's for the EGL backend (or a GPU driver).
#include "HeadlessContext.h"

#include <GL/osmesa.h> // types and attribute names only; nothing is linked

#include <dlfcn.h>
#include <vector>

namespace deepshadow
{
namespace headless
{
namespace
{
struct OSMesaAPI
{
  void* Library = nullptr;
  OSMesaContext (*CreateContextAttribs)(const int*, OSMesaContext) = nullptr;
  GLboolean (*MakeCurrent)(OSMesaContext, void*, GLenum, GLsizei, GLsizei) = nullptr;
  OSMesaContext (*GetCurrentContext)() = nullptr;
  void (*DestroyContext)(OSMesaContext) = nullptr;
  OSMESAproc (*GetProcAddress)(const char*) = nullptr;

  bool Load(std::string& error)
  {
    if (this->Library)
    {
      return true;
    }
    for (const char* soname : { "libOSMesa.so.8", "libOSMesa.so.6", "libOSMesa.so" })
    {
      this->Library = dlopen(soname, RTLD_NOW | RTLD_LOCAL);
      if (this->Library)
      {
        break;
      }
    }
    if (!this->Library)
    {
      error = "libOSMesa is not installed (Debian: apt-get install libosmesa6)";
      return false;
    }
    auto get = [this](const char* name) { return dlsym(this->Library, name); };
    this->CreateContextAttribs =
      reinterpret_cast<decltype(this->CreateContextAttribs)>(get("OSMesaCreateContextAttribs"));
    this->MakeCurrent = reinterpret_cast<decltype(this->MakeCurrent)>(get("OSMesaMakeCurrent"));
    this->GetCurrentContext =
      reinterpret_cast<decltype(this->GetCurrentContext)>(get("OSMesaGetCurrentContext"));
    this->DestroyContext =
      reinterpret_cast<decltype(this->DestroyContext)>(get("OSMesaDestroyContext"));
    this->GetProcAddress =
      reinterpret_cast<decltype(this->GetProcAddress)>(get("OSMesaGetProcAddress"));
    if (!this->CreateContextAttribs || !this->MakeCurrent || !this->GetCurrentContext ||
      !this->DestroyContext || !this->GetProcAddress)
    {
      error = "libOSMesa lacks OSMesaCreateContextAttribs (Mesa 11.2 or later is needed)";
      dlclose(this->Library);
      this->Library = nullptr;
      return false;
    }
    return true;
  }
};

OSMesaAPI& API()
{
  static OSMesaAPI api;
  return api;
}

class OSMesaHeadlessContext final : public HeadlessContext
{
public:
  explicit OSMesaHeadlessContext(OSMesaContext context)
    : Context(context)
  {
  }
  ~OSMesaHeadlessContext() override { API().DestroyContext(this->Context); }

  Backend GetBackend() const override { return Backend::OSMesa; }

  bool MakeCurrent() override
  {
    // VTK renders into its own framebuffer objects; the OSMesa buffer only has to exist.
    return API().MakeCurrent(
             this->Context, this->Pixels.data(), GL_UNSIGNED_BYTE, BufferSize, BufferSize) ==
      GL_TRUE;
  }
  bool IsCurrent() const override { return API().GetCurrentContext() == this->Context; }
  void ReleaseCurrent() override {}
  std::string Describe() const override { return "OSMesa (Mesa off-screen, llvmpipe)"; }

private:
  static constexpr int BufferSize = 4;
  OSMesaContext Context;
  std::vector<unsigned char> Pixels = std::vector<unsigned char>(4 * BufferSize * BufferSize);
};
}

GLProc OSMesaLookup(const char* name)
{
  std::string ignored;
  return API().Load(ignored) ? reinterpret_cast<GLProc>(API().GetProcAddress(name)) : nullptr;
}

std::unique_ptr<HeadlessContext> CreateOSMesaContext(std::string& error)
{
  if (!API().Load(error))
  {
    return nullptr;
  }
  for (int minor : { 5, 2 })
  {
    const int major = minor == 5 ? 4 : 3;
    const int attributes[] = { OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24,
      OSMESA_STENCIL_BITS, 8, OSMESA_PROFILE, OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION,
      major, OSMESA_CONTEXT_MINOR_VERSION, minor, 0 };
    if (OSMesaContext context = API().CreateContextAttribs(attributes, nullptr))
    {
      return std::unique_ptr<HeadlessContext>(new OSMesaHeadlessContext(context));
    }
  }
  error = "OSMesa could not create an OpenGL 3.2 core context";
  return nullptr;
}

}
}
