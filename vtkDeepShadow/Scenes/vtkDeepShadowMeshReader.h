/**
 * @class   vtkDeepShadowMeshReader
 * @brief   Reads a mesh from a file, choosing VTK's reader by the file's extension, after
 *          checking the file against what its header declares.
 *
 * Extensions (case-insensitive): .vtp (vtkXMLPolyDataReader), .vtk (vtkPolyDataReader),
 * .stl (vtkSTLReader, coincident points merged), .ply (vtkPLYReader), .obj (vtkOBJReader).
 * The output is a vtkPolyData with at least one cell.
 *
 * Bad input (no file name, missing or unreadable file, unknown extension, a file the reader
 * cannot parse, no cells) is reported with one vtkErrorMacro line that names the file and
 * the problem, also kept in GetLastError(); the output stays empty. Messages of VTK's reader
 * are collected by observers on it (VTK's global warning display held on while it runs,
 * whatever the application set) and what it prints to std::cerr, not printed.
 *
 * VTK's PLY reader trusts the file (a truncated binary PLY or a header declaring 1e8
 * vertices crash it), so a PLY file is walked first: its header's grammar, and every element
 * within the file, the vertex indices of its faces within its vertices; an OBJ file's
 * corners must refer to vertices, texture coordinates and normals it declares. A binary STL
 * file must hold the triangles it declares. What VTK will
 * allocate must fit MemoryBudget. The cells' point ids and the points themselves are not
 * checked here: vtkDeepShadowPolyDataMapper::CheckInput does that for any vtkPolyData.
 */
#ifndef vtkDeepShadowMeshReader_h
#define vtkDeepShadowMeshReader_h

#include "vtkDeepShadowScenesModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"
#include "vtkSmartPointer.h" // For the collector

#include <cstdint> // For std::uint64_t
#include <string>  // For GetLastError
#include <vector>  // For GetSupportedExtensions

class vtkCommand;

class VTKDEEPSHADOWSCENES_EXPORT vtkDeepShadowMeshReader : public vtkPolyDataAlgorithm
{
public:
  static vtkDeepShadowMeshReader* New();
  vtkTypeMacro(vtkDeepShadowMeshReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** The file to read. */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /**
   * The most bytes VTK's reader may be expected to allocate for the file (estimated from its
   * header); 0 (the default) is deepshadow::DefaultMemoryBudget().
   */
  vtkSetClampMacro(MemoryBudget, vtkTypeInt64, 0, VTK_TYPE_INT64_MAX);
  vtkGetMacro(MemoryBudget, vtkTypeInt64);
  ///@}

  /** Supported extensions, lower case with the dot: .vtp, .vtk, .stl, .ply, .obj. */
  static std::vector<std::string> GetSupportedExtensions();

  /** The one-line reason of the last failure; empty after a successful read. */
  const std::string& GetLastError() const { return this->LastError; }

protected:
  vtkDeepShadowMeshReader();
  ~vtkDeepShadowMeshReader() override;

  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  /** Reports `problem` about the file as the one-line error; returns 0 for RequestData. */
  int Fail(const std::string& problem);

  char* FileName = nullptr;
  vtkTypeInt64 MemoryBudget = 0;
  std::string LastError;
  vtkSmartPointer<vtkCommand> Errors; // collects the delegate's messages

private:
  vtkDeepShadowMeshReader(const vtkDeepShadowMeshReader&) = delete;
  void operator=(const vtkDeepShadowMeshReader&) = delete;
};

#endif
