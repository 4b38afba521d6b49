// Internal: points other libraries' imports of a function at our definition, after the
// dynamic linker has already bound them elsewhere.
//
// A program linked with vtkDeepShadowRendering before VTK's OpenGL libraries needs none of
// this: the linker binds VTK's GL calls to our forwarders (GLEntryPoints.cxx). Python loads
// extension modules with RTLD_LOCAL and binds them at load (RTLD_NOW), so after `import vtk`
// libvtkRenderingOpenGL2's and libGLEW's GL imports already point at libOpenGL/libGLX, and our
// library, loaded later, cannot win by symbol order. Rewriting the imports' GOT slots (the
// same slots the dynamic linker filled) makes the result independent of the import order.
#ifndef vtkDeepShadowImportRebinding_h
#define vtkDeepShadowImportRebinding_h

#include <string>
#include <vector>

namespace deepshadow
{
namespace headless
{

struct ImportDefinition
{
  const char* Name;
  void* Address;
};

struct RebindReport
{
  int Rewritten = 0;     // slots that pointed elsewhere and now point at the definition
  int AlreadyBound = 0;  // slots that already pointed at it (the linked-program case)
  int Unbound = 0;       // lazily bound slots not called yet, now set to the definition
  int Objects = 0;       // loaded objects with at least one such import
};

/**
 * Makes every import of `definitions` by a loaded object call the given address. Skipped:
 * the object that holds the definitions (`self`, any address inside it), objects that
 * define the name themselves, and the OpenGL implementation libraries (libGL, libGLX,
 * libOpenGL, libEGL, libOSMesa, Mesa's and vendors' drivers), whose own calls must reach
 * the real functions. Returns false, with `error`, when a slot cannot be written.
 */
bool RebindImports(const std::vector<ImportDefinition>& definitions, const void* self,
  RebindReport& report, std::string& error);

/** Number of objects ever loaded in the process: unchanged means nothing new to rebind. */
unsigned long long LoadedObjectGeneration();

}
}
#endif
