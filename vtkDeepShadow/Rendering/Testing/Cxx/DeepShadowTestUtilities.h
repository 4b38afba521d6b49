// Helpers shared by the regression tests: grabbing images, synthetic volumes, capturing
// errors, and comparisons with stated tolerances.
#ifndef DeepShadowTestUtilities_h
#define DeepShadowTestUtilities_h

#include "Core/Image.h"
#include "vtkDeepShadowImageConversion.h"
#include "vtkDeepShadowPolyDataMapper.h"
#include "vtkDeepShadowReferenceRenderer.h"
#include "vtkDeepShadowRenderWindow.h"
#include "vtkDeepShadowStandardScene.h"
#include "vtkDeepShadowTechnique.h"
#include "vtkDeepShadowTechniqueFactory.h"
#include "vtkDeepShadowVolumeMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkLight.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPNGReader.h"
#include "vtkPlaneSource.h"
#include "vtkPolyData.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkSmartPointer.h"
#include "vtkTesting.h"
#include "vtkVersionMacros.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

namespace deepshadow
{
namespace testing
{

/** The window's pixels as linear RGB in [0, 1]. */
inline Image Grab(vtkRenderWindow* window)
{
  return CaptureWindow(window);
}

/** The CPU reference of the renderer's scene (exact, or the GPU's twin). */
inline Image Reference(vtkRenderer* renderer, bool gpuTwin)
{
  vtkNew<vtkDeepShadowReferenceRenderer> reference;
  reference->SetGpuTwin(gpuTwin);
  Image image;
  reference->Render(renderer, image);
  return image;
}

/** Fraction of pixels that differ from `background` by more than 2/255 in some channel. */
inline double CoveredFraction(const Image& image, const glm::dvec3& background)
{
  size_t covered = 0;
  for (int y = 0; y < image.Height; ++y)
    for (int x = 0; x < image.Width; ++x)
    {
      const glm::dvec3 d = glm::abs(image.At(x, y) - background);
      covered += (std::max({ d.x, d.y, d.z }) > 2.0 / 255.0) ? 1 : 0;
    }
  return static_cast<double>(covered) / (static_cast<double>(image.Width) * image.Height);
}

/** Prints one checked statement with ok or FAILED (ctest shows it) and returns `good`. */
inline bool Check(const std::string& what, bool good)
{
  std::printf("%-60s %s\n", what.c_str(), good ? "ok" : "FAILED");
  return good;
}

/** Whether a list of shader features (a mapper's GetShaderFeatures()) has `feature`. */
inline bool HasFeature(const std::vector<std::string>& features, const std::string& feature)
{
  return std::find(features.begin(), features.end(), feature) != features.end();
}
/** Whether the mapper's last composed shader has `feature`. */
inline bool HasFeature(vtkDeepShadowVolumeMapper* mapper, const std::string& feature)
{
  return HasFeature(mapper->GetShaderFeatures(), feature);
}

/**
 * Checks a difference against stated bounds and prints it (ctest shows it). Returns true
 * when RMSE <= maxRMSE and at most `maxFraction` of pixels differ by more than `threshold`.
 */
inline bool WithinTolerance(const char* what, const Image& a, const Image& b, double maxRMSE,
  double threshold, double maxFraction)
{
  const ImageDifference d = Compare(a, b, threshold);
  if (const char* directory = std::getenv("DEEPSHADOW_TEST_IMAGES"))
  {
    // Set DEEPSHADOW_TEST_IMAGES=DIR to keep both images and their difference (x10).
    std::string stem = std::string(directory) + "/" + what;
    std::replace(stem.begin() + std::string(directory).size(), stem.end(), ' ', '_');
    WritePNG(a, stem + "-a.png");
    WritePNG(b, stem + "-b.png");
    WritePNG(AbsoluteDifference(a, b, 10.0), stem + "-diff.png");
  }
  const bool ok = d.RMSE <= maxRMSE && d.FractionAbove <= maxFraction;
  std::printf("%s: RMSE %.5f (<= %.5f), max %.4f, %.4f%% of pixels > %.4f (<= %.4f%%) %s\n",
    what, d.RMSE, maxRMSE, d.MaxAbs, 100.0 * d.FractionAbove, threshold, 100.0 * maxFraction,
    ok ? "ok" : "FAILED");
  return ok;
}

/**
 * The regression-image comparison of our tests, instead of VTK 9.1's (whose threshold of 0.15
 * passes TestShadowTechniques against TestBoundedVolume's baseline, another scene). The test
 * and its baseline are rendered by the same llvmpipe and agree within RMSE 0.0004 (most
 * exactly); the tolerance fails a different scene (baselines differ by RMSE 0.038 to 0.31) and
 * a different technique on one scene (TestImageComparison: 0.0044 for the closest pair, a deep
 * shadow map and opacity levels, 0.017 to 0.095 for the others).
 */
struct BaselineTolerance
{
  double MaxRMSE = 0.5 / 255.0;         // over all channels of all pixels, linear [0, 1]
  double PixelThreshold = 8.0 / 255.0;  // a pixel differs when some channel is off by more
  double MaxFraction = 0.001;           // share of pixels allowed to differ
};

/** Loads an 8-bit RGB(A) PNG; false if it is not one. */
inline bool LoadPNG(const std::string& path, Image& image)
{
  vtkNew<vtkPNGReader> reader;
  if (!reader->CanReadFile(path.c_str()))
  {
    return false;
  }
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkImageData* pixels = reader->GetOutput();
  const int* dims = pixels->GetDimensions();
  if (pixels->GetScalarType() != VTK_UNSIGNED_CHAR || pixels->GetNumberOfScalarComponents() < 3)
  {
    return false;
  }
  image = Image::FromBytes(static_cast<const uint8_t*>(pixels->GetScalarPointer()), dims[0],
    dims[1], pixels->GetNumberOfScalarComponents());
  return true;
}

/** Whether `picture` matches `baseline` within `tolerance`; says how it compares. */
inline bool MatchesBaseline(const Image& picture, const Image& baseline,
  const BaselineTolerance& tolerance, std::string& how)
{
  char text[256];
  if (picture.Width != baseline.Width || picture.Height != baseline.Height)
  {
    std::snprintf(text, sizeof(text), "the picture is %dx%d, the baseline %dx%d", picture.Width,
      picture.Height, baseline.Width, baseline.Height);
    how = text;
    return false;
  }
  const ImageDifference d = Compare(picture, baseline, tolerance.PixelThreshold);
  const bool ok = d.RMSE <= tolerance.MaxRMSE && d.FractionAbove <= tolerance.MaxFraction;
  std::snprintf(text, sizeof(text),
    "RMSE %.5f (<= %.5f), %.3f%% of pixels off by more than %.0f/255 (<= %.3f%%), max %.4f", d.RMSE,
    tolerance.MaxRMSE, 100.0 * d.FractionAbove, 255.0 * tolerance.PixelThreshold,
    100.0 * tolerance.MaxFraction, d.MaxAbs);
  how = text;
  return ok;
}

/**
 * The baselines a picture may match: FILE (llvmpipe's) and, named as VTK's own regression
 * tests name theirs, the alternatives FILE_1.png ... FILE_9.png that exist beside it, for a
 * driver whose rounding differs beyond the tolerance (a GPU's texture filtering and fused
 * arithmetic). Each keeps the tight tolerance; none widens it for the others. Built with
 * VTK 9.2 onwards, whose volume lighting our VTK shading follows (Core/VolumeShading.h),
 * FILE.vtk92.png replaces FILE where it exists: a picture with VTK's shading in it.
 */
inline std::vector<std::string> BaselineAndAlternatives(std::string path)
{
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 2, 0)
  const std::string::size_type end = path.rfind(".png");
  const std::string lit = end == std::string::npos ? path : path.substr(0, end) + ".vtk92.png";
  if (std::ifstream(lit).good())
  {
    path = lit;
  }
#endif
  std::vector<std::string> paths{ path };
  const std::string::size_type dot = path.rfind(".png");
  for (int i = 1; dot != std::string::npos && i <= 9; ++i)
  {
    const std::string alternative = path.substr(0, dot) + "_" + std::to_string(i) + ".png";
    if (std::ifstream(alternative).good())
    {
      paths.push_back(alternative);
    }
  }
  return paths;
}

/**
 * The window's picture against the baseline vtk_add_test_cxx passes (-V FILE) or one of its
 * alternatives, with MatchesBaseline. Returns vtkTesting::PASSED or FAILED (NOT_RUN without
 * -V). A failure prints "the picture differs from the baseline FILE: ..." for each and writes
 * the picture and the difference (x10) to FILE into the test's temporary directory (-T DIR)
 * as NAME.png, NAME-diff.png.
 */
inline int RegressionTestImage(vtkRenderWindow* window, int argc, char* argv[],
  const BaselineTolerance& tolerance = BaselineTolerance())
{
  std::string baselinePath, temporary = ".";
  for (int i = 1; i + 1 < argc; ++i)
  {
    const std::string key = argv[i];
    baselinePath = key == "-V" ? argv[i + 1] : baselinePath;
    temporary = key == "-T" ? argv[i + 1] : temporary;
  }
  if (baselinePath.empty())
  {
    std::printf("no baseline given (-V FILE): the picture is not compared\n");
    return vtkTesting::NOT_RUN;
  }
  const Image picture = CaptureWindow(window);
  Image baseline;
  bool ok = false;
  for (const std::string& candidate : BaselineAndAlternatives(baselinePath))
  {
    Image loaded;
    std::string how = "the baseline is not an 8-bit RGB PNG";
    ok = LoadPNG(candidate, loaded) && MatchesBaseline(picture, loaded, tolerance, how);
    std::printf("%s the baseline %s: %s\n",
      ok ? "the picture matches" : "FAILED: the picture differs from", candidate.c_str(), how.c_str());
    baseline = candidate == baselinePath ? loaded : baseline;
    if (ok)
    {
      break;
    }
  }
  if (!ok)
  {
    std::string name = argc > 0 ? argv[0] : "test";
    for (int i = 1; i < argc; ++i)
    {
      name = std::string(argv[i]).rfind("Test", 0) == 0 ? argv[i] : name;
    }
    name = temporary + "/" + name.substr(name.find_last_of('/') + 1);
    WritePNG(picture, name + ".png");
    if (baseline.Width == picture.Width && baseline.Height == picture.Height)
    {
      WritePNG(AbsoluteDifference(picture, baseline, 10.0), name + "-diff.png");
    }
    std::printf("the picture: %s.png\n", name.c_str());
  }
  return ok ? vtkTesting::PASSED : vtkTesting::FAILED;
}

/** Records the messages of error and warning events instead of printing them. */
class MessageCapture : public vtkCommand
{
public:
  static MessageCapture* New() { return new MessageCapture; }
  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    const std::string text = data ? static_cast<const char*>(data) : "";
    (event == vtkCommand::ErrorEvent ? this->Errors : this->Warnings).push_back(text);
  }
  void Watch(vtkObject* object)
  {
    object->AddObserver(vtkCommand::ErrorEvent, this);
    object->AddObserver(vtkCommand::WarningEvent, this);
  }
  bool ErrorContains(const std::string& needle) const
  {
    for (const auto& e : this->Errors)
    {
      if (e.find(needle) != std::string::npos)
      {
        return true;
      }
    }
    return false;
  }
  std::vector<std::string> Errors;
  std::vector<std::string> Warnings;
};

