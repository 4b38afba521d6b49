// Internal: what every technique that looks up light-space faces shares (the light-space
// maps and the resolution-matched maps): Shaders/Shadows/LightSpace.glsl composed for the
// kinds of face the lights use, and its face uniforms.
#ifndef vtkDeepShadowLightSpaceFaces_h
#define vtkDeepShadowLightSpaceFaces_h

#include "Core/Shadows/LightSpace.h"

#include <string>
#include <vector>

namespace deepshadow
{
class UniformSink;

/** Faces per shadowed light (slot). */
using SlotFaces = std::vector<std::vector<ShadowMapFace>>;

/**
 * LightSpace.glsl with the kinds of face the lights use defined (LIGHT_SPACE_PERSPECTIVE,
 * _ORTHOGRAPHIC, _CUBES; before any face exists, every kind), so that only their code is
 * compiled, and LIGHT_SPACE_SLOTS, the number of lights that cast shadows; as a feature's
 * Dec part.
 */
std::string LightSpaceSource(const SlotFaces& faces);

/**
 * LightSpace.glsl's face uniforms: each slot's first face (a cube's are derived from it),
 * its face count, the map size in texels per side, faces per light and layers per face.
 */
void SetLightSpaceFaceUniforms(
  UniformSink& sink, const SlotFaces& faces, float size, int facesPerLight, int layersPerFace);
}

#endif
