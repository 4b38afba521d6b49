#include "vtkDeepShadowVolumeReader.h"

#include "DicomSeries.h"
#include "NiftiFileChecks.h"
#include "ReaderMessages.h"
#include "VolumeFileChecks.h"
#include "XMLFileChecks.h"
#include "vtkDeepShadowMemoryBudget.h"

#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkMetaImageReader.h"
#include "vtkNIFTIImageReader.h"
#include "vtkNrrdReader.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkXMLImageDataReader.h"

#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <new>
#include <sstream>

vtkStandardNewMacro(vtkDeepShadowVolumeReader);

namespace
{
using deepshadow::reader::CerrCapture;
using deepshadow::reader::ErrorCollector;
using deepshadow::reader::WarningDisplayOn;
using deepshadow::volumefile::Format;
using deepshadow::volumefile::FormatOf;

std::string LowerExtension(const std::string& fileName)
{
  return vtksys::SystemTools::LowerCase(vtksys::SystemTools::GetFilenameLastExtension(fileName));
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
    case Format::Nifti:
      return "NIfTI (.nii/.nii.gz)";
    case Format::Dicom:
      return "DICOM series directory";
    default:
      return "unknown";
  }
}

// The delegate for a format, and whether it accepts the file's header.
vtkSmartPointer<vtkAlgorithm> MakeReader(Format format, const char* fileName, bool& accepted)
{
  accepted = false;
  CerrCapture quiet; // MetaIO's parse errors: the reader says why in its own words
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
    case Format::Nifti:
    {
      auto reader = vtkSmartPointer<vtkNIFTIImageReader>::New();
      accepted = reader->CanReadFile(fileName) != 0;
      reader->SetFileName(fileName);
      return reader;
    }
    default:
      return nullptr;
  }
}

// A NIfTI file's placement in DICOM's patient axes (LPS), as every other reader's data: its
// sform (else qform) maps VTK's index * spacing to RAS (VTK has already reversed the slices
// when qfac is -1); LPS negates x and y. False when the file has neither.
bool NiftiPlacement(vtkNIFTIImageReader* reader, double origin[3], double direction[9])
{
  vtkMatrix4x4* form = reader->GetSFormMatrix() ? reader->GetSFormMatrix() : reader->GetQFormMatrix();
  if (!form)
  {
    return false;
  }
  const double flip[3] = { -1.0, -1.0, 1.0 };
  for (int r = 0; r < 3; ++r)
  {
    origin[r] = flip[r] * form->GetElement(r, 3);
    for (int c = 0; c < 3; ++c)
    {
      direction[3 * r + c] = flip[r] * form->GetElement(r, c);
    }
  }
  return true;
}

// Where the delegate's image lies in patient coordinates, for NIfTI, whose reader leaves it
// at the origin unrotated; false for the others.
bool Placement(vtkAlgorithm* reader, double origin[3], double direction[9])
{
  auto* nifti = vtkNIFTIImageReader::SafeDownCast(reader);
  return nifti && NiftiPlacement(nifti, origin, direction);
}

// Whether a NIfTI file's values are stored scaled (scl_slope not 0, and not the identity):
// they are read as float, value * scl_slope + scl_inter, as dcm2niix and nibabel read them.
bool NiftiRescaled(vtkNIFTIImageReader* reader)
{
  const double slope = reader->GetRescaleSlope(), intercept = reader->GetRescaleIntercept();
  return std::isfinite(slope) && std::isfinite(intercept) && slope != 0.0 && (slope != 1.0 || intercept != 0.0);
}

// The NIfTI volume `index` (its components, from a read of every volume as components when
// index > 0), rescaled by scl_slope and scl_inter where they are set.
vtkSmartPointer<vtkDataArray> NiftiValues(vtkNIFTIImageReader* reader, vtkDataArray* all, int index)
{
  const int volumes = std::max(reader->GetTimeDimension(), 1);
  const int components = index > 0 ? all->GetNumberOfComponents() / volumes : all->GetNumberOfComponents();
  const bool rescaled = NiftiRescaled(reader);
  if (index == 0 && !rescaled)
  {
    return all;
  }
  vtkSmartPointer<vtkDataArray> values;
  values.TakeReference(rescaled ? vtkDataArray::CreateDataArray(VTK_FLOAT) : all->NewInstance());
  values->SetName(all->GetName());
  values->SetNumberOfComponents(components);
  values->SetNumberOfTuples(all->GetNumberOfTuples());
  const double slope = rescaled ? reader->GetRescaleSlope() : 1.0;
  const double intercept = rescaled ? reader->GetRescaleIntercept() : 0.0;
  const int first = index > 0 ? index * components : 0;
  for (vtkIdType t = 0; t < all->GetNumberOfTuples(); ++t)
  {
    for (int c = 0; c < components; ++c)
    {
      values->SetComponent(t, c, all->GetComponent(t, first + c) * slope + intercept);
    }
  }
  return values;
}

