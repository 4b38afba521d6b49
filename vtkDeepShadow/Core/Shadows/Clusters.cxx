#include "Core/Shadows/Clusters.h"

#include "Core/Geometry/SurfaceSet.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/vector_relational.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace deepshadow
{

VolumeObjects OccupiedObjects(const EmptySpaceMap& empty, const glm::ivec3& dims)
{
  const glm::ivec3 count = empty.Blocks.BlockCount;
  const int size = empty.Blocks.BlockSize;
  const auto at = [&](const glm::ivec3& b) { return (static_cast<size_t>(b.z) * count.y + b.y) * count.x + b.x; };
  VolumeObjects objects;
  objects.BlockObject.assign(empty.Occupied.size(), -1);
  std::vector<glm::ivec3> stack;
  for (int k = 0; k < count.z; ++k)
    for (int j = 0; j < count.y; ++j)
      for (int i = 0; i < count.x; ++i)
      {
        const glm::ivec3 first(i, j, k);
        if (!empty.Occupied[at(first)] || objects.BlockObject[at(first)] >= 0)
        {
          continue;
        }
        const int id = static_cast<int>(objects.Boxes.size());
        glm::ivec3 lo = first, hi = first;
        objects.BlockObject[at(first)] = id;
        stack.assign(1, first);
        while (!stack.empty())
        {
          const glm::ivec3 b = stack.back();
          stack.pop_back();
          lo = glm::min(lo, b);
          hi = glm::max(hi, b);
          for (int n = 0; n < 27; ++n)
          {
            const glm::ivec3 next = b + glm::ivec3(n % 3 - 1, (n / 3) % 3 - 1, n / 9 - 1);
            if (glm::any(glm::lessThan(next, glm::ivec3(0))) || glm::any(glm::greaterThanEqual(next, count)) ||
              !empty.Occupied[at(next)] || objects.BlockObject[at(next)] >= 0)
            {
              continue;
            }
            objects.BlockObject[at(next)] = id;
            stack.push_back(next);
          }
        }
        // Block b holds the samples at indices [b * size, (b + 1) * size); one voxel of apron.
        IndexBox box;
        box.Lo = glm::max(glm::dvec3(lo * size) - 1.0, glm::dvec3(0.0));
        box.Hi = glm::min(glm::dvec3((hi + 1) * size) + 1.0, glm::dvec3(dims - 1));
        objects.Boxes.push_back(box);
      }
  return objects;
}

double ExtentDistance(const glm::dvec4& a, const glm::dvec4& b)
{
  return std::max(glm::length(glm::dvec2(a.x, a.y) - glm::dvec2(b.x, b.y)),
    glm::length(glm::dvec2(a.z, a.w) - glm::dvec2(b.z, b.w)));
}

std::vector<int> ClusterObjects(size_t n, const std::function<double(size_t, size_t)>& distance,
  int maxClusters, double threshold, const std::vector<double>* weights)
{
  const auto weight = [&](size_t o) { return weights ? std::max(1.0, (*weights)[o]) : 1.0; };
  std::vector<double> d(n * n, 0.0);
  std::vector<std::pair<size_t, size_t>> pairs;
  for (size_t i = 0; i < n; ++i)
  {
    for (size_t j = i + 1; j < n; ++j)
    {
      d[i * n + j] = d[j * n + i] = distance(i, j) * std::max(weight(i), weight(j));
      pairs.emplace_back(i, j);
    }
  }
  std::stable_sort(pairs.begin(), pairs.end(),
    [&](const auto& a, const auto& b) { return d[a.first * n + a.second] < d[b.first * n + b.second]; });
  // Objects in the order they first appear in the sorted pairs (a lone object: itself),
  // heavier objects first.
  std::vector<size_t> order;
  std::vector<bool> listed(n, false);
  for (const auto& pair : pairs)
  {
    for (const size_t o : { pair.first, pair.second })
    {
      if (!listed[o])
      {
        listed[o] = true;
        order.push_back(o);
      }
    }
  }
  for (size_t o = 0; o < n; ++o)
  {
    if (!listed[o])
    {
      order.push_back(o);
    }
  }
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return weight(a) > weight(b); });

  std::vector<std::vector<size_t>> clusters;
  const auto farthest = [&](size_t c, size_t o) {
    double far = 0.0;
    for (const size_t member : clusters[c])
    {
      far = std::max(far, d[member * n + o]);
    }
    return far;
  };
  // The cluster whose farthest member is nearest to o (the first of equals).
  const auto nearest = [&](size_t o) {
    size_t best = 0;
    for (size_t c = 1; c < clusters.size(); ++c)
    {
      if (farthest(c, o) < farthest(best, o))
      {
        best = c;
      }
    }
    return best;
  };
  std::vector<size_t> remaining;
  const size_t most = static_cast<size_t>(std::max(1, maxClusters));
  for (const size_t o : order)
  {
    if (!clusters.empty() && farthest(nearest(o), o) <= threshold)
    {
      clusters[nearest(o)].push_back(o);
    }
    else if (clusters.size() < most)
    {
      clusters.push_back({ o });
    }
    else
    {
      remaining.push_back(o);
    }
  }
  for (const size_t o : remaining)
  {
    clusters[nearest(o)].push_back(o);
  }
  std::vector<int> cluster(n, 0);
  for (size_t c = 0; c < clusters.size(); ++c)
  {
    for (const size_t o : clusters[c])
    {
      cluster[o] = static_cast<int>(c);
    }
  }
  return cluster;
}