/**
 * A 48^3-ish test volume of the given VTK scalar type: a soft sphere, a thin slab and a
 * gradient, with values `v = offset + scale * u` for u in [0, 1].
 */
inline vtkSmartPointer<vtkImageData> MakeTestVolume(
  int type, int n = 48, double scale = 255.0, double offset = 0.0)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(n, n, n);
  image->SetSpacing(1.0, 1.0, 1.25);
  image->SetOrigin(-0.5 * (n - 1), -0.5 * (n - 1), -0.625 * (n - 1));
  image->AllocateScalars(type, 1);
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        const double x = 2.0 * i / (n - 1) - 1.0, y = 2.0 * j / (n - 1) - 1.0,
                     z = 2.0 * k / (n - 1) - 1.0;
        const double r = std::sqrt(x * x + y * y + z * z);
        double u = r < 0.75 ? 1.0 - r / 0.75 : 0.0;
        if (std::abs(x - 0.1) < 0.08 && std::abs(y) < 0.6 && std::abs(z) < 0.8)
        {
          u = 0.8;
        }
        scalars->SetComponent(i + n * (j + n * k), 0, std::round(offset + scale * u));
      }
  return image;
}

/**
 * A scene made for shadows, 48^3 unsigned char: a dense ball (200) above a thinner floor
 * plate (90) and a translucent pillar (140), on a 2-unit grid.
 */
