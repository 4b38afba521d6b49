// Internal: what the other volumes of a scene cast onto one receiver (a volume or a mesh).
//
// Light reaching a point crosses every volume on its way, and optical depths add, so a
// light's visibility is the product of every shadowing volume's answer. A receiver's own
// volume (or, for meshes, the scene's first shadowing volume) is looked up by its technique's
// shader code; the other volumes' techniques are evaluated once per node of a grid over the
// receiver (deepshadow::GridFrame) by their own lookups (vtkDeepShadowTechnique::
// EvaluateOnGrid), multiplied together into one RGBA16F texel per node and light, and fetched
// trilinearly by the receiver (Features/OtherVolumeShadows.glsl). Two techniques' shader code
// never meets in one program this way. The grid is rebuilt only when a caster, its
// structures, the lights or the receiver's placement changed. The CPU twin is
// deepshadow::ReferenceRenderer with Scene::OtherVolumeShadowSize > 0.
#ifndef vtkDeepShadowOtherVolumeShadows_h
#define vtkDeepShadowOtherVolumeShadows_h

#include "Core/Shadows/ShadowGrid.h"

#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkDeepShadowTechnique;
class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

namespace deepshadow
{
struct ShadowContext;
class UniformSink;

/** A volume that casts onto others: its technique, prepared this frame, and its context. */
struct VolumeCaster
{
  vtkDeepShadowTechnique* Technique = nullptr;
  const ShadowContext* Context = nullptr;
};

class OtherVolumeShadows
{
public:
  /**
   * Brings the grid over `frame` up to date with what `casters` cast for each of their
   * lights (slab l: the casters' light l). False, with `error`, if a pass failed or the grid
   * exceeds the GL's 3D texture limit; the receiver then gets nothing from them.
   */
  bool Update(vtkOpenGLRenderWindow* window, const GridFrame& frame,
    const std::vector<VolumeCaster>& casters, std::string& error);

  /** Whether any light is shadowed by the casters (the receiver needs the feature). */
  bool Any() const { return this->WrittenSlabs != 0; }
  int GetBuildCount() const { return this->Builds; }
  long long GetBytes() const;

  /** Binds the grid and sets Features/OtherVolumeShadows.glsl's uniforms. */
  void Activate(UniformSink& sink, int lightCount) const;
  void Deactivate() const;
  void Release(vtkWindow* window);

private:
  vtkSmartPointer<vtkTextureObject> Grid;
  GridFrame Frame;
  int Slabs = 0;
  int WrittenSlabs = 0; // bit l: light l is shadowed by a caster
  std::vector<double> Key;
  int Builds = 0;
};

}
#endif
