#include "LightSpaceClusters.h"

#include "GL/ClampedTexture.h"
#include "GL/ComputeProgram.h"
#include "GL/UniformSink.h"

#include "vtkTextureObject.h"

#include <algorithm>

namespace deepshadow
{
namespace
{
// LightSpace.glsl's MaxClusterFaces and MaxShadowLights.
constexpr size_t MaxClusterFaces = 8;
constexpr size_t MaxShadowLights = 4;

bool SameBoxes(const std::vector<IndexBox>& a, const std::vector<IndexBox>& b)
{
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](const IndexBox& x, const IndexBox& y) {
    return x.Lo == y.Lo && x.Hi == y.Hi;
  });
}
}

void LightSpaceClusters::BeginFrame(int slots)
{
  this->LastSlots = std::move(this->Slots);
  this->Slots.assign(static_cast<size_t>(slots), ClusteredFaces());
}

void LightSpaceClusters::Cluster(int slot, const Light& light, const glm::dmat4& indexToWorld,
  const glm::ivec3& dims, const EmptySpaceMap& empty, const SurfaceSet* surfaces, int maxClusters,
  double distance, const glm::dvec3& eye, std::vector<ShadowMapFace>& faces)
{
  ClusteredFaces& clustered = this->Slots[static_cast<size_t>(slot)];
  clustered = ClusterFaces(light, indexToWorld, dims, empty, surfaces, maxClusters, distance, &eye);
  faces = clustered.Faces;
}

bool LightSpaceClusters::EndFrame(vtkOpenGLRenderWindow* window, const glm::ivec3& blockCount)
{
  // A slot that disappeared or appeared counts as unclustered on the other side.
  bool changed = false;
  const ClusteredFaces none;
  for (size_t slot = 0; slot < std::max(this->Slots.size(), this->LastSlots.size()); ++slot)
  {
    const ClusteredFaces& now = slot < this->Slots.size() ? this->Slots[slot] : none;
    const ClusteredFaces& before = slot < this->LastSlots.size() ? this->LastSlots[slot] : none;
    changed = changed || !SameBoxes(now.Clips, before.Clips);
  }
  if (!changed)
  {
    return false;
  }
  this->Labels.assign(this->Slots.size(), nullptr);
  for (size_t slot = 0; slot < this->Slots.size(); ++slot)
  {
    if (this->Slots[slot].Faces.empty())
    {
      continue;
    }
    vtkSmartPointer<vtkTextureObject> labels = NewClampedTexture(window);
    labels->SetMinificationFilter(vtkTextureObject::Nearest);
    labels->SetMagnificationFilter(vtkTextureObject::Nearest);
    labels->Create3DFromRaw(static_cast<unsigned int>(blockCount.x), static_cast<unsigned int>(blockCount.y),
      static_cast<unsigned int>(blockCount.z), 1, VTK_UNSIGNED_CHAR, this->Slots[slot].BlockLabels.data());
    this->Labels[slot] = labels;
  }
  return true;
}

bool LightSpaceClusters::Any() const
{
  return std::any_of(this->Slots.begin(), this->Slots.end(), [](const ClusteredFaces& c) { return !c.Faces.empty(); });
}

std::vector<int> LightSpaceClusters::Counts() const
{
  std::vector<int> counts;
  for (const ClusteredFaces& clustered : this->Slots)
  {
    counts.push_back(static_cast<int>(clustered.Faces.size()));
  }
  return counts;
}

std::string LightSpaceClusters::BuildDefines() const
{
  return this->Any() ? "//@Dec\n#define LIGHT_SPACE_CLIP\n" : "";
}

void LightSpaceClusters::ActivateLabels()
{
  for (auto& labels : this->Labels)
  {
    if (labels)
    {
      labels->Activate();
    }
  }
}

void LightSpaceClusters::DeactivateLabels()
{
  for (auto& labels : this->Labels)
  {
    if (labels)
    {
      labels->Deactivate();
    }
  }
}

