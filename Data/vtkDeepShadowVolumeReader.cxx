#include "vtkDeepShadowVolumeReader.h"

#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMetaImageReader.h"
#include "vtkNrrdReader.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkXMLImageDataReader.h"

#include <vtksys/SystemTools.hxx>

#include <cstdint>
#include <fstream>
#include <sstream>

vtkStandardNewMacro(vtkDeepShadowVolumeReader);

namespace
{
enum class Format
{
  Unknown,
  XML,
  Meta,
  Nrrd
};

std::string LowerExtension(const std::string& fileName)
{
  return vtksys::SystemTools::LowerCase(vtksys::SystemTools::GetFilenameLastExtension(fileName));
}

Format FormatOf(const std::string& fileName)
{
  const std::string ext = LowerExtension(fileName);
  if (ext == ".vti")
  {
    return Format::XML;
  }
  if (ext == ".mhd" || ext == ".mha")
  {
    return Format::Meta;
  }
  if (ext == ".nrrd" || ext == ".nhdr")
  {
    return Format::Nrrd;
  }
  return Format::Unknown;
}

const char* FormatName(Format format)
{
  switch (format)
  {
    case Format::XML:
      return "VTK XML image data (.vti)";
    case Format::Meta:
      return "MetaImage (.mhd/.mha)";
    case Format::Nrrd:
      return "NRRD (.nrrd/.nhdr)";
    default:
      return "unknown";
  }
}

// The delegate for a format, and whether it accepts the file's header.
vtkSmartPointer<vtkAlgorithm> MakeReader(Format format, const char* fileName, bool& accepted)
{
  accepted = false;
  switch (format)
  {
    case Format::XML:
    {
      auto reader = vtkSmartPointer<vtkXMLImageDataReader>::New();
      accepted = reader->CanReadFile(fileName) != 0;
      reader->SetFileName(fileName);
      return reader;
    }
    case Format::Meta:
    {
      auto reader = vtkSmartPointer<vtkMetaImageReader>::New();
      accepted = reader->CanReadFile(fileName) != 0;
      reader->SetFileName(fileName);
      return reader;
    }
    case Format::Nrrd:
    {
      auto reader = vtkSmartPointer<vtkNrrdReader>::New();
      accepted = reader->CanReadFile(fileName) != 0;
      reader->SetFileName(fileName);
      return reader;
    }
    default:
      return nullptr;
  }
}

// "ERROR: In file, line N\nvtkClass (0x...): text\n\n" -> "text", on one line.
std::string OneLine(const char* message)
{
  std::string text = message ? message : "";
  if (text.compare(0, 6, "ERROR:") == 0 || text.compare(0, 8, "Warning:") == 0)
  {
    const size_t eol = text.find('\n');
    text = eol == std::string::npos ? text : text.substr(eol + 1);
  }
  const size_t prefix = text.find("): ");
  if (prefix != std::string::npos && prefix < text.find('\n'))
  {
    text = text.substr(prefix + 3);
  }
  for (char& c : text)
  {
    c = (c == '\n' || c == '\r') ? ' ' : c;
  }
  const size_t last = text.find_last_not_of(" .");
  return last == std::string::npos ? std::string() : text.substr(0, last + 1);
}

std::string Trim(const std::string& text)
{
  const size_t first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos)
  {
    return "";
  }
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

// NRRD and MetaImage data files that are missing, or raw (uncompressed) data shorter than the
// image: VTK's readers only print a warning (MetaIO writes to std::cerr) and may return
// garbage, so this is checked from the header before reading. Returns the problem, or "" when
// the data look complete or the layout is one this check does not cover (compressed or ASCII
// sizes, skips, lists of files).
std::string CheckDataFile(Format format, const std::string& fileName, uint64_t needed)
{
  std::ifstream in(fileName, std::ios::binary);
  std::string line, dataFile;
  uint64_t headerEnd = 0;
  bool raw = true;
  while (std::getline(in, line))
  {
    if (format == Format::Nrrd && Trim(line).empty())
    {
      headerEnd = static_cast<uint64_t>(in.tellg());
      break;
    }
    const size_t at = line.find(format == Format::Nrrd ? ':' : '=');
    if (at == std::string::npos)
    {
      continue;
    }
    const std::string key = vtksys::SystemTools::LowerCase(Trim(line.substr(0, at)));
    const std::string value = Trim(line.substr(at + 1));
    const std::string lower = vtksys::SystemTools::LowerCase(value);
    if (format == Format::Nrrd)
    {
      if (key == "encoding")
      {
        raw = lower == "raw";
      }
      else if (key == "data file" || key == "datafile")
      {
        dataFile = value;
      }
      else if (key == "byte skip" || key == "byteskip" || key == "line skip" || key == "lineskip")
      {
        return "";
      }
    }
    else
    {
      if (key == "compresseddata")
      {
        raw = lower != "true";
      }
      else if (key == "headersize")
      {
        return "";
      }
      else if (key == "elementdatafile")
      {
        dataFile = value;
        headerEnd = static_cast<uint64_t>(in.tellg());
        break;
      }
    }
  }
  const bool local =
    format == Format::Nrrd ? dataFile.empty() : vtksys::SystemTools::LowerCase(dataFile) == "local";
  if (!local &&
    (dataFile.empty() || vtksys::SystemTools::LowerCase(dataFile) == "list" ||
      dataFile.find_first_of(" %") != std::string::npos))
  {
    return ""; // no data file named, or a list or pattern of files
  }
  std::string path = fileName;
  if (!local)
  {
    path = vtksys::SystemTools::CollapseFullPath(
      dataFile, vtksys::SystemTools::GetFilenamePath(fileName));
    if (!vtksys::SystemTools::FileExists(path, true))
    {
      return "its data file '" + path + "' does not exist";
    }
  }
  if (!raw)
  {
    return "";
  }
  const uint64_t size = vtksys::SystemTools::FileLength(path);
  const uint64_t available = local ? (size > headerEnd ? size - headerEnd : 0) : size;
  if (available >= needed)
  {
    return "";
  }
  std::ostringstream problem;
  problem << "its raw data " << (local ? "" : "file '" + path + "' ") << "holds " << available
          << " bytes where the image needs " << needed << " (truncated?)";
  return problem.str();
}

// The same, with the size the delegate announced in its output information.
std::string CheckDataFile(Format format, const std::string& fileName, vtkInformation* info)
{
  int extent[6];
  vtkInformation* scalars = vtkDataObject::GetActiveFieldInformation(
    info, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
  if (!scalars || !scalars->Has(vtkDataObject::FIELD_ARRAY_TYPE()) ||
    !info->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
  {
    return "";
  }
  info->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent);
  const int components = scalars->Has(vtkDataObject::FIELD_NUMBER_OF_COMPONENTS())
    ? scalars->Get(vtkDataObject::FIELD_NUMBER_OF_COMPONENTS())
    : 1;
  uint64_t needed = static_cast<uint64_t>(components) *
    static_cast<uint64_t>(
      vtkDataArray::GetDataTypeSize(scalars->Get(vtkDataObject::FIELD_ARRAY_TYPE())));
  for (int a = 0; a < 3; ++a)
  {
    needed *= static_cast<uint64_t>(extent[2 * a + 1] - extent[2 * a] + 1);
  }
  return CheckDataFile(format, fileName, needed);
}

// Collects the delegate's errors (and those of its XML parser and its executive) instead of
// letting them print, so that the reader can report one clear line.
class ErrorCollector : public vtkCommand
{
public:
  static ErrorCollector* New() { return new ErrorCollector; }
  vtkTypeMacro(ErrorCollector, vtkCommand);

  void Execute(vtkObject* caller, unsigned long event, void* callData) override
  {
    const std::string text = OneLine(static_cast<const char*>(callData));
    if (event == vtkCommand::WarningEvent)
    {
      this->Warnings.push_back(text);
    }
    else if (vtkExecutive::SafeDownCast(caller))
    {
      // "Algorithm ... returned failure for request: <dump>": the delegate's own message, if
      // any, came first and says more.
      this->ExecutiveFailed = true;
    }
    else
    {
      this->Errors.push_back(text);
    }
  }

  void Clear()
  {
    this->Errors.clear();
    this->Warnings.clear();
    this->ExecutiveFailed = false;
  }

  bool Failed() const { return !this->Errors.empty() || this->ExecutiveFailed; }

  std::string Reason(const std::string& fallback) const
  {
    return this->Errors.empty() ? fallback : this->Errors.front();
  }

  std::vector<std::string> Errors;
  std::vector<std::string> Warnings;
  bool ExecutiveFailed = false;
};

// Our own executive reports "returned failure for request" with a dump of the request after
// we have already said why in one line; it is dropped then, and shown otherwise.
class ExecutiveFilter : public vtkCommand
{
public:
  static ExecutiveFilter* New() { return new ExecutiveFilter; }
  vtkTypeMacro(ExecutiveFilter, vtkCommand);

  void Execute(vtkObject*, unsigned long, void* callData) override
  {
    if (this->Reader && this->Reader->GetLastError().empty())
    {
      vtkOutputWindowDisplayErrorText(static_cast<const char*>(callData));
    }
  }

  vtkDeepShadowVolumeReader* Reader = nullptr;
};
}

//------------------------------------------------------------------------------
vtkDeepShadowVolumeReader::vtkDeepShadowVolumeReader()
  : Errors(vtkSmartPointer<ErrorCollector>::New())
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(1);
}

