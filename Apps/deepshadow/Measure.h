// How shadow-bench and report measure a technique on a standard scene, in one place:
// - the frame time while only the camera orbits (structures reused) and while the key light
//   turns 3 degrees a frame (a rebuild every frame), medians after a warm-up, GL finished;
// - the build time (median over the light-moving frames) and the shadow memory;
// - the image and its shadow term (vtkDeepShadowVolumeMapper::OutputShadowTerm) at the error
//   size, from the start view, to compare with the ground truth: the CPU reference with
//   translucent shadow rays at a quarter step (coloured for coloured techniques). Meshes show
//   their shadow term too (vtkDeepShadowPolyDataMapper::OutputShadowTerm).
#ifndef deepshadow_tool_Measure_h
#define deepshadow_tool_Measure_h

#include "Core/Image.h"
#include "Options.h"
#include "SceneSetup.h"

// SceneBench holds a SceneSetup by value: its smart pointers need the complete types.
#include "vtkCamera.h"
#include "vtkDeepShadowRenderWindow.h"
#include "vtkDeepShadowTechnique.h"
#include "vtkDeepShadowVolumeMapper.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkVolume.h"

#include <string>
#include <vector>

namespace deepshadow
{
namespace tool
{

class Json;

/** A technique's statistics (vtkDeepShadowTechnique::GetStatistics()) as JSON members. */
void SetStatistics(Json& json, const vtkDeepShadowTechnique::Statistics& statistics);

/** What one technique (or none) measured on one scene. */
struct Measurement
{
  double CameraMs = 0.0; // frame while only the camera moves
  double LightMs = 0.0;  // frame while the light moves (a build every frame)
  double BuildMs = 0.0;  // 0 for techniques that build nothing
  long long ShadowBytes = 0;
  bool RebuiltForCamera = false; // must stay false: a camera move rebuilds nothing
  std::vector<std::string> CameraPasses; // GPU passes of a camera-only frame
  std::vector<std::string> Features;     // shader features composed
  Image Picture;    // at the error size, start view
  Image ShadowTerm; // the same, shadow term alone (empty unless asked for)
  // The technique's own statistics after the camera-only frames: its last build, or the last
  // camera frame's analysis (see vtkDeepShadowTechnique::GetStatistics()).
  vtkDeepShadowTechnique::Statistics Statistics;
};

/** The ground truth of a scene's start view at the error size. */
struct GroundTruth
{
  Image Picture;
  Image ShadowTerm;
  Image SurfaceTerm; // at each pixel's first receiver, -1 where none (ReferenceRenderer::Render)
  double Milliseconds = 0.0;
};

/** A standard scene set up for measuring, with its start view and key light. */
class SceneBench
{
public:
  /**
   * Builds scene `name` with `options`' sizes (throws UsageError for an unknown scene); an
   * empty name builds what the options name (their --volume file).
   */
  SceneBench(const Options& options, const std::string& name);

  /**
   * Measures `technique` (null: unshadowed); `shadowTerm` also captures the shadow term. A
   * scene with a second volume (hybrid-smoke) gives it `second`, a technique of the same
   * kind: builds, times and memory are then both techniques' together (and the grids that
   * carry each volume's shadows to the other). Without `lightMoves` the light-moving frames
   * are left out: LightMs stays unmeasured and BuildMs is the warm-up frame's build.
   */
  Measurement Measure(vtkDeepShadowTechnique* technique, bool shadowTerm,
    vtkDeepShadowTechnique* second = nullptr, bool lightMoves = true);

  /** The ground truth, grey or coloured, computed once per kind. */
  const GroundTruth& Truth(bool colored);

  /**
   * The shadow term at each pixel's first receiver with `technique`'s CPU twin (the exact
   * march of the ground truth otherwise), at --error-size, -1 where there is none: the
   * error of the representation alone, where a viewer sees it.
   */
  Image TwinSurfaceTerm(vtkDeepShadowTechnique* technique, vtkDeepShadowTechnique* second = nullptr);

  /** The start view at --size with `technique` (null: none; `second` as in Measure). */
  Image Picture(vtkDeepShadowTechnique* technique, vtkDeepShadowTechnique* second = nullptr);

  SceneSetup& Setup() { return this->Scene; }
  /** The options the scene was built with (its name in Scene). */
  const Options& GetOptions() const { return this->Settings; }

private:
  void Restore();
  /** Gives the scene's mappers their techniques (null: none; `second` only if there is a
   * second volume). */
  void Use(vtkDeepShadowTechnique* technique, vtkDeepShadowTechnique* second);
  void Orbit();
  void TurnLight();
  Image Capture(bool shadowTerm);

  Options Settings;
  SceneSetup Scene;
  vtkNew<vtkCamera> StartCamera;
  vtkLight* Key = nullptr;
  double StartPosition[3] = { 0.0, 0.0, 0.0 };
  GroundTruth Truths[2];
  bool HaveTruth[2] = { false, false };
};

}
}
#endif