inline vtkSmartPointer<vtkImageData> MakeShadowVolume(int n = 48)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(n, n, n);
  image->SetSpacing(2.0, 2.0, 2.0);
  image->SetOrigin(-(n - 1.0), -(n - 1.0), -(n - 1.0));
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  auto* v = static_cast<unsigned char*>(image->GetScalarPointer());
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        const double x = 2.0 * i / (n - 1) - 1.0, y = 2.0 * j / (n - 1) - 1.0,
                     z = 2.0 * k / (n - 1) - 1.0;
        unsigned char value = 0;
        if (z < -0.75 && z > -0.95 && std::abs(x) < 0.9 && std::abs(y) < 0.9)
        {
          value = 90; // floor
        }
        if ((x + 0.1) * (x + 0.1) + y * y + (z - 0.2) * (z - 0.2) < 0.3 * 0.3)
        {
          value = 200; // ball
        }
        if (std::abs(x - 0.55) < 0.08 && std::abs(y + 0.3) < 0.08 && z > -0.75 && z < 0.4)
        {
          value = 140; // pillar
        }
        v[i + n * (j + n * k)] = value;
      }
  return image;
}

// A soft puff of smoke: 24^3 points, 3 units apart, centred at `centre`.
inline vtkSmartPointer<vtkImageData> MakeSmokeVolume(const glm::dvec3& centre)
{
  const int n = 24;
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(n, n, n);
  image->SetSpacing(3.0, 3.0, 2.0);
  image->SetOrigin(centre.x - 1.5 * (n - 1), centre.y - 1.5 * (n - 1), centre.z - (n - 1.0));
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  auto* v = static_cast<unsigned char*>(image->GetScalarPointer());
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        const double x = 2.0 * i / (n - 1) - 1.0, y = 2.0 * j / (n - 1) - 1.0, z = 2.0 * k / (n - 1) - 1.0;
        const double r2 = 1.6 * x * x + y * y + 3.0 * z * z;
        v[i + n * (j + n * k)] = static_cast<unsigned char>(std::lround(255.0 * std::exp(-3.0 * r2)));
      }
  return image;
}

