// Unit tests of DeepShadow::Scenes: the procedural standard scenes and the volume reader.
#include "vtkDeepShadowStandardScene.h"
#include "vtkDeepShadowMeshReader.h"
#include "vtkDeepShadowVolumeReader.h"

#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkMetaImageWriter.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkShortArray.h"
#include "vtkVolumeProperty.h"
#include "vtkXMLImageDataWriter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace
{
// Collects the error messages an object reports (and keeps them off the console).
class ErrorObserver : public vtkCommand
{
public:
  static ErrorObserver* New() { return new ErrorObserver; }
  void Execute(vtkObject*, unsigned long, void* callData) override
  {
    this->Messages.emplace_back(callData ? static_cast<const char*>(callData) : "");
  }
  std::vector<std::string> Messages;
};

struct Expected
{
  std::array<int, 3> Dims; // at scale 1
  int ScalarType;
};

const std::map<std::string, Expected>& ExpectedScenes()
{
  static const std::map<std::string, Expected> scenes = {
    { "box", { { 64, 64, 64 }, VTK_UNSIGNED_CHAR } },
    { "bucky", { { 32, 32, 32 }, VTK_UNSIGNED_CHAR } },
    { "rods", { { 64, 64, 64 }, VTK_UNSIGNED_CHAR } },
    { "clouds", { { 512, 512, 32 }, VTK_UNSIGNED_CHAR } },
    { "spheres", { { 128, 128, 128 }, VTK_UNSIGNED_CHAR } },
    { "head", { { 256, 256, 160 }, VTK_SHORT } },
    { "sparse", { { 256, 256, 48 }, VTK_UNSIGNED_CHAR } },
  };
  return scenes;
}

const double TestScale = 0.25;
const double Pi = 3.14159265358979323846;

int ScaledDim(int dim, double scale)
{
  return std::max(2, static_cast<int>(std::floor(dim * scale + 0.5)));
}

// A fresh directory under the test temp dir, removed by the destructor.
class TempDir
{
public:
  TempDir()
  {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    this->Path = fs::path(::testing::TempDir()) /
      (std::string("TestScenes_") + info->test_suite_name() + "_" + info->name());
    fs::remove_all(this->Path);
    fs::create_directories(this->Path);
  }
  ~TempDir()
  {
    std::error_code ignored;
    fs::remove_all(this->Path, ignored);
  }
  std::string File(const std::string& name) const { return (this->Path / name).string(); }

  fs::path Path;
};

// Generates the scene at the given scale (a new object each time: nothing cached).
vtkSmartPointer<vtkImageData> Generate(const std::string& name, double scale)
{
  vtkNew<vtkDeepShadowStandardScene> scene;
  EXPECT_TRUE(scene->SetScene(name));
  scene->SetResolutionScale(scale);
  return scene->GetVolume();
}

size_t ByteSize(vtkDataArray* array)
{
  return static_cast<size_t>(array->GetNumberOfValues()) * array->GetDataTypeSize();
}

bool SameValues(vtkDataArray* a, vtkDataArray* b)
{
  return a && b && a->GetDataType() == b->GetDataType() &&
    a->GetNumberOfValues() == b->GetNumberOfValues() &&
    std::memcmp(a->GetVoidPointer(0), b->GetVoidPointer(0), ByteSize(a)) == 0;
}

// Reads a file with vtkDeepShadowVolumeReader; errors go to `errors`.
vtkSmartPointer<vtkImageData> Read(
  const std::string& file, ErrorObserver* errors = nullptr, std::string* lastError = nullptr)
{
  vtkNew<vtkDeepShadowVolumeReader> reader;
  if (errors)
  {
    reader->AddObserver(vtkCommand::ErrorEvent, errors);
  }
  reader->SetFileName(file.c_str());
  reader->Update();
  if (lastError)
  {
    *lastError = reader->GetLastError();
  }
  return reader->GetOutput();
}

void ExpectSameImage(vtkImageData* expected, vtkImageData* actual)
{
  ASSERT_NE(actual, nullptr);
  int de[3], da[3];
  expected->GetDimensions(de);
  actual->GetDimensions(da);
  for (int a = 0; a < 3; ++a)
  {
    EXPECT_EQ(de[a], da[a]) << "axis " << a;
    // The writers store spacing and origin in single precision.
    const double tolerance = 1e-6 * (1.0 + std::fabs(expected->GetOrigin()[a]));
    EXPECT_NEAR(expected->GetSpacing()[a], actual->GetSpacing()[a], tolerance) << "axis " << a;
    EXPECT_NEAR(expected->GetOrigin()[a], actual->GetOrigin()[a], tolerance) << "axis " << a;
  }
  vtkDataArray* scalars = actual->GetPointData()->GetScalars();
  ASSERT_NE(scalars, nullptr) << "no active point scalars";
  EXPECT_TRUE(SameValues(expected->GetPointData()->GetScalars(), scalars));
}
}

