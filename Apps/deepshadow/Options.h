// Command-line options of the deepshadow tool: parsed once, validated, with one-line errors.
#ifndef deepshadow_tool_Options_h
#define deepshadow_tool_Options_h

#include "Core/ShadowTechniques.h"

#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
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

/** A light given on the command line (--light-dir, --light-pos, --light). */
struct LightSpec
{
  enum Type
  {
    Directional, // Vector: direction towards the light
    Positional,  // Vector: position
    Spot         // Vector: position; aims at the volume's centre with ConeAngle
  };
  Type Kind = Directional;
  std::array<double, 3> Vector{ { 0.0, 0.0, 1.0 } };
  double ConeAngle = 30.0;
  double Intensity = 1.0;
};

/** A mesh given on the command line (--mesh and the options that follow it). */
struct MeshSpec
{
  std::string File;
  double Opacity = 1.0;
  std::array<double, 3> Color{ { 0.8, 0.8, 0.8 } };
  std::array<double, 3> Translate{ { 0.0, 0.0, 0.0 } };
  double Scale = 1.0;
};

/** A file named on the command line: the option that named it, and its path. */
struct NamedFile
{
  std::string Option; // "--out", "--volume", ...
  std::string Path;
};

struct Options
{
  std::string Command; // render | view | reference | all | gallery | bench | shadow-bench | report | scenes | presets | series | help
  std::vector<std::string> Arguments; // as given, after the command
  std::string HelpCommand; // help: the command whose --help it is ("" for all)

  // What to render.
  std::string Scene;      // standard scene name
  std::string VolumeFile; // or a file
  std::string MaskFile;   // --mask: a binary mask volume of the data's dimensions
  std::string Series;     // --series: the DICOM series of a folder, by number or UID
  int VolumeIndex = 0;    // --volume-index: the volume of a 4D NIfTI file
  double SceneScale = 1.0;
  int ObjectCount = 0;    // --objects: the sparse scene's first N objects (0: all)
  std::vector<std::string> BoundFiles; // --bound, repeatable: bounds A, B, ...
  std::string Csg;                     // --csg: how they combine ("" = their union)
  std::vector<MeshSpec> Meshes;        // --mesh, repeatable: meshes that cast and receive
  bool Ground = false;                 // --ground: a ground plane under the volume
  int TranslucentLayers = 4;           // --translucent-layers: peeled layers merged into the volume
  int VolumeSegments = 8;              // --volume-segments: a second volume's pieces merged into the first
  bool CsgMesh = false;                // bound by the CGAL mesh of the expression instead
  double CsgMaxWork = 5e5;             // --csg-max-work: vtkDeepShadowCSGFilter::SetMaximumTriangleWork
  int Width = 512;
  int Height = 512;
  double SampleDistance = 0.0; // 0: the mapper's default
  std::vector<LightSpec> Lights; // empty: the scene's key light, or the headlight for files
  bool Shade = true;
  bool ShadeGiven = false;       // --shade/--no-shading given: overrides a preset's
  std::vector<double> IsoValues; // --isosurface: isosurface blending at these contour values
  double GradientOpacityFull = 0.0; // --gradient-opacity: magnitude of full opacity; 0: none
  std::string TransferFunction;  // --tf: a preset name or a ParaView JSON preset file
  double Window = 0.0;           // --window/--level: the preset's interval mapped onto
  double Level = 0.0;            //   [L - W/2, L + W/2]; Window 0: the preset's own
  double OpacityUnitDistance = 0.0; // 0: the preset's or scene's
  double Ambient = -1.0, Diffuse = -1.0, Specular = -1.0; // negative: the preset's or scene's
  // The camera (Look.h): a patient view, then turns and zoom, or a camera file for all of it.
  std::string View;       // --view anterior|posterior|left|right|superior|inferior
  double Azimuth = 0.0, Elevation = 0.0, Roll = 0.0, Zoom = 1.0;
  std::string CameraFile; // --camera: JSON as render --json writes under "camera"
  std::string ViewKeys;      // view --keys: keys fed without a person, comma-separated
  std::string ScreenshotDir; // view --screenshots: where 's' writes view-N.png and .json
  bool Jitter = false;
  unsigned int JitterSeed = 0;
  bool VTKShading = false; // --shading vtk (the mapper's default); the tool draws Blinn-Phong
  bool EmptySpaceSkipping = true;
  bool ReplaceNonFinite = false;
  // A name of the technique registry (ShadowTechniques.h); a --volume file given none: dsm.
  std::string Technique = "none";
  // The technique parameters given (--KEY or a spec's KEY=VALUE, registry keys, checked),
  // in order; the others keep the technique's defaults.
  std::vector<std::pair<std::string, std::vector<double>>> TechniqueSettings;
  std::string Backend; // "" = VTK_DEEPSHADOW_BACKEND or OSMesa

  // Outputs and measurement.
  std::string Out;
  std::string Json;
  std::string OutDir;
  int Frames = 5;
  bool Verbose = false; // show VTK's own error and warning messages
  unsigned long long MemoryBudget = 0; // --memory-budget; 0: half the machine's memory

  // reference
  bool GpuTwin = false;
  bool GroundTruth = false; // translucent shadow rays at a fine step, whatever the technique
  int Threads = 0;

  // bench
  std::vector<int> BenchSizes{ 128, 256 };
  /** --blend-modes: each of these on the shaded head at the first size, instead of the default cases. */
  std::vector<std::string> BenchBlendModes;
  // shadow-bench
  std::vector<std::string> BenchScenes; // empty: all standard scenes
  std::vector<std::string> BenchTechniques; // empty: all but none
  int ErrorWidth = 256;
  int ErrorHeight = 256;
  bool ReceiverError = false; // also the shadow term's error at the first receivers (CPU twins)
  std::string ChartsDirectory; // one chart of error against bits and frame time per scene
  // report
  bool Quick = false; // the short sweep at smaller sizes

  /**
   * The files the command reads: --volume and --mask with the files they are read from (a
   * header's detached data, a DICOM folder's files), --bound, --mesh, a --tf file, --camera.
   */
  std::vector<NamedFile> InputFiles() const;
  /** The files the command writes: render's and reference's --out, and --json. */
  std::vector<NamedFile> OutputFiles() const;

  /** The value given for a technique parameter (the last one), or null. */
  const std::vector<double>* Setting(const std::string& key) const;
  /**
   * The chosen technique's parameters: its registry defaults, then the settings given for
   * the keys it reads (the others are ignored, as each technique ignores them).
   */
  ShadowParameters TechniqueParameters() const;

  /** Parses argv; throws UsageError. `--help` sets Command to "help". */
  static Options Parse(int argc, char* argv[]);
  static std::string Usage();
  /** One command's synopsis and description, and the options (`deepshadow CMD --help`). */
  static std::string CommandUsage(const std::string& command);
};

/** A finite number, or UsageError naming the option. */
double ParseNumber(const std::string& option, const std::string& text);

/**
 * A technique spec, NAME[:OPTION=VALUE...] with OPTION a technique option without its dashes
 * (dsm:layers=2:shadow-map-size=1024, cssm:cssm-photons=4): `base` with them applied.
 * Throws UsageError.
 */
Options WithTechniqueSpec(const Options& base, const std::string& spec);

}
}
#endif
