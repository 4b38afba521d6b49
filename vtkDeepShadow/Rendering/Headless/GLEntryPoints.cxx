// Definitions of the GL/GLX/GLEW symbols that let Debian's GLX-only VTK render into a
// headless context. See GLEntryPoints.h for why each exists.
#include "GLEntryPoints.h"
#include "ImportRebinding.h"

#include <GL/glew.h> // GL types, glewInit's declaration and error codes

#include <atomic>
#include <cstdlib>
#include <cstring>
#include <dlfcn.h>
#include <mutex>
#include <vector>

#define DEEPSHADOW_INTERPOSE extern "C" __attribute__((visibility("default")))

namespace deepshadow
{
namespace headless
{
namespace
{
std::atomic<int> ActiveBackendValue{ static_cast<int>(Backend::None) };
std::mutex BackendMutex;
int LiveContexts = 0;

// The definition that would have been used without us (libGLEW, libGLX, libOpenGL).
GLProc NextDefinition(const char* name)
{
  return reinterpret_cast<GLProc>(dlsym(RTLD_NEXT, name));
}

GLProc Lookup(Backend backend, const char* name)
{
  switch (backend)
  {
    case Backend::OSMesa:
      return OSMesaLookup(name);
    case Backend::EGL:
      return EGLLookup(name);
    case Backend::None:
      break;
  }
  return NextDefinition(name);
}

// One cache slot per backend and entry point, filled on first call.
template <int Index>
GLProc CachedLookup(const char* name)
{
  static std::atomic<GLProc> cache[3];
  const int backend = ActiveBackendValue.load(std::memory_order_relaxed);
  GLProc proc = cache[backend].load(std::memory_order_relaxed);
  if (!proc)
  {
    proc = Lookup(static_cast<Backend>(backend), name);
    cache[backend].store(proc, std::memory_order_relaxed);
  }
  return proc;
}

// Every name defined below, for RebindImports.
const char* const InterposedNames[] = {
#define ENTRY(ret, name, params, args) #name,
#include "GLCoreEntryPoints.def"
#undef ENTRY
  "glXGetCurrentDisplay", "glXGetProcAddressARB", "glewInit"
};
std::atomic<int> RewrittenImports{ 0 };

enum EntryIndex
{
#define ENTRY(ret, name, params, args) Index_##name,
#include "GLCoreEntryPoints.def"
#undef ENTRY
  EntryCount
};
}

bool AcquireBackend(Backend backend, std::string& error)
{
  std::lock_guard<std::mutex> lock(BackendMutex);
  const auto active = static_cast<Backend>(ActiveBackendValue.load());
  if (LiveContexts > 0 && active != backend)
  {
    error = std::string("a headless ") + BackendName(active) +
      " context is alive in this process; GLEW's entry points are process-wide, so a " +
      BackendName(backend) + " context cannot be used at the same time";
    return false;
  }
  ActiveBackendValue.store(static_cast<int>(backend));
  ++LiveContexts;
  return true;
}

void ReleaseBackend(Backend backend)
{
  std::lock_guard<std::mutex> lock(BackendMutex);
  if (LiveContexts > 0 && static_cast<Backend>(ActiveBackendValue.load()) == backend)
  {
    --LiveContexts;
  }
}

Backend ActiveBackend()
{
  return static_cast<Backend>(ActiveBackendValue.load());
}

bool InterpositionIsEffective(std::string& error)
{
  // Rebind once per set of loaded objects: a library loaded since (a later Python import)
  // may bring GL imports bound to libOpenGL/libGLEW/libGLX.
  static std::mutex mutex;
  static unsigned long long checkedGeneration = 0;
  std::lock_guard<std::mutex> lock(mutex);
  const unsigned long long generation = LoadedObjectGeneration();
  if (generation == checkedGeneration)
  {
    return true;
  }

  // Our own definitions, looked up in this library (not through the process's symbol order).
  Dl_info self{};
  void* handle = nullptr;
  if (dladdr(reinterpret_cast<void*>(&InterpositionIsEffective), &self) && self.dli_fname)
  {
    handle = dlopen(self.dli_fname, RTLD_LAZY | RTLD_NOLOAD);
  }
  if (!handle)
  {
    error = "cannot locate the vtkDeepShadowRendering library in memory";
    return false;
  }
  std::vector<ImportDefinition> definitions;
  for (const char* name : InterposedNames)
  {
    if (void* address = dlsym(handle, name))
    {
      definitions.push_back({ name, address });
    }
  }
  dlclose(handle);

  // VTK_DEEPSHADOW_NO_REBIND=1 (diagnostics, tests): leave the imports as the linker bound
  // them, to see what an import order does without the rewrite.
  const char* noRebind = std::getenv("VTK_DEEPSHADOW_NO_REBIND");
  if (noRebind && std::strcmp(noRebind, "1") == 0)
  {
    checkedGeneration = generation;
    return true;
  }
  RebindReport report;
  if (!RebindImports(definitions, self.dli_fbase, report, error))
  {
    return false;
  }
  RewrittenImports += report.Rewritten;
  checkedGeneration = generation;
  return true;
}

int RewrittenImportCount()
{
  return RewrittenImports.load();
}

}
}