// Runs a request of the delegate with its messages collected and std::cerr captured;
// returns the reason it failed, or "".
std::string RunDelegate(vtkAlgorithm* reader, ErrorCollector* errors, bool information,
  const std::string& fallback)
{
  errors->Clear();
  WarningDisplayOn heard;
  CerrCapture printed;
  try
  {
    if (information)
    {
      reader->UpdateInformation();
    }
    else
    {
      reader->Update();
    }
  }
  catch (const std::bad_alloc&)
  {
    return "not enough memory to read it";
  }
  if (errors->Failed() || (!information && reader->GetErrorCode() != 0))
  {
    return errors->Reason(fallback);
  }
  // MetaIO reports some failures (e.g. "Uncompress failed") only on std::cerr.
  const std::vector<std::string> lines = printed.Lines();
  return lines.empty() ? std::string() : lines.front();
}

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
  : Errors(vtkSmartPointer<deepshadow::reader::ErrorCollector>::New())
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(1);
}

vtkDeepShadowVolumeReader::~vtkDeepShadowVolumeReader()
{
  this->SetFileName(nullptr);
}

class vtkDeepShadowVolumeReader::DicomState
{
public:
  deepshadow::dicom::Geometry Geometry;
};

void vtkDeepShadowVolumeReader::SetSeries(const std::string& series)
{
  if (series != this->Series)
  {
    this->Series = series;
    this->Modified();
  }
}

std::vector<std::string> vtkDeepShadowVolumeReader::GetSeriesDescriptions(
  const std::string& directory, std::string& problem)
{
  problem.clear();
  std::vector<std::string> lines;
  const std::vector<std::string> files = vtksys::SystemTools::FileIsDirectory(directory)
    ? deepshadow::dicom::RegularFiles(directory, &problem)
    : std::vector<std::string>{ directory };
  if (!problem.empty())
  {
    return lines;
  }
  for (const auto& series : deepshadow::dicom::ListSeries(files, problem))
  {
    lines.push_back(deepshadow::dicom::Describe(series));
  }
  return lines;
}

//------------------------------------------------------------------------------
std::vector<std::string> vtkDeepShadowVolumeReader::GetSupportedExtensions()
{
  return { ".vti", ".mhd", ".mha", ".nrrd", ".nhdr", ".nii", ".nii.gz", ".dcm" };
}

std::vector<std::string> vtkDeepShadowVolumeReader::GetFilesOf(const std::string& fileName)
{
  const Format format = FormatOf(fileName);
  if (format == Format::Dicom)
  {
    return vtksys::SystemTools::FileIsDirectory(fileName) ? deepshadow::dicom::RegularFiles(fileName)
                                                          : std::vector<std::string>{ fileName };
  }
  std::vector<std::string> files = { fileName };
  const std::vector<std::string> data = deepshadow::volumefile::DataFiles(format, fileName);
  files.insert(files.end(), data.begin(), data.end());
  return files;
}

bool vtkDeepShadowVolumeReader::CanReadFile(const char* fileName)
{
  if (!fileName || !vtksys::SystemTools::FileExists(fileName, true))
  {
    return false;
  }
  if (FormatOf(fileName) == Format::Dicom)
  {
    std::string problem;
    return !GetSeriesDescriptions(fileName, problem).empty();
  }
  bool accepted = false;
  MakeReader(FormatOf(fileName), fileName, accepted);
  return accepted;
}

//------------------------------------------------------------------------------
void vtkDeepShadowVolumeReader::Fail(const std::string& problem)
{
  std::ostringstream message;
  message << "cannot read volume '" << (this->FileName ? this->FileName : "") << "': " << problem;
  this->LastError = message.str();
  vtkErrorMacro(<< this->LastError);
}

