/**
 * @class   vtkDeepShadowReferenceRenderer
 * @brief   Renders a vtkRenderer's volumes on the CPU, in double precision: the ground truth.
 *
 * Takes the renderer's volumes (any vtkVolumeMapper with a vtkImageData input), their
 * vtkVolumeProperty, the lights, the active camera, the viewport size and the background,
 * converts them with the same code the GPU mapper uses, and runs
 * deepshadow::ReferenceRenderer. Use it after the renderer has rendered once (so the camera
 * clipping range and the automatic headlight exist) or call PrepareRenderer() first.
 *
 * Two modes:
 * - exact (default): transfer functions evaluated exactly, no early ray termination; this is
 *   the ground truth every reported error is measured against;
 * - GpuTwin: what vtkDeepShadowVolumeMapper computes (its transfer table, its termination
 *   opacity, its jitter, and under a vtkDeepShadowPass only as many translucent mesh crossings
 *   per view ray as it peels layers), to compare GPU and CPU formula by formula.
 * Shadows follow each mapper's vtkDeepShadowTechnique (its CPU twin), or the ground truth.
 * The image shows what the mapper's OutputMode says: the lit colour, or the shadow term.
 */
#ifndef vtkDeepShadowReferenceRenderer_h
#define vtkDeepShadowReferenceRenderer_h

#include "vtkDeepShadowRenderingModule.h" // For export macro
#include "vtkObject.h"

#include <string> // For std::string

class vtkImageData;
class vtkRenderer;

namespace deepshadow
{
struct Image;
}

class VTKDEEPSHADOWRENDERING_EXPORT vtkDeepShadowReferenceRenderer : public vtkObject
{
public:
  static vtkDeepShadowReferenceRenderer* New();
  vtkTypeMacro(vtkDeepShadowReferenceRenderer, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** World distance between samples; 0 (default) takes each mapper's effective distance. */
  vtkSetClampMacro(SampleDistance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(SampleDistance, double);
  ///@}

  ///@{
  /** Reproduce the GPU mapper's approximations instead of the exact model (default off). */
  vtkSetMacro(GpuTwin, bool);
  vtkGetMacro(GpuTwin, bool);
  vtkBooleanMacro(GpuTwin, bool);
  ///@}

  ///@{
  /**
   * Shadows: the CPU twin of each volume's technique (TechniqueShadows, the default; none
   * for volumes without one), or the ground truth for every volume (GroundTruthShadows:
   * translucent shadow rays at a quarter of the sample distance, no early termination,
   * coloured when the volume's technique is coloured). Either casts with the technique's
   * shadow property when it has one.
   */
  enum ShadowModes
  {
    TechniqueShadows = 0,
    GroundTruthShadows = 1
  };
  vtkSetClampMacro(Shadows, int, TechniqueShadows, GroundTruthShadows);
  vtkGetMacro(Shadows, int);
  ///@}

  ///@{
  /**
   * 1 (default): shadows per sample. N > 1: the twin of a vtkDeepShadowVolumeMapper's
   * interactive frame with InteractiveShadowSubsampling N (deepshadow::RenderShadowSubsampled:
   * shadows from one ray per N x N pixels); a scene of one volume and no meshes only.
   */
  vtkSetClampMacro(ShadowSubsampling, int, 1, 16);
  vtkGetMacro(ShadowSubsampling, int);
  ///@}

  ///@{
  /** Threads (0: all cores, or DEEPSHADOW_THREADS). */
  vtkSetClampMacro(Threads, int, 0, 1024);
  vtkGetMacro(Threads, int);
  ///@}

  ///@{
  /** Replace non-finite samples instead of failing (see vtkDeepShadowVolumeMapper). */
  vtkSetMacro(ReplaceNonFiniteScalars, bool);
  vtkGetMacro(ReplaceNonFiniteScalars, bool);
  ///@}

  /** Creates the automatic headlight and resets the clipping range, as a render would. */
  static void PrepareRenderer(vtkRenderer* renderer);

  /**
   * Renders into `image` (RGB, unsigned char, viewport-sized). Returns false and sets
   * GetLastError() (also vtkErrorMacro) when the scene cannot be rendered.
   */
  bool Render(vtkRenderer* renderer, vtkImageData* image);
  /**
   * The same, as linear double RGB; with `shadowTerm`, also the shadow-term image
   * (vtkDeepShadowVolumeMapper::OutputShadowTerm) from the same march, for about the cost of
   * one; with `surfaceTerm`, the shadow term at each pixel's first receiver, -1 where there
   * is none (deepshadow::ReferenceRenderer::Render).
   */
  bool Render(vtkRenderer* renderer, deepshadow::Image& image, deepshadow::Image* shadowTerm = nullptr,
    deepshadow::Image* surfaceTerm = nullptr);

  const std::string& GetLastError() const { return this->LastError; }

protected:
  vtkDeepShadowReferenceRenderer() = default;
  ~vtkDeepShadowReferenceRenderer() override = default;

  double SampleDistance = 0.0;
  bool GpuTwin = false;
  int Shadows = TechniqueShadows;
  int Threads = 0;
  int ShadowSubsampling = 1;
  bool ReplaceNonFiniteScalars = false;
  std::string LastError;

private:
  vtkDeepShadowReferenceRenderer(const vtkDeepShadowReferenceRenderer&) = delete;
  void operator=(const vtkDeepShadowReferenceRenderer&) = delete;
};

#endif