vtkDeepShadowVolumeReader::~vtkDeepShadowVolumeReader()
{
  this->SetFileName(nullptr);
}

//------------------------------------------------------------------------------
std::vector<std::string> vtkDeepShadowVolumeReader::GetSupportedExtensions()
{
  return { ".vti", ".mhd", ".mha", ".nrrd", ".nhdr" };
}

bool vtkDeepShadowVolumeReader::CanReadFile(const char* fileName)
{
  if (!fileName || !vtksys::SystemTools::FileExists(fileName, true))
  {
    return false;
  }
  bool accepted = false;
  MakeReader(FormatOf(fileName), fileName, accepted);
  return accepted;
}

//------------------------------------------------------------------------------
void vtkDeepShadowVolumeReader::Fail(const std::string& problem)
{
  std::ostringstream message;
  message << "Cannot read volume '" << (this->FileName ? this->FileName : "") << "': " << problem;
  this->LastError = message.str();
  vtkErrorMacro(<< this->LastError);
}

bool vtkDeepShadowVolumeReader::PrepareReader()
{
  this->LastError.clear();
  this->Reader = nullptr;
  vtkExecutive* executive = this->GetExecutive();
  if (executive && !executive->HasObserver(vtkCommand::ErrorEvent))
  {
    vtkNew<ExecutiveFilter> filter;
    filter->Reader = this;
    executive->AddObserver(vtkCommand::ErrorEvent, filter);
  }

  if (!this->FileName || !*this->FileName)
  {
    this->Fail("no file name was set");
    return false;
  }
  const std::string name = this->FileName;
  if (!vtksys::SystemTools::FileExists(name))
  {
    this->Fail("no such file");
    return false;
  }
  if (vtksys::SystemTools::FileIsDirectory(name))
  {
    this->Fail("it is a directory, not a file");
    return false;
  }
  if (!vtksys::SystemTools::TestFileAccess(name, vtksys::TEST_FILE_READ))
  {
    this->Fail("permission denied");
    return false;
  }
  const Format format = FormatOf(name);
  if (format == Format::Unknown)
  {
    const std::string ext = LowerExtension(name);
    std::ostringstream problem;
    problem << (ext.empty() ? std::string("no file extension") : "unknown extension '" + ext + "'")
            << " (supported:";
    for (const std::string& e : GetSupportedExtensions())
    {
      problem << " " << e;
    }
    problem << ")";
    this->Fail(problem.str());
    return false;
  }
  bool accepted = false;
  auto reader = MakeReader(format, name.c_str(), accepted);
  if (!accepted)
  {
    this->Fail(std::string("not a valid ") + FormatName(format) + " file (" +
      reader->GetClassName() + " does not recognise its header)");
    return false;
  }

  auto* errors = static_cast<ErrorCollector*>(this->Errors.Get());
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->AddObserver(vtkCommand::WarningEvent, errors);
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, errors);
  if (auto* xml = vtkXMLImageDataReader::SafeDownCast(reader))
  {
    xml->SetReaderErrorObserver(errors);
    xml->SetParserErrorObserver(errors);
  }
  this->Reader = reader;
  return true;
}

