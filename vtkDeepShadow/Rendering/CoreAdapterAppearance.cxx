// VTK's description of how a volume looks (vtkVolumeProperty, the mapper's blend mode) ->
// Core: transfer functions, materials, gradient opacity, contour values, components. The
// rest of the adapter (inputs, placement, bounds, lights, camera) is in CoreAdapter.cxx.
#include "CoreAdapter.h"

#include "vtkColorTransferFunction.h"
#include "vtkContourValues.h"
#include "vtkDataArray.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkPiecewiseFunction.h"
#include "vtkVersionMacros.h"
#include "vtkVolumeMapper.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <type_traits>

namespace deepshadow
{
namespace adapter
{
namespace
{
// Functions with midpoints, sharpness or HSV/Lab colour are sampled this densely.
constexpr int DenseSamples = 4097;

// The i-th of DenseSamples points evenly from x0 to x1; without forming x1 - x0 where that
// overflows (nodes at -+1.7e308).
double Spaced(double x0, double x1, int i)
{
  if (std::isfinite(x1 - x0))
  {
    return x0 + (x1 - x0) * i / (DenseSamples - 1.0);
  }
  const double t = i / (DenseSamples - 1.0);
  return x0 * (1.0 - t) + x1 * t;
}

PiecewiseLinear FromVTK(vtkPiecewiseFunction* function)
{
  const int size = function ? function->GetSize() : 0;
  if (size == 0)
  {
    return PiecewiseLinear({ { 0.0, 0.0 } });
  }
  bool linear = true;
  std::vector<std::pair<double, double>> nodes;
  for (int i = 0; i < size; ++i)
  {
    double node[4];
    function->GetNodeValue(i, node);
    nodes.emplace_back(node[0], node[1]);
    linear = linear && node[2] == 0.5 && node[3] == 0.0;
  }
  if (!linear && size > 1)
  {
    const double x0 = nodes.front().first, x1 = nodes.back().first;
    std::vector<double> table(DenseSamples);
    function->GetTable(x0, x1, DenseSamples, table.data());
    nodes.clear();
    for (int i = 0; i < DenseSamples; ++i)
    {
      nodes.emplace_back(Spaced(x0, x1, i), table[i]);
    }
  }
  return PiecewiseLinear(std::move(nodes), function->GetClamping() != 0);
}

void FromVTK(vtkColorTransferFunction* function, TransferFunction& tf)
{
  std::vector<std::pair<double, double>> r, g, b;
  const int size = function ? function->GetSize() : 0;
  bool linear = function && function->GetColorSpace() == VTK_CTF_RGB;
  for (int i = 0; i < size; ++i)
  {
    double node[6];
    function->GetNodeValue(i, node);
    r.emplace_back(node[0], node[1]);
    g.emplace_back(node[0], node[2]);
    b.emplace_back(node[0], node[3]);
    linear = linear && node[4] == 0.5 && node[5] == 0.0;
  }
  if (size == 0)
  {
    // VTK's default: a grey ramp is not assumed; an absent colour function is white.
    r = g = b = { { 0.0, 1.0 } };
  }
  else if (!linear && size > 1)
  {
    r.clear(), g.clear(), b.clear();
    const double x0 = function->GetRange()[0], x1 = function->GetRange()[1];
    for (int i = 0; i < DenseSamples; ++i)
    {
      const double x = Spaced(x0, x1, i);
      double rgb[3];
      function->GetColor(x, rgb);
      r.emplace_back(x, rgb[0]);
      g.emplace_back(x, rgb[1]);
      b.emplace_back(x, rgb[2]);
    }
  }
  const bool clamp = !function || function->GetClamping() != 0;
  tf.Red = PiecewiseLinear(std::move(r), clamp);
  tf.Green = PiecewiseLinear(std::move(g), clamp);
  tf.Blue = PiecewiseLinear(std::move(b), clamp);
}
}

std::string CheckVolumeProperty(vtkVolumeProperty* property)
{
  const double unit = property->GetScalarOpacityUnitDistance(0);
  if (!(unit > 0.0) || !std::isfinite(unit))
  {
    std::ostringstream why;
    why << "the volume property's scalar opacity unit distance is " << unit
        << "; it must be positive and finite";
    return why.str();
  }
  // The first point of a piecewise or colour function (Values numbers a point) that is not
  // finite, or -1.
  auto firstNonFinite = [](auto* function, auto values) {
    double node[decltype(values)::value];
    for (int i = 0; function && i < function->GetSize(); ++i)
    {
      function->GetNodeValue(i, node);
      if (!std::all_of(node, node + decltype(values)::value, [](double v) { return std::isfinite(v); }))
      {
        return i;
      }
    }
    return -1;
  };
  using PiecewisePoint = std::integral_constant<int, 4>;
  using ColorPoint = std::integral_constant<int, 6>;
  const bool gray = property->GetColorChannels(0) == 1;
  const int opacityBad = firstNonFinite(property->GetScalarOpacity(0), PiecewisePoint());
  const int colorBad = gray ? firstNonFinite(property->GetGrayTransferFunction(0), PiecewisePoint())
                            : firstNonFinite(property->GetRGBTransferFunction(0), ColorPoint());
  if (opacityBad >= 0)
  {
    return "the scalar opacity function's point " + std::to_string(opacityBad) + " is not finite";
  }
  if (colorBad >= 0)
  {
    return std::string(gray ? "the grey" : "the colour") + " transfer function's point " +
      std::to_string(colorBad) + " is not finite";
  }
  return std::string();
}

ProjectionSettings MakeProjection(vtkVolumeMapper* mapper, const glm::dvec2& dataRange)
{
  ProjectionSettings projection;
  switch (mapper->GetBlendMode())
  {
    case vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND:
      projection.Mode = BlendMode::Maximum;
      break;
    case vtkVolumeMapper::MINIMUM_INTENSITY_BLEND:
      projection.Mode = BlendMode::Minimum;
      break;
    case vtkVolumeMapper::AVERAGE_INTENSITY_BLEND:
      projection.Mode = BlendMode::Average;
      break;
    case vtkVolumeMapper::ADDITIVE_BLEND:
      projection.Mode = BlendMode::Additive;
      break;
    default: // composite; isosurface and slice are said unsupported and drawn composite
      break;
  }
  projection.RangeMin = dataRange.x;
  projection.RangeMax = dataRange.y;
  projection.AverageMin = mapper->GetAverageIPScalarRange()[0];
  projection.AverageMax = mapper->GetAverageIPScalarRange()[1];
  return projection;
}

std::optional<GradientOpacity> MakeGradientOpacity(vtkVolumeMapper* mapper, vtkVolumeProperty* property,
  const glm::dvec2& range, const glm::dvec3& spacing, int component)
{
  // HasGradientOpacity first: GetStoredGradientOpacity would create a default function in
  // the user's property, and VTK's mapper, drawing the same property later, would then take
  // gradient opacity as set (it changes its multi-component pictures).
  if (mapper->GetBlendMode() != vtkVolumeMapper::COMPOSITE_BLEND || !property ||
    property->GetTransferFunctionMode() != vtkVolumeProperty::TF_1D || !property->HasGradientOpacity(component) ||
    property->GetDisableGradientOpacity(component))
  {
    return std::nullopt;
  }
  vtkPiecewiseFunction* function = property->GetStoredGradientOpacity(component);
  bool changes = false;
  for (int i = 0; function && i < function->GetSize(); ++i)
  {
    double node[4];
    function->GetNodeValue(i, node);
    changes = changes || node[1] != 1.0;
  }
  if (!changes)
  {
    return std::nullopt;
  }
  return GradientOpacity::For(FromVTK(function), range, spacing);
}

std::vector<std::optional<GradientOpacity>> MakeComponentGradients(vtkVolumeMapper* mapper,
  vtkVolumeProperty* property, const std::vector<glm::dvec2>& ranges, const glm::dvec3& spacing)
{
  std::vector<std::optional<GradientOpacity>> gradients;
  if (!property || !property->GetIndependentComponents())
  {
    return gradients;
  }
  bool any = false;
  for (size_t c = 0; c < ranges.size(); ++c)
  {
    gradients.push_back(MakeGradientOpacity(mapper, property, ranges[c], spacing, static_cast<int>(c)));
    any = any || gradients.back().has_value();
  }
  if (!any)
  {
    gradients.clear();
  }
  return gradients;
}

std::optional<GradientOpacity> MakeDependentGradientOpacity(vtkVolumeMapper* mapper, vtkVolumeProperty* property,
  const glm::dvec2& firstRange, const glm::dvec2& lastRange, const glm::dvec3& spacing)
{
  std::optional<GradientOpacity> gradient = MakeGradientOpacity(mapper, property, lastRange, spacing);
  if (gradient)
  {
    // min(|g0|, r0 / 4) r_last / r0 = min(|g0| r_last / r0, r_last / 4): the table's magnitude.
    const double first = firstRange.y > firstRange.x ? firstRange.y - firstRange.x : 1.0;
    const double last = lastRange.y > lastRange.x ? lastRange.y - lastRange.x : 1.0;
    gradient->IndexScale *= last / first;
  }
  return gradient;
}

std::vector<double> MakeIsoValues(vtkVolumeMapper* mapper, vtkVolumeProperty* property, int* given)
{
  std::vector<double> values;
  if (mapper->GetBlendMode() == vtkVolumeMapper::ISOSURFACE_BLEND && property)
  {
    vtkContourValues* contours = property->GetIsoSurfaceValues();
    for (int i = 0; i < contours->GetNumberOfContours(); ++i)
    {
      const double value = contours->GetValue(i);
      if (std::isfinite(value))
      {
        values.push_back(value);
      }
    }
    std::sort(values.begin(), values.end());
  }
  if (given)
  {
    *given = static_cast<int>(values.size());
  }
  if (values.size() > static_cast<size_t>(MaxIsoValues))
  {
    values.resize(static_cast<size_t>(MaxIsoValues));
  }
  return values;
}

TransferFunction MakeTransferFunction(vtkVolumeProperty* property, double unitScale, int component)
{
  TransferFunction tf;
  tf.Opacity = FromVTK(property->GetScalarOpacity(component));
  if (property->GetColorChannels(component) == 1)
  {
    tf.Red = tf.Green = tf.Blue = FromVTK(property->GetGrayTransferFunction(component));
  }
  else
  {
    FromVTK(property->GetRGBTransferFunction(component), tf);
  }
  tf.OpacityUnitDistance = property->GetScalarOpacityUnitDistance(component) * unitScale;
  return tf;
}

vtkImageData* UsableTransfer2D(
  vtkVolumeMapper* mapper, vtkVolumeProperty* property, int components, std::string& error)
{
  if (!property || property->GetTransferFunctionMode() != vtkVolumeProperty::TF_2D ||
    mapper->GetBlendMode() != vtkVolumeMapper::COMPOSITE_BLEND || components != 1)
  {
    return nullptr; // UnsupportedSettings says what is drawn instead
  }
  vtkImageData* image = property->GetTransferFunction2D();
  vtkDataArray* texels = image ? image->GetPointData()->GetScalars() : nullptr;
  int dims[3] = { 0, 0, 0 };
  if (image)
  {
    image->GetDimensions(dims);
  }
  std::ostringstream problem;
  if (!image)
  {
    problem << "the transfer function mode is TF_2D but the property has no 2D transfer function "
               "(vtkVolumeProperty::SetTransferFunction2D)";
  }
  else if (!texels || texels->GetDataType() != VTK_FLOAT || texels->GetNumberOfComponents() != 4 || dims[2] != 1 ||
    dims[0] < 1 || dims[1] < 1)
  {
    problem << "the 2D transfer function is a " << dims[0] << "x" << dims[1] << "x" << dims[2] << " image of "
            << (texels ? texels->GetDataTypeAsString() : "no scalars") << " with "
            << (texels ? texels->GetNumberOfComponents() : 0)
            << " components; VTK's mapper reads a W x H x 1 image of 4 float components (RGBA)";
  }
  else if (dims[0] > MaxTransfer2DSize || dims[1] > MaxTransfer2DSize)
  {
    problem << "the 2D transfer function is " << dims[0] << "x" << dims[1] << " texels; at most " << MaxTransfer2DSize
            << " an axis are read";
  }
  error = problem.str();
  return error.empty() ? image : nullptr;
}

Transfer2D MakeTransfer2D(vtkImageData* image, const glm::dvec2& range, const glm::dvec3& spacing, bool texels)
{
  Transfer2D function;
  int dims[3];
  image->GetDimensions(dims);
  function.Width = dims[0];
  function.Height = dims[1];
  function.Range = range;
  function.Gradient = GradientOpacity::For(PiecewiseLinear({ { 0.0, 1.0 } }), range, spacing);
  if (texels)
  {
    const auto* values = static_cast<const float*>(image->GetPointData()->GetScalars()->GetVoidPointer(0));
    function.RGBA.assign(values, values + 4 * static_cast<size_t>(dims[0]) * static_cast<size_t>(dims[1]));
  }
  return function;
}

std::shared_ptr<const LabelMap> MakeLabelMap(
  vtkGPUVolumeRayCastMapper* mapper, vtkVolumeProperty* property, const glm::dvec2& maskRange)
{
  if (!property || mapper->GetMaskType() != vtkGPUVolumeRayCastMapper::LabelMapMaskType ||
    !(mapper->GetMaskBlendFactor() > 0.0f))
  {
    return nullptr;
  }
  const std::set<int> labels = property->GetLabelMapLabels();
  if (labels.empty() || *labels.rbegin() < 1)
  {
    return nullptr;
  }
  auto map = std::make_shared<LabelMap>();
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 2, 0)
  // VTK 9.2 onwards spans [0, the number of labels with functions], whatever the mask holds.
  (void)maskRange;
  map->MaskRange = glm::dvec2(0.0, static_cast<double>(labels.size()));
#else
  map->MaskRange = maskRange;
#endif
  map->BlendFactor = mapper->GetMaskBlendFactor();
  const TransferFunction volume = MakeTransferFunction(property);
  for (int label = 1; label <= *labels.rbegin(); ++label)
  {
    // The label's own functions, else the volume's; opacity as given (a unit step's).
    TransferFunction function = volume;
    if (vtkColorTransferFunction* color = property->GetLabelColor(label))
    {
      FromVTK(color, function);
    }
    if (vtkPiecewiseFunction* opacity = property->GetLabelScalarOpacity(label))
    {
      function.Opacity = FromVTK(opacity);
    }
    function.OpacityUnitDistance = 1.0;
    map->Functions.push_back(std::move(function));
  }
  return map;
}

Material MakeMaterial(vtkVolumeProperty* property, int component)
{
  Material material;
  material.Ambient = property->GetAmbient(component);
  material.Diffuse = property->GetDiffuse(component);
  material.Specular = property->GetSpecular(component);
  material.SpecularPower = property->GetSpecularPower(component);
  return material;
}

std::string MakeComponentSet(
  vtkVolumeProperty* property, int count, int dataType, double unitScale, ComponentSet& set)
{
  const bool independent = property->GetIndependentComponents() != 0;
  if (!independent && count != 2 && count != 4)
  {
    return std::to_string(count) + " dependent components are not drawn (VTK's mapper draws 2, luminance and "
                                    "opacity, or 4, RGBA); set IndependentComponents on";
  }
  set.Mode = independent ? ComponentMode::Independent
    : count == 2         ? ComponentMode::LuminanceAlpha
                         : ComponentMode::RGBA;
  set.Transfers.clear();
  set.Materials.clear();
  for (int i = 0; i < count; ++i)
  {
    // Dependent components share component 0's functions and material, over their own range.
    const int source = independent ? i : 0;
    set.Transfers.push_back(MakeTransferFunction(property, unitScale, source));
    set.Materials.push_back(MakeMaterial(property, source));
    set.Weights[i] = independent ? property->GetComponentWeight(i) : 1.0;
    // What VTK's texture holds: 8- and 16-bit integers normalized by the type's largest.
    switch (dataType)
    {
      case VTK_UNSIGNED_CHAR:
        set.TextureScale[i] = 1.0 / VTK_UNSIGNED_CHAR_MAX;
        break;
      case VTK_CHAR:
      case VTK_SIGNED_CHAR:
        set.TextureScale[i] = 1.0 / VTK_SIGNED_CHAR_MAX;
        break;
      case VTK_UNSIGNED_SHORT:
        set.TextureScale[i] = 1.0 / VTK_UNSIGNED_SHORT_MAX;
        break;
      case VTK_SHORT:
        set.TextureScale[i] = 1.0 / VTK_SHORT_MAX;
        break;
      default:
        set.TextureScale[i] = 1.0;
    }
  }
  return std::string();
}

}
}
