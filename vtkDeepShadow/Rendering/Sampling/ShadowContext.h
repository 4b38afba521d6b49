// Internal: the GPU view of a volume: what vtkDeepShadowVolumeMapper's holders (Volume/) hold
// for one frame, as plain data, handed to the ray caster, the shadow techniques and the mesh
// receivers. The features that read it compose and bind themselves (SamplingFeatures.h).
#ifndef vtkDeepShadowShadowContext_h
#define vtkDeepShadowShadowContext_h

#include "Core/Light.h"
#include "Core/VolumeShading.h"
#include "Volume/TriangleHierarchy.h"
#include "Core/Camera.h"
#include "Core/Components.h"
#include "Core/Transfer2D.h"
#include "Core/EmptySpace.h"
#include "Core/GradientOpacity.h"
#include "Core/TransferFunction.h"
#include "Core/VolumeGrid.h"

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <string>
#include <optional>
#include <vector>

class vtkOpenGLRenderWindow;
class vtkTextureObject;

namespace deepshadow
{
class SurfaceSet;

struct ShadowContext
{
  vtkOpenGLRenderWindow* Window = nullptr;

  // The volume as the GPU holds it.
  vtkTextureObject* Volume = nullptr;
  vtkTextureObject* Occupancy = nullptr; // null when no block is empty
  const EmptySpaceMap* EmptyBlocks = nullptr; // the same on the CPU (with Occupancy)
  float BlockSize = 8.0f;
  glm::ivec3 Dims{ 0 };
  glm::dvec2 Range{ 0.0, 1.0 };     // finite scalar range
  glm::dvec2 ScalarMap{ 1.0, 0.0 }; // texel -> the shaders' scalar
  int GradientReach = 1;            // deepshadow::VolumeGrid::GetGradientReach
  /**
   * Data scalar -> the shaders' scalar: the identity, or for float data Range onto [0, 1]
   * (a float range may be denormal or span +-FLT_MAX, which float arithmetic cannot map to a
   * table; the maps are composed here, in double).
   */
  glm::dvec2 ShaderScalar{ 1.0, 0.0 };
  glm::dvec2 TableMap{ 1.0, 0.0 };  // data scalar -> table coordinate (any table of TableSize)

  /** The shaders' scalar -> table coordinate (u_tableMap). */
  glm::dvec2 ShaderTableMap() const;
  /** Range in the shaders' scalar (u_scalarRange). */
  glm::dvec2 ShaderRange() const;
  int TableSize = 4096;
  Interpolation Sampling = Interpolation::Linear;
  glm::dmat4 IndexToWorld{ 1.0 };
  glm::dmat4 WorldToIndex{ 1.0 };
  double ViewStep = 1.0;            // world step of the view rays this frame
  double OpacityUnitScale = 1.0;    // world length of a dataset unit (adapter::DatasetLengthScale)
  /**
   * World step the shadow structures are built for: ViewStep, except while the interactor
   * moves with AutoAdjustSampleDistances on, when the view rays step coarser and the shadows
   * stay as built (not rebuilt for the coarser step).
   */
  double ShadowStep = 1.0;
  /**
   * Interactive frames (vtkDeepShadowVolumeMapper::InteractiveShadowLag): a light that turned
   * less than this many degrees about the volume's centre since its structure was built keeps
   * that structure; 0 (still frames) rebuilds whenever a light moved.
   */
  double LightLagDegrees = 0.0;
  /**
   * Interactive frames with coarser shadows (vtkDeepShadowVolumeMapper::
   * InteractiveShadowSubsampling N > 1): a structure that must be rebuilt is built N times
   * coarser (a light-space technique's maps N times smaller a side, as the coarse rays are N
   * pixels apart) and stays so while these frames last; the first frame without this builds it
   * in full again. 1: full detail. It is the frame's subsampling, decided once
   * (deepshadow::ShadowSubsampling) and read again by the mapper's draw.
   */
  int RebuildCoarsening = 1;
  const BoundTextures* Bound = nullptr; // null: the volume fills its box
  const SurfaceTextures* Surfaces = nullptr; // null: only the volume casts shadows
  const SurfaceSet* CastingSurfaces = nullptr; // the same surfaces in world space (CPU side)

