// Builds the VTK scene a command renders: headless window, renderer, volume, light, camera.
#ifndef deepshadow_tool_SceneSetup_h
#define deepshadow_tool_SceneSetup_h

#include "Options.h"

#include "vtkDeepShadowPass.h"           // For the smart pointers
#include "vtkDeepShadowPolyDataMapper.h" // For the smart pointers

#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkDeepShadowRenderWindow;
class vtkDeepShadowTechnique;
class vtkDeepShadowVolumeMapper;
class vtkImageData;
class vtkPolyData;
class vtkRenderer;
class vtkVolume;

namespace deepshadow
{
namespace tool
{

struct SceneSetup
{
  vtkSmartPointer<vtkDeepShadowRenderWindow> Window;
  vtkSmartPointer<vtkRenderer> Renderer;
  vtkSmartPointer<vtkVolume> Volume;
  vtkSmartPointer<vtkDeepShadowVolumeMapper> Mapper;
  vtkSmartPointer<vtkDeepShadowTechnique> Technique; // null for --technique none
  vtkSmartPointer<vtkImageData> Data;
  std::string Name; // scene name or file name
  std::string Modality; // a DICOM file's ("CT", "MR", ...); "" otherwise
  std::string Look;     // the look chosen for a file given no --tf (e.g. "CT-Bone")
  double GenerationSeconds = 0.0;
  // The polyhedral bound (--bound / --csg, or a bounded scene's), as given to the mapper.
  std::vector<vtkSmartPointer<vtkPolyData>> Bounds;
  std::string BoundExpression;
  double CsgMilliseconds = 0.0; // CGAL: checking the bounds and evaluating the expression
  bool BoundIsEmpty = false;    // the expression's result encloses nothing
  // Hybrid scenes (a hybrid scene's meshes, --ground, --mesh): the meshes and their pass.
  std::vector<vtkSmartPointer<vtkDeepShadowPolyDataMapper>> Meshes;
  vtkSmartPointer<vtkDeepShadowPass> Pass;
  // A hybrid scene's second volume (hybrid-smoke's smoke), with its own technique; null if none.
  vtkSmartPointer<vtkVolume> SecondVolume;
  vtkSmartPointer<vtkDeepShadowVolumeMapper> SecondMapper;
  vtkSmartPointer<vtkDeepShadowTechnique> SecondTechnique;

  /** Loads or generates the volume and sets up the view; throws UsageError on bad input. */
  static SceneSetup Build(const Options& options);
};

/** The shortest voxel edge: the opacity unit distance files and presets are given. */
double SmallestSpacing(vtkImageData* data);

/** Throws UsageError, listing the scenes, unless `name` is a standard, bounded or hybrid scene. */
void RequireSceneName(const std::string& name);

/** The technique --technique names, with its parameters (null for none). */
vtkSmartPointer<vtkDeepShadowTechnique> MakeTechnique(const Options& options);

/** Renders one frame and waits for the GPU; returns wall milliseconds. */
double RenderFrame(vtkDeepShadowRenderWindow* window);

/** Throws UsageError if the window has no context (the backend's driver or library is missing). */
void RequireContext(vtkDeepShadowRenderWindow* window);

/** Throws UsageError if the mapper could not draw (no context, bad data, unsupported type, ...). */
void RequireDrawn(const SceneSetup& setup);

/**
 * Reads a mesh (.vtp, .vtk, .stl, .ply, .obj) with vtkDeepShadowMeshReader and checks its
 * points and point ids; throws UsageError on failure.
 */
vtkSmartPointer<vtkPolyData> ReadMesh(const std::string& path);

/** The GL renderer's name (e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"). */
std::string RendererString(vtkDeepShadowRenderWindow* window);

/** The window's pixels, or an image, as a PNG file's bytes (for Outputs::Write). */
std::string PNGBytes(vtkDeepShadowRenderWindow* window);
std::string PNGBytes(vtkImageData* image);
/** Writes a PNG straight to `path` (the report's folders); throws UsageError if it cannot. */
void WritePNG(vtkImageData* image, const std::string& path);

}
}
#endif
