// Command-line options of the deepshadow tool: parsed once, validated, with one-line errors.
#ifndef deepshadow_tool_Options_h
#define deepshadow_tool_Options_h

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

namespace deepshadow
{
namespace tool
{

/** Bad arguments, unreadable files, unsupported data: printed as one line, exit code 2. */
struct UsageError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

struct Options
{
  std::string Command; // render | reference | bench | all | scenes | help

  // What to render.
  std::string Scene;      // standard scene name
  std::string VolumeFile; // or a file
  double SceneScale = 1.0;
  int Width = 512;
  int Height = 512;
  double SampleDistance = 0.0; // 0: the mapper's default
  bool HasLightDirection = false;
  std::array<double, 3> LightDirection{ { 0.0, 0.0, 1.0 } };
  bool Shade = true;
  bool Jitter = false;
  unsigned int JitterSeed = 0;
  bool EmptySpaceSkipping = true;
  bool ReplaceNonFinite = false;
  std::string Technique = "none";
  std::string Backend; // "" = VTK_DEEPSHADOW_BACKEND or OSMesa

  // Outputs and measurement.
  std::string Out;
  std::string Json;
  std::string OutDir;
  int Frames = 5;
  bool Verbose = false; // show VTK's own error and warning messages

  // reference
  bool GpuTwin = false;
  int Threads = 0;

  // bench
  std::vector<int> BenchSizes{ 128, 256 };

  /** Parses argv; throws UsageError. `--help` sets Command to "help". */
  static Options Parse(int argc, char* argv[]);
  static std::string Usage();
};

}
}
#endif
