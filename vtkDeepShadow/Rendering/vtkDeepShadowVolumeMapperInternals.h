// Internal: what vtkDeepShadowVolumeMapper holds on the GPU (each holder in Volume/, with its
// own update and release) and between frames. Shared by the mapper's two files: the frame
// (vtkDeepShadowVolumeMapper.cxx) and the holders' updates (vtkDeepShadowVolumeMapperHolders.cxx).
#ifndef vtkDeepShadowVolumeMapperInternals_h
#define vtkDeepShadowVolumeMapperInternals_h

#include "vtkDeepShadowVolumeMapper.h"

#include "Core/Geometry/SurfaceSet.h"
#include "GL/FramebufferCopy.h"
#include "Volume/BoxDrawer.h"
#include "Volume/CutRegion.h"
#include "Volume/DrawnScalars.h"
#include "Volume/OccupancyTexture.h"
#include "Volume/TransferTableTexture.h"
#include "Volume/TriangleHierarchy.h"
#include "RayCast/SubsampledShadows.h"
#include "RayCast/UserShaderCode.h"
#include "Volume/VolumeTexture.h"

#include "vtkPolyData.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkSmartPointer.h"
#include "vtkWeakPointer.h"

#include <array>
#include <memory>
#include <string>
#include <vector>

class vtkDeepShadowVolumeMapper::Internals
{
public:
  // The input's selected array as the point scalars drawn (cell scalars resampled).
  deepshadow::DrawnScalars Drawn;
  // The fragment code of the volume's vtkShaderProperty, read each frame.
  deepshadow::UserShaderCode UserCode;
  // The GPU resources, each with its own update and release (Volume/).
  deepshadow::VolumeTexture Volume;
  deepshadow::TransferTableTexture Transfer;
  deepshadow::TransferTableTexture GradientOpacity; // the function in alpha (GradientOpacity.h)
  deepshadow::VolumeTexture Mask;                   // a binary mask or a label map (Core/Mask.h)
  deepshadow::TransferTableTexture LabelTables;     // a label map's: a row per label
  deepshadow::TransferTableTexture Transfer2D;      // a 2D transfer function's image (Core/Transfer2D.h)
  // Components 1.. of a volume of several (Core/Components.h): a texture and a table each.
  std::array<deepshadow::VolumeTexture, 3> ComponentVolumes;
  std::array<deepshadow::TransferTableTexture, 3> ComponentTables;
  deepshadow::TransferTableTexture ComponentGradientOpacity; // independent ones': a row each
  int MaskUploads = 0;
  deepshadow::OccupancyTexture Occupancy;
  deepshadow::BoundHierarchy Bound;
  // What clipping planes and cropping keep, as bound leaves (in the data's coordinates).
  deepshadow::CutRegion Cut;
  deepshadow::SurfaceHierarchy SurfacesGPU;
  // Depth of the opaque geometry, copied from the framebuffer each frame that needs it.
  deepshadow::FramebufferCopy Opaque;
  deepshadow::BoxDrawer Box;
  // The coarse pass's target of shadows while interacting (InteractiveShadowSubsampling).
  deepshadow::ShadowRatioTarget Ratio;
  double EffectiveStep = 0.0; // world sample distance of the last frame

  // The polyhedral bounds as set (feature Bound).
  std::vector<vtkSmartPointer<vtkPolyData>> Bounds;
  // Surfaces that cast shadows onto the volume, in world space (uploaded by SurfacesGPU).
  std::shared_ptr<const deepshadow::SurfaceSet> Surfaces;

  std::string LastSource;       // the composed shader of the ray-cast pass
  std::string LastCoarseSource; // of the coarse pass of shadows while interacting

  // The window the GPU resources were made in (AdoptWindow), if it still exists.
  vtkWeakPointer<vtkOpenGLRenderWindow> Window;

  // vtkDeepShadowPass prepared this frame (PrepareShadows): Render() keeps the passes it ran.
  bool PreparedByPass = false;

  // The GPU resources and what was made from them; what was set (bounds, surfaces, the pass's
  // state, the composed source) stays.
  void Release(vtkWindow* window)
  {
    this->Volume.Release(window);
    this->Transfer.Release(window);
    this->GradientOpacity.Release(window);
    for (size_t c = 0; c < this->ComponentVolumes.size(); ++c)
    {
      this->ComponentVolumes[c].Release(window);
      this->ComponentTables[c].Release(window);
    }
    this->ComponentGradientOpacity.Release(window);
    this->Mask.Release(window);
    this->LabelTables.Release(window);
    this->Transfer2D.Release(window);
    this->Occupancy.Release(window);
    this->Bound.Release(window);
    this->SurfacesGPU.Release(window);
    this->Opaque.Release(window);
    this->Box.Release();
    this->Ratio.Release(window);
    this->EffectiveStep = 0.0;
    this->PreparedByPass = false;
  }
};

#endif