void LightSpaceClusters::SetBuildUniforms(ComputeProgram& build, int slot, int face) const
{
  if (!this->Any())
  {
    return;
  }
  const ClusteredFaces& clustered = this->Slots[static_cast<size_t>(slot)];
  if (clustered.Faces.empty())
  {
    // An unclustered light beside clustered ones: all of the volume, every occupied block.
    build.Set("u_clipLo", glm::vec3(-1e30f));
    build.Set("u_clipHi", glm::vec3(1e30f));
    build.Set("u_clipLabel", 0);
    build.Set("u_clipSurfaces", 1);
    return;
  }
  build.Set("u_clipLo", glm::vec3(clustered.Clips[static_cast<size_t>(face)].Lo));
  build.Set("u_clipHi", glm::vec3(clustered.Clips[static_cast<size_t>(face)].Hi));
  build.Set("u_clipLabel", face + 1);
  build.Set("u_clipSurfaces", clustered.CastsSurfaces[static_cast<size_t>(face)] ? 1 : 0);
  build.Set("u_clusterLabels", this->Labels[static_cast<size_t>(slot)]->GetTextureUnit());
}

std::string LightSpaceClusters::LookupDefines() const
{
  if (!this->Any())
  {
    return "";
  }
  // An unclustered light that needs a cube of faces keeps the unclustered lookup beside the
  // loop (LIGHT_SPACE_CUBES, from the technique's face kinds).
  return "//@Dec\n#define LIGHT_SPACE_CLUSTERS\n";
}

void LightSpaceClusters::SetLookupUniforms(UniformSink& sink, const std::vector<std::vector<ShadowMapFace>>& faces) const
{
  if (!this->Any())
  {
    return;
  }
  // Face f of slot s at s * MaxClusterFaces + f. A light that is not clustered has its one
  // face there, unwindowed; a cube none (the unclustered lookup).
  const size_t entries = MaxShadowLights * MaxClusterFaces;
  std::vector<int> counts, perspective(entries, 0), windowed(entries, 0);
  std::vector<glm::vec3> origin(entries), forward(entries), right(entries), up(entries);
  std::vector<float> extent(entries, 1.0f), nearDistance(entries, 0.0f), start(entries, 0.0f);
  for (size_t slot = 0; slot < faces.size(); ++slot)
  {
    const bool clustered = slot < this->Slots.size() && !this->Slots[slot].Faces.empty();
    const size_t count = clustered || faces[slot].size() == 1 ? faces[slot].size() : 0;
    counts.push_back(static_cast<int>(count));
    for (size_t f = 0; f < count; ++f)
    {
      const ShadowMapFace& face = faces[slot][f];
      const size_t i = slot * MaxClusterFaces + f;
      perspective[i] = face.Perspective ? 1 : 0;
      origin[i] = glm::vec3(face.Origin);
      forward[i] = glm::vec3(face.Forward);
      right[i] = glm::vec3(face.Right);
      up[i] = glm::vec3(face.Up);
      extent[i] = static_cast<float>(face.Extent);
      nearDistance[i] = static_cast<float>(face.Near);
      windowed[i] = clustered ? 1 : 0;
      start[i] = clustered ? static_cast<float>(this->Slots[slot].Starts[f]) : 0.0f;
    }
  }
  sink.Set("u_shadowClusters", counts);
  sink.Set("u_shadowClusterPerspective", perspective);
  sink.Set("u_shadowClusterOrigin", origin);
  sink.Set("u_shadowClusterForward", forward);
  sink.Set("u_shadowClusterRight", right);
  sink.Set("u_shadowClusterUp", up);
  sink.Set("u_shadowClusterExtent", extent);
  sink.Set("u_shadowClusterNear", nearDistance);
  sink.Set("u_shadowClusterStart", start);
  sink.Set("u_shadowClusterWindowed", windowed);
}

void LightSpaceClusters::Release(vtkWindow* window)
{
  for (auto& labels : this->Labels)
  {
    if (labels && window)
    {
      labels->ReleaseGraphicsResources(window);
    }
  }
  this->Labels.clear();
  this->Slots.clear();
  this->LastSlots.clear();
}

}
