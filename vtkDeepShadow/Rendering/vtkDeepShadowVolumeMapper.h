/**
 * @class   vtkDeepShadowVolumeMapper
 * @brief   GPU ray-casting volume mapper of vtkDeepShadow, with shadows.
 *
 * A vtkGPUVolumeRayCastMapper: code written for VTK's mapper compiles unchanged, and with
 * vtkDeepShadowVolumeMapperFactory::Override() `vtkGPUVolumeRayCastMapper::New()` (and so
 * vtkSmartVolumeMapper) returns this mapper. Composite blending (with shadows), MIP, MinIP,
 * average intensity and additive blending (without), clipping planes and cropping (which the
 * shadows see), VTK's sampling settings. What it inherits and does not draw yet (isosurfaces,
 * masks, image sample distance, final colour window/level, ...) is said once per setting
 * (GetUnsupportedSettings()), never ignored in silence.
 *
 * Renders a vtkImageData (the point or cell array that the scalar mode and SelectScalarArray
 * select, of any numeric type, those wider than 16-bit integers kept in single precision;
 * 1 to 4 components, independent or dependent, combined as VTK's mapper combines them: Core/
 * Components.h) with a vtkVolumeProperty: colour and scalar-opacity transfer functions,
 * scalar opacity unit distance, nearest or linear interpolation, and shading of the gradient
 * with the renderer's lights as the VTK it was built with shades it (SetShadingModel). Honours the
 * image's spacing, origin and direction and the vtkVolume's transform, and the fragment code
 * of its vtkShaderProperty at VTK's Base and RenderToImage tags (anything else is refused,
 * said once). Opaque geometry already drawn ends the rays (depth buffer).
 *
 * The optical model is the one of the CPU reference (deepshadow::ReferenceRenderer): samples
 * every SampleDistance world units from the ray's entry into the volume (at the middle of
 * each step, or jittered), opacity corrected for the step, front-to-back compositing, early
 * termination once opacity exceeds TerminationOpacity. Empty-space skipping jumps over
 * blocks of zero opacity exactly (the samples taken are the same).
 *
 * The shader is composed from the features in use (VolumeSampling, EmptySpace, Lighting,
 * Phong, Jitter, OpaqueDepth, a technique's Shadow...: one component each, listed in
 * Rendering/Sampling/SamplingFeatures.cxx for the data's and Rendering/RayCast/VolumeFeatures.cxx
 * for the view's): see GetShaderFeatures() and GetFragmentShaderSource().
 * Work is redone only when what it depends on changed; the counters below make that
 * observable.
 *
 * Polyhedral bounds (AddBound, SetBoundExpression) restrict the volume to the inside of
 * closed meshes combined by Boolean operations: it is drawn, and casts and receives shadows,
 * only there (feature Bound; the CPU twin is deepshadow::BoundRegion).
 *
 * Bad input (no input, empty or flat volume, unsupported type or component count,
 * non-finite samples, a volume larger than the GL's 3D texture limit; a spacing, origin or
 * direction matrix that is not finite or singular, or a placement single precision cannot
 * resolve (see deepshadow::adapter::CheckVolumePlacement); a scalar opacity unit distance
 * that is not positive, a transfer function point that is not finite; a light whose
 * position is not finite or beyond 1e18) is reported once per change with vtkErrorMacro
 * (also in GetLastError()) and the volume is not drawn (what makes VTK's renderer cull the
 * volume is reported by GetBounds()).
 */
#ifndef vtkDeepShadowVolumeMapper_h
#define vtkDeepShadowVolumeMapper_h

#include "vtkDeepShadowRenderingModule.h" // For export macro
#include "vtkNew.h"                       // For vtkNew
#include "vtkGPUVolumeRayCastMapper.h"

#ifndef __VTK_WRAP__ // VTK's wrapper parser does not get through glm's templates
#include <glm/mat4x4.hpp> // For glm::dmat4
#endif
#include <functional> // For std::function
#include <memory> // For std::unique_ptr, std::shared_ptr
#include <optional> // For std::optional
#include <string> // For std::string
#include <vector> // For std::vector