//------------------------------------------------------------------------------
TEST(StandardScene, NamesAndDescriptions)
{
  const std::vector<std::string> expected = { "box", "bucky", "rods", "clouds", "spheres", "head", "sparse" };
  EXPECT_EQ(vtkDeepShadowStandardScene::GetSceneNames(), expected);
  for (const std::string& name : expected)
  {
    EXPECT_FALSE(vtkDeepShadowStandardScene::GetSceneDescription(name).empty()) << name;
    EXPECT_TRUE(vtkDeepShadowStandardScene::IsSceneName(name));
  }
  EXPECT_EQ(vtkDeepShadowStandardScene::GetSceneDescription("teapot"), "");
  EXPECT_FALSE(vtkDeepShadowStandardScene::IsSceneName("teapot"));
}

TEST(StandardScene, UnknownSceneIsRejectedWithTheValidNames)
{
  vtkNew<vtkDeepShadowStandardScene> scene;
  vtkNew<ErrorObserver> errors;
  scene->AddObserver(vtkCommand::ErrorEvent, errors);
  ASSERT_TRUE(scene->SetScene("rods"));
  EXPECT_FALSE(scene->SetScene("teapot"));
  EXPECT_EQ(scene->GetScene(), "rods");
  ASSERT_EQ(errors->Messages.size(), 1u);
  for (const std::string& name : vtkDeepShadowStandardScene::GetSceneNames())
  {
    EXPECT_NE(errors->Messages[0].find(name), std::string::npos) << errors->Messages[0];
  }
  EXPECT_NE(errors->Messages[0].find("teapot"), std::string::npos);
}

TEST(StandardScene, SetSceneAndScaleDropTheCache)
{
  vtkNew<vtkDeepShadowStandardScene> scene;
  scene->SetScene("box");
  scene->SetResolutionScale(TestScale);
  vtkImageData* first = scene->GetVolume();
  EXPECT_EQ(scene->GetVolume(), first); // cached
  scene->SetResolutionScale(0.5);
  int dims[3];
  scene->GetVolume()->GetDimensions(dims);
  EXPECT_EQ(dims[0], 32);
  scene->SetScene("bucky");
  scene->GetVolume()->GetDimensions(dims);
  EXPECT_EQ(dims[0], 16);
}

namespace
{
// Groups of 26-connected non-zero voxels (the sparse scene's objects do not touch).
int CountObjects(vtkImageData* image)
{
  int dims[3];
  image->GetDimensions(dims);
  const auto* v = static_cast<const unsigned char*>(image->GetScalarPointer());
  const long n = static_cast<long>(dims[0]) * dims[1] * dims[2];
  std::vector<char> seen(static_cast<size_t>(n), 0);
  int objects = 0;
  std::vector<long> stack;
  for (long start = 0; start < n; ++start)
  {
    if (!v[start] || seen[start])
    {
      continue;
    }
    ++objects;
    seen[start] = 1;
    stack.push_back(start);
    while (!stack.empty())
    {
      const long at = stack.back();
      stack.pop_back();
      const int x = static_cast<int>(at % dims[0]), y = static_cast<int>((at / dims[0]) % dims[1]),
                z = static_cast<int>(at / (static_cast<long>(dims[0]) * dims[1]));
      for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx)
          {
            const int i = x + dx, j = y + dy, k = z + dz;
            if (i < 0 || j < 0 || k < 0 || i >= dims[0] || j >= dims[1] || k >= dims[2])
            {
              continue;
            }
            const long next = i + dims[0] * (j + static_cast<long>(dims[1]) * k);
            if (v[next] && !seen[next])
            {
              seen[next] = 1;
              stack.push_back(next);
            }
          }
    }
  }
  return objects;
}
}

