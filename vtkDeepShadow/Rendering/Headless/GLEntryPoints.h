// Internal: routes VTK's OpenGL calls to the headless context that is current.
//
// Debian's VTK reaches OpenGL three ways, all of which assume GLX:
//  1. glewInit() loads GL 1.2+ entry points through glXGetProcAddressARB, then fails with
//     GLEW_ERROR_NO_GLX_DISPLAY because there is no X display, which VTK treats as fatal;
//  2. GL 1.0/1.1 functions (glClear, glViewport, ...) are called directly, bound to libglvnd,
//     which knows nothing of an OSMesa context;
//  3. glXGetCurrentDisplay() tells GLEW whether GLX is there.
// GLEntryPoints.cxx defines those symbols in our library, which the dynamic linker finds
// before libGLEW/libGLX/libOpenGL, and forwards each to the active backend.
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
 * True when our forwarders are the definitions the process actually uses. They are not if
 * libGLEW or libOpenGL was loaded ahead of vtkDeepShadowRendering; `error` then says so.
 */
bool InterpositionIsEffective(std::string& error);

}
}
#endif