class vtkDeepShadowTechnique;
namespace deepshadow
{
struct GradientOpacity;
struct LabelMap;
struct PassFrame;
struct RayCastFrame;
struct ShadowContext;
class SurfaceSet;
}
class vtkOpenGLRenderWindow;
class vtkPolyData;
class vtkVolumeProperty;

class VTKDEEPSHADOWRENDERING_EXPORT vtkDeepShadowVolumeMapper : public vtkGPUVolumeRayCastMapper
{
public:
  static vtkDeepShadowVolumeMapper* New();
  vtkTypeMacro(vtkDeepShadowVolumeMapper, vtkGPUVolumeRayCastMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * World distance between samples along a ray (GetSampleDistance() is VTK's). 0 (our
   * default; VTK's is 1) means deepshadow::DefaultSampleDistance: half the shortest
   * world-space voxel edge. With LockSampleDistanceToInputSpacing on, the distance is VTK's
   * spacing-adjusted one instead. A negative, infinite or NaN distance is an error
   * (vtkErrorMacro) and the old one is kept.
   */
  void SetSampleDistance(float distance) override;
  ///@}
  /*
   * AutoAdjustSampleDistances (VTK's; off by default here, on in VTK): while the window asks
   * for 1 frame a second or more (an interactor moving the camera), the view rays take
   * samples twice as far apart; the shadow structures are kept, not rebuilt for the coarser
   * step, so shadows stay on while moving. Still frames step as set.
   */
  /** The distance used in the last frame (0 before the first). */
  double GetEffectiveSampleDistance();

  ///@{
  /**
   * Shadows while interacting: on frames whose window asks for 1 frame a second or more (an
   * interactor moving the camera, ParaView's interactive renders), a shadow-casting light that
   * turned less than this many degrees about the volume's centre since its shadow structure was
   * built keeps that structure; the shadows then lag the light by at most that angle, and the
   * next still frame rebuilds them. A light that follows the camera (the headlight, ParaView's
   * light kit) otherwise rebuilds its structure on every frame of a rotation. 0 (the default)
   * rebuilds whenever a light moved; [0, 90] (clamped). Shadow rays have no structure to keep.
   */
  vtkSetClampMacro(InteractiveShadowLag, double, 0.0, 90.0);
  vtkGetMacro(InteractiveShadowLag, double);
  ///@}

  ///@{
  /**
   * Shadows while interacting, looked up on a coarser grid: on the same interactive frames,
   * a volume with a technique is drawn in two passes, one shadowed ray per N x N block of
   * pixels (the shadowed colour over the unshadowed one, and the opacity, per ray) and then
   * every pixel without any shadow lookup (lit, if shaded, by the same lights), its colour
   * times that ratio interpolated from the four nearest blocks (Core/ShadowSubsampling.h). A shadow structure rebuilt on
   * these frames (its light turned past InteractiveShadowLag) is built N times coarser (a
   * light-space technique's maps N times smaller a side, down to 64 texels), as the rays
   * that read it are N pixels apart. The volume keeps its full resolution; the shadows' own
   * detail is that of the blocks until the next still frame, which is drawn per sample with
   * the structures in full. On a CPU rasterizer a lookup per sample costs about as much as
   * the sample, so this is what makes shadows cheap while the view moves. Translucent
   * meshes, other volumes along the rays, label maps, several components, isosurfaces, the
   * user's shader code and the shadow term keep the lookup per sample. 1 (the default): per
   * sample on every frame; [1, 16] (clamped).
   */
  vtkSetClampMacro(InteractiveShadowSubsampling, int, 1, 16);
  vtkGetMacro(InteractiveShadowSubsampling, int);
  ///@}

  ///@{
  /**
   * Jitter each ray's first sample by a hash of the pixel and JitterSeed (off by default).
   * Jitter is VTK's UseJittering under a shorter name.
   */
  void SetJitter(bool jitter) { this->SetUseJittering(jitter ? 1 : 0); }
  bool GetJitter() { return this->GetUseJittering() != 0; }
  void JitterOn() { this->SetJitter(true); }
  void JitterOff() { this->SetJitter(false); }
  vtkSetMacro(JitterSeed, unsigned int);
  vtkGetMacro(JitterSeed, unsigned int);
  ///@}

  /** No reduction: the volume is uploaded whole (or refused when it does not fit). */
  void GetReductionRatio(double ratio[3]) override;
  /** 1 in any OpenGL render window (vtkSmartVolumeMapper asks before choosing us). */
  int IsRenderSupported(vtkRenderWindow* window, vtkVolumeProperty* property) override;

  ///@{
  /**
   * Stop a ray once its opacity exceeds this (default 1 - 1/255, as VTK); 1 never stops.
   * Clamped to [0, 1]; NaN is an error (vtkErrorMacro) and the old value is kept.
   */
  virtual void SetTerminationOpacity(double opacity);
  vtkGetMacro(TerminationOpacity, double);
  ///@}

  ///@{
  /** Skip blocks of zero opacity (on by default; exact). */
  vtkSetMacro(EmptySpaceSkipping, bool);
  vtkGetMacro(EmptySpaceSkipping, bool);
  vtkBooleanMacro(EmptySpaceSkipping, bool);
  ///@}

  ///@{
  /** Texels of the transfer-function table over the scalar range (default 4096). */
  vtkSetClampMacro(TransferTableSize, int, 2, 65536);
  vtkGetMacro(TransferTableSize, int);
  ///@}

  ///@{
  /**
   * Non-finite samples (NaN, +-Inf in float data) are an error by default. On, they are
   * replaced as deepshadow::ReplaceNonFinite says (NaN -> smallest finite value, +-Inf ->
   * largest / smallest) and rendering goes on with a warning.
   */
  vtkSetMacro(ReplaceNonFiniteScalars, bool);
  vtkGetMacro(ReplaceNonFiniteScalars, bool);
  vtkBooleanMacro(ReplaceNonFiniteScalars, bool);
  ///@}

  ///@{
  /**
   * With a shadow technique, a renderer lit only by VTK's automatic headlight is lit instead
   * by a key light 45 degrees above and 45 to the right of the camera (as bright as the
   * headlight, casting the shadows) and a fill from the eye (half as bright, casting none),
   * as a light kit lights a scene: a headlight casts its shadows straight behind what it
   * lights, where the camera cannot see them, and the picture only darkened. Together
   * brighter than the headlight, since the key meets a surface facing the camera at an angle
   * and through the volume's own outer layers: the lit side keeps about 0.8 to 0.9 of the
   * unshadowed picture's brightness. On by default; off: the headlight as it is. Any other
   * lighting is kept.
   */
  vtkSetMacro(HeadlightKeyLight, bool);
  vtkGetMacro(HeadlightKeyLight, bool);
  vtkBooleanMacro(HeadlightKeyLight, bool);
  ///@}

  enum ShadingModels
  {
    VTK_SHADING = 0,
    BLINN_PHONG_SHADING = 1
  };

  ///@{
  /**
   * How the lights shade a volume whose property shades (ShadeOn). VTK_SHADING, the default,
   * draws what the vtkOpenGLGPUVolumeRayCastMapper of the VTK this module was built with
   * draws (VTK 9.1's half vector, or VTK 9.2's reflected light), quirks included, so that a
   * swapped-in mapper keeps a script's picture: under scene lights or a light kit the ambient
   * term is Ka times the lights' ambient colours (black unless vtkLight::SetAmbientColor: a
   * shadow is then black), the normal leans towards the volume's long axes, the specular
   * highlight is VTK's (Core/VolumeShading.h lists each difference). BLINN_PHONG_SHADING
   * lights with the gradient's true normal, the half vector normalize(L + V) and Ka x colour x
   * the renderer's ambient light: the shading the deepshadow tool and its report use. Both
   * have their CPU twin (vtkDeepShadowReferenceRenderer follows this setting).
   */
  vtkSetClampMacro(ShadingModel, int, VTK_SHADING, BLINN_PHONG_SHADING);
  vtkGetMacro(ShadingModel, int);
  void SetShadingModelToVTK() { this->SetShadingModel(VTK_SHADING); }
  void SetShadingModelToBlinnPhong() { this->SetShadingModel(BLINN_PHONG_SHADING); }
  ///@}

  /**
   * VTK's "lighting complexity" this mapper has reached while shading (0 none yet, 1 a lone
   * headlight, 2 directional lights, 3 a positional light): the path of VTK's shading it
   * draws. Built with VTK 9.1 it only grows, as in VTK 9.1's mapper, so a mapper that once
   * shaded under a positional light keeps VTK's positional path when the lights change back;
   * with VTK 9.2 onwards it follows the lights.
   */
  vtkGetMacro(VTKLightingComplexity, int);

  ///@{
  /**
   * How the volume shadows itself (null, the default: no shadows, and no shadow code in the
   * shader). A technique replaced releases its GL objects in the window last drawn in. See vtkDeepShadowRayTechnique, vtkDeepShadowShadowMapTechnique,
   * vtkDeepShadowDeepShadowMapTechnique, vtkDeepShadowOpacityLevelsTechnique and
   * vtkDeepShadowStochasticShadowMapTechnique.
   */
  void SetShadowTechnique(vtkDeepShadowTechnique* technique);
  vtkGetObjectMacro(ShadowTechnique, vtkDeepShadowTechnique);
  ///@}
  /** Shadow structures built so far (0 without a technique). */
  int GetShadowBuilds();

  ///@{
  /**
   * What the image shows: the lit colour (OutputColor, the default), or the shadow term
   * alone (OutputShadowTerm): each sample's colour replaced by the product, over the lights
   * that reach it, of 1 - ShadowAttenuation (1 - visibility), composited with the volume's
   * opacity; 1 (white) where nothing shadows. It measures a technique's error without the
   * shading; vtkDeepShadowReferenceRenderer::SetOutput() is its CPU twin.
   */
  enum OutputModes
  {
    OutputColor = 0,
    OutputShadowTerm = 1
  };
  vtkSetClampMacro(OutputMode, int, OutputColor, OutputShadowTerm);
  vtkGetMacro(OutputMode, int);
  void SetOutputModeToColor() { this->SetOutputMode(OutputColor); }
  void SetOutputModeToShadowTerm() { this->SetOutputMode(OutputShadowTerm); }
  ///@}

  ///@{
  /**
   * Polyhedral bounds: the volume exists only inside the region they enclose. It is drawn
   * there only, and casts and receives shadows there only, with every technique. Each bound
   * is a closed triangle mesh (polygons and strips are triangulated; points shared or merely
   * coincident, as in STL) in the coordinates of the image data's points, so it moves with the
   * vtkVolume; any shape: non-convex, with holes, several components. Bounds are named A, B,
   * C... in the order added; SetBoundExpression combines them, e.g. "union(A,diff(B,C))"
   * (union, intersection/inter, difference/diff; see deepshadow::CSGExpression); "" (the
   * default) is their union. At most 8 bounds: combine more, or use the mesh of
   * vtkDeepShadowCSGFilter as one bound. Along each ray the region is evaluated exactly from
   * every bound's crossings (every entry and exit, not only the first and last); samples
   * outside are skipped, which also saves time. A bound that is open or not consistently
   * oriented is an error naming it; an empty bound (e.g. an empty CSG result) encloses
   * nothing, and a volume bounded by nothing is not drawn (with a warning).
   */
  void AddBound(vtkPolyData* bound);
  void RemoveAllBounds();
  int GetNumberOfBounds() const;
  vtkPolyData* GetBound(int index) const;
  void SetBoundExpression(const std::string& expression);
  const std::string& GetBoundExpression() const { return this->BoundExpression; }
#ifndef __VTK_WRAP__
  /**
   * The region drawn: the bounds above, then (as further leaves, intersected with them) the
   * closed meshes of what the clipping planes and cropping keep, in the image's coordinates,
   * for the prop `volume` (clipping planes are in world coordinates). The CPU reference
   * bounds its volume with the same. Cut meshes are rebuilt only when the cut changed.
   */
  void GetDrawnRegion(vtkVolume* volume, std::vector<vtkPolyData*>& meshes, std::string& expression);
#endif
  ///@}

  /**
   * Used by vtkDeepShadowPass: what it hands the volume for one frame (deepshadow::PassFrame),
   * set when the frame starts and null after it. From it the volume takes:
   * - the surfaces that cast shadows onto it (and onto whatever receives its shadows), in
   *   world coordinates, the scene's casting meshes; every technique meets them on its light
   *   rays and feelers: an opaque surface stops the light, a translucent one lets through its
   *   transmission (deepshadow::SurfaceTransmission). The set stays with the mapper after the
   *   frame; a replaced set marks it modified. It is uploaded again only when it is replaced
   *   or the volume moves (counter SurfaceUploads, pass "surface-upload"), and shadow
   *   structures are rebuilt then only;
   * - what the scene's other shadowing volumes cast onto this one, on a grid over its box,
   *   multiplied into each light's visibility (with a technique only: a volume receives
   *   shadows when it has one);
   * - the peeled layers of the translucent meshes, which the ray caster composites at their
   *   depths along each view ray, with the opaque image behind them (the volume's pixels are
   *   replaced, not blended);
   * - the segments to draw the volume into, as a guest (pieces along each view ray that the
   *   merging volume sorts in among its own samples; pass "ray-cast-segments"), instead of
   *   onto the screen.
   */
  void SetPassFrame(deepshadow::PassFrame* frame);
#ifndef __VTK_WRAP__
  /** The surfaces casting shadows onto the volume, as the last frame left them (null: none). */
  std::shared_ptr<const deepshadow::SurfaceSet> GetCastingSurfaces() const;
#endif

  /**
   * Used by vtkDeepShadowPass before opaque geometry is drawn, with its frame set: brings the
   * volume's data, tables and the technique's shadow structures up to date without drawing.
   * Returns what mesh receivers read to look the structures up, kept in the frame (null
   * without a working technique). The frame's Render() then finds nothing left to build.
   */
  const deepshadow::ShadowContext* PrepareShadows(vtkRenderer* renderer, vtkVolume* volume);

  /**
   * The image drawn: the input's array that the scalar mode and SelectScalarArray select, as
   * point scalars (cell scalars resampled as VTK's mapper draws them: Volume/DrawnScalars.h).
   * Null without an input, or, said once, when the selection finds nothing to draw.
   */
  vtkImageData* GetImageInput();

  void Render(vtkRenderer* renderer, vtkVolume* volume) override;

  /**
   * The input's bounds. VTK's renderer culls a volume whose bounds are not finite (NaN
   * spacing, origin or direction) or too small for its camera before Render() is called, so
   * the input's and its placement's errors are also reported here.
   */
  double* GetBounds() override;
  using Superclass::GetBounds;

  /** Without any input, reports our one clear error instead of the pipeline's. */
  using Superclass::Update;
  void Update() override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

  ///@{
  /** Observability: what the last frames did and built. */
  vtkGetMacro(RenderCount, int);          // frames drawn
  vtkGetMacro(VolumeUploads, int);        // 3D texture (re)uploads: data changed
  vtkGetMacro(TransferTableBuilds, int);  // TF table rebuilds: TF, range or step changed
  vtkGetMacro(OccupancyBuilds, int);      // empty-space block maps: data or opacity changed
  vtkGetMacro(ShaderCompositions, int);   // times the composed shader source changed
  vtkGetMacro(BoundBuilds, int);          // bound hierarchies built: a bound or placement changed
  vtkGetMacro(SurfaceUploads, int);       // casting surfaces uploaded: the set or placement changed
  /**
   * Features compiled into the last shader, e.g. {"EmptySpace", "VolumeSampling"}, then "Bound"
   * and "Shadow:<technique>" when in use.
   */
  const std::vector<std::string>& GetShaderFeatures() const { return this->ShaderFeatures; }
  const std::string& GetFragmentShaderSource() const { return this->FragmentShaderSource; }
  /**
   * The GPU passes the last frame ran, in order: "volume-upload", "transfer-table",
   * "occupancy", "bound-upload", "surface-upload" (each only when what it depends on changed), the technique's passes
   * (vtkDeepShadowTechnique::GetLastPasses()) and "ray-cast" (or "ray-cast-segments").
   */
  const std::vector<std::string>& GetLastPasses() const { return this->LastPasses; }
  /** Fraction of empty-space blocks that are skipped (0 when skipping is off). */
  vtkGetMacro(EmptyBlockFraction, double);
  /** GPU memory of the volume, table, block map and bound, in bytes. */
  vtkGetMacro(GPUMemoryBytes, long long);
  ///@}

  /**
   * What went wrong in the last frame (the volume not drawn, or drawn without shadows); empty
   * after a frame without trouble.
   */
  const std::string& GetLastError() const { return this->LastError; }

  /**
   * What the last frame was asked for and did not draw (blend modes other than composite,
   * cropping, clipping planes, gradient opacity, 2D transfer functions), one line each naming
   * what is drawn instead; each is also said once with vtkWarningMacro. Empty when none.
   */
  const std::vector<std::string>& GetUnsupportedSettings() const { return this->Unsupported; }

protected:
  vtkDeepShadowVolumeMapper();
  ~vtkDeepShadowVolumeMapper() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  // vtkGPUVolumeRayCastMapper's AMR entry points (vtkAMRVolumeMapper): refused.
  void PreRender(vtkRenderer* renderer, vtkVolume* volume, double bounds[6], double range[2],
    int components, unsigned int levels) override;
  void RenderBlock(vtkRenderer* renderer, vtkVolume* volume, unsigned int level) override;
  void PostRender(vtkRenderer* renderer, int components) override;

  unsigned int JitterSeed = 0;
  double InteractiveShadowLag = 0.0;
  int InteractiveShadowSubsampling = 1;
  double TerminationOpacity;
  bool EmptySpaceSkipping = true;
  int TransferTableSize = 4096;
  bool ReplaceNonFiniteScalars = false;
  int OutputMode = OutputColor;
  vtkDeepShadowTechnique* ShadowTechnique = nullptr;
  std::string BoundExpression;

  int RenderCount = 0;
  int VolumeUploads = 0;
  int TransferTableBuilds = 0;
  int OccupancyBuilds = 0;
  int ShaderCompositions = 0;
  int BoundBuilds = 0;
  int SurfaceUploads = 0;
  std::vector<std::string> ShaderFeatures;
  std::vector<std::string> LastPasses;
  std::string FragmentShaderSource;
  double EmptyBlockFraction = 0.0;
  long long GPUMemoryBytes = 0;
  std::string LastError;
  std::vector<std::string> Unsupported; // the last frame's, see GetUnsupportedSettings()
  std::vector<std::string> UnsupportedSaid; // each said once
  bool ErrorThisFrame = false;
  bool HeadlightKeyLight = true;
  int ShadingModel = VTK_SHADING;
  int VTKLightingComplexity = 0;

private:
  vtkDeepShadowVolumeMapper(const vtkDeepShadowVolumeMapper&) = delete;
  void operator=(const vtkDeepShadowVolumeMapper&) = delete;

  void ReportError(const std::string& message);
  /** Starts a frame (Render, or the pass's PrepareShadows before it). */
  void BeginFrame();
  /**
   * Makes `window` the one the GPU resources live in. GL objects belong to the context that
   * made them: drawn in another window, they are released in the old one (its context made
   * current) and built again here, as VTK's own mapper does (vtkGenericOpenGLResourceFreeCallback).
   */
  void AdoptWindow(vtkOpenGLRenderWindow* window);
  /**
   * Brings every GPU resource and the technique's structures up to date and fills `frame`;
   * false when the volume is not drawn (said by ReportError, or an empty bound).
   */
  bool Prepare(vtkRenderer* renderer, vtkVolume* volume, deepshadow::RayCastFrame& frame);
  /** Reads the volume's vtkShaderProperty code and says each unsupported setting once (Prepare). */
  void ReadUserCodeAndSayUnsupported(vtkVolume* volume, deepshadow::RayCastFrame& frame);
  /** Fills the frame and its context from the resources Prepare brought up to date. */
  void FillFrame(vtkRenderer* renderer, vtkVolume* volume, deepshadow::RayCastFrame& frame,
    const glm::dmat4& indexToWorld, double stillStep, double step, double unitScale);
  /** The lights and the technique's structures (the last part of Prepare). */
  bool PrepareLightsAndShadows(deepshadow::RayCastFrame& frame);
  /**
   * Casts the rays: in one pass, or in the two of shadows on a coarser grid while
   * interacting (InteractiveShadowSubsampling).
   */
  bool Draw(deepshadow::RayCastFrame& frame);
  /**
   * One pass: composes the shader for the frame's features (`lastSource`: the pass's last
   * composition, to count changes), binds them and draws the box; `begin` and `end` around
   * the draw call (a render target).
   */
  bool DrawPass(const deepshadow::RayCastFrame& frame, std::string& lastSource, bool blend,
    const std::function<void()>& begin, const std::function<void()>& end);
  /** Re-uploads the volume if the data changed (and then drops what was made from it). */
  bool UpdateVolume(vtkOpenGLRenderWindow* window, vtkImageData* input);
  /** The transfer table and the empty-space block map, if what they depend on changed. */
  void UpdateTables(
    vtkOpenGLRenderWindow* window, vtkVolumeProperty* property, double step, double unitScale);
  /** Rebuilds the bound's hierarchy and textures if it changed; false on bad bounds. */
  bool UpdateBound(vtkOpenGLRenderWindow* window, vtkImageData* input, vtkVolume* volume);
  /**
   * The gradient-opacity table and the binary mask, if they are in use and changed, into the
   * frame's context; false on a bad mask (said by ReportError).
   */
  bool UpdateOpacityFactors(vtkOpenGLRenderWindow* window, vtkVolumeProperty* property, vtkImageData* input,
    deepshadow::RayCastFrame& frame);
  /**
   * Components 1.. of a volume of several: their textures and tables (for the view's `step`,
   * or `uncorrected`), uploaded and rebuilt when they changed, into the frame's context; false
   * (said) when the property cannot classify them (3 dependent components) or a component
   * cannot be drawn.
   */
  bool UpdateComponents(vtkOpenGLRenderWindow* window, vtkVolumeProperty* property, double step,
    bool uncorrected, double unitScale, deepshadow::RayCastFrame& frame);
  /** Gradient opacity's table, rebuilt when it changed, into the frame's context (none: nothing). */
  void UpdateGradientOpacity(vtkOpenGLRenderWindow* window,
    const std::optional<deepshadow::GradientOpacity>& gradient, deepshadow::RayCastFrame& frame);
  void UpdateComponentGradients(
    vtkOpenGLRenderWindow* window, vtkVolumeProperty* property, deepshadow::RayCastFrame& frame);
  /** A label map's tables (a row per label), rebuilt when they changed, into the frame's context. */
  void UpdateLabelTables(
    vtkOpenGLRenderWindow* window, const deepshadow::LabelMap& labels, deepshadow::RayCastFrame& frame);
#ifndef __VTK_WRAP__
  /** The world step of the view rays: locked to the spacing as VTK's, set, or the default. */
  double SampleStep(vtkImageData* input, const glm::dmat4& indexToWorld);
  /** Uploads the casting surfaces in index space if they or the placement changed. */
  bool UpdateSurfaces(vtkOpenGLRenderWindow* window, const glm::dmat4& worldToIndex);
#endif
  /** GPU memory: the sum of what the holders in use report. */
  long long GetHolderBytes() const;

  class Internals;
  std::unique_ptr<Internals> Impl;
  // vtkDeepShadowPass's frame while it draws (outside Internals: a release keeps it).
  deepshadow::PassFrame* Frame = nullptr;
};

#endif