TEST(StandardScene, SparseObjectCountKeepsTheFirstObjectsOrAddsMore)
{
  vtkNew<vtkDeepShadowStandardScene> scene;
  scene->SetScene("sparse");
  vtkSmartPointer<vtkImageData> all = scene->GetVolume();
  EXPECT_EQ(CountObjects(all), 19);
  const auto* full = static_cast<const unsigned char*>(all->GetScalarPointer());
  for (int count : { 1, 4, 12, 24 })
  {
    scene->SetObjectCount(count);
    EXPECT_EQ(scene->GetObjectCount(), count);
    vtkImageData* some = scene->GetVolume();
    EXPECT_EQ(CountObjects(some), count) << count;
    // The objects kept are the scene's own, voxel for voxel.
    const auto* v = static_cast<const unsigned char*>(some->GetScalarPointer());
    long differ = 0;
    for (vtkIdType i = 0; i < some->GetNumberOfPoints(); ++i)
    {
      differ += (v[i] != 0 && count <= 19 && v[i] != full[i]) || (count > 19 && full[i] != 0 && v[i] != full[i]) ? 1 : 0;
    }
    EXPECT_EQ(differ, 0) << count;
  }
  scene->SetObjectCount(99);
  EXPECT_EQ(scene->GetObjectCount(), vtkDeepShadowStandardScene::GetMaxObjectCount());
}

//------------------------------------------------------------------------------
class EachScene : public ::testing::TestWithParam<std::string>
{
};

TEST_P(EachScene, DimensionsTypeAndWorldSize)
{
  const std::string name = GetParam();
  const Expected& expected = ExpectedScenes().at(name);
  vtkNew<vtkDeepShadowStandardScene> full;
  full->SetScene(name);
  double fullSpacing[3], fullOrigin[3];
  int fullDims[3];
  full->GetDimensions(fullDims);
  full->GetSpacing(fullSpacing);
  full->GetOrigin(fullOrigin);

  vtkNew<vtkDeepShadowStandardScene> scene;
  scene->SetScene(name);
  scene->SetResolutionScale(TestScale);
  vtkImageData* volume = scene->GetVolume();
  ASSERT_NE(volume, nullptr);
  int dims[3];
  volume->GetDimensions(dims);
  for (int a = 0; a < 3; ++a)
  {
    EXPECT_EQ(fullDims[a], expected.Dims[a]);
    EXPECT_EQ(dims[a], ScaledDim(expected.Dims[a], TestScale)) << "axis " << a;
    // Same world-space size at any scale, centred on the origin.
    const double extent = (dims[a] - 1) * volume->GetSpacing()[a];
    EXPECT_NEAR(extent, (fullDims[a] - 1) * fullSpacing[a], 1e-9);
    EXPECT_NEAR(volume->GetOrigin()[a], -0.5 * extent, 1e-9);
    EXPECT_NEAR(volume->GetOrigin()[a], fullOrigin[a], 1e-9);
    EXPECT_GE(extent, 10.0);
    EXPECT_LE(extent, 300.0);
  }
  vtkDataArray* scalars = volume->GetPointData()->GetScalars();
  ASSERT_NE(scalars, nullptr);
  EXPECT_STREQ(scalars->GetName(), "scalars");
  EXPECT_EQ(scalars->GetNumberOfComponents(), 1);
  EXPECT_EQ(scalars->GetDataType(), expected.ScalarType);
  EXPECT_EQ(scene->GetScalarType(), expected.ScalarType);
  EXPECT_EQ(scalars->GetNumberOfTuples(), volume->GetNumberOfPoints());
  double range[2];
  scalars->GetRange(range);
  EXPECT_LT(range[0], range[1]) << "constant volume";
  EXPECT_LE(range[0], scene->GetBackgroundValue() + 10.0); // empty space is present

  double spacing[3];
  scene->GetSpacing(spacing);
  const double smallest = std::min(std::min(spacing[0], spacing[1]), spacing[2]);
  EXPECT_NEAR(scene->GetSuggestedSampleDistance(), 0.5 * smallest, 0.1 * smallest);
}