//------------------------------------------------------------------------------
int vtkDeepShadowVolumeReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  if (!this->PrepareReader())
  {
    return 0;
  }
  auto* errors = static_cast<ErrorCollector*>(this->Errors.Get());
  errors->Clear();
  this->Reader->UpdateInformation();
  if (errors->Failed())
  {
    this->Fail(errors->Reason("the file's header could not be read"));
    return 0;
  }

  vtkInformation* in = this->Reader->GetOutputInformation(0);
  vtkInformation* out = outputVector->GetInformationObject(0);
  using SDDP = vtkStreamingDemandDrivenPipeline;
  int extent[6];
  if (!in->Has(SDDP::WHOLE_EXTENT()))
  {
    this->Fail("the file holds no image extent");
    return 0;
  }
  in->Get(SDDP::WHOLE_EXTENT(), extent);
  if (extent[1] < extent[0] || extent[3] < extent[2] || extent[5] < extent[4])
  {
    this->Fail("the image in the file is empty");
    return 0;
  }
  out->Set(SDDP::WHOLE_EXTENT(), extent, 6);
  if (in->Has(vtkDataObject::SPACING()))
  {
    out->CopyEntry(in, vtkDataObject::SPACING());
  }
  if (in->Has(vtkDataObject::ORIGIN()))
  {
    out->CopyEntry(in, vtkDataObject::ORIGIN());
  }
  if (in->Has(vtkDataObject::DIRECTION()))
  {
    out->CopyEntry(in, vtkDataObject::DIRECTION());
  }
  if (vtkInformation* scalars = vtkDataObject::GetActiveFieldInformation(
        in, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS))
  {
    const int type = scalars->Has(vtkDataObject::FIELD_ARRAY_TYPE())
      ? scalars->Get(vtkDataObject::FIELD_ARRAY_TYPE())
      : VTK_DOUBLE;
    const int components = scalars->Has(vtkDataObject::FIELD_NUMBER_OF_COMPONENTS())
      ? scalars->Get(vtkDataObject::FIELD_NUMBER_OF_COMPONENTS())
      : 1;
    vtkDataObject::SetPointDataActiveScalarInfo(out, type, components);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkDeepShadowVolumeReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkImageData* output = vtkImageData::GetData(outputVector);
  if (!output)
  {
    this->Fail("no image output to fill");
    return 0;
  }
  output->Initialize();
  if (!this->Reader)
  {
    this->Fail("the file's header was not read");
    return 0;
  }
  const Format format = FormatOf(this->FileName);
  if (format == Format::Nrrd || format == Format::Meta)
  {
    const std::string problem =
      CheckDataFile(format, this->FileName, this->Reader->GetOutputInformation(0));
    if (!problem.empty())
    {
      this->Fail(problem);
      return 0;
    }
  }
  auto* errors = static_cast<ErrorCollector*>(this->Errors.Get());
  errors->Clear();
  this->Reader->Update();
  vtkImageData* image = vtkImageData::SafeDownCast(this->Reader->GetOutputDataObject(0));
  if (errors->Failed() || this->Reader->GetErrorCode() != 0)
  {
    this->Fail(errors->Reason("the reader failed on the file's data"));
    return 0;
  }
  if (!image || image->GetNumberOfPoints() == 0)
  {
    this->Fail("the file holds no image data");
    return 0;
  }
  // The active scalars, else the first numeric point array.
  vtkPointData* pd = image->GetPointData();
  vtkDataArray* scalars = pd->GetScalars();
  for (int a = 0; !scalars && a < pd->GetNumberOfArrays(); ++a)
  {
    scalars = pd->GetArray(a);
  }
  if (!scalars)
  {
    this->Fail("the file has no point scalars");
    return 0;
  }
  if (scalars->GetNumberOfTuples() != image->GetNumberOfPoints())
  {
    std::ostringstream problem;
    problem << "the point scalars have " << scalars->GetNumberOfTuples() << " values for "
            << image->GetNumberOfPoints() << " points";
    this->Fail(problem.str());
    return 0;
  }
  output->ShallowCopy(image);
  output->GetPointData()->SetScalars(scalars);
  for (const std::string& warning : errors->Warnings)
  {
    vtkWarningMacro(<< "'" << this->FileName << "': " << warning);
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkDeepShadowVolumeReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "LastError: " << (this->LastError.empty() ? "(none)" : this->LastError) << "\n";
}
