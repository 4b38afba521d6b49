// Helpers shared by the regression tests: grabbing images, synthetic volumes, capturing
// errors, and comparisons with stated tolerances.
#ifndef DeepShadowTestUtilities_h
#define DeepShadowTestUtilities_h

#include "Image.h"
#include "vtkDeepShadowImageConversion.h"
#include "vtkDeepShadowReferenceRenderer.h"

#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkSmartPointer.h"

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

}
}
#endif
