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
  if (!this->FileName || !*this->FileName)
  {
    return this->Fail("no file name was set");
  }
  const std::string name = this->FileName;
  if (!SystemTools::FileExists(name, true))
  {
    return this->Fail(SystemTools::FileIsDirectory(name) ? "it is a directory, not a file" : "no such file");
  }
  if (!SystemTools::TestFileAccess(name, vtksys::TEST_FILE_READ))
  {
    return this->Fail("permission denied");
  }
  const std::string ext = SystemTools::LowerCase(SystemTools::GetFilenameLastExtension(name));
  std::uint64_t bytes = SystemTools::FileLength(name) * 4; // text formats: at most this
  std::string problem;
  vtkSmartPointer<vtkAbstractPolyDataReader> geometry; // the readers with SetFileName(const char*)
  vtkSmartPointer<vtkAlgorithm> reader;
  if (ext == ".vtp")
  {
    problem = deepshadow::xmlfile::CheckStructure(name);
    if (problem.empty())
    {
      problem = deepshadow::meshfile::CheckVTP(name, bytes);
    }
    auto xml = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    xml->SetFileName(name.c_str());
    reader = xml;
  }
  else if (ext == ".vtk")
  {
    problem = deepshadow::meshfile::CheckLegacyVTK(name);
    auto legacy = vtkSmartPointer<vtkPolyDataReader>::New();
    legacy->SetFileName(name.c_str());
    reader = legacy;
  }
  else if (ext == ".stl")
  {
    problem = deepshadow::meshfile::CheckSTL(name, bytes);
    auto stl = vtkSmartPointer<vtkSTLReader>::New();
    stl->MergingOn();
    reader = geometry = stl;
  }
  else if (ext == ".ply")
  {
    problem = deepshadow::meshfile::CheckPLY(name, bytes);
    reader = geometry = vtkSmartPointer<vtkPLYReader>::New();
  }
  else if (ext == ".obj")
  {
    problem = deepshadow::meshfile::CheckOBJ(name, bytes);
    reader = geometry = vtkSmartPointer<vtkOBJReader>::New();
  }
  else
  {
    std::string supported;
    for (const std::string& e : GetSupportedExtensions())
    {
      supported += " " + e;
    }
    return this->Fail(
      (ext.empty() ? std::string("no file extension") : "unsupported format '" + ext + "'") +
      " (supported:" + supported + ")");
  }
  if (!problem.empty())
  {
    return this->Fail(problem);
  }
  const std::uint64_t budget = this->MemoryBudget > 0 ? static_cast<std::uint64_t>(this->MemoryBudget)
                                                      : deepshadow::DefaultMemoryBudget();
  problem = deepshadow::CheckMemoryBudget("reading it", bytes, budget);
  if (!problem.empty())
  {
    return this->Fail(problem);
  }
  if (geometry)
  {
    geometry->SetFileName(name.c_str());
  }

  auto* errors = static_cast<ErrorCollector*>(this->Errors.Get());
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
    return this->Fail("not enough memory to read it");
  }
  if (errors->Failed() || reader->GetErrorCode() != 0)
  {
    return this->Fail(errors->Reason("VTK's reader failed on it"));
  }
  if (!printed.empty())
  {
    return this->Fail(printed.front());
  }
  vtkPolyData* mesh = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
  if (!mesh || mesh->GetNumberOfCells() == 0)
  {
    return this->Fail("it holds no cells");
  }
  output->ShallowCopy(mesh);
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
