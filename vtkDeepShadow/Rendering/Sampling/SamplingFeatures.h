// Internal: the features of the volume's data (its components, opacity modifiers, mask, empty
// space, bound, casting surfaces), one entry each, registered in one list (SamplingFeatures.cxx).
// Every shader that reads the volume is composed of and bound with these entries: the ray
// caster's (RayCast/VolumeFeatures adds the view's own features), a technique's build passes
// and a mesh receiver's shadow lookup. Adding a data feature: its .glsl file, its tags in the
// templates, and one entry in the list.
#ifndef vtkDeepShadowSamplingFeatures_h
#define vtkDeepShadowSamplingFeatures_h

#include "ShaderComposer.h"

#include <vector>

namespace deepshadow
{
struct ShadowContext;
class UniformSink;

/** Which shader reads the volume: whether the shadow-casting surfaces are met by its marches. */
struct SamplingUse
{
  const ShadowContext& Context;
  bool Surfaces = false; // ShadowContext::Surfaces are intersected (when there are any)
};

struct SamplingFeature
{
  /** Its GLSL: the embedded feature of this name (unless Compose says otherwise). */
  const char* Name;
  /** Whether the volume, as read by this use, has it. */
  bool (*Enabled)(const SamplingUse& use);
  /** Optional: adds what it is made of instead of Name (parts built at run time). */
  void (*Compose)(const ShadowContext& context, ComposedFeatures& features);
  /** Optional: activates its textures and sets its uniforms on the composed program (in use). */
  void (*Bind)(const ShadowContext& context, UniformSink& sink);
  /** Optional: releases its textures after the draw. */
  void (*Unbind)(const ShadowContext& context);
};

/** Every data feature, in the order they are composed and bound. */
const std::vector<SamplingFeature>& SamplingFeatures();

/** Adds the enabled features' GLSL to `features`. */
void ComposeSamplingFeatures(const SamplingUse& use, ComposedFeatures& features);
/** Binds, then unbinds, every enabled feature. */
void BindSamplingFeatures(const SamplingUse& use, UniformSink& sink);
void UnbindSamplingFeatures(const SamplingUse& use);

}
#endif
