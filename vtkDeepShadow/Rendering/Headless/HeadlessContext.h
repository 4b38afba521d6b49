// Internal: an OpenGL context with no window and no X server, on Mesa (llvmpipe) or a GPU.
//
// Debian's VTK 9.1 is built for GLX only. vtkDeepShadowRenderWindow drives VTK's OpenGL code
// from a context made here instead; GLEntryPoints.cxx makes VTK's GL calls reach it.
#ifndef vtkDeepShadowHeadlessContext_h
#define vtkDeepShadowHeadlessContext_h

#include <memory>
#include <string>

namespace deepshadow
{
namespace headless
{

enum class Backend
{
  None = 0,
  OSMesa = 1,
  EGL = 2
};

const char* BackendName(Backend backend);

using GLProc = void (*)();

class HeadlessContext
{
public:
  virtual ~HeadlessContext() = default;

  virtual Backend GetBackend() const = 0;
  virtual bool MakeCurrent() = 0;
  virtual bool IsCurrent() const = 0;
  virtual void ReleaseCurrent() = 0;
  /** Where the context comes from, e.g. "EGL surfaceless platform". */
  virtual std::string Describe() const = 0;

  /**
   * Creates a core-profile context (4.5 if offered, else 3.2) of the given backend. Returns
   * null and sets `error` to one line saying why when it cannot.
   */
  static std::unique_ptr<HeadlessContext> Create(Backend backend, std::string& error);
};

// Backend factories, one per translation unit (each includes only its own API's headers).
std::unique_ptr<HeadlessContext> CreateOSMesaContext(std::string& error);
std::unique_ptr<HeadlessContext> CreateEGLContext(std::string& error);

// Entry-point lookup of each backend, used by the forwarders in GLEntryPoints.cxx.
GLProc OSMesaLookup(const char* name);
GLProc EGLLookup(const char* name);

}
}
#endif
