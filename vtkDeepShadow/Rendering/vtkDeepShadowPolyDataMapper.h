/**
 * @class   vtkDeepShadowPolyDataMapper
 * @brief   Renders meshes that cast shadows into volumes and receive the scene's shadows.
 *
 * Draws the triangles of a vtkPolyData (polygons and strips are triangulated; points without
 * normals get them from vtkPolyDataNormals) with the actor's vtkProperty (colour, opacity,
 * ambient, diffuse, specular and its colour, specular power) or its point scalars mapped per
 * point, lit by the renderer's lights as vtkPolyDataMapper lights them (deepshadow::
 * SurfaceLight: one-sided per light, back faces turned to the viewer under two-sided
 * lighting, Phong's reflection). Cell scalars are not drawn (the property's colour is).
 *
 * In a renderer whose pass is vtkDeepShadowPass the mesh takes part in the scene's shadows:
 * - it casts (CastShadows, on by default) into every technique's structure: an opaque mesh
 *   stops the light, a translucent one lets its transmission through (the actor's colour is
 *   what it lets through of the light it stops: deepshadow::SurfaceTransmission);
 * - it receives (ReceiveShadows, on by default): each light's diffuse and specular light is
 *   scaled by the visibility the shadowing volume's technique gives, exactly as for volume
 *   samples. The lookup starts ShadowBias world units towards the light (more at grazing
 *   light: deepshadow::ReceiverOffset), so a mesh that casts does not shadow itself (acne).
 * - when translucent in a scene with a volume, it is peeled into layers that the volume
 *   composites at their depths along each view ray (vtkDeepShadowPass::SetTranslucentLayers).
 * Without the pass (in a renderer whose passes are another's, as in ParaView's views), the
 * mesh is lit without shadows, or receives those of one volume (SetShadowingVolume).
 *
 * Bad input: no input or no triangles draws nothing (with a warning); non-finite points and
 * cells whose point ids lie outside the points are an error (one vtkErrorMacro per change,
 * also in GetLastError(), naming the count or the id) found before any VTK filter sees the
 * mesh, and nothing is drawn (nor cast).
 */
#ifndef vtkDeepShadowPolyDataMapper_h
#define vtkDeepShadowPolyDataMapper_h

#include "vtkDeepShadowRenderingModule.h" // For export macro
#include "vtkPolyDataMapper.h"
#include "vtkWeakPointer.h" // For ShadowingVolume

#include <memory> // For std::unique_ptr
#include <string> // For std::string
#include <vector> // For std::vector

namespace deepshadow
{
struct PassFrame;
struct PeelStep;
struct SurfaceMesh;
}
class vtkPolyData;
class vtkVolume;

class VTKDEEPSHADOWRENDERING_EXPORT vtkDeepShadowPolyDataMapper : public vtkPolyDataMapper
{
public:
  static vtkDeepShadowPolyDataMapper* New();
  vtkTypeMacro(vtkDeepShadowPolyDataMapper, vtkPolyDataMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Whether the mesh casts shadows (default on) and receives them (default on). */
  vtkSetMacro(CastShadows, bool);
  vtkGetMacro(CastShadows, bool);
  vtkBooleanMacro(CastShadows, bool);
  vtkSetMacro(ReceiveShadows, bool);
  vtkGetMacro(ReceiveShadows, bool);
  vtkBooleanMacro(ReceiveShadows, bool);
  ///@}

  ///@{
  /**
   * Without a vtkDeepShadowPass: the volume (drawn by a vtkDeepShadowVolumeMapper with a
   * technique) whose shadows the mesh receives. The mesh's render brings that volume's shadow
   * structures up to date itself, as the pass would (the volume's own render then finds
   * nothing to rebuild); the mesh casts nothing into them this way. Under the pass, which
   * gathers every volume, it is not used. None by default (held weakly).
   */
  void SetShadowingVolume(vtkVolume* volume);
  vtkVolume* GetShadowingVolume();
  ///@}

  ///@{
  /**
   * World distance towards the light where a shadow lookup starts, at normal incidence
   * (default 0: twice the shadowing volume's feeler step).
   */
  vtkSetClampMacro(ShadowBias, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(ShadowBias, double);
  ///@}

  ///@{
  /**
   * What the mesh shows: its lit colour (OutputColor, the default), or the shadow term alone
   * (OutputShadowTerm): the product, over the lights that reach it, of 1 - ShadowAttenuation
   * * (1 - visibility), with the mesh's opacity; 1 (white) where nothing shadows it. As
   * vtkDeepShadowVolumeMapper's output modes; give every mapper of a scene the same one.
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

  /**
   * "" when `mesh` can be drawn without reading out of bounds, else why not in one line:
   * non-finite points (their count), a cell's point id outside the points. The mapper checks
   * its input with it; applications and tools may check a mesh before other filters see it.
   */
  static std::string CheckInput(vtkPolyData* mesh);

  /** The triangles as the scene's shadows see them: world coordinates (the actor's matrix). */
  bool GetSurfaceMesh(vtkActor* actor, deepshadow::SurfaceMesh& mesh, std::string& error);

  /**
   * The input's bounds; for an input CheckInput refuses, uninitialized bounds (VTK's own
   * computation would write through the bad point ids) and the error reported here, since
   * the renderer then culls the actor before Render().
   */
  double* GetBounds() override;
  using Superclass::GetBounds;

  void Render(vtkRenderer* renderer, vtkActor* actor) override;
  void RenderPiece(vtkRenderer* renderer, vtkActor* actor) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

  ///@{
  /** Observability. */
  vtkGetMacro(GeometryUploads, int); // vertex buffers (re)built: the data or colours changed
  vtkGetMacro(ShaderCompositions, int);
  const std::vector<std::string>& GetShaderFeatures() const { return this->ShaderFeatures; }
  const std::string& GetLastError() const { return this->LastError; }
  ///@}

  // ---- Used by vtkDeepShadowPass, not by applications ----
  /**
   * What the pass hands the mesh for one frame (null after it): where its shadows come from
   * (the scene's shadow source; none: lit without shadows) and what the scene's other
   * shadowing volumes cast onto it.
   */
  void SetPassFrame(const deepshadow::PassFrame* frame);
  /** While set, Render draws one layer of depth peeling (see Translucency/TranslucentLayers.h). */
  void SetPeelStep(const deepshadow::PeelStep* step);

protected:
  vtkDeepShadowPolyDataMapper();
  ~vtkDeepShadowPolyDataMapper() override;

  bool CastShadows = true;
  bool ReceiveShadows = true;
  vtkWeakPointer<vtkVolume> ShadowingVolume;
  double ShadowBias = 0.0;
  int OutputMode = OutputColor;
  int GeometryUploads = 0;
  int ShaderCompositions = 0;
  std::vector<std::string> ShaderFeatures;
  std::string LastError;

private:
  vtkDeepShadowPolyDataMapper(const vtkDeepShadowPolyDataMapper&) = delete;
  void operator=(const vtkDeepShadowPolyDataMapper&) = delete;

  /** Says why the input cannot be drawn, once per change (an error for bad input). */
  void ReportPrepareError();
  void Report(const std::string& problem, bool error);

  class Internals;
  std::unique_ptr<Internals> Impl;
};

#endif
