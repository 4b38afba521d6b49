#include "Volume/CutRegion.h"

#include "CoreAdapter.h"

#include "vtkCellArray.h"
#include "vtkClipClosedSurface.h"
#include "vtkImageData.h"
#include "vtkMatrix4x4.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkVolumeMapper.h"

#include <glm/matrix.hpp>

#include <algorithm>

namespace deepshadow
{
namespace
{
// The image's box [-1, Dims] in index space (a voxel beyond the samples on every side, so no
// face of the cut lies on the volume's own faces) in data coordinates.
void DataBox(vtkImageData* input, glm::dvec3 corners[8])
{
  const glm::dmat4 indexToData = adapter::IndexToWorld(input, nullptr);
  int dims[3];
  input->GetDimensions(dims);
  for (int c = 0; c < 8; ++c)
  {
    const glm::dvec4 index((c & 1) ? dims[0] : -1.0, (c & 2) ? dims[1] : -1.0, (c & 4) ? dims[2] : -1.0, 1.0);
    corners[c] = glm::dvec3(indexToData * index);
  }
}

// A closed box mesh, outward-facing triangles, from 8 corners indexed by bits (x, y, z).
vtkSmartPointer<vtkPolyData> BoxMesh(const glm::dvec3 corners[8])
{
  static const int faces[6][4] = { { 0, 4, 6, 2 }, { 1, 3, 7, 5 }, { 0, 1, 5, 4 }, { 2, 6, 7, 3 },
    { 0, 2, 3, 1 }, { 4, 5, 7, 6 } };
  vtkNew<vtkPoints> points;
  for (int c = 0; c < 8; ++c)
  {
    points->InsertNextPoint(corners[c].x, corners[c].y, corners[c].z);
  }
  vtkNew<vtkCellArray> triangles;
  for (const auto& f : faces)
  {
    const vtkIdType a[3] = { f[0], f[1], f[2] }, b[3] = { f[0], f[2], f[3] };
    triangles->InsertNextCell(3, a);
    triangles->InsertNextCell(3, b);
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(triangles);
  return mesh;
}

// The box cut by the clipping planes (world planes taken to data coordinates by the inverse
// of the prop's matrix), closed by caps.
vtkSmartPointer<vtkPolyData> ClipBox(
  const glm::dvec3 corners[8], vtkPlaneCollection* planes, const glm::dmat4& dataToWorld)
{
  const glm::dmat4 worldToData = glm::inverse(dataToWorld);
  vtkNew<vtkPlaneCollection> dataPlanes;
  for (int p = 0; p < planes->GetNumberOfItems(); ++p)
  {
    vtkPlane* plane = planes->GetItem(p);
    double o[3], n[3];
    plane->GetOrigin(o);
    plane->GetNormal(n);
    // n . (M y + t - o) >= 0  <=>  (M^T n) . (y - M^-1 o) >= 0
    const glm::dvec3 origin(worldToData * glm::dvec4(o[0], o[1], o[2], 1.0));
    const glm::dvec3 normal = glm::transpose(glm::dmat3(dataToWorld)) * glm::dvec3(n[0], n[1], n[2]);
    vtkNew<vtkPlane> cut;
    cut->SetOrigin(origin.x, origin.y, origin.z);
    cut->SetNormal(normal.x, normal.y, normal.z);
    dataPlanes->AddItem(cut);
  }
  vtkNew<vtkClipClosedSurface> clip;
  clip->SetInputData(BoxMesh(corners));
  clip->SetClippingPlanes(dataPlanes);
  clip->GenerateFacesOn();
  clip->TriangulationErrorDisplayOff();
  clip->Update();
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->ShallowCopy(clip->GetOutput());
  return mesh;
}

// The union of the cropping sub-boxes the flags keep: the faces between a kept cell of the
// 3x3x3 grid and one not kept (or the outside), facing out of the kept one. Axis-aligned in
// data coordinates, as VTK's cropping planes are.
vtkSmartPointer<vtkPolyData> CropMesh(const glm::dvec3 corners[8], const double planes[6], int flags)
{
  double edges[3][4];
  for (int a = 0; a < 3; ++a)
  {
    const double lo = std::min(corners[0][a], corners[7][a]), hi = std::max(corners[0][a], corners[7][a]);
    const double p0 = std::clamp(std::min(planes[2 * a], planes[2 * a + 1]), lo, hi);
    const double p1 = std::clamp(std::max(planes[2 * a], planes[2 * a + 1]), lo, hi);
    edges[a][0] = lo;
    edges[a][1] = p0;
    edges[a][2] = p1;
    edges[a][3] = hi;
  }
  auto kept = [flags](int i, int j, int k) {
    return i >= 0 && i < 3 && j >= 0 && j < 3 && k >= 0 && k < 3 && ((flags >> (i + 3 * j + 9 * k)) & 1);
  };
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> triangles;
  auto quad = [&](const glm::dvec3 q[4]) {
    vtkIdType ids[4];
    for (int v = 0; v < 4; ++v)
    {
      ids[v] = points->InsertNextPoint(q[v].x, q[v].y, q[v].z);
    }
    const vtkIdType a[3] = { ids[0], ids[1], ids[2] }, b[3] = { ids[0], ids[2], ids[3] };
    triangles->InsertNextCell(3, a);
    triangles->InsertNextCell(3, b);
  };
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i)
      {
        if (!kept(i, j, k))
        {
          continue;
        }
        const int cell[3] = { i, j, k };
        for (int axis = 0; axis < 3; ++axis)
          for (int side = 0; side < 2; ++side)
          {
            int neighbour[3] = { i, j, k };
            neighbour[axis] += side ? 1 : -1;
            if (kept(neighbour[0], neighbour[1], neighbour[2]))
            {
              continue;
            }
            // The face at edges[axis][cell + side], its corners counter-clockwise seen from
            // outside the kept cell.
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            glm::dvec3 q[4];
            const double uv[4][2] = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
            for (int c = 0; c < 4; ++c)
            {
              const int corner = side ? c : 3 - c;
              q[c][axis] = edges[axis][cell[axis] + side];
              q[c][u] = edges[u][cell[u] + static_cast<int>(uv[corner][0])];
              q[c][v] = edges[v][cell[v] + static_cast<int>(uv[corner][1])];
            }
            quad(q);
          }
      }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(triangles);
  return mesh;
}
}

const std::vector<vtkPolyData*>& CutRegion::Update(
  vtkVolumeMapper* mapper, vtkImageData* input, vtkMatrix4x4* propMatrix)
{
  vtkPlaneCollection* planes = mapper->GetClippingPlanes();
  const bool clipping = planes && planes->GetNumberOfItems() > 0;
  const bool cropping = mapper->GetCropping() != 0;
  // What the cut depends on, as numbers: unchanged numbers keep the meshes.
  std::vector<double> signature{ clipping ? 1.0 : 0.0, cropping ? 1.0 : 0.0 };
  glm::dvec3 corners[8];
  DataBox(input, corners);
  for (const auto& c : corners)
  {
    signature.insert(signature.end(), { c.x, c.y, c.z });
  }
  const glm::dmat4 dataToWorld = propMatrix ? adapter::ToGlm(propMatrix) : glm::dmat4(1.0);
  for (int p = 0; clipping && p < planes->GetNumberOfItems(); ++p)
  {
    double o[3], n[3];
    planes->GetItem(p)->GetOrigin(o);
    planes->GetItem(p)->GetNormal(n);
    signature.insert(signature.end(), { o[0], o[1], o[2], n[0], n[1], n[2] });
  }
  if (clipping)
  {
    for (int e = 0; e < 16; ++e)
    {
      signature.push_back(dataToWorld[e / 4][e % 4]);
    }
  }
  if (cropping)
  {
    const double* region = mapper->GetCroppingRegionPlanes();
    signature.insert(signature.end(), region, region + 6);
    signature.push_back(mapper->GetCroppingRegionFlags());
  }
  if (signature == this->Signature)
  {
    return this->Meshes;
  }
  this->Signature = signature;
  this->Clipped = clipping ? ClipBox(corners, planes, dataToWorld) : nullptr;
  this->Cropped =
    cropping ? CropMesh(corners, mapper->GetCroppingRegionPlanes(), mapper->GetCroppingRegionFlags()) : nullptr;
  this->Meshes.clear();
  for (vtkPolyData* mesh : { this->Clipped.Get(), this->Cropped.Get() })
  {
    if (mesh)
    {
      this->Meshes.push_back(mesh);
    }
  }
  return this->Meshes;
}

std::string CutRegion::Combine(int userLeaves, const std::string& userExpression, int cutLeaves)
{
  if (userLeaves + cutLeaves <= 1 || cutLeaves == 0)
  {
    return cutLeaves == 0 ? userExpression : std::string();
  }
  auto leaf = [](int i) { return std::string(1, static_cast<char>('A' + i)); };
  std::string user;
  if (userLeaves > 0)
  {
    user = userExpression;
    if (user.empty())
    {
      user = leaf(0);
      if (userLeaves > 1)
      {
        user = "union(" + leaf(0);
        for (int i = 1; i < userLeaves; ++i)
        {
          user += "," + leaf(i);
        }
        user += ")";
      }
    }
  }
  std::string combined = "inter(" + user;
  for (int i = 0; i < cutLeaves; ++i)
  {
    combined += (combined.size() > 6 ? "," : "") + leaf(userLeaves + i);
  }
  return combined + ")";
}

}
