// vtkDeepShadowVolumeReader on medical formats: NIfTI (.nii, .nii.gz) placed by its s/q-form
// in patient coordinates, DICOM series directories, and their broken variants. The real files
// are Debian's python3-nibabel test data (scripts/setup.sh installs it); without them the
// cases that need them are skipped.
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

bool HaveNibabel()
{
  return vtksys::SystemTools::FileExists(NibabelData + "anatomical.nii", true);
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
  if (!HaveNibabel())
  {
    GTEST_SKIP() << "python3-nibabel's test data is not installed";
  }
  const auto slice0 = Bytes(NibabelData + "0.dcm"), slice1 = Bytes(NibabelData + "1.dcm");
  const std::string good = TempDir("dicom-good");
  Write(good + "/0.dcm", slice0, slice0.size());
  Write(good + "/1.dcm", slice1, slice1.size());
  auto reader = Read(good);
  ASSERT_EQ(reader->GetLastError(), "");
  int dims[3];
  reader->GetOutput()->GetDimensions(dims);
  EXPECT_EQ(std::vector<int>(dims, dims + 3), (std::vector<int>{ 256, 256, 2 }));
  // The first slice's first pixel (DICOM's top-left) is at ImagePositionPatient; VTK turned
  // the image upside down, so it is voxel (0, 255, 0).
  const auto corner = World(reader->GetOutput(), 0, 255, 0);
  EXPECT_NEAR(corner[0], -805.0, 1e-3);
  EXPECT_NEAR(corner[1], -825.0191, 1e-3);
  EXPECT_NEAR(corner[2], -75.0976, 1e-3);

  const std::string empty = TempDir("dicom-empty");
  std::ofstream(empty + "/notes.txt") << "no images here";
  EXPECT_NE(Read(empty)->GetLastError().find("no DICOM files"), std::string::npos);

  const std::string cut = TempDir("dicom-cut");
  Write(cut + "/0.dcm", slice0, slice0.size());
  Write(cut + "/1.dcm", slice1, slice1.size() - 1000);
  EXPECT_NE(Read(cut)->GetLastError().find("'1.dcm': its pixel data is missing or cut short"),
    std::string::npos) << Read(cut)->GetLastError();

  // Another series: a digit of the series instance UID (0020,000E; implicit VR, the value
  // 8 bytes after the tag) changed.
  auto other = slice1;
  const std::string text(other.begin(), other.end());
  const size_t series = text.find(std::string("\x20\x00\x0e\x00", 4));
  ASSERT_NE(series, std::string::npos);
  char& digit = other[series + 8 + 30];
  digit = digit == '9' ? '8' : '9';
  const std::string mixed = TempDir("dicom-mixed");
  Write(mixed + "/0.dcm", slice0, slice0.size());
  Write(mixed + "/1.dcm", other, other.size());
  const std::string problem = Read(mixed)->GetLastError();
  EXPECT_NE(problem.find("mixes series"), std::string::npos) << problem;
}