TEST_P(EachScene, Deterministic)
{
  auto a = Generate(GetParam(), TestScale);
  auto b = Generate(GetParam(), TestScale);
  EXPECT_TRUE(SameValues(a->GetPointData()->GetScalars(), b->GetPointData()->GetScalars()));
}

TEST_P(EachScene, TransferFunctionSkipsTheBackground)
{
  vtkNew<vtkDeepShadowStandardScene> scene;
  scene->SetScene(GetParam());
  scene->SetResolutionScale(TestScale);
  vtkVolumeProperty* property = scene->GetVolumeProperty();
  ASSERT_NE(property, nullptr);
  EXPECT_TRUE(property->GetShade());
  EXPECT_EQ(property->GetInterpolationType(), VTK_LINEAR_INTERPOLATION);
  EXPECT_GT(property->GetScalarOpacityUnitDistance(), 0.0);
  vtkPiecewiseFunction* opacity = property->GetScalarOpacity();
  ASSERT_NE(opacity, nullptr);
  EXPECT_EQ(opacity->GetValue(scene->GetBackgroundValue()), 0.0);

  double range[2];
  scene->GetVolume()->GetPointData()->GetScalars()->GetRange(range);
  double maxOpacity = 0.0;
  for (int i = 0; i <= 256; ++i)
  {
    maxOpacity =
      std::max(maxOpacity, opacity->GetValue(range[0] + (range[1] - range[0]) * i / 256));
  }
  EXPECT_GT(maxOpacity, 0.0);
}

TEST_P(EachScene, CameraFramesTheSceneAndLightIsOffAxis)
{
  vtkNew<vtkDeepShadowStandardScene> scene;
  scene->SetScene(GetParam());
  scene->SetResolutionScale(TestScale);
  vtkNew<vtkCamera> camera;
  scene->ApplyCamera(camera);
  EXPECT_DOUBLE_EQ(camera->GetViewAngle(), 30.0);

  double bounds[6];
  scene->GetVolume()->GetBounds(bounds);
  const double tanHalf = std::tan(15.0 * Pi / 180.0);
  vtkMatrix4x4* view = camera->GetViewTransformMatrix();
  int cornersInView = 0;
  for (int corner = 0; corner < 8; ++corner)
  {
    const double p[4] = { bounds[(corner & 1) ? 1 : 0], bounds[(corner & 2) ? 3 : 2],
      bounds[(corner & 4) ? 5 : 4], 1.0 };
    double e[4];
    view->MultiplyPoint(p, e);
    cornersInView += e[2] < 0.0 && std::fabs(e[0] / e[2]) < tanHalf && std::fabs(e[1] / e[2]) < tanHalf;
  }
  const double* focal = camera->GetFocalPoint();
  const double* pos = camera->GetPosition();
  if (GetParam() == "sparse")
  {
    // Close to one object: the focal point on a visible sample, the camera outside the volume
    // but nearer than a third of its diagonal, most of the volume out of view.
    const double diagonal = std::sqrt(std::pow(bounds[1] - bounds[0], 2) +
      std::pow(bounds[3] - bounds[2], 2) + std::pow(bounds[5] - bounds[4], 2));
    EXPECT_LT(std::sqrt(vtkMath::Distance2BetweenPoints(pos, focal)), diagonal / 3.0);
    bool inside = true;
    for (int a = 0; a < 3; ++a)
    {
      EXPECT_GT(focal[a], bounds[2 * a]);
      EXPECT_LT(focal[a], bounds[2 * a + 1]);
      inside = inside && pos[a] > bounds[2 * a] && pos[a] < bounds[2 * a + 1];
    }
    EXPECT_FALSE(inside) << "the camera inside the volume";
    EXPECT_LT(cornersInView, 8);
    double pcoords[3];
    int ijk[3];
    ASSERT_EQ(scene->GetVolume()->ComputeStructuredCoordinates(focal, ijk, pcoords), 1);
    const double value = scene->GetVolume()->GetScalarComponentAsDouble(ijk[0], ijk[1], ijk[2], 0);
    EXPECT_GT(scene->GetVolumeProperty()->GetScalarOpacity()->GetValue(value), 0.05) << value;
  }
  else
  {
    EXPECT_EQ(cornersInView, 8) << "the whole volume in view";
  }

  double light[3], toCamera[3];
  scene->GetLightDirection(light);
  double n = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    toCamera[a] = pos[a] - focal[a];
    n += toCamera[a] * toCamera[a];
  }
  n = std::sqrt(n);
  EXPECT_NEAR(
    std::sqrt(light[0] * light[0] + light[1] * light[1] + light[2] * light[2]), 1.0, 1e-9);
  const double cosine =
    (light[0] * toCamera[0] + light[1] * toCamera[1] + light[2] * toCamera[2]) / n;
  // Far enough from the view direction for shadows to show, still lighting the visible side.
  EXPECT_LT(cosine, std::cos(25.0 * Pi / 180.0));
  EXPECT_GT(cosine, 0.0);
}

