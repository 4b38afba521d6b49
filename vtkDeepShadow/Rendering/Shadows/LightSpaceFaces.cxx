#include "LightSpaceFaces.h"

#include "GL/UniformSink.h"
#include "vtkDeepShadowLightSpace.h"

#include <algorithm>

namespace deepshadow
{

std::string LightSpaceSource(const SlotFaces& faces)
{
  bool perspective = false, orthographic = false, cubes = false;
  for (const auto& lightFaces : faces)
  {
    cubes = cubes || lightFaces.size() == 6;
    for (const ShadowMapFace& face : lightFaces)
    {
      (face.Perspective ? perspective : orthographic) = true;
    }
  }
  if (!perspective && !orthographic)
  {
    perspective = orthographic = cubes = true;
  }
  std::string defines;
  defines += perspective ? "#define LIGHT_SPACE_PERSPECTIVE\n" : "";
  defines += orthographic ? "#define LIGHT_SPACE_ORTHOGRAPHIC\n" : "";
  defines += cubes ? "#define LIGHT_SPACE_CUBES\n" : "";
  defines += "#define LIGHT_SPACE_SLOTS " + std::to_string(std::max<size_t>(faces.size(), 1)) + "\n";
  return "//@Dec\n" + defines + vtkDeepShadowLightSpace;
}

void SetLightSpaceFaceUniforms(
  UniformSink& sink, const SlotFaces& faces, float size, int facesPerLight, int layersPerFace)
{
  std::vector<int> faceCount, perspective;
  std::vector<glm::vec3> origin, forward, right, up;
  std::vector<float> extent, nearDistance;
  for (const auto& slotFaces : faces)
  {
    faceCount.push_back(static_cast<int>(slotFaces.size()));
    perspective.push_back(slotFaces.front().Perspective ? 1 : 0);
    origin.emplace_back(slotFaces.front().Origin);
    forward.emplace_back(slotFaces.front().Forward);
    right.emplace_back(slotFaces.front().Right);
    up.emplace_back(slotFaces.front().Up);
    extent.push_back(static_cast<float>(slotFaces.front().Extent));
    nearDistance.push_back(static_cast<float>(slotFaces.front().Near));
  }
  sink.Set("u_shadowFaceCount", faceCount);
  sink.Set("u_shadowPerspective", perspective);
  sink.Set("u_shadowOrigin", origin);
  sink.Set("u_shadowForward", forward);
  sink.Set("u_shadowRight", right);
  sink.Set("u_shadowUp", up);
  sink.Set("u_shadowExtent", extent);
  sink.Set("u_shadowNear", nearDistance);
  sink.Set("u_shadowSize", size);
  sink.Set("u_shadowFacesPerLight", facesPerLight);
  sink.Set("u_shadowLayersPerFace", layersPerFace);
}
}