/**
 * A standard scene (vtkDeepShadowStandardScene) at a resolution scale in its own renderer:
 * its volume drawn by a vtkDeepShadowVolumeMapper with the scene's property, seen by the
 * scene's camera and, when `lit`, lit by a scene light from the scene's light direction. The
 * test adds Renderer to its window.
 */
struct StandardSceneView
{
  vtkNew<vtkDeepShadowStandardScene> Scene;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkDeepShadowVolumeMapper> Mapper;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkLight> Light;

  StandardSceneView(const std::string& name, double scale, bool lit)
  {
    this->Scene->SetScene(name);
    this->Scene->SetResolutionScale(scale);
    this->Mapper->SetShadingModelToBlinnPhong(); // the scenes' own look, as the tool draws them
    this->Mapper->SetInputData(this->Scene->GetVolume());
    this->Volume->SetMapper(this->Mapper);
    this->Volume->SetProperty(this->Scene->GetVolumeProperty());
    this->Renderer->AddVolume(this->Volume);
    if (lit)
    {
      double direction[3];
      this->Scene->GetLightDirection(direction);
      this->Light->SetLightTypeToSceneLight();
      this->Light->SetPosition(direction);
      this->Light->SetFocalPoint(0.0, 0.0, 0.0);
      this->Renderer->AddLight(this->Light);
    }
    this->Scene->ApplyCamera(this->Renderer->GetActiveCamera());
  }
};

/**
 * The view and look TestVolumeMapperMatchesVTK compares with VTK's mapper (on MakeTestVolume):
 * from (60, 90, 160) towards the origin; an orange-to-white colour ramp, opacity from 20 up
 * to 0.3, linear interpolation; shaded when asked.
 */
inline void ApplyComparisonView(vtkRenderer* renderer)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(60.0, 90.0, 160.0);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  renderer->ResetCamera();
}

