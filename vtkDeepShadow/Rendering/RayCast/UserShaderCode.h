// Internal: the fragment-shader replacements of a volume's vtkShaderProperty, taken at the
// points of our ray caster that correspond to VTK 9.1's tags, with VTK's names for what that
// code reads and writes (Features/UserShader.glsl). A tag with no counterpart refuses them
// all, named in one error. Documentation/VolumeMapper.md has the table.
#ifndef vtkDeepShadowUserShaderCode_h
#define vtkDeepShadowUserShaderCode_h

#include "ShaderComposer.h"

#include <string>
#include <vector>

class vtkVolume;

namespace deepshadow
{

struct UserShaderCode
{
  // The user's code at our hooks (the replacement text, the tag in it replaced by what VTK's
  // mapper puts there, as far as it applies here).
  std::string Dec, Init, Impl, Exit, Output;
  std::string Uniforms; // declarations of the fragment custom uniforms
  /** Why the replacements cannot be taken (one line); empty when they are. */
  std::string Refusal;
  bool Empty() const;
};

/** What `volume`'s shader property asks of the fragment shader. */
UserShaderCode ReadUserShaderCode(vtkVolume* volume);

/** The runtime feature "UserShader" for `code` (not Empty, not refused). */
ShaderFeature UserShaderFeature(const UserShaderCode& code);

}
#endif
