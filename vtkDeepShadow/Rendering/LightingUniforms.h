// Internal: the Lighting feature's uniforms (Shaders/Features/Lighting.glsl), shared by the
// volume and poly-data mappers so that volumes and meshes are lit by one formula.
#ifndef vtkDeepShadowLightingUniforms_h
#define vtkDeepShadowLightingUniforms_h

#include "Light.h"
#include "OpticalModel.h"
#include "Volume/ShadowContext.h"

#include <vector>

class vtkRenderer;

namespace deepshadow
{

/** Lights in world space (in the order given), ambient light, two-sided lighting, material. */
void SetLightingUniforms(UniformSink& sink, const std::vector<Light>& lights, vtkRenderer* renderer,
  const Material& material);

}
#endif
