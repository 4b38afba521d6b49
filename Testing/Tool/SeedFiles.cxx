#include "SeedFiles.h"

#include "vtkCubeSource.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMetaImageWriter.h"
#include "vtkNew.h"
#include "vtkOBJWriter.h"
#include "vtkPLYWriter.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataWriter.h"
#include "vtkSTLWriter.h"
#include "vtkSphereSource.h"
#include "vtkTriangleFilter.h"
#include "vtkUnsignedCharArray.h"
#include "vtkXMLImageDataWriter.h"
#include "vtkXMLPolyDataWriter.h"

#include <zlib.h>

#include <cmath>
#include <fstream>
#include <type_traits>
#include <vector>

namespace deepshadow
{
namespace testing
{
namespace
{
constexpr int N = 16;

// A soft ball over a faint gradient, as 8-bit values (and the same over 255 as floats).
vtkSmartPointer<vtkImageData> Ball(bool asFloat)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(N, N, N);
  image->SetSpacing(2.0, 2.0, 2.5);
  image->SetOrigin(-15.0, -15.0, -18.75);
  image->AllocateScalars(asFloat ? VTK_FLOAT : VTK_UNSIGNED_CHAR, 1);
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  scalars->SetName("density");
  for (int k = 0; k < N; ++k)
    for (int j = 0; j < N; ++j)
      for (int i = 0; i < N; ++i)
      {
        const double x = 2.0 * i / (N - 1) - 1.0, y = 2.0 * j / (N - 1) - 1.0,
                     z = 2.0 * k / (N - 1) - 1.0;
        const double r = std::sqrt(x * x + y * y + z * z);
        const double u = std::max(0.0, 1.0 - r / 0.8) + 0.1 * (x + 1.0);
        const double value = std::round(std::min(1.0, u) * 255.0);
        scalars->SetComponent(i + N * (j + N * k), 0, asFloat ? value / 255.0 : value);
      }
  return image;
}

void WriteXML(vtkImageData* image, const std::string& path, int mode, bool zlib)
{
  vtkNew<vtkXMLImageDataWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(path.c_str());
  writer->SetDataMode(mode);
  writer->SetEncodeAppendedData(false);
  if (zlib)
  {
    writer->SetCompressorTypeToZLib();
  }
  else
  {
    writer->SetCompressorTypeToNone();
  }
  writer->Write();
}

void WriteMeta(vtkImageData* image, const std::string& path, const std::string& raw, bool compressed)
{
  vtkNew<vtkMetaImageWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(path.c_str());
  if (!raw.empty())
  {
    writer->SetRAWFileName(raw.c_str());
  }
  writer->SetCompression(compressed);
  writer->Write();
}

// NRRD: attached raw, attached gzip, or a detached header naming `dataFile`.
void WriteNrrd(vtkImageData* image, const std::string& path, const std::string& encoding,
  const std::string& directory, const std::string& dataFile = "")
{
  const auto* values = static_cast<const unsigned char*>(image->GetScalarPointer());
  const size_t count = static_cast<size_t>(N) * N * N;
  std::ofstream out(path, std::ios::binary);
  out << "NRRD0004\ntype: uchar\ndimension: 3\nsizes: " << N << " " << N << " " << N
      << "\nspacings: 2 2 2.5\nencoding: " << encoding << "\n";
  if (!dataFile.empty())
  {
    out << "data file: " << dataFile << "\n\n";
    std::ofstream(directory + "/" + dataFile, std::ios::binary)
      .write(reinterpret_cast<const char*>(values), static_cast<std::streamsize>(count));
    return;
  }
  out << "\n";
  if (encoding == "raw")
  {
    out.write(reinterpret_cast<const char*>(values), static_cast<std::streamsize>(count));
    return;
  }
  // gzip: deflate with a gzip wrapper (window bits 15 + 16).
  z_stream stream{};
  deflateInit2(&stream, Z_BEST_COMPRESSION, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY);
  std::vector<unsigned char> packed(deflateBound(&stream, static_cast<uLong>(count)) + 32);
  stream.next_in = const_cast<Bytef*>(values);
  stream.avail_in = static_cast<uInt>(count);
  stream.next_out = packed.data();
  stream.avail_out = static_cast<uInt>(packed.size());
  deflate(&stream, Z_FINISH);
  out.write(reinterpret_cast<const char*>(packed.data()), static_cast<std::streamsize>(stream.total_out));
  deflateEnd(&stream);
}

vtkSmartPointer<vtkPolyData> Sphere()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(10.0);
  sphere->SetThetaResolution(8);
  sphere->SetPhiResolution(8);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(sphere->GetOutputPort());
  triangles->Update();
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->ShallowCopy(triangles->GetOutput());
  mesh->GetPointData()->SetNormals(nullptr); // positions and triangles only
  return mesh;
}

template <typename Writer>
void WriteMesh(vtkPolyData* mesh, const std::string& path, int fileType = 0)
{
  vtkNew<Writer> writer;
  writer->SetInputData(mesh);
  writer->SetFileName(path.c_str());
  if constexpr (std::is_same<Writer, vtkPLYWriter>::value || std::is_same<Writer, vtkSTLWriter>::value)
  {
    writer->SetFileType(fileType);
  }
  writer->Write();
}
}