using deepshadow::headless::ActiveBackend;
using deepshadow::headless::Backend;
using deepshadow::headless::GLProc;

// (2) GL 1.0/1.1 functions called directly by VTK.
#define ENTRY(ret, name, params, args)                                                            \
  DEEPSHADOW_INTERPOSE ret name params                                                            \
  {                                                                                               \
    using Fn = ret(GLAPIENTRY*) params;                                                           \
    return reinterpret_cast<Fn>(                                                                  \
      deepshadow::headless::CachedLookup<deepshadow::headless::Index_##name>(#name)) args;        \
  }
#include "GLCoreEntryPoints.def"
#undef ENTRY

// (3) With a headless context current there is no GLX display, whatever libGLX believes
// (glvnd's answer is undefined while an EGL context is current).
DEEPSHADOW_INTERPOSE void* glXGetCurrentDisplay()
{
  if (ActiveBackend() != Backend::None)
  {
    return nullptr;
  }
  using Fn = void* (*)();
  static Fn next = reinterpret_cast<Fn>(dlsym(RTLD_NEXT, "glXGetCurrentDisplay"));
  return next ? next() : nullptr;
}

// (1a) GLEW's loader: GL names come from the active backend.
DEEPSHADOW_INTERPOSE GLProc glXGetProcAddressARB(const GLubyte* procName)
{
  const char* name = reinterpret_cast<const char*>(procName);
  const Backend backend = ActiveBackend();
  if (backend == Backend::None)
  {
    using Fn = GLProc (*)(const GLubyte*);
    static Fn next = reinterpret_cast<Fn>(dlsym(RTLD_NEXT, "glXGetProcAddressARB"));
    return next ? next(procName) : nullptr;
  }
  if (std::strncmp(name, "glX", 3) == 0)
  {
    // GLEW probes GLX only to learn there is no display.
    return std::strcmp(name, "glXGetCurrentDisplay") == 0
      ? reinterpret_cast<GLProc>(&glXGetCurrentDisplay)
      : nullptr;
  }
  return backend == Backend::OSMesa ? deepshadow::headless::OSMesaLookup(name)
                                    : deepshadow::headless::EGLLookup(name);
}

// (1b) "No GLX display" is the expected answer for a headless context: the GL entry points
// were loaded before GLEW looked for GLX, so report success.
DEEPSHADOW_INTERPOSE GLenum glewInit()
{
  using Fn = GLenum (*)();
  static Fn next = reinterpret_cast<Fn>(dlsym(RTLD_NEXT, "glewInit"));
  if (!next)
  {
    return GLEW_ERROR_NO_GL_VERSION;
  }
  const GLenum result = next();
  if (result == GLEW_ERROR_NO_GLX_DISPLAY && ActiveBackend() != Backend::None)
  {
    return GLEW_OK;
  }
  return result;
}