/** Our mapper and VTK's, one of them drawn in a comparison (VTK's auto-adjustment off). */
struct ComparisonMappers
{
  vtkNew<vtkDeepShadowVolumeMapper> Ours;
  vtkNew<vtkGPUVolumeRayCastMapper> Theirs;

  /** VTK's (`vtks`) or ours, at sample distance `step`, VTK's jittered if asked. */
  vtkGPUVolumeRayCastMapper* Pick(bool vtks, float step, bool jitter = false)
  {
    this->Theirs->SetAutoAdjustSampleDistances(0);
    this->Theirs->SetUseJittering(jitter);
    vtkGPUVolumeRayCastMapper* mapper = vtks ? static_cast<vtkGPUVolumeRayCastMapper*>(this->Theirs) : this->Ours;
    mapper->SetSampleDistance(step);
    return mapper;
  }
};

/** What a comparison draws: the GPU picture, and for our mapper its CPU twin. */
struct ComparisonPicture
{
  Image Picture;
  Image Twin; // empty unless asked for
};

/**
 * Draws `data` with `mapper` (ours or VTK's) and `property` in a fresh renderer of `window`
 * (the comparison view, background `background`); with `twin`, the CPU twin of that renderer.
 */
inline ComparisonPicture DrawForComparison(vtkRenderWindow* window, vtkVolumeMapper* mapper, vtkImageData* data,
  vtkVolumeProperty* property, const glm::dvec3& background, bool twin)
{
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(background.x, background.y, background.z);
  window->GetRenderers()->RemoveAllItems();
  window->AddRenderer(renderer);
  mapper->SetInputData(data);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  renderer->AddVolume(volume);
  ApplyComparisonView(renderer);
  window->Render();
  ComparisonPicture drawn;
  drawn.Picture = Grab(window);
  if (twin)
  {
    drawn.Twin = Reference(renderer, true);
  }
  return drawn;
}

/** Bounds of a comparison with VTK's mapper, calibrated on VTK against itself. */
struct VTKTolerance
{
  double MaxRMSE = 0.0;
  double MaxFraction = 0.0; // of pixels beyond 8/255
};

/**
 * Calibrates a comparison with VTK's picture `vtks`: VTK's own picture drawn again by
 * `draw(step scale, jittered)` at 0.8x and 1.25x its sample distance and jittered differs
 * from it by at most D; ours may differ by 1.5 D, at least RMSE `floor` and 1 % of pixels
 * beyond 8/255. Prints each calibration picture's difference.
 */
inline VTKTolerance CalibrateOnVTK(const std::string& what, const Image& vtks,
  const std::function<Image(float stepScale, bool jitter)>& draw, double floor = 0.007)
{
  ImageDifference self;
  for (const auto& [scale, jitter] : { std::make_pair(0.8f, false), std::make_pair(1.25f, false),
         std::make_pair(1.0f, true) })
  {
    const ImageDifference d = Compare(draw(scale, jitter), vtks, 8.0 / 255.0);
    std::printf("%s: VTK at %.2fx its sample distance%s: RMSE %.5f, %.3f%% of pixels off by more than 8/255\n",
      what.c_str(), scale, jitter ? ", jittered" : "", d.RMSE, 100.0 * d.FractionAbove);
    self.RMSE = std::max(self.RMSE, d.RMSE);
    self.FractionAbove = std::max(self.FractionAbove, d.FractionAbove);
  }
  return { std::max(floor, 1.5 * self.RMSE), std::max(0.01, 1.5 * self.FractionAbove) };
}

inline vtkSmartPointer<vtkVolumeProperty> MakeComparisonProperty(bool shade)
{
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0, 0.0, 0.0, 0.0);
  color->AddRGBPoint(60, 1.0, 0.5, 0.2);
  color->AddRGBPoint(255, 0.9, 0.9, 1.0);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0, 0.0);
  opacity->AddPoint(20, 0.0);
  opacity->AddPoint(255, 0.3);
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetInterpolationTypeToLinear();
  property->SetShade(shade);
  return property;
}

/**
 * An 8-bit volume and its functions mirrored (v -> 255 - v, every component): a minimum of the
 * mirror is the mirror of a maximum, so its minimum intensity picture is the original's maximum
 * one (the closed relation that checks MinIP where VTK's own slips).
 */