namespace
{
std::vector<glm::dvec3> WorldCorners(const IndexBox& box, const glm::dmat4& indexToWorld)
{
  std::vector<glm::dvec3> corners;
  for (int c = 0; c < 8; ++c)
  {
    const glm::dvec3 index((c & 1) ? box.Hi.x : box.Lo.x, (c & 2) ? box.Hi.y : box.Lo.y, (c & 4) ? box.Hi.z : box.Lo.z);
    corners.emplace_back(indexToWorld * glm::dvec4(index, 1.0));
  }
  return corners;
}

// The surfaces' box in index space (where the faces clip).
IndexBox SurfacesBox(const SurfaceSet& surfaces, const glm::dmat4& indexToWorld)
{
  const TriangleBVH::Node& root = surfaces.GetHierarchy().GetNodes().front();
  const glm::dmat4 worldToIndex = glm::inverse(indexToWorld);
  const double far = std::numeric_limits<double>::infinity();
  IndexBox box{ glm::dvec3(far), glm::dvec3(-far) };
  for (int c = 0; c < 8; ++c)
  {
    const glm::dvec3 world((c & 1) ? root.Max.x : root.Min.x, (c & 2) ? root.Max.y : root.Min.y,
      (c & 4) ? root.Max.z : root.Min.z);
    const glm::dvec3 index(worldToIndex * glm::dvec4(world, 1.0));
    box.Lo = glm::min(box.Lo, index - 1.0);
    box.Hi = glm::max(box.Hi, index + 1.0);
  }
  return box;
}

// Whether a sphere lies wholly outside a spot light's cone.
bool OutsideSpot(const Light& light, const glm::dvec3& centre, double radius)
{
  if (!light.Positional || light.ConeCosine() < -1.0)
  {
    return false;
  }
  const glm::dvec3 toCentre = centre - light.Position;
  const double distance = glm::length(toCentre);
  const glm::dvec3 axis = light.FocalPoint - light.Position;
  if (distance <= radius || glm::length(axis) == 0.0)
  {
    return false;
  }
  const double angle = std::acos(std::clamp(glm::dot(toCentre, axis) / (distance * glm::length(axis)), -1.0, 1.0));
  const double cone = light.ConeAngle * 3.14159265358979323846 / 180.0;
  return angle > cone + std::asin(radius / distance);
}

// Each object's angular size from the eye over the median object's, as a power of two >= 1.
std::vector<double> ScreenWeights(const std::vector<IndexBox>& objects, const glm::dmat4& indexToWorld, const glm::dvec3& eye)
{
  std::vector<double> angles;
  for (const IndexBox& object : objects)
  {
    const std::vector<glm::dvec3> corners = WorldCorners(object, indexToWorld);
    const glm::dvec3 centre = 0.5 * (corners.front() + corners.back());
    const double radius = 0.5 * glm::length(corners.back() - corners.front());
    angles.push_back(radius / std::max(glm::length(centre - eye), radius));
  }
  std::vector<double> sorted = angles;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<long>(sorted.size() / 2), sorted.end());
  const double median = sorted[sorted.size() / 2];
  std::vector<double> weights;
  for (const double angle : angles)
  {
    weights.push_back(std::max(1.0, std::exp2(std::round(std::log2(angle / median)))));
  }
  return weights;
}
}

