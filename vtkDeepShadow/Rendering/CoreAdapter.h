// Internal: VTK objects -> Core descriptions. The GPU mapper and the CPU reference both take
// volumes, transfer functions, lights and the camera from here, so they see the same scene.
#ifndef vtkDeepShadowCoreAdapter_h
#define vtkDeepShadowCoreAdapter_h

#include "Core/Bound/BoundRegion.h"
#include "Core/Camera.h"
#include "Core/Components.h"
#include "Core/GradientOpacity.h"
#include "Core/Isosurface.h"
#include "Core/Light.h"
#include "Core/Mask.h"
#include "Core/OpticalModel.h"
#include "Core/Projection.h"
#include "Core/Geometry/SurfaceSet.h"
#include "Core/Transfer2D.h"
#include "Core/TransferFunction.h"
#include "Core/VolumeGrid.h"
#include "Core/VolumeShading.h"

#include <glm/mat4x4.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

class vtkDataArray;
class vtkGPUVolumeRayCastMapper;
class vtkImageData;
class vtkMatrix4x4;
class vtkPolyData;
class vtkProperty;
class vtkRenderer;
class vtkVolume;
class vtkVolumeMapper;
class vtkVolumeProperty;

namespace deepshadow
{
namespace adapter
{

/** Lights beyond this many (per renderer) are ignored, with a warning, on GPU and CPU alike. */
constexpr int MaxLights = 8;
/** The largest 2D transfer function read, texels an axis (VTK's texture holds at most this). */
constexpr int MaxTransfer2DSize = 16384;

glm::dmat4 ToGlm(const vtkMatrix4x4* matrix);

/**
 * Checks that `image` can be volume rendered: point scalars, one component, a supported type
 * (any numeric type but bit; doubles within float's range), at least 2 points per axis,
 * positive finite spacing. Returns "" when it can, else one line saying why not. `scalars` is set on success.
 */
std::string CheckVolumeInput(vtkImageData* image, vtkDataArray*& scalars);

/**
 * Checks that a mesh can be drawn or used as a bound without reading out of bounds: every
 * point finite and within MaxMeshCoordinate of the origin, every cell's point ids within the
 * points. Returns "" when it can, else one line saying why not (no input, the number of
 * non-finite points, the largest coordinate, the first bad id).
 */
std::string CheckMeshInput(vtkPolyData* mesh);
/** Beyond this, squared distances overflow in single precision on the GPU (as for lights). */
constexpr double MaxMeshCoordinate = 1e18;

/**
 * Checks a checked mesh where `modelToWorld` (an actor's matrix) puts it: every corner of its
 * box finite and within MaxMeshCoordinate. "" when it is, else one line with the coordinate.
 */
std::string CheckMeshPlacement(vtkPolyData* mesh, const glm::dmat4& modelToWorld);


/**
 * Checks where a volume lies in the world for single-precision GPU rendering: `indexToWorld`
 * finite and invertible (a zero or NaN direction matrix is not), every world voxel edge
 * between MinVoxelEdge and MaxVoxelEdge, and the box no farther from the world origin than
 * MaxOffsetRatio times its size (float positions must still resolve a voxel there). Returns
 * "" when it is fine, else one line saying why not.
 */
std::string CheckVolumePlacement(const glm::dmat4& indexToWorld, const glm::ivec3& dims);
constexpr double MinVoxelEdge = 1e-15;
constexpr double MaxVoxelEdge = 1e15;
constexpr double MaxOffsetRatio = 1e5;

/**
 * Checks a volume property's component 0: scalar opacity unit distance positive and finite,
 * every node of the colour and opacity transfer functions finite. "" when it is fine.
 */
std::string CheckVolumeProperty(vtkVolumeProperty* property);

/**
 * Checks lights from MakeLights: finite positions and focal points, and positional lights
 * within MaxLightCoordinate of the origin (beyond, squared distances overflow in single
 * precision on the GPU). "" when they are fine, else one line naming the light.
 */
std::string CheckLights(const std::vector<Light>& lights);
constexpr double MaxLightCoordinate = 1e18;

/** Voxel index -> world: the image's index-to-physical matrix, then the prop's matrix. */
glm::dmat4 IndexToWorld(vtkImageData* image, const vtkMatrix4x4* propMatrix);

/**
 * Float copy of a checked image's scalars as a VolumeGrid. Non-finite samples are an error
 * (returns null, sets `error`) unless `replaceNonFinite`, which applies ReplaceNonFinite and
 * counts them in `replaced`; so is a finite value beyond float's range (a double).
 */
std::shared_ptr<VolumeGrid> MakeVolumeGrid(vtkImageData* image, const vtkMatrix4x4* propMatrix,
  bool replaceNonFinite, std::string& error, size_t* replaced = nullptr);

/**
 * Transfer function of a component (0 by default). Linear RGB nodes with default midpoint/sharpness are
 * copied exactly; other shapes (midpoints, sharpness, HSV/Lab interpolation) are sampled at
 * 4097 points, which makes them piecewise linear. The opacity unit distance is the
 * property's times `unitScale` (DatasetLengthScale: opacity per dataset unit, as VTK's).
 */
TransferFunction MakeTransferFunction(vtkVolumeProperty* property, double unitScale = 1.0, int component = 0);

/**
 * World length of a dataset unit under the prop's matrix, so that opacity is per dataset unit
 * as VTK's mapper integrates it: the scale of a uniformly scaled prop, the cube root of the
 * volume change otherwise (`anisotropic` says so: VTK's then depends on the direction).
 */
double DatasetLengthScale(const vtkMatrix4x4* propMatrix, bool* anisotropic = nullptr);
Material MakeMaterial(vtkVolumeProperty* property, int component = 0);
/**
 * How `property` classifies `count` (2 to 4) components (Core/Components.h): independent
 * (IndependentComponents on) with each component's functions, material and weight; else 2
 * (luminance, opacity) or 4 (RGBA) dependent ones sharing component 0's; `dataType` (the
 * scalars' VTK type) sets TextureScale. Fills all but the grids; returns "" or one line (3
 * dependent components).
 */
std::string MakeComponentSet(
  vtkVolumeProperty* property, int count, int dataType, double unitScale, ComponentSet& set);
/** A mesh's material from its actor's vtkProperty: colour, opacity (clamped to [0, 1]), Phong. */
SurfaceMaterial MakeSurfaceMaterial(vtkProperty* property);

/**
 * The mapper's blend mode as a projection over `dataRange` (the data's scalar range): its
 * mode (Composite for composite, for isosurface (MakeIsoValues) and for slice, which is
 * drawn composite) and AverageIPScalarRange.
 */
ProjectionSettings MakeProjection(vtkVolumeMapper* mapper, const glm::dvec2& dataRange);
/**
 * Under isosurface blending, the property's contour values, finite ones sorted, the lowest
 * MaxIsoValues of them; empty under any other blend mode. `given`: how many finite values
 * the property holds (more than MaxIsoValues are said unsupported).
 */
std::vector<double> MakeIsoValues(vtkVolumeMapper* mapper, vtkVolumeProperty* property, int* given = nullptr);
/**
 * The property's gradient opacity (of `component`) for data of scalar range `range` and
 * dataset spacing `spacing`, when the mapper composites (VTK's applies it there only) and it
 * changes anything (enabled, some node below 1); empty otherwise.
 */
std::optional<GradientOpacity> MakeGradientOpacity(vtkVolumeMapper* mapper, vtkVolumeProperty* property,
  const glm::dvec2& range, const glm::dvec3& spacing, int component = 0);
/**
 * Independent components' gradient opacities (Core/Components.h), each component's own over
 * its own range (`ranges`, component 0's first); empty when none has one, or the components
 * are dependent.
 */
std::vector<std::optional<GradientOpacity>> MakeComponentGradients(vtkVolumeMapper* mapper,
  vtkVolumeProperty* property, const std::vector<glm::dvec2>& ranges, const glm::dvec3& spacing);
/**
 * Dependent components' gradient opacity as VTK 9.1 applies it: component 0's gradient
 * (`firstRange` its range), through the function's table over a quarter of the opacity
 * component's range (`lastRange`), indexed by the magnitude over a quarter of component 0's.
 */
std::optional<GradientOpacity> MakeDependentGradientOpacity(vtkVolumeMapper* mapper, vtkVolumeProperty* property,
  const glm::dvec2& firstRange, const glm::dvec2& lastRange, const glm::dvec3& spacing);

/**
 * The mapper's mask input when it can be drawn: an image of `volume`'s dimensions, under
 * composite blending; null otherwise (UnsupportedSettings says why when one is set).
 */
vtkImageData* UsableMask(vtkGPUVolumeRayCastMapper* mapper, vtkImageData* volume);

/**
 * The property's 2D transfer function image when the mapper draws one (TF_2D, composite
 * blending, one component); null otherwise, with `error` set when the image cannot be read
 * (none, or not a 2D image of 4 float components, as VTK's mapper reads it).
 */
vtkImageData* UsableTransfer2D(
  vtkVolumeMapper* mapper, vtkVolumeProperty* property, int components, std::string& error);
/** A usable 2D transfer function for data of `range` and `spacing`; its texels only if asked. */
Transfer2D MakeTransfer2D(vtkImageData* image, const glm::dvec2& range, const glm::dvec3& spacing, bool texels);

/**
 * A label-map mask's labels (Core/Mask.h) when the mapper's mask type is a label map and
 * anything changes: labels with functions and a mask blend factor above 0; null otherwise
 * (VTK then draws the volume as if unmasked). `maskRange`: the mask's finite range, which
 * VTK 9.1 maps onto the labels; VTK 9.2 onwards maps [0, number of labels] instead.
 */
std::shared_ptr<const LabelMap> MakeLabelMap(
  vtkGPUVolumeRayCastMapper* mapper, vtkVolumeProperty* property, const glm::dvec2& maskRange);

/**
 * The polyhedral bound of a volume in voxel-index space: each vtkPolyData's polygons and
 * strips as triangles (points moved by `dataToIndex`), checked (CheckClosedMesh), oriented
 * outward, combined by `expression` (CSGExpression; "" is the union). An empty bound is an
 * empty solid, not an error. Returns null with `error` naming the bound ("bound B ...") on
 * bad input.
 */

std::shared_ptr<const BoundRegion> MakeBoundRegion(const std::vector<vtkPolyData*>& bounds,
  const std::string& expression, const glm::dmat4& dataToIndex, std::string& error);

/**
 * Switched-on lights of the renderer in world space (at most MaxLights). A directional
 * light's position is moved to one unit from its focal point along its direction,
 * normalised in double without overflow, so that downstream code never squares 1e308.
 */
std::vector<Light> MakeLights(vtkRenderer* renderer, bool* truncated = nullptr);

/**
 * What a lone headlight becomes in a shadowed scene: a key light above and to the side of the
 * camera, as a light kit's key light (the headlight casts its shadows straight behind what it
 * lights, where the camera cannot see them), and a fill from the eye that casts none, keeping
 * the key's shadowed side readable. Together brighter than the headlight, as a light kit is:
 * the key reaches a surface facing the camera at an angle, and through the volume's own
 * outer layers (a dense medium lit along the view loses half its light to them).
 */
struct KeyLight
{
  double Elevation = 45.0;    // degrees above the view direction
  double Azimuth = 45.0;      // degrees to the right: its shadows fall beside what casts them
  double KeyIntensity = 1.0;  // of the headlight's
  double FillIntensity = 0.5; // of the headlight's
};

/**
 * `lights` (MakeLights) with a lone headlight replaced as KeyLight says, seen from the
 * renderer's camera (`replaced` set); the same lights otherwise.
 */
std::vector<Light> KeyForLoneHeadlight(vtkRenderer* renderer, std::vector<Light> lights,
  const KeyLight& key = KeyLight(), bool* replaced = nullptr);

/**
 * The lighting path of the VTK this module was built with for the renderer's lights, as
 * vtkOpenGLGPUVolumeRayCastMapper picks it (every light of the collection is looked at, on or
 * off): VTKHeadlight for one light on that is a headlight of intensity 1, VTKPositional when a
 * light is positional (VTK 9.1: on or off; 9.2 onwards: on), VTKDirectional otherwise;
 * BlinnPhong when no light is on.
 */
ShadingPath VTKLightingPath(vtkRenderer* renderer);

/**
 * The path a mapper that had `previous` takes now: VTK 9.1 raises its "lighting complexity"
 * while it shades and never lowers it; VTK 9.2 onwards picks its path again whenever the
 * lights change.
 */
ShadingPath NextVTKLightingPath(ShadingPath previous, vtkRenderer* renderer);

/** The lighting of the VTK this module was built with: VTK 9.2 rewrote it. */
VTKShadingRevision BuiltVTKShadingRevision();

/**
 * How `volume`'s shaded samples are lit (Core/VolumeShading.h) under `model`, VTK's on `path`
 * (VTKLightingPath, or the path a mapper reached): `drawn` is the image the ray caster
 * samples, `indexToWorld` its placement, `input` the mapper's input (the box VTK's texture
 * spans), `keyLit` whether KeyForLoneHeadlight replaced the lights. Under VTK's model,
 * `lights` are shaded from the eye exactly when VTK's headlight path is taken.
 */
VolumeShading MakeVolumeShading(vtkRenderer* renderer, vtkVolume* volume, vtkImageData* drawn,
  vtkImageData* input, const glm::dmat4& indexToWorld, ShadingModel model, ShadingPath path, bool keyLit,
  std::vector<Light>& lights);

/** {v[0], v[1], v[2]}. */
glm::dvec3 ToGlm3(const double v[3]);

/** The renderer's active camera over its (tiled) viewport. */
Camera MakeCamera(vtkRenderer* renderer);

}
}
#endif
