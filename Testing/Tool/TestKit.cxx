// deepshadow-testkit: what the tool's shell tests need besides the tool.
//   deepshadow-testkit seeds DIR        writes the seed files (SeedFiles.h) into DIR
//   deepshadow-testkit stats A.png      "mean M stddev S covered C": the mean and standard
//                                       deviation of all channels, and the share of pixels
//                                       that differ from the corner pixel (the background)
//                                       by more than 2/255
//   deepshadow-testkit flat A.png       exit 1 unless A is flat (stddev < 1/255 or covered < 1 %)
//   deepshadow-testkit compare A.png B.png [--at-most RMSE | --at-least RMSE]
//                                       prints "rmse R max M"; with a bound, exit 1 if the
//                                       RMSE (linear RGB in [0, 1]) breaks it
#include "SeedFiles.h"

#include "Core/Image.h"

#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGReader.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace
{
bool Load(const char* path, deepshadow::Image& image)
{
  vtkNew<vtkPNGReader> reader;
  if (!reader->CanReadFile(path))
  {
    std::fprintf(stderr, "deepshadow-testkit: %s is not a PNG file\n", path);
    return false;
  }
  reader->SetFileName(path);
  reader->Update();
  vtkImageData* pixels = reader->GetOutput();
  const int* dims = pixels->GetDimensions();
  if (pixels->GetScalarType() != VTK_UNSIGNED_CHAR || dims[0] < 1 || dims[1] < 1 ||
    pixels->GetNumberOfScalarComponents() < 3)
  {
    std::fprintf(stderr, "deepshadow-testkit: %s is not an 8-bit image\n", path);
    return false;
  }
  image = deepshadow::Image::FromBytes(static_cast<const uint8_t*>(pixels->GetScalarPointer()),
    dims[0], dims[1], pixels->GetNumberOfScalarComponents());
  return true;
}

struct Stats
{
  double Mean = 0.0, Deviation = 0.0, Covered = 0.0;
};

Stats Measure(const deepshadow::Image& image)
{
  Stats stats;
  const size_t n = image.RGB.size();
  for (double v : image.RGB)
  {
    stats.Mean += v / static_cast<double>(n);
  }
  for (double v : image.RGB)
  {
    stats.Deviation += (v - stats.Mean) * (v - stats.Mean) / static_cast<double>(n);
  }
  stats.Deviation = std::sqrt(stats.Deviation);
  const glm::dvec3 corner = image.At(0, 0);
  size_t covered = 0;
  for (int y = 0; y < image.Height; ++y)
    for (int x = 0; x < image.Width; ++x)
    {
      const glm::dvec3 d = glm::abs(image.At(x, y) - corner);
      covered += std::max({ d.x, d.y, d.z }) > 2.0 / 255.0 ? 1 : 0;
    }
  stats.Covered = static_cast<double>(covered) / (static_cast<double>(image.Width) * image.Height);
  return stats;
}

int Usage()
{
  std::fprintf(stderr, "usage: deepshadow-testkit seeds DIR | stats A.png | flat A.png | "
                       "compare A.png B.png [--at-most RMSE | --at-least RMSE]\n");
  return 2;
}
}

int main(int argc, char* argv[])
{
  const std::string command = argc > 1 ? argv[1] : "";
  if (command == "seeds" && argc == 3)
  {
    for (const auto& seed : deepshadow::testing::WriteSeedFiles(argv[2]))
    {
      std::printf("%s\n", seed.Name.c_str());
    }
    return 0;
  }
  deepshadow::Image a, b;
  if ((command == "stats" || command == "flat") && argc == 3)
  {
    if (!Load(argv[2], a))
    {
      return 2;
    }
    const Stats stats = Measure(a);
    std::printf("mean %.4f stddev %.4f covered %.4f\n", stats.Mean, stats.Deviation, stats.Covered);
    return command == "stats" || stats.Deviation < 1.0 / 255.0 || stats.Covered < 0.01 ? 0 : 1;
  }
  if (command == "compare" && (argc == 4 || argc == 6))
  {
    if (!Load(argv[2], a) || !Load(argv[3], b))
    {
      return 2;
    }
    if (a.Width != b.Width || a.Height != b.Height)
    {
      std::printf("sizes differ: %dx%d and %dx%d\n", a.Width, a.Height, b.Width, b.Height);
      return 1;
    }
    const deepshadow::ImageDifference d = deepshadow::Compare(a, b);
    std::printf("rmse %.5f max %.4f\n", d.RMSE, d.MaxAbs);
    if (argc == 6)
    {
      const std::string bound = argv[4];
      const double limit = std::atof(argv[5]);
      if (bound == "--at-most")
      {
        return d.RMSE <= limit ? 0 : 1;
      }
      if (bound == "--at-least")
      {
        return d.RMSE >= limit ? 0 : 1;
      }
      return Usage();
    }
    return 0;
  }
  return Usage();
}