inline vtkSmartPointer<vtkImageData> Mirrored(vtkImageData* data)
{
  auto mirrored = vtkSmartPointer<vtkImageData>::New();
  mirrored->DeepCopy(data);
  vtkDataArray* values = mirrored->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
    for (int c = 0; c < values->GetNumberOfComponents(); ++c)
    {
      values->SetComponent(i, c, 255.0 - values->GetComponent(i, c));
    }
  return mirrored;
}

inline vtkSmartPointer<vtkVolumeProperty> MirroredFunctions(vtkVolumeProperty* property, int count)
{
  // Built afresh: DeepCopy would give the copy default gradient opacities.
  auto mirrored = vtkSmartPointer<vtkVolumeProperty>::New();
  mirrored->SetIndependentComponents(property->GetIndependentComponents());
  mirrored->SetInterpolationType(property->GetInterpolationType());
  for (int c = 0; c < count; ++c)
  {
    mirrored->SetComponentWeight(c, property->GetComponentWeight(c));
    mirrored->SetShade(c, property->GetShade(c));
  }
  for (int c = 0; c < count; ++c)
  {
    vtkNew<vtkColorTransferFunction> color;
    vtkColorTransferFunction* from = property->GetRGBTransferFunction(c);
    for (int n = 0; n < from->GetSize(); ++n)
    {
      double node[6];
      from->GetNodeValue(n, node);
      color->AddRGBPoint(255.0 - node[0], node[1], node[2], node[3]);
    }
    vtkNew<vtkPiecewiseFunction> opacity;
    vtkPiecewiseFunction* fromOpacity = property->GetScalarOpacity(c);
    for (int n = 0; n < fromOpacity->GetSize(); ++n)
    {
      double node[4];
      fromOpacity->GetNodeValue(n, node);
      opacity->AddPoint(255.0 - node[0], node[1]);
    }
    mirrored->SetColor(c, color);
    mirrored->SetScalarOpacity(c, opacity);
  }
  return mirrored;
}

/**
 * The scene the shadow tests share: MakeShadowVolume() with a coloured transfer function,
 * shaded, lit from above and slightly off axis, seen from the side at 160x160.
 */
struct ShadowScene
{
  vtkSmartPointer<vtkImageData> Data = MakeShadowVolume();
  vtkNew<vtkColorTransferFunction> Color;
  vtkNew<vtkPiecewiseFunction> Opacity;
  vtkNew<vtkVolumeProperty> Property;
  vtkNew<vtkDeepShadowRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkDeepShadowVolumeMapper> Mapper;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkLight> Light;

  ShadowScene()
  {
    this->Color->AddRGBPoint(0, 1.0, 1.0, 1.0);
    this->Color->AddRGBPoint(90, 0.9, 0.85, 0.7);
    this->Color->AddRGBPoint(140, 0.5, 0.7, 1.0);
    this->Color->AddRGBPoint(200, 1.0, 0.4, 0.3);
    this->Opacity->AddPoint(0, 0.0);
    this->Opacity->AddPoint(40, 0.0);
    this->Opacity->AddPoint(90, 0.25);
    this->Opacity->AddPoint(140, 0.12);
    this->Opacity->AddPoint(200, 0.9);
    this->Property->SetColor(this->Color);
    this->Property->SetScalarOpacity(this->Opacity);
    this->Property->ShadeOn();
    this->Property->SetAmbient(0.2);
    this->Window->SetSize(160, 160);
    this->Renderer->SetBackground(0.05, 0.05, 0.08);
    this->Window->AddRenderer(this->Renderer);
    // Shadows are what these tests measure: lit by Blinn-Phong (VTK's shading has no ambient
    // light under a scene light, and would draw every shadow black).
    this->Mapper->SetShadingModelToBlinnPhong();
    this->Mapper->SetInputData(this->Data);
    this->Volume->SetMapper(this->Mapper);
    this->Volume->SetProperty(this->Property);
    this->Renderer->AddVolume(this->Volume);
    this->Light->SetLightTypeToSceneLight();
    this->Light->SetPosition(0.3, 0.2, 1.0); // from above, slightly off axis
    this->Light->SetFocalPoint(0.0, 0.0, 0.0);
    this->Renderer->AddLight(this->Light);
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetPosition(0.0, -3.0, 1.6);
    camera->SetFocalPoint(0.0, 0.0, -0.2);
    camera->SetViewUp(0.0, 0.0, 1.0);
    this->Renderer->ResetCamera();
    camera->Zoom(1.3);
    this->Renderer->ResetCameraClippingRange();
  }