ClusteredFaces ClusterFaces(const Light& light, const glm::dmat4& indexToWorld, const glm::ivec3& dims,
  const EmptySpaceMap& empty, const SurfaceSet* surfaces, int maxClusters, double distanceThreshold,
  const glm::dvec3* eye)
{
  const VolumeObjects volumeObjects = OccupiedObjects(empty, dims);
  std::vector<IndexBox> objects = volumeObjects.Boxes;
  const bool casting = surfaces && !surfaces->Empty();
  if (casting)
  {
    objects.push_back(SurfacesBox(*surfaces, indexToWorld)); // the last object
  }
  if (objects.empty())
  {
    return {};
  }
  // Light-space extents on the unclustered face, or on each face of its cube.
  const std::vector<ShadowMapFace> whole = ShadowMapFaces(light, CasterBoundsOf(indexToWorld, dims, surfaces));
  const double far = std::numeric_limits<double>::infinity();
  std::vector<std::vector<glm::dvec4>> extents(whole.size()); // per face, per object; x > z: not seen
  for (size_t f = 0; f < whole.size(); ++f)
  {
    for (const IndexBox& object : objects)
    {
      glm::dvec4 e(far, far, -far, -far);
      for (const glm::dvec3& corner : WorldCorners(object, indexToWorld))
      {
        double u = 0.0, v = 0.0, depth = 0.0;
        if (whole[f].Project(corner, u, v, depth))
        {
          u = whole.size() == 6 ? std::clamp(u, -1.0, 1.0) : u; // a cube face sees [-1, 1]
          v = whole.size() == 6 ? std::clamp(v, -1.0, 1.0) : v;
          e = glm::dvec4(std::min(e.x, u), std::min(e.y, v), std::max(e.z, u), std::max(e.w, v));
        }
      }
      extents[f].push_back(e);
    }
  }
  const auto distance = [&](size_t a, size_t b) {
    double d = 0.0;
    for (const auto& face : extents)
    {
      const bool seesA = face[a].x <= face[a].z, seesB = face[b].x <= face[b].z;
      // Seen on different faces of a cube: as far apart as a face is wide.
      d = std::max(d, seesA && seesB ? ExtentDistance(face[a], face[b]) : (seesA || seesB) ? 2.0 * std::sqrt(2.0) : 0.0);
    }
    return d;
  };
  const std::vector<double> weights = eye ? ScreenWeights(objects, indexToWorld, *eye) : std::vector<double>();
  const std::vector<int> cluster = ClusterObjects(objects.size(), distance, maxClusters, distanceThreshold, eye ? &weights : nullptr);
  const int count = 1 + *std::max_element(cluster.begin(), cluster.end());

  ClusteredFaces result;
  result.BlockLabels.assign(empty.Occupied.size(), 0);
  for (size_t b = 0; b < empty.Occupied.size(); ++b)
  {
    const int object = volumeObjects.BlockObject[b];
    result.BlockLabels[b] = object < 0 ? 0 : static_cast<uint8_t>(1 + cluster[static_cast<size_t>(object)]);
  }
  for (int c = 0; c < count; ++c)
  {
    IndexBox box{ glm::dvec3(std::numeric_limits<double>::infinity()), glm::dvec3(-std::numeric_limits<double>::infinity()) };
    for (size_t o = 0; o < objects.size(); ++o)
    {
      if (cluster[o] == c)
      {
        box = IndexBox{ glm::min(box.Lo, objects[o].Lo), glm::max(box.Hi, objects[o].Hi) };
      }
    }
    CasterBounds bounds;
    bounds.Corners = WorldCorners(box, indexToWorld);
    bounds.Centre = 0.5 * (bounds.Corners.front() + bounds.Corners.back());
    for (const glm::dvec3& corner : bounds.Corners)
    {
      bounds.Radius = std::max(bounds.Radius, glm::length(corner - bounds.Centre));
    }
    if (OutsideSpot(light, bounds.Centre, bounds.Radius))
    {
      // Its blocks belong to no face: nothing lit lies behind them.
      std::replace(result.BlockLabels.begin(), result.BlockLabels.end(), static_cast<uint8_t>(c + 1), uint8_t(0));
      continue;
    }
    const std::vector<ShadowMapFace> faces = ShadowMapFaces(light, bounds);
    if (faces.size() != 1)
    {
      return {};
    }
    result.Faces.push_back(faces.front());
    result.Clips.push_back(box);
    double start = std::numeric_limits<double>::infinity();
    for (const glm::dvec3& corner : bounds.Corners)
    {
      double u = 0.0, v = 0.0, depth = 0.0;
      start = std::min(start, faces.front().Project(corner, u, v, depth) ? std::max(depth, 0.0) : 0.0);
    }
    result.Starts.push_back(start);
    // Skipping reads the blocks' layout and occupancy only, not their scalar ranges.
    EmptySpaceMap own;
    own.Blocks.BlockSize = empty.Blocks.BlockSize;
    own.Blocks.BlockCount = empty.Blocks.BlockCount;
    own.Occupied.resize(empty.Occupied.size());
    for (size_t b = 0; b < own.Occupied.size(); ++b)
    {
      own.Occupied[b] = result.BlockLabels[b] == c + 1 ? 1 : 0;
    }
    // Labels name faces (1 + face): a cluster skipped above leaves a gap the next ones close.
    std::replace(result.BlockLabels.begin(), result.BlockLabels.end(), static_cast<uint8_t>(c + 1),
      static_cast<uint8_t>(result.Faces.size()));
    result.Occupied.push_back(std::move(own));
    result.CastsSurfaces.push_back(casting && cluster.back() == c);
  }
  return result;
}

}
