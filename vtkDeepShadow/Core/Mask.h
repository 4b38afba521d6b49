// Masks (vtkGPUVolumeRayCastMapper::SetMaskInput) as VTK 9.1's mapper reads them; the CPU twins
// of Rendering/Shaders/Features/Mask.glsl and LabelMap.glsl.
//   - Binary: a sample is clear where the mask's nearest voxel is 0 or less, whatever the
//     volume's interpolation (measured against VTK's: a mask over voxels 10-21 shows
//     [9.5, 21.5)). Shadows are cast by what the mask keeps (ShadowCaster::Mask).
//   - Label map: the mask's nearest voxel picks a label, and a labelled sample takes its
//     label's colour and opacity (vtkVolumeProperty::SetLabelColor/SetLabelScalarOpacity; the
//     volume's functions where the label has none) at the volume's scalar; label 0 keeps the
//     volume's own. As VTK 9.1: the label is floor(N (m - min) / (max - min)) for mask value
//     m over the mask's range, N the largest label with a function (so labels are the mask's
//     values when its range is [0, N]); a label's opacity is its function's, not corrected
//     for the step (the volume's is); MaskBlendFactor f < 1 mixes (1 - f) the volume's colour
//     and opacity (none where clear) with f the label's, each lit apart: where the label's
//     opacity is 0 its colour is mixed in unlit (VTK lights it only where it is seen), so
//     that part is kept apart (LabelledSample::Unlit). Shadows are cast by what is drawn: a
//     light ray's step of s view steps sees a label's opacity a as 1 - (1 - a)^s.
#ifndef deepshadow_Mask_h
#define deepshadow_Mask_h

#include "Core/TransferFunction.h"
#include "Core/VolumeGrid.h"
#include "vtkDeepShadowCoreModule.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <vector>

namespace deepshadow
{

/** 1 where `mask` (null: none) keeps the sample at continuous voxel index `index`, else 0. */
inline double MaskFactor(const VolumeGrid* mask, const glm::dvec3& index)
{
  return !mask || mask->Sample(index, Interpolation::Nearest) > 0.0 ? 1.0 : 0.0;
}

/** A labelled sample: the colour (not premultiplied) and opacity the lights shade, and what
 * is added to the shaded colour unlit. */
struct LabelledSample
{
  glm::dvec4 Lit;
  glm::dvec3 Unlit{ 0.0 };
  /** Lit and unlit together (what light rays see). */
  glm::dvec4 Whole() const { return glm::dvec4(glm::dvec3(this->Lit) + this->Unlit, this->Lit.a); }
};

struct VTKDEEPSHADOWCORE_EXPORT LabelMap
{
  /** Label k's function at [k - 1] (k = 1..N): its colour and opacity (opacity uncorrected). */
  std::vector<TransferFunction> Functions;
  glm::dvec2 MaskRange{ 0.0, 1.0 }; // the mask's finite range
  double BlendFactor = 1.0;         // vtkGPUVolumeRayCastMapper::MaskBlendFactor, in [0, 1]

  int Count() const { return static_cast<int>(this->Functions.size()); }
  /** The label a mask value picks (0: the volume's own colour and opacity). */
  int LabelOf(double maskValue) const;
  /** (scale, offset): mask value -> N (value - min) / (max - min), plus a margin that keeps
   * exact labels from rounding down (the GPU's u_maskToLabel). */
  glm::dvec2 LabelMapping() const;
  /**
   * The sample's colour and opacity (not premultiplied): `volume` (the volume's own, its
   * opacity corrected for the step) where `label` is 0, else the label's at `scalar`, from
   * `tables` (GPU twin: label k's at [k - 1]) or the functions, its opacity a taken as
   * 1 - (1 - a)^stepRatio, mixed with the volume's by BlendFactor.
   */
  LabelledSample Apply(const glm::dvec4& volume, double scalar, int label, double stepRatio,
    const std::vector<TransferTable>* tables) const;
};

}
#endif
