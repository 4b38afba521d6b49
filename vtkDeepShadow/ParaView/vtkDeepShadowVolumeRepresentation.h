/**
 * @class   vtkDeepShadowVolumeRepresentation
 * @brief   ParaView's volume representation of image data, drawn by vtkDeepShadowVolumeMapper.
 *
 * The "Shadowed Volume" representation type of the DeepShadow plugin. Everything ParaView's
 * "Volume" representation does (the selected point or cell array, its colour map and opacity
 * function, shading, blend modes, cropping) goes through unchanged: the superclass drives the
 * mapper with vtkVolumeMapper's API, which ours honours. Added: the shadow technique, by its
 * registry name, and its parameters as KEY=VALUE text, both read from the technique registry
 * (Core/ShadowTechniques.h), so every technique and key the tool knows is available here.
 */
#ifndef vtkDeepShadowVolumeRepresentation_h
#define vtkDeepShadowVolumeRepresentation_h

#include "vtkDeepShadowParaViewModule.h" // For export macro
#include "vtkImageVolumeRepresentation.h"
#include "vtkSmartPointer.h" // For ivars

#include <string> // For ivars

class vtkActor;
class vtkDeepShadowBrickExchange;
class vtkDeepShadowCastingMeshes;
class vtkRenderer;

class VTKDEEPSHADOWPARAVIEW_EXPORT vtkDeepShadowVolumeRepresentation : public vtkImageVolumeRepresentation
{
public:
  static vtkDeepShadowVolumeRepresentation* New();
  vtkTypeMacro(vtkDeepShadowVolumeRepresentation, vtkImageVolumeRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The shadow technique by registry name: "none", "dsm" (the default), "rays",
   * "dsm-color-cached", ... (deepshadow::ShadowTechniqueNames()). Applied with the
   * parameters at the next render, so that the two can change together: an unknown name is
   * one error then; the technique in use stays.
   */
  void SetShadowTechnique(const char* name);
  const char* GetShadowTechnique() const { return this->TechniqueName.c_str(); }

  /**
   * The technique's parameters as KEY=VALUE pairs separated by spaces or commas, with the
   * tool's keys and ranges ("epsilon=0.01 shadow-map-size=1024"); empty: the technique's
   * defaults. A key the technique does not read, or a value out of range, is one error naming
   * it at the next render; the technique in use stays.
   */
  void SetShadowParameters(const char* text);
  const char* GetShadowParameters() const { return this->ParameterText.c_str(); }

  /**
   * Which of the view's lights cast shadows: 0, the brightest one (ParaView's key light, the
   * default; its other lights are fill, head and back lights); 1, the four brightest (the
   * mapper shadows at most four; ParaView's light kit has five). Set on the lights' vtkLight::ShadowAttenuation at each render.
   */
  vtkSetClampMacro(ShadowLights, int, 0, 1);
  vtkGetMacro(ShadowLights, int);

  ///@{
  /**
   * A ground plane that receives the volume's shadow (a shadow is read on a ground): 0, none
   * (the default); 1 to 6, on the side -X, +X, -Y, +Y, -Z or +Z of the volume's box, a
   * twentieth of the box beyond it and half the box wider on every side (ParaView's own
   * surfaces receive the shadow as "Shadowed Surface", vtkDeepShadowSurfaceRepresentation);
   * this plane is drawn by vtkDeepShadowPolyDataMapper with the volume as its shadowing volume, in the colour of
   * ShadowGroundColor. Under MPI it is not drawn (said once): a rank's lookups see its own
   * brick and those in front of it, not the bricks between it and a receiver beyond them.
   */
  vtkSetClampMacro(ShadowGround, int, 0, 6);
  vtkGetMacro(ShadowGround, int);
  vtkSetVector3Macro(ShadowGroundColor, double);
  vtkGetVector3Macro(ShadowGroundColor, double);
  ///@}

  ///@{
  /**
   * While the view is interacted with (ParaView's interactive renders), a shadow-casting light
   * that turned less than this many degrees since its shadow was built keeps that shadow; the
   * still render after the interaction rebuilds it (vtkDeepShadowVolumeMapper::
   * InteractiveShadowLag). ParaView's light kit follows the camera, so without it every frame
   * of a rotation rebuilds the key light's maps. Default 10; 0 rebuilds on every frame.
   */
  void SetShadowInteractiveLag(double degrees);
  double GetShadowInteractiveLag();
  /**
   * While the view is interacted with, the volume's shadows come from one ray per N x
   * N pixels, and structures rebuilt meanwhile are N times coarser
   * (vtkDeepShadowVolumeMapper::InteractiveShadowSubsampling); the still render looks them up
   * per sample, in full. Default 8; 1 per sample on every frame.
   */
  void SetShadowInteractiveSubsampling(int pixels);
  int GetShadowInteractiveSubsampling();
  /** Shadow structures built so far, counted per light (vtkDeepShadowVolumeMapper::GetShadowBuilds). */
  int GetShadowBuilds();
  ///@}

  ///@{
  /**
   * Under MPI (mpirun -np N pvbatch), what the light-space technique's exchange between the
   * ranks' bricks (vtkDeepShadowBrickExchange) cost at the frame before the last render: the
   * largest over the ranks of the bytes and messages a rank received, and of the milliseconds
   * it spent (gathered at each render's start, so that no rank waits after drawing). 0 on one
   * rank, or when the pieces shadow themselves only (said once: a technique that is not
   * exchanged, or a rank without a piece).
   */
  double GetShadowExchangeBytes();
  int GetShadowExchangeMessages();
  double GetShadowExchangeMilliseconds();
  ///@}

  ///@{
  /**
   * Whether the ranks scan their light-space totals along each light (on, the default:
   * ceil(log2 ranks) messages of one map per rank and light) or gather every rank's (ranks - 1
   * maps). The pictures are the same; off is for comparing.
   */
  void SetShadowExchangeScan(int scan);
  int GetShadowExchangeScan();
  ///@}
  /**
   * The technique's statistics of the last frame on this rank (vtkDeepShadowTechnique::
   * GetStatistics(): a deep shadow map's nodes per texel, rmsm's pages, ...) as NAME=VALUE
   * pairs separated by spaces; empty without a technique or for one that reports none.
   */
  const char* GetShadowStatistics();
  /** The error of the last technique or parameters set, "" when they were applied. */
  const char* GetShadowError() const { return this->Error.c_str(); }
  /**
   * The view's Shadowed Surfaces that cast into the volume's shadow structures (gathered at
   * the start of each render, again only when one of them changed: GetBuilds()). Under MPI
   * none cast (said by the Shadowed Surfaces).
   */
  vtkDeepShadowCastingMeshes* GetCastingMeshes();

protected:
  vtkDeepShadowVolumeRepresentation();
  ~vtkDeepShadowVolumeRepresentation() override;

  bool AddToView(vtkView* view) override;
  bool RemoveFromView(vtkView* view) override;
  int ProcessViewRequest(vtkInformationRequestKey* request, vtkInformation* in, vtkInformation* out) override;

private:
  vtkDeepShadowVolumeRepresentation(const vtkDeepShadowVolumeRepresentation&) = delete;
  void operator=(const vtkDeepShadowVolumeRepresentation&) = delete;

  /** Makes the technique from the name and parameters set; false (Error set) if they are bad. */
  bool ApplyTechnique();

  /** Sets the lights' ShadowAttenuation as ShadowLights says (only values that change). */
  void ChooseShadowLights();

  /** Places the ground plane (ShadowGround) beside the volume's whole box, or hides it. */
  void UpdateGround();
  /** Collective (every rank updates): how many ranks hold no piece of the volume. */
  void CountPieces();
  void GatherExchangeStatistics();
  /** Gives a light-space technique the ranks' exchange, or says why the pieces cannot share. */
  void ShareShadowsAcrossRanks();
  /** At the renderer's start: the visible Shadowed Surfaces cast into the volume's structures. */
  void GatherCastingSurfaces();
  vtkSmartPointer<vtkDeepShadowCastingMeshes> Casting;
  unsigned long RenderObserver = 0; // on Renderer's StartEvent
  int ShadowLights = 0;
  int ShadowGround = 0;
  double ShadowGroundColor[3] = { 0.85, 0.85, 0.8 };
  vtkSmartPointer<vtkActor> Ground; // drawn by a vtkDeepShadowPolyDataMapper
  bool SaidGroundAlone = false;
  int RanksWithoutPiece = 0;
  vtkSmartPointer<vtkDeepShadowBrickExchange> Exchange; // the ranks' bricks (MPI)
  double ExchangeLargest[3] = { 0.0, 0.0, 0.0 }; // bytes, messages, ms: GatherExchangeStatistics
  std::string SaidAlone; // why the pieces of an MPI run shadow themselves only: said once
  vtkRenderer* Renderer = nullptr; // the view's, while the representation is in one
  std::string TechniqueName = "dsm";
  std::string ParameterText;
  bool TechniqueChanged = false; // applied at the next render (ApplyTechnique)
  std::string Error;
  std::string StatisticsText; // GetShadowStatistics()'s
};

#endif