INSTANTIATE_TEST_SUITE_P(StandardScene, EachScene,
  ::testing::Values("box", "bucky", "rods", "clouds", "spheres", "head", "sparse"),
  [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

//------------------------------------------------------------------------------
TEST(StandardScene, HeadHasHounsfieldRanges)
{
  vtkNew<vtkDeepShadowStandardScene> scene;
  scene->SetScene("head");
  scene->SetResolutionScale(TestScale);
  vtkImageData* volume = scene->GetVolume();
  auto* scalars = vtkShortArray::SafeDownCast(volume->GetPointData()->GetScalars());
  ASSERT_NE(scalars, nullptr);
  vtkIdType air = 0, bone = 0, soft = 0;
  for (vtkIdType i = 0; i < scalars->GetNumberOfValues(); ++i)
  {
    const short v = scalars->GetValue(i);
    air += v <= -900;
    bone += v >= 500;
    soft += v >= 0 && v <= 80;
  }
  EXPECT_GT(air, 0);
  EXPECT_GT(bone, 0);
  EXPECT_GT(soft, 0);
  double range[2];
  scalars->GetRange(range);
  EXPECT_GE(range[0], -1024.0);
  EXPECT_LE(range[1], 3071.0);
  EXPECT_EQ(scene->GetBackgroundValue(), -1000.0);
  // Anisotropic like a CT: slices thicker than the in-plane spacing.
  EXPECT_GT(volume->GetSpacing()[2], volume->GetSpacing()[0]);
}

//------------------------------------------------------------------------------
TEST(VolumeReader, SupportedExtensions)
{
  const auto extensions = vtkDeepShadowVolumeReader::GetSupportedExtensions();
  for (const char* ext : { ".vti", ".mhd", ".mha", ".nrrd", ".nhdr" })
  {
    EXPECT_NE(std::find(extensions.begin(), extensions.end(), ext), extensions.end()) << ext;
  }
}

TEST(VolumeReader, RoundTripsEveryScene)
{
  TempDir dir;
  for (const std::string& name : vtkDeepShadowStandardScene::GetSceneNames())
  {
    SCOPED_TRACE(name);
    auto volume = Generate(name, TestScale);

    const std::string vti = dir.File(name + ".vti");
    vtkNew<vtkXMLImageDataWriter> xml;
    xml->SetInputData(volume);
    xml->SetFileName(vti.c_str());
    ASSERT_EQ(xml->Write(), 1);
    EXPECT_TRUE(vtkDeepShadowVolumeReader::CanReadFile(vti.c_str()));
    ExpectSameImage(volume, Read(vti));

    const std::string mhd = dir.File(name + ".mhd");
    vtkNew<vtkMetaImageWriter> meta;
    meta->SetInputData(volume);
    meta->SetFileName(mhd.c_str());
    meta->SetRAWFileName(dir.File(name + ".raw").c_str());
    meta->SetCompression(false);
    meta->Write();
    EXPECT_TRUE(vtkDeepShadowVolumeReader::CanReadFile(mhd.c_str()));
    ExpectSameImage(volume, Read(mhd));
  }
}

TEST(VolumeReader, ReadsMetaImageWithLocalData)
{
  TempDir dir;
  auto volume = Generate("head", TestScale);
  const std::string mha = dir.File("head.mha");
  vtkNew<vtkMetaImageWriter> meta;
  meta->SetInputData(volume);
  meta->SetFileName(mha.c_str());
  meta->SetCompression(false);
  meta->Write();
  ExpectSameImage(volume, Read(mha));
}

TEST(VolumeReader, ExtensionIsCaseInsensitive)
{
  TempDir dir;
  auto volume = Generate("box", TestScale);
  const std::string vti = dir.File("BOX.VTI");
  vtkNew<vtkXMLImageDataWriter> xml;
  xml->SetInputData(volume);
  xml->SetFileName(vti.c_str());
  ASSERT_EQ(xml->Write(), 1);
  ExpectSameImage(volume, Read(vti));
}

// A small NRRD written by hand: 12 x 10 x 3 shorts, raw little-endian. (vtkNrrdReader takes
// a first axis of 9 or fewer samples for vector components, hence 12.)
TEST(VolumeReader, ReadsNrrdAndDetachedHeader)
{
  TempDir dir;
  const int nx = 12, ny = 10, nz = 3;
  std::vector<short> values(nx * ny * nz);
  for (size_t i = 0; i < values.size(); ++i)
  {
    values[i] = static_cast<short>(static_cast<int>(i * 37 % 2001) - 1000);
  }
  const std::string header = "type: short\n"
                             "dimension: 3\n"
                             "space dimension: 3\n"
                             "sizes: 12 10 3\n"
                             "space directions: (0.5,0,0) (0,0.75,0) (0,0,1.25)\n"
                             "space origin: (1,2,3)\n"
                             "endian: little\n"
                             "encoding: raw\n";
  const char* data = reinterpret_cast<const char*>(values.data());
  const size_t bytes = values.size() * sizeof(short);
  {
    std::ofstream attached(dir.File("small.nrrd"), std::ios::binary);
    attached << "NRRD0004\n" << header << "\n";
    attached.write(data, bytes);
    std::ofstream detached(dir.File("small.nhdr"), std::ios::binary);
    detached << "NRRD0004\n" << header << "data file: small.raw\n\n";
    std::ofstream raw(dir.File("small.raw"), std::ios::binary);
    raw.write(data, bytes);
  }
  for (const char* file : { "small.nrrd", "small.nhdr" })
  {
    SCOPED_TRACE(file);
    vtkNew<ErrorObserver> errors;
    auto image = Read(dir.File(file), errors);
    EXPECT_TRUE(errors->Messages.empty());
    ASSERT_NE(image, nullptr);
    int dims[3];
    image->GetDimensions(dims);
    EXPECT_EQ(dims[0], nx);
    EXPECT_EQ(dims[1], ny);
    EXPECT_EQ(dims[2], nz);
    EXPECT_DOUBLE_EQ(image->GetSpacing()[0], 0.5);
    EXPECT_DOUBLE_EQ(image->GetSpacing()[1], 0.75);
    EXPECT_DOUBLE_EQ(image->GetSpacing()[2], 1.25);
    EXPECT_DOUBLE_EQ(image->GetOrigin()[0], 1.0);
    EXPECT_DOUBLE_EQ(image->GetOrigin()[1], 2.0);
    EXPECT_DOUBLE_EQ(image->GetOrigin()[2], 3.0);
    vtkDataArray* scalars = image->GetPointData()->GetScalars();
    ASSERT_NE(scalars, nullptr);
    ASSERT_EQ(scalars->GetDataType(), VTK_SHORT);
    ASSERT_EQ(scalars->GetNumberOfValues(), static_cast<vtkIdType>(values.size()));
    EXPECT_EQ(std::memcmp(scalars->GetVoidPointer(0), data, bytes), 0);
  }
}

//------------------------------------------------------------------------------
// Bad input: a clear one-line error naming the file, an empty output, no crash.
class BadInput : public ::testing::Test
{
protected:
  // `headerIsBad`: CanReadFile (which looks at the name and the header only) says no too.
  void ExpectFailure(const std::string& file, const std::string& why, bool headerIsBad = true)
  {
    SCOPED_TRACE(file);
    if (headerIsBad)
    {
      EXPECT_FALSE(vtkDeepShadowVolumeReader::CanReadFile(file.c_str()));
    }
    vtkNew<ErrorObserver> errors;
    std::string lastError;
    auto image = Read(file, errors, &lastError);
    ASSERT_FALSE(errors->Messages.empty());
    const std::string& message = errors->Messages.front();
    EXPECT_FALSE(message.empty());
    EXPECT_NE(message.find(file), std::string::npos) << message;
    EXPECT_NE(message.find(why), std::string::npos) << message;
    EXPECT_FALSE(lastError.empty());
    EXPECT_EQ(lastError.find('\n'), std::string::npos) << "not one line: " << lastError;
    EXPECT_NE(lastError.find(why), std::string::npos) << lastError;
    ASSERT_NE(image, nullptr);
    EXPECT_EQ(image->GetNumberOfPoints(), 0);
  }

  TempDir Dir;
};

TEST_F(BadInput, MissingFile)
{
  this->ExpectFailure(this->Dir.File("missing.vti"), "no such file");
}

TEST_F(BadInput, UnknownExtension)
{
  const std::string file = this->Dir.File("volume.xyz");
  std::ofstream(file) << "not a volume\n";
  this->ExpectFailure(file, "unknown extension '.xyz'");
}

TEST_F(BadInput, GarbageVti)
{
  const std::string file = this->Dir.File("garbage.vti");
  std::ofstream(file) << "this is not XML at all\n";
  this->ExpectFailure(file, "not a valid");
}

TEST_F(BadInput, TruncatedVti)
{
  const std::string file = this->Dir.File("truncated.vti");
  vtkNew<vtkXMLImageDataWriter> xml;
  xml->SetInputData(Generate("spheres", TestScale));
  xml->SetFileName(file.c_str());
  ASSERT_EQ(xml->Write(), 1);
  fs::resize_file(file, fs::file_size(file) / 2);
  vtkNew<ErrorObserver> errors;
  std::string lastError;
  auto image = Read(file, errors, &lastError);
  ASSERT_FALSE(errors->Messages.empty());
  EXPECT_NE(errors->Messages.front().find(file), std::string::npos);
  EXPECT_EQ(lastError.find('\n'), std::string::npos) << lastError;
  EXPECT_EQ(image->GetNumberOfPoints(), 0);
}

TEST_F(BadInput, MetaImageWithoutItsData)
{
  const std::string file = this->Dir.File("lonely.mhd");
  std::ofstream(file) << "ObjectType = Image\nNDims = 3\nDimSize = 4 4 4\n"
                         "ElementType = MET_UCHAR\nElementDataFile = lonely.raw\n";
  this->ExpectFailure(file, "does not exist", false);
}

// VTK's raw readers only warn about short data; the reader must refuse it.
TEST_F(BadInput, TruncatedRawData)
{
  const std::string nrrd = this->Dir.File("short.nrrd");
  std::ofstream(nrrd, std::ios::binary) << "NRRD0004\ntype: short\ndimension: 3\n"
                                           "sizes: 12 10 3\nencoding: raw\nendian: little\n\nabc";
  this->ExpectFailure(nrrd, "truncated", false);

  const std::string mhd = this->Dir.File("short.mhd");
  std::ofstream(mhd) << "ObjectType = Image\nNDims = 3\nDimSize = 4 4 4\n"
                        "ElementType = MET_UCHAR\nElementDataFile = short.raw\n";
  std::ofstream(this->Dir.File("short.raw"), std::ios::binary) << "abc";
  this->ExpectFailure(mhd, "truncated", false);
}

TEST_F(BadInput, NoPointScalars)
{
  vtkNew<vtkImageData> empty;
  empty->SetDimensions(4, 4, 4);
  const std::string file = this->Dir.File("noscalars.vti");
  vtkNew<vtkXMLImageDataWriter> xml;
  xml->SetInputData(empty);
  xml->SetFileName(file.c_str());
  ASSERT_EQ(xml->Write(), 1);
  this->ExpectFailure(file, "no point scalars", false);
}

// VTK 9.1's global warning display also gates error events: an application that turned it
// off must still get the reason (GetLastError), VTK's own reason included.
TEST_F(BadInput, ReasonsAreHeardWithVTKWarningsOff)
{
  const std::string file = this->Dir.File("hex.nrrd");
  std::ofstream(file, std::ios::binary) << "NRRD0004\ntype: uchar\ndimension: 3\n"
                                           "sizes: 2 2 2\nencoding: hex\n\n0011223344556677\n";
  vtkObject::GlobalWarningDisplayOff();
  std::string lastError;
  auto image = Read(file, nullptr, &lastError);
  vtkObject::GlobalWarningDisplayOn();
  EXPECT_NE(lastError.find("Unsupported encoding: hex"), std::string::npos) << lastError;
  EXPECT_EQ(image->GetNumberOfPoints(), 0);
  EXPECT_EQ(vtkObject::GetGlobalWarningDisplay(), 1);
}

// Headers VTK trusts, checked before it reads: counts against dimensions, memory.
TEST_F(BadInput, HeadersVTKTrusts)
{
  const std::string two = this->Dir.File("two.nrrd");
  std::ofstream(two, std::ios::binary) << "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 2 2\n"
                                          "encoding: raw\n\n01234567";
  this->ExpectFailure(two, "does not have dimension: 3 sizes", false);
  const std::string huge = this->Dir.File("huge.mhd");
  std::ofstream(huge) << "ObjectType = Image\nNDims = 3\nDimSize = 100000 100000 100000\n"
                         "ElementType = MET_UCHAR\nElementDataFile = huge.raw\n";
  std::ofstream(this->Dir.File("huge.raw"), std::ios::binary) << "abc";
  this->ExpectFailure(huge, "would take 1000000000000000 bytes", false);
  const std::string type = this->Dir.File("type.mhd");
  std::ofstream(type) << "ObjectType = Image\nNDims = 3\nDimSize = 2 2 2\n"
                         "ElementType = MET_BANANA\nElementDataFile = huge.raw\n";
  this->ExpectFailure(type, "MET_BANANA", false);
}

//------------------------------------------------------------------------------
// vtkDeepShadowMeshReader: good files read; files VTK's readers crash on are refused first.
TEST(MeshReader, ReadsAndRefuses)
{
  TempDir dir;
  auto read = [](const std::string& file, std::string& error) {
    vtkNew<vtkDeepShadowMeshReader> reader;
    reader->SetFileName(file.c_str());
    reader->Update();
    error = reader->GetLastError();
    return reader->GetOutput()->GetNumberOfCells();
  };
  std::string error;
  const std::string ply = dir.File("tetra.ply");
  std::ofstream(ply) << "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\n"
                        "property float y\nproperty float z\nelement face 4\n"
                        "property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n"
                        "0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  EXPECT_EQ(read(ply, error), 4) << error;
  EXPECT_TRUE(error.empty()) << error;
  const std::string past = dir.File("past.ply");
  std::ofstream(past) << "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                         "property float y\nproperty float z\nelement face 1\n"
                         "property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n"
                         "0 1 0\n3 0 1 99\n";
  EXPECT_EQ(read(past, error), 0);
  EXPECT_NE(error.find("refers to the vertex 99 of 3"), std::string::npos) << error;
  const std::string huge = dir.File("huge.ply");
  std::ofstream(huge, std::ios::binary) << "ply\nformat binary_little_endian 1.0\n"
                                           "element vertex 100000000\nproperty float x\n"
                                           "property float y\nproperty float z\nend_header\n";
  EXPECT_EQ(read(huge, error), 0);
  EXPECT_NE(error.find("truncated"), std::string::npos) << error;
  const std::string obj = dir.File("past.obj");
  std::ofstream(obj) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//2\n";
  EXPECT_EQ(read(obj, error), 0);
  EXPECT_NE(error.find("normal '2' of 1"), std::string::npos) << error;
  EXPECT_EQ(read(dir.File("none.stl"), error), 0);
  EXPECT_NE(error.find("no such file"), std::string::npos) << error;
}

TEST_F(BadInput, NoFileName)
{
  vtkNew<vtkDeepShadowVolumeReader> reader;
  vtkNew<ErrorObserver> errors;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->Update();
  EXPECT_FALSE(errors->Messages.empty());
  EXPECT_FALSE(reader->GetLastError().empty());
}
