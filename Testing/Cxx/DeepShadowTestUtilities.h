// Helpers shared by the regression tests: grabbing images, synthetic volumes, capturing
// errors, and comparisons with stated tolerances.
#ifndef DeepShadowTestUtilities_h
#define DeepShadowTestUtilities_h

#include "Image.h"
#include "vtkDeepShadowImageConversion.h"
#include "vtkDeepShadowPolyDataMapper.h"
#include "vtkDeepShadowReferenceRenderer.h"
#include "vtkDeepShadowRenderWindow.h"
#include "vtkDeepShadowVolumeMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkLight.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlaneSource.h"
#include "vtkPolyData.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkSmartPointer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
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
