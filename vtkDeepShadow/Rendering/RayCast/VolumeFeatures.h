// Internal: the ray caster's features, one component each, registered in one list
// (VolumeFeatures.cxx), as Inviwo's raycaster components are. A component names its GLSL
// (Shaders/Features/<Name>.glsl, embedded by the module's CMake without a list), says from the
// frame's state when it is on, and binds and unbinds its uniforms and textures. The volume's
// data features (Sampling/SamplingFeatures.h) come first; these are what the view adds. Adding
// a feature: its .glsl file, its tag in the template, and one entry in the list.
#ifndef vtkDeepShadowVolumeFeatures_h
#define vtkDeepShadowVolumeFeatures_h

#include "ShaderComposer.h"

#include <vector>

namespace deepshadow
{
struct RayCastFrame;
class UniformSink;

struct VolumeFeature
{
  /** Its GLSL: the embedded feature of this name (unless Compose says otherwise). */
  const char* Name;
  /** Whether the frame uses it. */
  bool (*Enabled)(const RayCastFrame& frame);
  /** Optional: adds what it is made of instead of Name (parts built at run time, others it needs). */
  void (*Compose)(const RayCastFrame& frame, ComposedFeatures& features);
  /** Optional: activates its textures and sets its uniforms on the composed program. */
  void (*Bind)(const RayCastFrame& frame, UniformSink& sink);
  /** Optional: releases its textures after the draw. */
  void (*Unbind)(const RayCastFrame& frame);
};

/** The view's features of the ray caster, in the order they are bound (after the data's). */
const std::vector<VolumeFeature>& VolumeFeatures();

/** The enabled features' GLSL, the data's and the view's. */
ComposedFeatures ComposeVolumeFeatures(const RayCastFrame& frame);
/** Binds, then unbinds, every enabled feature. */
void BindVolumeFeatures(const RayCastFrame& frame, UniformSink& sink);
void UnbindVolumeFeatures(const RayCastFrame& frame);

}
#endif
