#include "Volume/TriangleHierarchy.h"

#include "Core/Bound/BoundRegion.h"
#include "CoreAdapter.h"
#include "GL/FloatTexels.h"
#include "Core/Geometry/SurfaceSet.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkTextureObject.h"

#include <algorithm>

namespace deepshadow
{

std::string TriangleHierarchy::Limit(
  const std::vector<glm::vec4>& nodes, const std::vector<glm::vec4>& triangles, int maxDepth)
{
  return FloatTexelsLimit(std::max(triangles.size(), nodes.size()), triangles.size() / 3, maxDepth);
}

void TriangleHierarchy::Upload(
  vtkOpenGLRenderWindow* window, std::vector<glm::vec4> nodes, std::vector<glm::vec4> triangles)
{
  this->Bytes = UploadFloatTexels(window, this->Nodes, std::move(nodes)) +
    UploadFloatTexels(window, this->Triangles, std::move(triangles));
}

void TriangleHierarchy::Release(vtkWindow* window)
{
  for (vtkTextureObject* texture : { this->Nodes.Get(), this->Triangles.Get() })
  {
    if (texture)
    {
      texture->ReleaseGraphicsResources(window);
    }
  }
  *this = TriangleHierarchy();
}

bool BoundHierarchy::NeedsUpdate(
  const std::vector<vtkMTimeType>& times, const std::string& expression, const glm::dmat4& dataToIndex) const
{
  return times != this->Times || expression != this->Expression || dataToIndex != this->DataToIndex;
}

bool BoundHierarchy::Update(vtkOpenGLRenderWindow* window, const std::vector<vtkPolyData*>& meshes,
  const std::vector<vtkMTimeType>& times, const std::string& expression, const glm::dmat4& dataToIndex)
{
  this->Times = times;
  this->Expression = expression;
  this->DataToIndex = dataToIndex;
  this->Region = adapter::MakeBoundRegion(meshes, expression, dataToIndex, this->Error);
  if (!this->Region)
  {
    return false;
  }
  BoundRegion::GPUData data = this->Region->PackForGPU();
  const std::string limit = TriangleHierarchy::Limit(data.Nodes, data.Triangles, data.MaxDepth);
  if (!limit.empty())
  {
    this->Error = "the bound cannot be used: " + limit;
    this->Region.reset();
    return false;
  }
  this->Hierarchy.Upload(window, std::move(data.Nodes), std::move(data.Triangles));
  this->Textures.Nodes = this->Hierarchy.GetNodes();
  this->Textures.Triangles = this->Hierarchy.GetTriangles();
  this->Textures.LeafRoots = data.LeafRoots;
  this->Textures.TruthTable = data.TruthTable;
  // Nothing can be inside when the states the empty bounds allow all evaluate false.
  uint32_t emptyLeaves = 0;
  for (int i = 0; i < this->Region->GetLeafCount(); ++i)
  {
    emptyLeaves |= this->Region->GetLeaf(i).Empty() ? (1u << i) : 0u;
  }
  this->Nothing = true;
  for (uint32_t state = 0; state < (1u << this->Region->GetLeafCount()); ++state)
  {
    if (!(state & emptyLeaves) && this->Region->GetExpression().Evaluate(state))
    {
      this->Nothing = false;
      break;
    }
  }
  return true;
}

void BoundHierarchy::Clear()
{
  this->Region.reset();
  this->Times.clear();
}

void BoundHierarchy::Release(vtkWindow* window)
{
  this->Hierarchy.Release(window);
  *this = BoundHierarchy();
}

std::string SurfaceHierarchy::Update(vtkOpenGLRenderWindow* window,
  const std::shared_ptr<const SurfaceSet>& surfaces, const glm::dmat4& worldToIndex)
{
  SurfaceSet::GPUData data = surfaces->PackForGPU(worldToIndex);
  const std::string limit = TriangleHierarchy::Limit(data.Nodes, data.Triangles, data.MaxDepth);
  if (!limit.empty())
  {
    return limit;
  }
  this->Hierarchy.Upload(window, std::move(data.Nodes), std::move(data.Triangles));
  this->Textures.Nodes = this->Hierarchy.GetNodes();
  this->Textures.Triangles = this->Hierarchy.GetTriangles();
  this->Textures.Root = data.Root;
  this->Textures.Transmission = data.Transmission;
  this->Textures.Transmission.resize(SurfaceSet::MaxSurfaces, glm::vec4(1.0f));
  this->BuiltFrom = surfaces;
  this->WorldToIndex = worldToIndex;
  return "";
}

void SurfaceHierarchy::Release(vtkWindow* window)
{
  this->Hierarchy.Release(window);
  *this = SurfaceHierarchy();
}

}
