// vtkDeepShadowVolumeReader on medical formats: NIfTI (.nii, .nii.gz) placed by its s/q-form
// in patient coordinates, DICOM series directories, and their broken variants. The real files
// are Debian's python3-nibabel and python3-pydicom test data (scripts/setup.sh installs
// them); without them the cases that need them are skipped. Voxel values against an
// independent reader: Python.DicomOracle (dcm2niix, pydicom).
#include "vtkDeepShadowVolumeReader.h"

#include "vtkImageData.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"

#include <gtest/gtest.h>
#include <vtksys/SystemTools.hxx>

#include <fstream>
#include <string>
#include <vector>

namespace
{
const std::string NibabelData = "/usr/lib/python3/dist-packages/nibabel/tests/data/";

const std::string PydicomCT = "/usr/lib/python3/dist-packages/pydicom/data/test_files/dicomdirtests/98892001/CT5N/";

bool HaveNibabel()
{
  return vtksys::SystemTools::FileExists(NibabelData + "anatomical.nii", true);
}

bool HavePydicom()
{
  return vtksys::SystemTools::FileExists(PydicomCT + "2062", true);
}

std::vector<char> Bytes(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::vector<char>((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void Write(const std::string& path, const std::vector<char>& bytes, size_t count)
{
  std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(count));
}

// Reads `path`; returns the reader (its output and GetLastError()).
vtkSmartPointer<vtkDeepShadowVolumeReader> Read(const std::string& path)
{
  auto reader = vtkSmartPointer<vtkDeepShadowVolumeReader>::New();
  reader->SetFileName(path.c_str());
  vtkObject::GlobalWarningDisplayOff();
  reader->Update();
  vtkObject::GlobalWarningDisplayOn();
  return reader;
}

// World (patient, LPS) position of a voxel.
std::vector<double> World(vtkImageData* image, int i, int j, int k)
{
  double index[3] = { double(i), double(j), double(k) }, world[3];
  image->TransformContinuousIndexToPhysicalPoint(index, world);
  return { world[0], world[1], world[2] };
}

std::string TempDir(const std::string& name)
{
  const std::string dir = ::testing::TempDir() + "/" + name;
  vtksys::SystemTools::RemoveADirectory(dir);
  vtksys::SystemTools::MakeDirectory(dir);
  return dir;
}
}

TEST(MedicalReaders, NiftiIsPlacedByItsFormInPatientCoordinates)
{
  if (!HaveNibabel())
  {
    GTEST_SKIP() << "python3-nibabel's test data is not installed";
  }
  auto reader = Read(NibabelData + "anatomical.nii");
  ASSERT_EQ(reader->GetLastError(), "");
  vtkImageData* image = reader->GetOutput();
  int dims[3];
  image->GetDimensions(dims);
  EXPECT_EQ(std::vector<int>(dims, dims + 3), (std::vector<int>{ 33, 41, 25 }));
  // nibabel: voxel (3, 5, 17) is at RAS (26, -30, 18) (affine diag(-2, 2, 2), offset (32, -40,
  // -16)); VTK reverses the slices (qfac -1), so it is VTK's (3, 5, 7), at LPS (-26, 30, 18).
  const auto world = World(image, 3, 5, 7);
  EXPECT_NEAR(world[0], -26.0, 1e-4);
  EXPECT_NEAR(world[1], 30.0, 1e-4);
  EXPECT_NEAR(world[2], 18.0, 1e-4);
  int voxel[3] = { 3, 5, 7 };
  EXPECT_EQ(image->GetPointData()->GetScalars()->GetComponent(image->ComputePointId(voxel), 0),
    10505.0) << "nibabel's value at (3, 5, 17)";

  auto gz = Read(NibabelData + "example4d.nii.gz");
  ASSERT_EQ(gz->GetLastError(), "");
  gz->GetOutput()->GetDimensions(dims);
  EXPECT_EQ(std::vector<int>(dims, dims + 3), (std::vector<int>{ 128, 96, 24 })) << "the first volume";
}

TEST(MedicalReaders, CutNiftiFilesAreRefused)
{
  if (!HaveNibabel())
  {
    GTEST_SKIP() << "python3-nibabel's test data is not installed";
  }
  const std::string dir = TempDir("nifti");
  const auto nii = Bytes(NibabelData + "anatomical.nii");
  Write(dir + "/cut.nii", nii, 40000);
  EXPECT_NE(Read(dir + "/cut.nii")->GetLastError().find("truncated?"), std::string::npos);
  Write(dir + "/header.nii", nii, 300);
  EXPECT_NE(Read(dir + "/header.nii")->GetLastError().find("shorter than a NIfTI header"), std::string::npos);
  const auto gz = Bytes(NibabelData + "example4d.nii.gz");
  Write(dir + "/cut.nii.gz", gz, 50000);
  EXPECT_NE(Read(dir + "/cut.nii.gz")->GetLastError().find("gzip stream is broken"), std::string::npos);
}

TEST(MedicalReaders, DicomSeriesDirectoriesReadAndBrokenOnesAreNamed)
{
  if (!HavePydicom())
  {
    GTEST_SKIP() << "python3-pydicom's test files are not installed";
  }
  // pydicom's real CT: 5 axial slices, instance numbers running down the patient (the files'
  // order is not the slices' order).
  const std::vector<std::string> names = { "2062", "2392", "2693", "3023", "3353" };
  const std::string good = TempDir("dicom-good");
  for (const std::string& name : names)
  {
    const auto bytes = Bytes(PydicomCT + name);
    Write(good + "/" + name, bytes, bytes.size());
  }
  auto reader = Read(good);
  ASSERT_EQ(reader->GetLastError(), "");
  EXPECT_EQ(reader->GetModality(), "CT");
  int dims[3];
  reader->GetOutput()->GetDimensions(dims);
  EXPECT_EQ(std::vector<int>(dims, dims + 3), (std::vector<int>{ 16, 16, 5 }));
  EXPECT_EQ(reader->GetOutput()->GetScalarType(), VTK_SHORT) << "HU: stored + intercept -1024";
  // Slice 0 is the lowest (z = -1.2375, file 3353), slice 4 the highest (z = 8.7625, 2062);
  // index (i, j) is column i, row j from ImagePositionPatient.
  for (int k : { 0, 4 })
  {
    const auto corner = World(reader->GetOutput(), 0, 0, k);
    EXPECT_NEAR(corner[0], -72.2, 1e-3);
    EXPECT_NEAR(corner[1], -143.0, 1e-3);
    EXPECT_NEAR(corner[2], k == 0 ? -1.2375 : 8.7625, 1e-3);
  }
  const auto far = World(reader->GetOutput(), 15, 15, 0);
  EXPECT_NEAR(far[0], -72.2 + 15 * 0.488281, 1e-3);
  EXPECT_NEAR(far[1], -143.0 + 15 * 0.488281, 1e-3);

  const std::string empty = TempDir("dicom-empty");
  std::ofstream(empty + "/notes.txt") << "no images here";
  EXPECT_NE(Read(empty)->GetLastError().find("no DICOM files"), std::string::npos);

  const std::string cut = TempDir("dicom-cut");
  for (const std::string& name : names)
  {
    const auto bytes = Bytes(PydicomCT + name);
    Write(cut + "/" + name, bytes, name == "2693" ? bytes.size() - 300 : bytes.size());
  }
  EXPECT_NE(Read(cut)->GetLastError().find("'2693'"), std::string::npos) << Read(cut)->GetLastError();

  // Another series beside it: a digit of one file's SeriesInstanceUID (0020,000E; explicit VR,
  // the value 8 bytes after the tag) changed. The series are listed, and either can be chosen.
  auto other = Bytes(PydicomCT + "2062");
  const std::string text(other.begin(), other.end());
  const size_t series = text.find(std::string("\x20\x00\x0e\x00UI", 6));
  ASSERT_NE(series, std::string::npos);
  char& digit = other[series + 8 + 20];
  digit = digit == '9' ? '8' : '9';
  const std::string mixed = TempDir("dicom-mixed");
  for (const std::string& name : names)
  {
    const auto bytes = Bytes(PydicomCT + name);
    Write(mixed + "/" + name, bytes, bytes.size());
  }
  Write(mixed + "/other", other, other.size());
  std::string problem = Read(mixed)->GetLastError();
  EXPECT_NE(problem.find("holds 2 series"), std::string::npos) << problem;
  std::string listing;
  const auto lines = vtkDeepShadowVolumeReader::GetSeriesDescriptions(mixed, listing);
  ASSERT_EQ(lines.size(), 2u) << listing;
  const std::string uid = lines[1].substr(lines[1].rfind("UID ") + 4, lines[1].size() - lines[1].rfind("UID ") - 5);
  vtkNew<vtkDeepShadowVolumeReader> chosen;
  chosen->SetFileName(mixed.c_str());
  chosen->SetSeries(uid);
  vtkObject::GlobalWarningDisplayOff();
  chosen->Update();
  vtkObject::GlobalWarningDisplayOn();
  EXPECT_NE(chosen->GetLastError().find("one slice"), std::string::npos)
    << "the one-file series is chosen, and is one slice: " << chosen->GetLastError();

  EXPECT_NE(Read(good + "/2062")->GetLastError().find("give the folder of the series"), std::string::npos);
  if (HaveNibabel())
  {
    // nibabel's two Siemens files are mosaics: each a volume's slices tiled in one image.
    const std::string mosaic = TempDir("dicom-mosaic");
    for (const std::string& name : { "0.dcm", "1.dcm" })
    {
      const auto bytes = Bytes(NibabelData + name);
      Write(mosaic + "/" + name, bytes, bytes.size());
    }
    problem = Read(mosaic)->GetLastError();
    EXPECT_NE(problem.find("Siemens mosaic"), std::string::npos) << problem;
  }
}