std::vector<SeedFile> WriteSeedFiles(const std::string& directory)
{
  const std::string d = directory + "/";
  auto ball = Ball(false);
  WriteXML(ball, d + "volume-raw.vti", vtkXMLWriter::Appended, false);
  WriteXML(ball, d + "volume-zlib.vti", vtkXMLWriter::Appended, true);
  WriteXML(ball, d + "volume-base64.vti", vtkXMLWriter::Binary, false);
  WriteXML(Ball(true), d + "volume-float.vti", vtkXMLWriter::Appended, false);
  WriteMeta(ball, d + "volume.mhd", d + "volume.raw", false);
  WriteMeta(ball, d + "volume.mha", "", true);
  WriteNrrd(ball, d + "volume.nrrd", "raw", directory);
  WriteNrrd(ball, d + "volume-gzip.nrrd", "gzip", directory);
  WriteNrrd(ball, d + "volume.nhdr", "raw", directory, "volume-nhdr.raw");

  auto sphere = Sphere();
  WriteMesh<vtkPLYWriter>(sphere, d + "mesh.ply", VTK_BINARY);
  WriteMesh<vtkPLYWriter>(sphere, d + "mesh-ascii.ply", VTK_ASCII);
  WriteMesh<vtkSTLWriter>(sphere, d + "mesh.stl", VTK_BINARY);
  WriteMesh<vtkSTLWriter>(sphere, d + "mesh-ascii.stl", VTK_ASCII);
  WriteMesh<vtkOBJWriter>(sphere, d + "mesh.obj");
  WriteMesh<vtkPolyDataWriter>(sphere, d + "mesh.vtk");
  WriteMesh<vtkXMLPolyDataWriter>(sphere, d + "mesh.vtp");
  vtkNew<vtkCubeSource> cube;
  cube->SetBounds(-12.0, 12.0, -12.0, 12.0, -12.0, 12.0);
  vtkNew<vtkTriangleFilter> cubeTriangles;
  cubeTriangles->SetInputConnection(cube->GetOutputPort());
  cubeTriangles->Update();
  WriteMesh<vtkOBJWriter>(cubeTriangles->GetOutput(), d + "bound.obj");

  return { { SeedFile::Volume, "volume-raw.vti", {} }, { SeedFile::Volume, "volume-zlib.vti", {} },
    { SeedFile::Volume, "volume-base64.vti", {} }, { SeedFile::Volume, "volume-float.vti", {} },
    { SeedFile::Volume, "volume.mhd", { "volume.raw" } }, { SeedFile::Volume, "volume.mha", {} },
    { SeedFile::Volume, "volume.nrrd", {} }, { SeedFile::Volume, "volume-gzip.nrrd", {} },
    { SeedFile::Volume, "volume.nhdr", { "volume-nhdr.raw" } },
    { SeedFile::Mesh, "mesh.ply", {} }, { SeedFile::Mesh, "mesh-ascii.ply", {} },
    { SeedFile::Mesh, "mesh.stl", {} }, { SeedFile::Mesh, "mesh-ascii.stl", {} },
    { SeedFile::Mesh, "mesh.obj", {} }, { SeedFile::Mesh, "mesh.vtk", {} },
    { SeedFile::Mesh, "mesh.vtp", {} }, { SeedFile::Mesh, "bound.obj", {} } };
}

std::vector<std::string> SeedExpressions()
{
  return { "union(A,B)", "diff(A,B)", "inter(A,B)", "intersection(A,union(A,B))",
    "difference(union(A,B),inter(A,B))", "A", "union(A,diff(B,A),inter(B,B))" };
}

}
}
