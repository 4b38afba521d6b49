// Internal: what vtkDeepShadowVolumeMapper::Prepare() found for one frame, and what the ray
// caster's draw reads: the volume's GPU view, the camera, and the frame's state.
#ifndef vtkDeepShadowRayCastFrame_h
#define vtkDeepShadowRayCastFrame_h

#include "Core/Camera.h"
#include "Core/Projection.h"
#include "Sampling/ShadowContext.h"

#include <glm/mat3x3.hpp>

#include <optional>
#include <vector>

class vtkDeepShadowTechnique;
class vtkRenderer;
class vtkTextureObject;
class vtkVolume;
class vtkVolumeProperty;

namespace deepshadow
{
class FramebufferCopy;
class OtherVolumeShadows;
class TranslucentLayers;
class VolumeSegments;
struct UserShaderCode;

struct RayCastFrame
{
  ShadowContext Context;
  vtkRenderer* Renderer = nullptr;
  vtkVolume* Volume = nullptr;
  vtkVolumeProperty* Property = nullptr;
  Camera View;
  int X0 = 0, Y0 = 0, Width = 0, Height = 0; // the renderer's tile
  bool Shade = false;      // the property's shading: gradient and Phong
  bool ShadowTerm = false; // vtkDeepShadowVolumeMapper::OutputShadowTerm
  bool Lit = false;        // lights are evaluated (shading, shadows or the shadow term)
  bool Interactive = false; // the window asks for 1 frame a second or more (a moving view)
  ProjectionSettings Projection; // a projection blend mode (not Composite): unlit, unshadowed
  /** The technique whose structures are ready; null without one, or when it failed. */
  vtkDeepShadowTechnique* Technique = nullptr;
  vtkTextureObject* Transfer = nullptr; // the transfer table
  std::vector<vtkTextureObject*> ComponentTransfers; // components 1..'s tables (several components)

  // The mapper's properties and the pass's state for this frame, as the draw uses them.
  bool Jitter = false;
  int JitterSeed = 0;
  float TerminationOpacity = 1.0f;
  FramebufferCopy* Opaque = nullptr;          // opaque geometry's depth; null: none ends the rays
  const OtherVolumeShadows* Others = nullptr; // null: none cast, or no technique receives them
  const TranslucentLayers* Layers = nullptr;  // null: no translucent meshes
  VolumeSegments* Segments = nullptr;         // drawn into, not onto the screen (not with Layers)
  int SegmentGuest = 0;                       // this volume's slice of Segments
  const UserShaderCode* UserCode = nullptr;   // a vtkShaderProperty's code taken; null: none
  /**
   * A vtkVolume scaled differently along its axes, composited: its matrix's linear part undone
   * (world -> dataset), so that opacity is integrated per dataset unit as VTK's mapper does
   * (feature DatasetOpacity); empty otherwise.
   */
  std::optional<glm::dmat3> WorldToDataset;
  double DatasetScale = 1.0; // the matrix's mean scale, which the tables are corrected for
  /**
   * Shadows while interacting, looked up on a coarser grid (RayCast/SubsampledShadows.h):
   * which of its two passes this draw is, and the coarse texels the full pass reads.
   */
  enum class ShadowRatioPass
  {
    None,   // shadows per sample, as every still frame
    Coarse, // the shadowed rays of the coarse grid (feature ShadowRatio)
    Full    // every pixel without the technique, times the ratio (feature ShadowRatioApply)
  };
  ShadowRatioPass RatioPass = ShadowRatioPass::None;
  int RatioScale = 1;                    // view pixels per coarse ray, along each axis
  vtkTextureObject* RatioTexels = nullptr; // the coarse pass's targets, read by the full pass
  vtkTextureObject* RatioGuides = nullptr;
};

}
#endif