std::uint64_t vtkDeepShadowVolumeReader::GetEffectiveMemoryBudget() const
{
  return this->MemoryBudget > 0 ? static_cast<std::uint64_t>(this->MemoryBudget)
                                : deepshadow::DefaultMemoryBudget();
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
  if (format == Format::Dicom)
  {
    return true; // read with GDCM by DicomInformation and DicomData, no VTK reader
  }
  // The header is checked before VTK's reader parses any of it (its CanReadFile included).
  const std::string problem = deepshadow::volumefile::CheckHeader(format, name);
  if (!problem.empty())
  {
    this->Fail(problem);
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
  static_cast<ErrorCollector*>(this->Errors.Get())->Watch(reader);
  this->Reader = reader;
  return true;
}

//------------------------------------------------------------------------------
int vtkDeepShadowVolumeReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  this->Modality.clear();
  this->Dicom.reset();
  if (!this->PrepareReader())
  {
    return 0;
  }
  if (!this->Reader)
  {
    return this->DicomInformation(outputVector->GetInformationObject(0)) ? 1 : 0;
  }
  if (auto* nifti = vtkNIFTIImageReader::SafeDownCast(this->Reader))
  {
    // Another volume of a 4D file: all of them as components, the one asked for kept.
    nifti->SetTimeAsVector(this->VolumeIndex > 0);
  }
  std::string problem = RunDelegate(this->Reader, static_cast<ErrorCollector*>(this->Errors.Get()),
    true, "the file's header could not be read");
  vtkInformation* in = this->Reader->GetOutputInformation(0);
  if (problem.empty())
  {
    problem = deepshadow::volumefile::CheckInformation(in, this->GetEffectiveMemoryBudget());
  }
  if (!problem.empty())
  {
    this->Fail(problem);
    return 0;
  }

  vtkInformation* out = outputVector->GetInformationObject(0);
  using SDDP = vtkStreamingDemandDrivenPipeline;
  int extent[6];
  in->Get(SDDP::WHOLE_EXTENT(), extent);
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
  double origin[3], direction[9];
  if (Placement(this->Reader, origin, direction))
  {
    out->Set(vtkDataObject::ORIGIN(), origin, 3);
    out->Set(vtkDataObject::DIRECTION(), direction, 9);
  }
  if (vtkInformation* scalars = vtkDataObject::GetActiveFieldInformation(
        in, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS))
  {
    const int type = scalars->Has(vtkDataObject::FIELD_ARRAY_TYPE())
      ? scalars->Get(vtkDataObject::FIELD_ARRAY_TYPE())
      : VTK_DOUBLE;
    int components = scalars->Has(vtkDataObject::FIELD_NUMBER_OF_COMPONENTS())
      ? scalars->Get(vtkDataObject::FIELD_NUMBER_OF_COMPONENTS())
      : 1;
    int drawnType = type;
    if (auto* nifti = vtkNIFTIImageReader::SafeDownCast(this->Reader))
    {
      const int volumes = std::max(nifti->GetTimeDimension(), 1);
      if (this->VolumeIndex >= volumes)
      {
        this->Fail("it holds " + std::to_string(volumes) + (volumes == 1 ? " volume" : " volumes") +
          "; the volume index " + std::to_string(this->VolumeIndex) + " is past them (the first is 0)");
        return 0;
      }
      components = this->VolumeIndex > 0 ? components / volumes : components;
      drawnType = NiftiRescaled(nifti) ? VTK_FLOAT : type;
    }
    vtkDataObject::SetPointDataActiveScalarInfo(out, drawnType, components);
  }
  return 1;
}

//------------------------------------------------------------------------------
bool vtkDeepShadowVolumeReader::DicomInformation(vtkInformation* out)
{
  namespace dicom = deepshadow::dicom;
  const std::string name = this->FileName;
  const bool folder = vtksys::SystemTools::FileIsDirectory(name);
  std::string problem;
  const std::vector<std::string> files = folder ? dicom::RegularFiles(name, &problem) : std::vector<std::string>{ name };
  std::vector<dicom::SeriesInfo> series;
  if (problem.empty())
  {
    series = dicom::ListSeries(files, problem);
  }
  const dicom::SeriesInfo* chosen = problem.empty() ? dicom::Choose(series, this->Series, problem) : nullptr;
  if (chosen && !folder && chosen->Frames < 2)
  {
    problem = "a single DICOM file is one slice of a series; give the folder of the series ('" +
      vtksys::SystemTools::GetFilenamePath(name) + "' if it holds only that series)";
  }
  auto state = std::make_unique<DicomState>();
  if (problem.empty())
  {
    dicom::ReadGeometry(*chosen, state->Geometry, problem);
  }
  if (!problem.empty())
  {
    this->Fail(problem);
    return false;
  }
  const dicom::Geometry& g = state->Geometry;
  const int extent[6] = { 0, g.Dimensions[0] - 1, 0, g.Dimensions[1] - 1, 0, g.Dimensions[2] - 1 };
  out->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  out->Set(vtkDataObject::SPACING(), g.Spacing, 3);
  out->Set(vtkDataObject::ORIGIN(), g.Origin, 3);
  out->Set(vtkDataObject::DIRECTION(), g.Direction, 9);
  vtkDataObject::SetPointDataActiveScalarInfo(out, g.ScalarType, 1);
  problem = deepshadow::volumefile::CheckInformation(out, this->GetEffectiveMemoryBudget());
  if (!problem.empty())
  {
    this->Fail(problem);
    return false;
  }
  this->Modality = g.Modality;
  if (!g.Warning.empty())
  {
    vtkWarningMacro(<< "'" << name << "': " << g.Warning);
  }
  this->Dicom = std::move(state);
  return true;
}