  /**
   * Renders with `technique` and compares the picture with the CPU twin's within the given
   * tolerance (see WithinTolerance); the GPU's picture is left in `gpu`.
   */
  bool MatchesTwin(const char* name, vtkDeepShadowTechnique* technique, double maxRMSE,
    double threshold, double maxFraction, Image& gpu)
  {
    this->Mapper->SetShadowTechnique(technique);
    this->Window->Render();
    if (!this->Mapper->GetLastError().empty())
    {
      std::printf("%s: %s FAILED\n", name, this->Mapper->GetLastError().c_str());
      return false;
    }
    gpu = Grab(this->Window);
    return WithinTolerance(name, gpu, Reference(this->Renderer, true), maxRMSE, threshold, maxFraction);
  }

  /** A ground mesh under the volume (z = -52, 220 units square) drawn by `mapper` for `actor`. */
  void AddGround(vtkDeepShadowPolyDataMapper* mapper, vtkActor* actor)
  {
    vtkNew<vtkPlaneSource> plane;
    plane->SetOrigin(-110.0, -110.0, -52.0);
    plane->SetPoint1(110.0, -110.0, -52.0);
    plane->SetPoint2(-110.0, 110.0, -52.0);
    plane->Update();
    mapper->SetInputData(plane->GetOutput());
    actor->SetMapper(mapper);
    this->Renderer->AddActor(actor);
  }

  /**
   * The usual eight techniques against their CPU twins, named "`what`, NAME vs CPU twin":
   * translucent ones within RMSE 2/255 (at most 1 % of pixels beyond 12/255), binary ones
   * (opaque rays, shadow maps) within 4/255 (3 % beyond 24/255).
   */
  bool AllMatchTwins(const std::string& what)
  {
    bool ok = true;
    for (const char* name : { "rays", "dsm", "dsm-color", "dsm3", "cssm", "dsm-cached", "rays-opaque", "shadowmap" })
    {
      const bool binary = std::string(name) == "rays-opaque" || std::string(name) == "shadowmap";
      Image gpu;
      ok = this->MatchesTwin((what + ", " + name + " vs CPU twin").c_str(), vtkDeepShadowTechniqueFactory::New(name),
             (binary ? 4.0 : 2.0) / 255.0, (binary ? 24.0 : 12.0) / 255.0, binary ? 0.03 : 0.01, gpu) && ok;
    }
    return ok;
  }

  /**
   * Whether a deep shadow map darkens the floor under the ball (FloorUnderBall, summed over
   * the channels) below 0.8 of its unshadowed brightness; prints both as "`what`: ...". The
   * mapper is left with the deep shadow map.
   */
  bool DeepShadowDarkensFloor(const std::string& what)
  {
    auto brightness = [this] {
      this->Window->Render();
      const glm::dvec3 floor = FloorUnderBall(Grab(this->Window));
      return floor.x + floor.y + floor.z;
    };
    this->Mapper->SetShadowTechnique(nullptr);
    const double lit = brightness();
    this->Mapper->SetShadowTechnique(vtkDeepShadowTechniqueFactory::New("dsm"));
    const double shadowed = brightness();
    std::printf("%s: floor under the ball %.3f without shadows, %.3f with the deep shadow map\n", what.c_str(),
      lit, shadowed);
    return Check((what + ": a deep shadow on the floor").c_str(), shadowed < 0.8 * lit);
  }

  /** Mean colour of the floor in the ball's shadow (left of centre, lower quarter). */
  static glm::dvec3 FloorUnderBall(const Image& image)
  {
    glm::dvec3 sum(0.0);
    for (int y = 30; y < 40; ++y)
      for (int x = 44; x < 54; ++x)
        sum += image.At(x, y);
    return sum / 100.0;
  }
};

}
}
#endif