  // What shadow structures depend on, besides lights and technique parameters.
  int DataVersion = 0;            // increments with every volume upload
  int BoundVersion = 0;           // increments with every change of the bound
  int SurfacesVersion = 0;        // increments with every change of the casting surfaces
  TransferFunction Transfer;      // the volume's; a technique may cast with its own
  /**
   * Isosurface blending's contour values, sorted, in data scalars (Isosurface.h); empty
   * otherwise. The feature Isosurface is then part of every shader that reads the volume.
   */
  std::vector<double> IsoValues;
  /**
   * Gradient opacity (Features/GradientOpacity.glsl), drawn and cast: its table (the
   * function's values in alpha over [0, Gradient.MaxMagnitude]) and its parameters; null
   * when it changes nothing.
   */
  vtkTextureObject* GradientOpacityTable = nullptr;
  glm::dvec2 GradientOpacityMap{ 1.0, 0.0 }; // magnitude -> table coordinate
  GradientOpacity Gradient;
  /** A binary mask (Features/Mask.glsl; nearest filtering), drawn and cast; null: none. */
  vtkTextureObject* Mask = nullptr;
  glm::dvec2 MaskToData{ 1.0, 0.0 }; // texel -> the mask's data value
  int MaskVersion = 0;               // increments with every mask upload
  /**
   * With Mask: Mask is a label map (Features/LabelMap.glsl, Core/Mask.h), its labels' tables a
   * row each over the volume's range; null: a binary mask.
   */
  vtkTextureObject* LabelTable = nullptr;
  int LabelCount = 0;
  glm::dvec2 MaskToLabel{ 1.0, 0.0 }; // the mask's data value -> label (floored)
  double MaskBlendFactor = 1.0;
  std::vector<double> LabelKey;       // the tables' content, mapping and blend, to compare builds by
  /**
   * A 2D transfer function (Features/Transfer2D.glsl, Core/Transfer2D.h) replacing Transfer's
   * colour and opacity, drawn and cast; null: none.
   */
  vtkTextureObject* Transfer2DImage = nullptr;
  Transfer2D Transfer2DShape;         // its size, range and gradient axis (RGBA left empty)
  std::vector<double> Transfer2DKey;  // its content, to compare builds by
  /** The mask's feature: LabelMap or Mask ("" when there is no mask). */
  std::string MaskFeature() const { return !this->Mask ? "" : this->LabelTable ? "LabelMap" : "Mask"; }

  /**
   * A volume of several components (Core/Components.h, Features/Components.glsl), drawn and
   * cast: components 1.. as the GPU holds them (component 0 is Volume, with ScalarMap,
   * ShaderScalar, Range and Transfer), their mode and weights. Empty: one component.
   */
  struct Component
  {
    vtkTextureObject* Texture = nullptr;
    glm::dvec2 ScalarMap{ 1.0, 0.0 };    // texel -> the shaders' scalar
    glm::dvec2 ShaderScalar{ 1.0, 0.0 }; // data scalar -> the shaders' scalar
    glm::dvec2 Range{ 0.0, 1.0 };        // finite data range
    TransferFunction Transfer;           // its function (dependent: the volume's)
  };
  std::vector<Component> OtherComponents;
  ComponentMode Mode = ComponentMode::Independent;
  glm::dvec4 Weights{ 1.0 };
  glm::dvec4 TextureScale{ 1.0 }; // RGBA: texture value per data value (ComponentSet)
  bool ComponentsLitApart = false; // independent and shaded: each lit with its own gradient
  /**
   * Independent components' own gradient opacities (ComponentSet::Gradients), drawn and cast:
   * a row per component of its function over its magnitude as a fraction of its largest
   * (ComponentGradients[c]->MaxMagnitude); null when none has one.
   */
  vtkTextureObject* ComponentGradientTable = nullptr;
  glm::dvec2 ComponentGradientMap{ 1.0, 0.0 }; // fraction of the largest magnitude -> table coordinate
  std::vector<std::optional<GradientOpacity>> ComponentGradients;
  /** The table coordinate map (shaders' scalar -> coordinate) of component `c` (0: ShaderTableMap). */
  glm::dvec2 ComponentTableMap(int c) const;

  std::vector<Light> Lights;      // the lights the ray caster uses, in its order
  VolumeShading Shading;          // how they shade the volume's gradient (RayCastFrame::Shade)
  /** The centre of the camera's near plane (world): clustered maps weigh objects by it. */
  glm::dvec3 Eye{ 0.0 };
  /** The camera and viewport of the frame: resolution-matched maps build the pages its pixels need. */
  Camera View;

  /**
   * The content of Transfer (opacity, and colours if asked), IsoValues, the gradient opacity
   * and the mask's version, to compare builds by.
   */
  std::vector<double> TransferKey(bool colors) const;
};

}
#endif
