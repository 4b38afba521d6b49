/**
 * @class   vtkDeepShadowTechniqueFactory
 * @brief   Makes the GPU technique the registry names (deepshadow::ShadowTechniques()).
 *
 * Each vtkDeepShadowTechnique subclass registers itself here, in its own .cxx, for the
 * deepshadow::ShadowKind it implements; a technique written outside this module registers
 * the same way. New() turns a registry name ("dsm-color-cached") or a set of parameters
 * into a configured technique, so the tool and the tests need no list of classes.
 */
#ifndef vtkDeepShadowTechniqueFactory_h
#define vtkDeepShadowTechniqueFactory_h

#include "vtkDeepShadowRenderingModule.h"  // For export macro
#include "vtkSmartPointer.h"               // For vtkSmartPointer

#include <string> // For std::string

// C++ only: VTK's wrapper parser does not get through glm's templates, and Python builds a
// technique by class (vtkDeepShadowDeepShadowMapTechnique()) or by name
// (vtkDeepShadowTechnique.NewFromName("dsm")).
#ifndef __VTK_WRAP__
#include "Core/Shadows.h" // For deepshadow::ShadowKind, ShadowParameters

class vtkDeepShadowTechnique;

class VTKDEEPSHADOWRENDERING_EXPORT vtkDeepShadowTechniqueFactory
{
public:
  /** Returns a new technique (the caller owns the reference). */
  using Maker = vtkDeepShadowTechnique* (*)();

  /**
   * Registers the class that implements `kind` (its .cxx does, at load time). Returns true,
   * so that `static const bool registered = Register(...)` runs it.
   */
  static bool Register(deepshadow::ShadowKind kind, Maker maker);

  /**
   * The technique for `parameters` (its kind's class, every parameter applied); null for
   * ShadowKind::None or a kind no class registered.
   */
  static vtkSmartPointer<vtkDeepShadowTechnique> New(const deepshadow::ShadowParameters& parameters);

  /** The technique a registry name gives (NAME or NAME-cached) at its defaults; null for none. */
  static vtkSmartPointer<vtkDeepShadowTechnique> New(const std::string& name);
};

#endif // __VTK_WRAP__
#endif
