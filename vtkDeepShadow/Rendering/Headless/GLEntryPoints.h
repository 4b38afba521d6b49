// Internal: routes VTK's OpenGL calls to the headless context that is current.
//
// Debian's VTK reaches OpenGL three ways, all of which assume GLX:
//  1. glewInit() loads GL 1.2+ entry points through glXGetProcAddressARB, then fails with
//     GLEW_ERROR_NO_GLX_DISPLAY because there is no X display, which VTK treats as fatal;
//  2. GL 1.0/1.1 functions (glClear, glViewport, ...) are called directly, bound to libglvnd,
//     which knows nothing of an OSMesa context;
//  3. glXGetCurrentDisplay() tells GLEW whether GLX is there.
// GLEntryPoints.cxx defines those symbols in our library and forwards each to the active
// backend. In a program linked with our library first the dynamic linker binds VTK's calls
// to them; otherwise (Python's RTLD_LOCAL imports) ImportRebinding.h points them here.
#ifndef vtkDeepShadowGLEntryPoints_h
#define vtkDeepShadowGLEntryPoints_h

#include "HeadlessContext.h"

#include <string>

namespace deepshadow
{
namespace headless
{

/**
 * Makes `backend` the one that GL calls are routed to. GLEW's pointers are process-wide, so
 * only one backend can have live contexts at a time: fails (with `error`) when another does.
 */
bool AcquireBackend(Backend backend, std::string& error);
/** Drops one live context of `backend`; with none left, any backend can be acquired. */
void ReleaseBackend(Backend backend);
Backend ActiveBackend();

/**
 * Makes our forwarders the definitions the process uses: when VTK's OpenGL libraries were
 * bound before this library was loaded (Python, `import vtk` first), their GL imports are
 * rewritten to point here (ImportRebinding.h). Cheap when no library was loaded since the
 * last call. False, with `error`, when an import cannot be rewritten.
 */
bool InterpositionIsEffective(std::string& error);
/** Import slots rewritten so far in this process (0 in a program linked in our order). */
int RewrittenImportCount();

}
}
#endif
