// Volumes of two to four components per voxel, classified as VTK's GPU mapper classifies them
// (vtkVolumeProperty::IndependentComponents):
//   - Independent: each component has its own transfer function, material and weight; each
//     gives a colour c_i and an opacity a_i, and a sample is colour sum(w_i a_i c_i) / alpha,
//     alpha = sum(a_i^2) / sum(w_i a_i) (components of weight 0 add nothing): VTK's shader.
//     Shaded, each component is lit with its own gradient and material. With gradient
//     opacity (vtkVolumeProperty::SetGradientOpacity(i, f)), each component's opacity is
//     multiplied by its own function at its own gradient magnitude before they combine, as
//     the property documents it. VTK 9.1's shader (unchanged through 9.3) instead multiplies
//     each component's opacity by every component's function and weight, all at that
//     component's gradient (so identical functions act N times), and only when component 0
//     has one: not copied, said once by the mapper.
//   - LuminanceAlpha (2 dependent components): colour from component 0 through the colour
//     function, opacity from component 1 through the opacity function.
//   - RGBA (4 dependent components): VTK's shader reads these as its texture holds them, not
//     normalized: colour = each of components 0-2's texture value (the value over the type's
//     largest for 8- and 16-bit integers, the value itself for the others: TextureScale),
//     opacity = the opacity function at component 3's texture value taken as a fraction of
//     its range (its table spans the range, its coordinate is that texture value).
// Component 0 is the volume's own grid; a table or function per component spans that
// component's range (dependent components share the volume's function).
#ifndef deepshadow_Components_h
#define deepshadow_Components_h

#include "Core/GradientOpacity.h"
#include "Core/OpticalModel.h"
#include "Core/TransferFunction.h"
#include "Core/VolumeGrid.h"
#include "vtkDeepShadowCoreModule.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <memory>
#include <optional>
#include <vector>

namespace deepshadow
{

enum class ComponentMode : int
{
  Independent = 0,
  LuminanceAlpha = 1,
  RGBA = 2
};

constexpr int MaxComponents = 4;

/** Each component's colour (rgb) and opacity (a) at a sample, for a step (corrected opacity). */
using ComponentColors = std::array<glm::dvec4, MaxComponents>;

struct VTKDEEPSHADOWCORE_EXPORT ComponentSet
{
  ComponentMode Mode = ComponentMode::Independent;
  /** Components 1..N-1 (component 0 is the volume's grid), on the same geometry. */
  std::vector<std::shared_ptr<const VolumeGrid>> Others;
  /** Per component: its transfer function (dependent: the volume's, for each component). */
  std::vector<TransferFunction> Transfers;
  /** Per component: its material (independent components are lit apart). */
  std::vector<Material> Materials;
  glm::dvec4 Weights{ 1.0 };
  /**
   * Independent: per component, its gradient opacity over its own range (none: empty, or a
   * component without one). Dependent components take the volume's (VolumeInstance::Gradient).
   */
  std::vector<std::optional<GradientOpacity>> Gradients;
  /** RGBA: a component's texture value per data value (1 / 255 for unsigned char, ...). */
  glm::dvec4 TextureScale{ 1.0 };

  int Count() const { return 1 + static_cast<int>(this->Others.size()); }
  const VolumeGrid& Grid(const VolumeGrid& first, int component) const
  {
    return component == 0 ? first : *this->Others[static_cast<size_t>(component - 1)];
  }
  /** The components' values at a continuous index (unused components 0). */
  glm::dvec4 Sample(const VolumeGrid& first, const glm::dvec3& index, Interpolation interpolation) const;
  /** Whether any component has its own gradient opacity. */
  bool HasGradients() const;
  /** Each component's gradient-opacity factor at a continuous index (1: it has none). */
  glm::dvec4 GradientFactors(const VolumeGrid& first, const glm::dvec3& index, Interpolation interpolation) const;
  /** Each visible component's opacity in `colors` times its factor at a continuous index. */
  void ApplyGradients(
    ComponentColors& colors, const VolumeGrid& first, const glm::dvec3& index, Interpolation interpolation) const;
  /** Whether each component is lit apart (independent and shaded). */
  bool LitApart(bool shade) const { return shade && this->Mode == ComponentMode::Independent; }
};

/**
 * The sample's colour and opacity (rgb, a; rgb not premultiplied) as VTK's shader combines
 * them, from each component's table (or function) lookup, `colors[i]` (its colour already
 * lit when the components are lit apart), and the values themselves (RGBA's colour).
 */
VTKDEEPSHADOWCORE_EXPORT glm::dvec4 CombineComponents(
  const ComponentSet& set, const ComponentColors& colors, const glm::dvec4& values);

/** RGBA: the value component 3's opacity is looked up at (see above), for its range. */
inline double RGBAOpacityValue(const ComponentSet& set, double value, const glm::dvec2& range)
{
  return range.x + value * set.TextureScale[3] * (range.y - range.x);
}

/**
 * Each component's colour and opacity at its value, opacity corrected for a step: through a
 * table per component of `tableSize` texels sampled for `tableStep` (the GPU twin), or the
 * functions themselves (tableSize 0) for the step asked. The first component uses `first`
 * (the volume's drawn or casting function), the others the set's. `uncorrected`: each
 * opacity as its function gives it, whatever the step (the projections but additive).
 */
class VTKDEEPSHADOWCORE_EXPORT ComponentLookup
{
public:
  ComponentLookup(const ComponentSet& set, const VolumeGrid& grid, const TransferFunction& first,
    double tableStep, int tableSize, bool uncorrected = false);

  /** `step`: the exact functions' (tables keep theirs). */
  ComponentColors Colors(const glm::dvec4& values, double step) const;
  /**
   * The sample's colour and opacity, unlit (CombineComponents of Colors), each component's
   * opacity times its factor in `gradientFactors` (ComponentSet::GradientFactors).
   */
  glm::dvec4 Combined(const glm::dvec4& values, double step, const glm::dvec4& gradientFactors = glm::dvec4(1.0)) const
  {
    ComponentColors colors = this->Colors(values, step);
    for (size_t i = 0; i < colors.size(); ++i)
    {
      colors[i].a *= gradientFactors[static_cast<glm::length_t>(i)];
    }
    return CombineComponents(this->Set, colors, values);
  }
  const ComponentSet& GetSet() const { return this->Set; }
  /** Component `c`'s finite data range (its table spans it). */
  const glm::dvec2& GetRange(int c) const { return this->Ranges[static_cast<size_t>(c)]; }

private:
  const ComponentSet& Set;
  std::vector<const TransferFunction*> Functions;
  std::vector<TransferTable> Tables; // empty: exact
  std::array<glm::dvec2, MaxComponents> Ranges{};
  bool Uncorrected = false;
};

}
#endif
