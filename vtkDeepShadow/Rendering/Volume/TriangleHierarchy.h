// Internal: triangle hierarchies on the GPU (Features/TriangleHierarchy.glsl). One holder type,
// TriangleHierarchy, for the textures; the volume's polyhedral bound and the surfaces that cast
// shadows onto it each keep one, with what it was built from.
#ifndef vtkDeepShadowTriangleHierarchy_h
#define vtkDeepShadowTriangleHierarchy_h

#include "vtkSmartPointer.h"
#include "vtkTextureObject.h" // held by vtkSmartPointer, returned as a raw pointer
#include "vtkType.h"

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include <memory>
#include <string>
#include <vector>

class vtkOpenGLRenderWindow;
class vtkPolyData;
class vtkWindow;

namespace deepshadow
{
class BoundRegion;
class SurfaceSet;

/**
 * Surfaces that cast shadows as the GPU finds them (Features/Surfaces.glsl): one hierarchy
 * in the volume's index space, and each surface's transmission (rgb coloured, a grey).
 */
struct SurfaceTextures
{
  vtkTextureObject* Nodes = nullptr;
  vtkTextureObject* Triangles = nullptr;
  int Root = -1;
  std::vector<glm::vec4> Transmission;
};

/** A volume's polyhedral bound as the GPU walks it (Features/Bound.glsl). */
struct BoundTextures
{
  vtkTextureObject* Nodes = nullptr;
  vtkTextureObject* Triangles = nullptr;
  std::vector<int> LeafRoots;
  std::vector<int> TruthTable;
};

/** A hierarchy's nodes and triangles as float texels (GL/FloatTexels). */
class TriangleHierarchy
{
public:
  /** Why this GL cannot hold the hierarchy ("" if it can). */
  static std::string Limit(const std::vector<glm::vec4>& nodes, const std::vector<glm::vec4>& triangles, int maxDepth);
  void Upload(vtkOpenGLRenderWindow* window, std::vector<glm::vec4> nodes, std::vector<glm::vec4> triangles);
  void Release(vtkWindow* window);

  vtkTextureObject* GetNodes() const { return this->Nodes; }
  vtkTextureObject* GetTriangles() const { return this->Triangles; }
  long long GetBytes() const { return this->Bytes; }

private:
  vtkSmartPointer<vtkTextureObject> Nodes;
  vtkSmartPointer<vtkTextureObject> Triangles;
  long long Bytes = 0;
};

/** The volume's polyhedral bound (feature Bound): its region and hierarchy. */
class BoundHierarchy
{
public:
  /** Whether the bound was built from other meshes (their MTimes), expression or placement. */
  bool NeedsUpdate(const std::vector<vtkMTimeType>& times, const std::string& expression,
    const glm::dmat4& dataToIndex) const;
  /**
   * Builds the region and uploads it; true if it was uploaded, false on bad bounds (GetError()
   * says why).
   */
  bool Update(vtkOpenGLRenderWindow* window, const std::vector<vtkPolyData*>& meshes,
    const std::vector<vtkMTimeType>& times, const std::string& expression, const glm::dmat4& dataToIndex);
  /** No bounds: the volume fills its box (the textures are kept for the next bound). */
  void Clear();
  void Release(vtkWindow* window);

  /** The bound as the GPU walks it; null when the volume is not bounded. */
  const BoundTextures* GetTextures() const { return this->Region ? &this->Textures : nullptr; }
  bool EnclosesNothing() const { return this->Nothing; }
  const std::string& GetError() const { return this->Error; }
  long long GetBytes() const { return this->Region ? this->Hierarchy.GetBytes() : 0; }

private:
  std::shared_ptr<const BoundRegion> Region;
  TriangleHierarchy Hierarchy;
  BoundTextures Textures;
  std::vector<vtkMTimeType> Times; // each bound's MTime when built
  std::string Expression;
  glm::dmat4 DataToIndex{ 0.0 };
  bool Nothing = false;
  std::string Error;
};

/** The surfaces that cast shadows onto the volume, in its index space (feature Surfaces). */
class SurfaceHierarchy
{
public:
  bool NeedsUpdate(const std::shared_ptr<const SurfaceSet>& surfaces, const glm::dmat4& worldToIndex) const
  {
    return this->BuiltFrom != surfaces || this->WorldToIndex != worldToIndex;
  }
  /** Uploads `surfaces` carried by `worldToIndex`; "" or why this GL cannot hold them. */
  std::string Update(vtkOpenGLRenderWindow* window, const std::shared_ptr<const SurfaceSet>& surfaces,
    const glm::dmat4& worldToIndex);
  /** No surfaces: the next set is uploaded whatever it is. */
  void Clear() { this->BuiltFrom.reset(); }
  void Release(vtkWindow* window);

  const SurfaceTextures& GetTextures() const { return this->Textures; }
  long long GetBytes() const { return this->Hierarchy.GetBytes(); }

private:
  // Held, not a raw pointer: a new set allocated where a freed one was is still new.
  std::shared_ptr<const SurfaceSet> BuiltFrom;
  glm::dmat4 WorldToIndex{ 0.0 };
  TriangleHierarchy Hierarchy;
  SurfaceTextures Textures;
};

}
#endif
