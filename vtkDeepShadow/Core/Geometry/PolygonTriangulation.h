// One planar polygon as triangles over its own corners, for every place a mesh's polygons
// become triangles (the poly-data mapper, a bound, a CGAL solid). VTK's vtkPolygon ear-cutter
// takes minutes for a cylinder cap of 20,000 corners, and skips ears it finds too thin
// (the cap then had holes: "not closed: 8 border edges"); a convex polygon is cut here in
// rounds of neighbouring corners, in time linear in its corners, and a concave one is
// ear-clipped in its plane. Geometry tests
// run on the corners scaled by a power of two (exactly), so coordinates near 1e300 do not
// overflow.
#ifndef deepshadow_PolygonTriangulation_h
#define deepshadow_PolygonTriangulation_h

#include "vtkDeepShadowCoreModule.h"

#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace deepshadow
{

/** Corners a concave polygon may have: ear clipping takes time quadratic in them. */
constexpr std::size_t MaxConcavePolygonCorners = 4096;

/**
 * Appends the triangles of the polygon `corners` (in order, closing back to the first) to
 * `triangles` as index triples into `corners`, wound as the polygon is. A convex polygon
 * (collinear corners allowed) loses every other corner to a triangle of it and its two
 * neighbours, round after round; a concave one is ear-clipped in the plane of its Newell
 * normal. Returns false with `problem` set when it
 * cannot be: a concave polygon of more than MaxConcavePolygonCorners corners, or one with no
 * ear left (only a polygon that crosses itself has none; one that crosses itself may also be
 * cut into overlapping triangles, as VTK's own triangulation does). A polygon of fewer than
 * 3 corners gives no triangle.
 */
VTKDEEPSHADOWCORE_EXPORT bool TriangulatePolygon(const std::vector<glm::dvec3>& corners,
  std::vector<std::array<std::size_t, 3>>& triangles, std::string& problem);

/**
 * The polygons (TriangulatePolygon) and strips of a VTK poly data as triangles over its point
 * ids, appended to `triangles`; vertices and lines give none. A template over VTK's
 * vtkPolyData interface (GetPolys, GetStrips, GetPoint), so that Core needs no VTK; the
 * mesh's point ids must be checked first. False with `problem` for a polygon that cannot be
 * triangulated.
 */
template <class PolyData, class Id>
bool TriangulateCells(PolyData* mesh, std::vector<std::array<Id, 3>>& triangles, std::string& problem)
{
  std::vector<glm::dvec3> corners;
  std::vector<std::array<std::size_t, 3>> local;
  Id n = 0;
  const Id* ids = nullptr;
  auto* polys = mesh->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
  {
    corners.resize(static_cast<std::size_t>(n));
    for (Id i = 0; i < n; ++i)
    {
      mesh->GetPoint(ids[i], &corners[static_cast<std::size_t>(i)].x);
    }
    local.clear();
    if (!TriangulatePolygon(corners, local, problem))
    {
      return false;
    }
    for (const auto& t : local)
    {
      triangles.push_back({ ids[t[0]], ids[t[1]], ids[t[2]] });
    }
  }
  auto* strips = mesh->GetStrips();
  for (strips->InitTraversal(); strips->GetNextCell(n, ids);)
  {
    for (Id i = 0; i + 2 < n; ++i)
    {
      triangles.push_back(i % 2 == 0 ? std::array<Id, 3>{ ids[i], ids[i + 1], ids[i + 2] }
                                     : std::array<Id, 3>{ ids[i + 1], ids[i], ids[i + 2] });
    }
  }
  return true;
}

}
#endif