bool vtkDeepShadowVolumeReader::DicomData(vtkImageData* output)
{
  const deepshadow::dicom::Geometry& g = this->Dicom->Geometry;
  output->SetDimensions(g.Dimensions);
  output->SetSpacing(g.Spacing);
  output->SetOrigin(g.Origin);
  output->SetDirectionMatrix(g.Direction);
  try
  {
    output->AllocateScalars(g.ScalarType, 1);
  }
  catch (const std::bad_alloc&)
  {
    this->Fail("not enough memory to read it");
    return false;
  }
  std::string problem;
  if (!deepshadow::dicom::ReadPixels(g, output, problem))
  {
    output->Initialize();
    this->Fail(problem);
    return false;
  }
  // The type the headers allow is wide (16-bit stored plus an intercept: 32 bits); the values
  // read often fit a narrower one (CT's Hounsfield units: 16 bits), half the memory.
  vtkDataArray* values = output->GetPointData()->GetScalars();
  const int narrow = deepshadow::dicom::NarrowestType(values);
  if (narrow != values->GetDataType())
  {
    vtkSmartPointer<vtkDataArray> narrowed = vtk::TakeSmartPointer(vtkDataArray::CreateDataArray(narrow));
    narrowed->DeepCopy(values);
    output->GetPointData()->SetScalars(narrowed);
  }
  output->GetPointData()->GetScalars()->SetName("DICOM");
  return true;
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
  if (!this->Reader && this->Dicom)
  {
    return this->DicomData(output) ? 1 : 0;
  }
  if (!this->Reader)
  {
    this->Fail("the file's header was not read");
    return 0;
  }
  // What the header declares against what the file holds, before VTK's reader reads it.
  const Format format = FormatOf(this->FileName);
  std::string problem;
  if (format == Format::Nrrd || format == Format::Meta)
  {
    problem = deepshadow::volumefile::CheckDataFile(format, this->FileName,
      deepshadow::volumefile::ScalarBytes(this->Reader->GetOutputInformation(0)));
  }
  else if (format == Format::Nifti)
  {
    problem = deepshadow::volumefile::CheckNiftiData(this->FileName);
  }
  else if (auto* xml = vtkXMLImageDataReader::SafeDownCast(this->Reader))
  {
    problem = deepshadow::xmlfile::CheckImage(xml->GetXMLParser(), this->FileName);
  }
  auto* errors = static_cast<ErrorCollector*>(this->Errors.Get());
  if (problem.empty())
  {
    problem = RunDelegate(this->Reader, errors, false, "the reader failed on the file's data");
  }
  if (!problem.empty())
  {
    this->Fail(problem);
    return 0;
  }
  vtkImageData* image = vtkImageData::SafeDownCast(this->Reader->GetOutputDataObject(0));
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
  if (auto* nifti = vtkNIFTIImageReader::SafeDownCast(this->Reader))
  {
    output->GetPointData()->SetScalars(NiftiValues(nifti, scalars, this->VolumeIndex));
  }
  double origin[3], direction[9];
  if (Placement(this->Reader, origin, direction))
  {
    output->SetOrigin(origin);
    output->SetDirectionMatrix(direction);
  }
  if (auto* nifti = vtkNIFTIImageReader::SafeDownCast(this->Reader))
  {
    if (nifti->GetTimeDimension() > 1 && this->VolumeIndex == 0)
    {
      vtkWarningMacro(<< "'" << this->FileName << "' holds " << nifti->GetTimeDimension()
                      << " volumes (4D); the first is read (SetVolumeIndex, --volume-index: another)");
    }
  }

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
  os << indent << "MemoryBudget: " << this->MemoryBudget << " (0: the default, "
     << deepshadow::DefaultMemoryBudget() << ")\n";
  os << indent << "Series: " << (this->Series.empty() ? "(the folder's only one)" : this->Series) << "\n";
  os << indent << "VolumeIndex: " << this->VolumeIndex << "\n";
  os << indent << "Modality: " << (this->Modality.empty() ? "(none)" : this->Modality) << "\n";
  os << indent << "LastError: " << (this->LastError.empty() ? "(none)" : this->LastError) << "\n";
}
