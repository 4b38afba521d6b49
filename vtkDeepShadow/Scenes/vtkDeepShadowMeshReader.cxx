#include "vtkDeepShadowMeshReader.h"

#include "MeshFileChecks.h"
#include "XMLFileChecks.h"
#include "ReaderMessages.h"
#include "vtkDeepShadowMemoryBudget.h"

#include "vtkAbstractPolyDataReader.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkOBJReader.h"
#include "vtkObjectFactory.h"
#include "vtkPLYReader.h"
#include "vtkPolyData.h"
#include "vtkPolyDataReader.h"
#include "vtkSTLReader.h"
#include "vtkXMLPolyDataReader.h"

#include <vtksys/SystemTools.hxx>

#include <new>

vtkStandardNewMacro(vtkDeepShadowMeshReader);

using deepshadow::reader::CerrCapture;
using deepshadow::reader::ErrorCollector;

namespace
{
// Why the file cannot be opened for reading; "" when it can.
std::string FileAccessProblem(const char* fileName)
{
  using vtksys::SystemTools;
  if (!fileName || !*fileName)
  {
    return "no file name was set";
  }
  const std::string name = fileName;
  if (!SystemTools::FileExists(name, true))
  {
    return SystemTools::FileIsDirectory(name) ? "it is a directory, not a file" : "no such file";
  }
  if (!SystemTools::TestFileAccess(name, vtksys::TEST_FILE_READ))
  {
    return "permission denied";
  }
  return "";
}

// VTK's reader for a mesh file and what checking the file against its header said.
struct CheckedFile
{
  vtkSmartPointer<vtkAlgorithm> Reader; // null for an unsupported extension
  // The readers with SetFileName(const char*): given the file only once it passed the checks.
  vtkSmartPointer<vtkAbstractPolyDataReader> Geometry;
  std::string Problem;     // "" when the file passed
  std::uint64_t Bytes = 0; // what VTK's reader would allocate
};

// Checks the file `name` by its lower-case extension `ext`, and makes the reader for it.
CheckedFile CheckFile(const std::string& name, const std::string& ext)
{
  CheckedFile file;
  file.Bytes = vtksys::SystemTools::FileLength(name) * 4; // text formats: at most this
  if (ext == ".vtp")
  {
    file.Problem = deepshadow::xmlfile::CheckStructure(name);
    if (file.Problem.empty())
    {
      file.Problem = deepshadow::meshfile::CheckVTP(name, file.Bytes);
    }
    auto xml = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    xml->SetFileName(name.c_str());
    file.Reader = xml;
  }
  else if (ext == ".vtk")
  {
    file.Problem = deepshadow::meshfile::CheckLegacyVTK(name);
    auto legacy = vtkSmartPointer<vtkPolyDataReader>::New();
    legacy->SetFileName(name.c_str());
    file.Reader = legacy;
  }
  else if (ext == ".stl")
  {
    file.Problem = deepshadow::meshfile::CheckSTL(name, file.Bytes);
    auto stl = vtkSmartPointer<vtkSTLReader>::New();
    stl->MergingOn();
    file.Reader = file.Geometry = stl;
  }
  else if (ext == ".ply")
  {
    file.Problem = deepshadow::meshfile::CheckPLY(name, file.Bytes);
    file.Reader = file.Geometry = vtkSmartPointer<vtkPLYReader>::New();
  }
  else if (ext == ".obj")
  {
    file.Problem = deepshadow::meshfile::CheckOBJ(name, file.Bytes);
    file.Reader = file.Geometry = vtkSmartPointer<vtkOBJReader>::New();
  }
  return file;
}

// The problem of a file whose extension no reader here takes.
std::string UnsupportedExtension(const std::string& ext)
{
  std::string supported;
  for (const std::string& e : vtkDeepShadowMeshReader::GetSupportedExtensions())
  {
    supported += " " + e;
  }
  return (ext.empty() ? std::string("no file extension") : "unsupported format '" + ext + "'") +
    " (supported:" + supported + ")";
}

// Runs VTK's reader, its messages collected by `errors` and its printing captured, not shown;
// copies its mesh to `output`. Why it failed, or "" when it read cells.
std::string ReadCells(vtkAlgorithm* reader, ErrorCollector* errors, vtkPolyData* output)
{
  errors->Clear();
  errors->Watch(reader);
  std::vector<std::string> printed;
  try
  {
    deepshadow::reader::WarningDisplayOn heard;
    CerrCapture capture;
    reader->Update();
    printed = capture.Lines();
  }
  catch (const std::bad_alloc&)
  {
    return "not enough memory to read it";
  }
  if (errors->Failed() || reader->GetErrorCode() != 0)
  {
    return errors->Reason("VTK's reader failed on it");
  }
  if (!printed.empty())
  {
    return printed.front();
  }
  vtkPolyData* mesh = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
  if (!mesh || mesh->GetNumberOfCells() == 0)
  {
    return "it holds no cells";
  }
  output->ShallowCopy(mesh);
  return "";
}
}

vtkDeepShadowMeshReader::vtkDeepShadowMeshReader()
  : Errors(vtkSmartPointer<ErrorCollector>::New())
{
  this->SetNumberOfInputPorts(0);
}

vtkDeepShadowMeshReader::~vtkDeepShadowMeshReader()
{
  this->SetFileName(nullptr);
}

std::vector<std::string> vtkDeepShadowMeshReader::GetSupportedExtensions()
{
  return { ".vtp", ".vtk", ".stl", ".ply", ".obj" };
}

int vtkDeepShadowMeshReader::Fail(const std::string& problem)
{
  this->LastError =
    "cannot read mesh '" + std::string(this->FileName ? this->FileName : "") + "': " + problem;
  vtkErrorMacro(<< this->LastError);
  return 0;
}

int vtkDeepShadowMeshReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  using vtksys::SystemTools;
  this->LastError.clear();
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  output->Initialize();
  std::string problem = FileAccessProblem(this->FileName);
  if (!problem.empty())
  {
    return this->Fail(problem);
  }
  const std::string name = this->FileName;
  const std::string ext = SystemTools::LowerCase(SystemTools::GetFilenameLastExtension(name));
  const CheckedFile file = CheckFile(name, ext);
  if (!file.Reader)
  {
    return this->Fail(UnsupportedExtension(ext));
  }
  if (!file.Problem.empty())
  {
    return this->Fail(file.Problem);
  }
  const std::uint64_t budget = this->MemoryBudget > 0 ? static_cast<std::uint64_t>(this->MemoryBudget)
                                                      : deepshadow::DefaultMemoryBudget();
  problem = deepshadow::CheckMemoryBudget("reading it", file.Bytes, budget);
  if (!problem.empty())
  {
    return this->Fail(problem);
  }
  if (file.Geometry)
  {
    file.Geometry->SetFileName(name.c_str());
  }

  auto* errors = static_cast<ErrorCollector*>(this->Errors.Get());
  problem = ReadCells(file.Reader, errors, output);
  if (!problem.empty())
  {
    return this->Fail(problem);
  }
  for (const std::string& warning : errors->Warnings)
  {
    vtkWarningMacro(<< "'" << name << "': " << warning);
  }
  return 1;
}

void vtkDeepShadowMeshReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "MemoryBudget: " << this->MemoryBudget << " (0: the default)\n";
  os << indent << "LastError: " << (this->LastError.empty() ? "(none)" : this->LastError) << "\n";
}
