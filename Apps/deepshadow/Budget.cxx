#include "Budget.h"

#include "vtkDeepShadowMemoryBudget.h"

#include "vtkImageData.h"

#include <algorithm>

namespace deepshadow
{
namespace tool
{
namespace
{
// Measured with /usr/bin/time -f %M (maximum resident set) on llvmpipe, 2048^2 against
// 64^2: the box scene 56 bytes a pixel, hybrid-smoke (4 layers, 8 segments) 200; the CPU
// reference 10.
constexpr std::uint64_t GpuBytesPerPixel = 64;
constexpr std::uint64_t PassBytesPerPixel = 32; // plus 8 per layer and 16 per segment
constexpr std::uint64_t ReferenceBytesPerPixel = 32;
}

std::uint64_t MemoryBudget(const Options& options)
{
  return options.MemoryBudget > 0 ? options.MemoryBudget : DefaultMemoryBudget();
}

std::uint64_t FrameBytes(const Options& options, int width, int height, bool pass)
{
  const std::uint64_t pixels = static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height);
  if (options.Command == "reference")
  {
    return pixels * ReferenceBytesPerPixel;
  }
  std::uint64_t perPixel = GpuBytesPerPixel;
  if (pass)
  {
    perPixel += PassBytesPerPixel + 8 * static_cast<std::uint64_t>(options.TranslucentLayers) +
      16 * static_cast<std::uint64_t>(options.VolumeSegments);
  }
  return pixels * perPixel;
}

std::uint64_t ShadowBytes(const Options& options)
{
  const ShadowParameters parameters = options.TechniqueParameters();
  if (parameters.Kind == ShadowKind::None)
  {
    return 0;
  }
  // Bytes per texel of a light-space face (the registry's, after the GPU classes' formats).
  const std::uint64_t texel = ShadowTechniqueOf(parameters).TexelBytes(parameters);
  const std::uint64_t mapSize = static_cast<std::uint64_t>(parameters.MapSize);
  std::uint64_t total = 0;
  int faces = 0;
  const size_t lights = std::max<size_t>(options.Lights.size(), 1);
  for (size_t l = 0; l < std::min<size_t>(lights, texel ? 4 : 8); ++l)
  {
    // A positional light inside the volume's bounding sphere gets a cube of six faces.
    const bool positional = l < options.Lights.size() && options.Lights[l].Kind != LightSpec::Directional;
    faces += positional ? 6 : 1;
    total = SaturatingProduct(SaturatingProduct(mapSize * mapSize, texel), positional ? 6 : 1) + total;
    if (parameters.Cached)
    {
      const std::uint64_t nodes = static_cast<std::uint64_t>(parameters.VolumeSize);
      total += nodes * nodes * nodes * (parameters.IsColored() ? 8 : 2);
    }
  }
  const ShadowTechniqueInfo& technique = ShadowTechniqueOf(parameters);
  return total + (technique.FixedBytes ? technique.FixedBytes(parameters, faces) : 0);
}

std::uint64_t VolumeBytes(vtkImageData* data)
{
  return data ? SaturatingProduct(static_cast<std::uint64_t>(data->GetNumberOfPoints()), 8) : 0;
}

void RequireWithinBudget(const Options& options, vtkImageData* data, bool pass, int volumes)
{
  const std::uint64_t budget = MemoryBudget(options);
  // shadow-bench and report also render the error images.
  const bool errorImages = options.Command == "shadow-bench" || options.Command == "report";
  const std::uint64_t frame = std::max(FrameBytes(options, options.Width, options.Height, pass),
    errorImages ? FrameBytes(options, options.ErrorWidth, options.ErrorHeight, pass) : 0);
  const std::uint64_t shadows = SaturatingProduct(ShadowBytes(options), volumes);
  const std::uint64_t volume = VolumeBytes(data);
  const std::string size = std::to_string(options.Width) + "x" + std::to_string(options.Height);
  std::string problem = CheckMemoryBudget("--size " + size + " (the frame's buffers)", frame, budget);
  if (problem.empty())
  {
    problem = CheckMemoryBudget("the shadow structures of --technique " + options.Technique +
        (options.Setting("shadow-map-size") ? " --shadow-map-size " +
              std::to_string(static_cast<int>(options.Setting("shadow-map-size")->at(0))) : ""),
      shadows, budget);
  }
  if (problem.empty())
  {
    problem = CheckMemoryBudget("the volume's copy for the GPU", volume, budget);
  }
  if (problem.empty())
  {
    // Each is within the budget, so the sum cannot wrap.
    problem = CheckMemoryBudget("the frame, shadows and volume together", frame + shadows + volume, budget);
  }
  if (!problem.empty())
  {
    throw UsageError(problem + " (--memory-budget BYTES to change it)");
  }
}

}
}
