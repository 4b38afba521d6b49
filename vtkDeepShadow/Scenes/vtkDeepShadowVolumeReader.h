/**
 * @class   vtkDeepShadowVolumeReader
 * @brief   Reads a volume from a file, choosing VTK's reader by the file's extension.
 *
 * Extensions (case-insensitive): .vti (vtkXMLImageDataReader), .mhd and .mha
 * (vtkMetaImageReader), .nrrd and .nhdr (vtkNrrdReader), .nii and .nii.gz
 * (vtkNIFTIImageReader; placed by its sform, else qform, in DICOM's patient axes (LPS) through
 * the output's origin and direction matrix; its scl_slope and scl_inter applied; of a 4D file
 * the volume SetVolumeIndex chooses), and DICOM: a folder (its series SetSeries chooses), or
 * one multi-frame file, read with GDCM: slices sorted by position along their normal, placed
 * in LPS, rescaled to the modality's units (DicomSeries.h).
 * The output is a vtkImageData whose
 * active point scalars are the volume (the file's active scalars, else its first point array).
 *
 * Bad input (no file name, missing or unreadable file, unknown extension, a file the chosen
 * reader cannot parse, no point scalars) is reported with one vtkErrorMacro line that names the
 * file and the problem; the request then fails and the output stays empty. The same line is
 * kept in GetLastError() for command-line tools (with VTK's global warning display off, the
 * vtkErrorMacro is silent but GetLastError() is not). Messages of the underlying VTK reader
 * are collected by observers on it (VTK's global warning display is held on while it runs,
 * since it also gates the events, whatever the application set) and what it prints to
 * std::cerr is captured, rather than printed; the first one becomes the reason on that line.
 *
 * Before VTK's reader reads any data, the file is checked against what its header declares,
 * because VTK's readers trust it: header fields VTK misreads (counts that do not match the
 * dimensions, unknown element types), a spacing, origin or direction that is not finite (or
 * a zero spacing, a singular direction), data beyond MemoryBudget, missing data files, raw
 * data of NRRD and MetaImage files and appended data of VTK XML files shorter than the image.
 */
#ifndef vtkDeepShadowVolumeReader_h
#define vtkDeepShadowVolumeReader_h

#include "vtkDeepShadowScenesModule.h" // For export macro
#include "vtkImageAlgorithm.h"
#include "vtkSmartPointer.h" // For the delegate reader

#include <cstdint> // For std::uint64_t
#include <memory>  // For the DICOM state
#include <string>  // For GetLastError
#include <vector> // For GetSupportedExtensions

class vtkCommand;

class VTKDEEPSHADOWSCENES_EXPORT vtkDeepShadowVolumeReader : public vtkImageAlgorithm
{
public:
  static vtkDeepShadowVolumeReader* New();
  vtkTypeMacro(vtkDeepShadowVolumeReader, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** The file to read. */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /**
   * The most bytes the image's scalars may take; a file declaring more is refused, naming
   * the bytes, before anything is allocated. 0 (the default) is
   * deepshadow::DefaultMemoryBudget(): half the machine's memory or address-space limit.
   */
  vtkSetClampMacro(MemoryBudget, vtkTypeInt64, 0, VTK_TYPE_INT64_MAX);
  vtkGetMacro(MemoryBudget, vtkTypeInt64);
  ///@}

  ///@{
  /**
   * DICOM: the series of the folder to read, by its SeriesNumber or SeriesInstanceUID; empty
   * (the default) reads the folder's only series, and a folder of several is an error that
   * lists them (GetSeriesDescriptions).
   */
  void SetSeries(const std::string& series);
  const std::string& GetSeries() const { return this->Series; }
  ///@}

  ///@{
  /**
   * NIfTI: which volume of a 4D file to read (0, the default: the first). An index past the
   * file's volumes is an error naming their count.
   */
  vtkSetClampMacro(VolumeIndex, int, 0, VTK_INT_MAX);
  vtkGetMacro(VolumeIndex, int);
  ///@}

  /** The last file's Modality (DICOM's (0008,0060): "CT", "MR", ...); empty for other formats. */
  const std::string& GetModality() const { return this->Modality; }

  /**
   * One line on each image series of a DICOM folder (its number, modality, description,
   * slices, size and UID), as SetSeries takes them; empty with the reason in `problem` when
   * the folder holds none.
   */
  static std::vector<std::string> GetSeriesDescriptions(const std::string& directory, std::string& problem);

  /**
   * Supported extensions, lower case with the dot: .vti, .mhd, .mha, .nrrd, .nhdr, .nii,
   * .nii.gz, .dcm (a multi-frame file; any file with DICOM's preamble is read as DICOM, and
   * so is a folder).
   */
  static std::vector<std::string> GetSupportedExtensions();

  /**
   * The files a volume is read from: the file itself and the detached data files its header
   * names (MetaImage's ElementDataFile, NRRD's "data file", one, a LIST or a pattern), or
   * the regular files of a DICOM folder. A tool refuses to write over any of them.
   */
  static std::vector<std::string> GetFilesOf(const std::string& fileName);

  /** True if the file exists, has a supported extension and its reader accepts it. */
  static bool CanReadFile(const char* fileName);

  /** The one-line reason of the last failure; empty after a successful read. */
  const std::string& GetLastError() const { return this->LastError; }

protected:
  vtkDeepShadowVolumeReader();
  ~vtkDeepShadowVolumeReader() override;

  int RequestInformation(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  /** Checks the file and makes the delegate reader; false (with the error reported) if bad. */
  bool PrepareReader();

  /** MemoryBudget, or the default for 0. */
  std::uint64_t GetEffectiveMemoryBudget() const;

  /** Reports `problem` about the file as the one-line error. */
  void Fail(const std::string& problem);

  /** DICOM's RequestInformation and RequestData (no VTK reader: GDCM, DicomSeries.h). */
  bool DicomInformation(vtkInformation* out);
  bool DicomData(vtkImageData* output);

  char* FileName = nullptr;
  vtkTypeInt64 MemoryBudget = 0;
  std::string Series;
  int VolumeIndex = 0;
  std::string Modality;
  class DicomState;
  std::unique_ptr<DicomState> Dicom; // the chosen series' geometry, between the requests
  std::string LastError;
  vtkSmartPointer<vtkAlgorithm> Reader;
  vtkSmartPointer<vtkCommand> Errors; // collects the delegate's messages

private:
  vtkDeepShadowVolumeReader(const vtkDeepShadowVolumeReader&) = delete;
  void operator=(const vtkDeepShadowVolumeReader&) = delete;
};

#endif
