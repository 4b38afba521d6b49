// vtkDeepShadowVolumeMapper's GPU holders brought up to date for a frame: the volume, the
// transfer and gradient-opacity tables, the mask, the empty-space blocks, the bound and the
// casting surfaces, each rebuilt only when what it depends on changed (the counters and
// GetLastPasses() show it). The frame itself is in vtkDeepShadowVolumeMapper.cxx.
#include "vtkDeepShadowVolumeMapper.h"
#include "vtkDeepShadowVolumeMapperInternals.h"

#include "CoreAdapter.h"
#include "RayCast/RayCastFrame.h"

#include "vtkColorTransferFunction.h"
#include "vtkImageData.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkTextureObject.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

#include <cstdint>

namespace adapter = deepshadow::adapter;

bool vtkDeepShadowVolumeMapper::UpdateVolume(vtkOpenGLRenderWindow* window, vtkImageData* input)
{
  Internals& impl = *this->Impl;
  if (impl.Volume.NeedsUpdate(input, this->ReplaceNonFiniteScalars))
  {
    // Everything on the GPU was made from the old data: rebuilt below as needed.
    impl.Release(window);
    std::string warning;
    if (impl.Volume.Update(window, input, this->ReplaceNonFiniteScalars, warning))
    {
      if (!warning.empty())
      {
        vtkWarningMacro(<< warning);
      }
      ++this->VolumeUploads;
      this->LastPasses.emplace_back("volume-upload");
    }
  }
  if (!impl.Volume.GetError().empty())
  {
    this->ReportError(impl.Volume.GetError());
    return false;
  }
  return true;
}

void vtkDeepShadowVolumeMapper::UpdateTables(
  vtkOpenGLRenderWindow* window, vtkVolumeProperty* property, double step, double unitScale)
{
  Internals& impl = *this->Impl;
  // What the table and the block map depend on: the functions themselves, not the property.
  vtkObject* colorFunction = property->GetColorChannels(0) == 1
    ? static_cast<vtkObject*>(property->GetGrayTransferFunction(0))
    : static_cast<vtkObject*>(property->GetRGBTransferFunction(0));
  const vtkMTimeType opacityTime = property->GetScalarOpacity(0)->GetMTime();

  // Transfer table: colour and step-corrected opacity (deepshadow::TransferTable).
  std::vector<double> transferKey{ static_cast<double>(colorFunction->GetMTime()),
    static_cast<double>(opacityTime), property->GetScalarOpacityUnitDistance(0) * unitScale,
    static_cast<double>(this->VolumeUploads), step, static_cast<double>(this->TransferTableSize) };
  if (impl.Transfer.NeedsUpdate(transferKey))
  {
    impl.Transfer.Update(window, adapter::MakeTransferFunction(property, unitScale), impl.Volume.GetRange(),
      this->TransferTableSize, step, std::move(transferKey));
    ++this->TransferTableBuilds;
    this->LastPasses.emplace_back("transfer-table");
  }

  // Empty-space block map: depends on the data and the opacity function only.
  if (this->EmptySpaceSkipping && impl.Occupancy.NeedsUpdate(opacityTime, this->VolumeUploads))
  {
    impl.Occupancy.Update(window, impl.Volume.GetBlocks(), adapter::MakeTransferFunction(property).Opacity,
      opacityTime, this->VolumeUploads);
    ++this->OccupancyBuilds;
    this->LastPasses.emplace_back("occupancy");
  }
  this->EmptyBlockFraction = this->EmptySpaceSkipping ? impl.Occupancy.GetEmptyFraction() : 0.0;
}

void vtkDeepShadowVolumeMapper::UpdateGradientOpacity(vtkOpenGLRenderWindow* window,
  const std::optional<deepshadow::GradientOpacity>& gradient, deepshadow::RayCastFrame& frame)
{
  // Gradient opacity, drawn and cast: its function sampled over the magnitudes VTK's mapper
  // measures (a table of 1024; the magnitude's range depends on the data's).
  if (!gradient)
  {
    return;
  }
  Internals& impl = *this->Impl;
  std::vector<double> key{ gradient->MaxMagnitude };
  for (const auto& [x, y] : gradient->Function.GetNodes())
  {
    key.insert(key.end(), { x, y });
  }
  if (impl.GradientOpacity.NeedsUpdate(key))
  {
    deepshadow::TransferFunction table; // the function as an opacity for a unit step
    table.Opacity = gradient->Function;
    impl.GradientOpacity.Update(window, table, { 0.0, gradient->MaxMagnitude }, 1024, 1.0, std::move(key));
    this->LastPasses.emplace_back("gradient-opacity-table");
  }
  frame.Context.Gradient = *gradient;
  frame.Context.GradientOpacityTable = impl.GradientOpacity.GetTexture();
  frame.Context.GradientOpacityMap = impl.GradientOpacity.GetTable().CoordinateMap();
}

bool vtkDeepShadowVolumeMapper::UpdateOpacityFactors(vtkOpenGLRenderWindow* window,
  vtkVolumeProperty* property, vtkImageData* input, deepshadow::RayCastFrame& frame)
{
  Internals& impl = *this->Impl;
  this->UpdateGradientOpacity(window,
    adapter::MakeGradientOpacity(this, property, impl.Volume.GetRange(), glm::make_vec3(input->GetSpacing())), frame);
  // A 2D transfer function's image, uploaded when it changed; drawn and cast.
  std::string problem;
  if (vtkImageData* image = adapter::UsableTransfer2D(this, property, 1, problem))
  {
    const deepshadow::Transfer2D shape =
      adapter::MakeTransfer2D(image, impl.Volume.GetRange(), glm::make_vec3(input->GetSpacing()), false);
    std::vector<double> key{ static_cast<double>(reinterpret_cast<std::uintptr_t>(image)),
      static_cast<double>(image->GetMTime()), static_cast<double>(image->GetPointData()->GetScalars()->GetMTime()),
      static_cast<double>(shape.Width), static_cast<double>(shape.Height) };
    if (impl.Transfer2D.NeedsUpdate(key))
    {
      impl.Transfer2D.UpdateImage(window, shape.Width, shape.Height,
        static_cast<const float*>(image->GetPointData()->GetScalars()->GetVoidPointer(0)), key);
      this->LastPasses.emplace_back("transfer-2d-upload");
    }
    frame.Context.Transfer2DImage = impl.Transfer2D.GetTexture();
    frame.Context.Transfer2DShape = shape;
    frame.Context.Transfer2DKey = key;
    frame.Context.Transfer2DKey.insert(frame.Context.Transfer2DKey.end(),
      { shape.Range.x, shape.Range.y, shape.Gradient.MaxMagnitude });
  }
  else if (!problem.empty())
  {
    this->ReportError(problem);
    return false;
  }
  // The mask, uploaded when it changed; drawn and cast, read nearest as VTK reads it.
  if (vtkImageData* mask = adapter::UsableMask(this, input))
  {
    const bool labelMap = this->GetMaskType() == vtkGPUVolumeRayCastMapper::LabelMapMaskType;
    if (impl.Mask.NeedsUpdate(mask, false))
    {
      std::string warning;
      if (!impl.Mask.Update(window, mask, false, warning))
      {
        this->ReportError("the mask: " + impl.Mask.GetError());
        return false;
      }
      impl.Mask.GetTexture()->SetMinificationFilter(vtkTextureObject::Nearest);
      impl.Mask.GetTexture()->SetMagnificationFilter(vtkTextureObject::Nearest);
      ++impl.MaskUploads;
      this->LastPasses.emplace_back("mask-upload");
    }
    const std::shared_ptr<const deepshadow::LabelMap> labels =
      labelMap ? adapter::MakeLabelMap(this, property, impl.Mask.GetRange()) : nullptr;
    if (labelMap && !labels)
    {
      return true; // a label map without labels (or blended away) changes nothing, as in VTK's
    }
    // texel -> the shaders' scalar -> the mask's data value.
    const glm::dvec2 toShader = impl.Mask.GetScalarMap();
    const glm::dvec2 shader = impl.Mask.GetShaderScalar();
    frame.Context.Mask = impl.Mask.GetTexture();
    frame.Context.MaskToData = glm::dvec2(toShader.x / shader.x, (toShader.y - shader.y) / shader.x);
    frame.Context.MaskVersion = impl.MaskUploads;
    if (labels)
    {
      this->UpdateLabelTables(window, *labels, frame);
    }
  }
  return true;
}

void vtkDeepShadowVolumeMapper::UpdateLabelTables(
  vtkOpenGLRenderWindow* window, const deepshadow::LabelMap& labels, deepshadow::RayCastFrame& frame)
{
  Internals& impl = *this->Impl;
  // Each label's function over the volume's range, in the view table's texels (its map serves).
  const glm::dvec2 range = impl.Volume.GetRange();
  std::vector<double> key{ range.x, range.y, static_cast<double>(this->TransferTableSize) };
  for (const deepshadow::TransferFunction& function : labels.Functions)
  {
    for (const deepshadow::PiecewiseLinear* f : { &function.Opacity, &function.Red, &function.Green, &function.Blue })
    {
      for (const auto& [x, y] : f->GetNodes())
      {
        key.insert(key.end(), { x, y });
      }
      key.push_back(-1.0);
    }
  }
  if (impl.LabelTables.NeedsUpdate(key))
  {
    impl.LabelTables.UpdateRows(window, labels.Functions, range, this->TransferTableSize, key);
    this->LastPasses.emplace_back("label-tables");
  }
  deepshadow::ShadowContext& context = frame.Context;
  context.LabelTable = impl.LabelTables.GetTexture();
  context.LabelCount = labels.Count();
  context.MaskToLabel = labels.LabelMapping();
  context.MaskBlendFactor = labels.BlendFactor;
  // What the shadows depend on: the tables' content, the labels' mapping and the blend.
  context.LabelKey = key;
  context.LabelKey.insert(context.LabelKey.end(),
    { context.MaskToLabel.x, context.MaskToLabel.y, context.MaskBlendFactor });
}

bool vtkDeepShadowVolumeMapper::UpdateBound(
  vtkOpenGLRenderWindow* window, vtkImageData* input, vtkVolume* volume)
{
  Internals& impl = *this->Impl;
  std::vector<vtkPolyData*> meshes;
  std::string expression;
  this->GetDrawnRegion(volume, meshes, expression);
  if (meshes.empty())
  {
    impl.Bound.Clear();
    return true;
  }
  // The bound lives in the data's coordinates: it follows the image's placement, not the prop's.
  const glm::dmat4 dataToIndex = glm::inverse(adapter::IndexToWorld(input, nullptr));
  std::vector<vtkMTimeType> times;
  for (vtkPolyData* mesh : meshes)
  {
    times.push_back(mesh ? mesh->GetMTime() : 0);
  }
  if (impl.Bound.NeedsUpdate(times, expression, dataToIndex) &&
    impl.Bound.Update(window, meshes, times, expression, dataToIndex))
  {
    if (impl.Bound.EnclosesNothing())
    {
      vtkWarningMacro("the volume's bound encloses nothing (its meshes are empty): nothing is drawn");
    }
    ++this->BoundBuilds;
    this->LastPasses.emplace_back("bound-upload");
  }
  if (!impl.Bound.GetError().empty())
  {
    this->ReportError(impl.Bound.GetError());
    return false;
  }
  return true;
}

bool vtkDeepShadowVolumeMapper::UpdateSurfaces(vtkOpenGLRenderWindow* window, const glm::dmat4& worldToIndex)
{
  Internals& impl = *this->Impl;
  if (!impl.Surfaces || impl.Surfaces->Empty())
  {
    impl.SurfacesGPU.Clear();
    return true;
  }
  if (!impl.SurfacesGPU.NeedsUpdate(impl.Surfaces, worldToIndex))
  {
    return true;
  }
  const std::string limit = impl.SurfacesGPU.Update(window, impl.Surfaces, worldToIndex);
  if (!limit.empty())
  {
    this->ReportError("the surfaces that cast shadows cannot be used: " + limit);
    return false;
  }
  ++this->SurfaceUploads;
  this->LastPasses.emplace_back("surface-upload");
  return true;
}

long long vtkDeepShadowVolumeMapper::GetHolderBytes() const
{
  const Internals& impl = *this->Impl;
  const bool surfaces = impl.Surfaces && !impl.Surfaces->Empty();
  return impl.Volume.GetBytes() + impl.Transfer.GetBytes() +
    (impl.GradientOpacity.GetTexture() ? impl.GradientOpacity.GetBytes() : 0) +
    (impl.Mask.GetTexture() ? impl.Mask.GetBytes() : 0) +
    (this->EmptySpaceSkipping ? impl.Occupancy.GetBytes() : 0) + impl.Bound.GetBytes() +
    (surfaces ? impl.SurfacesGPU.GetBytes() : 0) + impl.Ratio.GetBytes();
}

void vtkDeepShadowVolumeMapper::UpdateComponentGradients(
  vtkOpenGLRenderWindow* window, vtkVolumeProperty* property, deepshadow::RayCastFrame& frame)
{
  // Independent components' own gradient opacities, drawn and cast: one texture, a row per
  // component of its function over the fraction of its largest magnitude (each component's
  // range differs, so each row spans [0, 1]).
  Internals& impl = *this->Impl;
  deepshadow::ShadowContext& context = frame.Context;
  std::vector<glm::dvec2> ranges{ impl.Volume.GetRange() };
  for (const deepshadow::ShadowContext::Component& component : context.OtherComponents)
  {
    ranges.push_back(component.Range);
  }
  context.ComponentGradients =
    adapter::MakeComponentGradients(this, property, ranges, glm::make_vec3(this->GetImageInput()->GetSpacing()));
  context.ComponentGradientTable = nullptr;
  if (context.ComponentGradients.empty())
  {
    return;
  }
  std::vector<deepshadow::TransferFunction> rows;
  std::vector<double> key;
  for (const std::optional<deepshadow::GradientOpacity>& gradient : context.ComponentGradients)
  {
    deepshadow::TransferFunction row; // opacity 1 where the component has none (never read)
    row.Opacity = deepshadow::PiecewiseLinear({ { 0.0, 1.0 } });
    if (gradient)
    {
      std::vector<std::pair<double, double>> nodes;
      for (const auto& [x, y] : gradient->Function.GetNodes())
      {
        nodes.emplace_back(x / gradient->MaxMagnitude, y);
      }
      row.Opacity = deepshadow::PiecewiseLinear(std::move(nodes));
    }
    for (const auto& [x, y] : row.Opacity.GetNodes())
    {
      key.insert(key.end(), { x, y });
    }
    key.push_back(-1.0);
    rows.push_back(std::move(row));
  }
  if (impl.ComponentGradientOpacity.NeedsUpdate(key))
  {
    impl.ComponentGradientOpacity.UpdateRows(window, rows, { 0.0, 1.0 }, 1024, std::move(key));
    this->LastPasses.emplace_back("component-gradient-table");
  }
  context.ComponentGradientTable = impl.ComponentGradientOpacity.GetTexture();
  context.ComponentGradientMap = impl.ComponentGradientOpacity.GetTable().CoordinateMap();
}

bool vtkDeepShadowVolumeMapper::UpdateComponents(vtkOpenGLRenderWindow* window, vtkVolumeProperty* property,
  double step, bool uncorrected, double unitScale, deepshadow::RayCastFrame& frame)
{
  Internals& impl = *this->Impl;
  const auto& others = impl.Drawn.GetOtherComponents();
  deepshadow::ComponentSet set;
  const std::string problem = adapter::MakeComponentSet(property, 1 + static_cast<int>(others.size()),
    others.front()->GetPointData()->GetScalars()->GetDataType(), unitScale, set);
  if (!problem.empty())
  {
    this->ReportError(problem);
    return false;
  }
  deepshadow::ShadowContext& context = frame.Context;
  context.Mode = set.Mode;
  context.Weights = set.Weights;
  context.TextureScale = set.TextureScale;
  context.ComponentsLitApart = set.LitApart(frame.Shade);
  context.OtherComponents.clear();
  const int filter = property->GetInterpolationType() == VTK_NEAREST_INTERPOLATION ? vtkTextureObject::Nearest
                                                                                    : vtkTextureObject::Linear;
  for (size_t c = 0; c < others.size(); ++c)
  {
    deepshadow::VolumeTexture& texture = impl.ComponentVolumes[c];
    if (texture.NeedsUpdate(others[c], this->ReplaceNonFiniteScalars))
    {
      std::string warning;
      if (!texture.Update(window, others[c], this->ReplaceNonFiniteScalars, warning))
      {
        this->ReportError("component " + std::to_string(c + 1) + ": " + texture.GetError());
        return false;
      }
      this->LastPasses.emplace_back("component-upload");
    }
    texture.GetTexture()->SetMinificationFilter(filter);
    texture.GetTexture()->SetMagnificationFilter(filter);
    const deepshadow::TransferFunction& function = set.Transfers[c + 1];
    // Its table: its function over its own range, for the view's step (uncorrected: for a
    // step of its unit distance, which corrects nothing).
    const double tableStep = uncorrected ? function.OpacityUnitDistance : step;
    std::vector<double> key{ static_cast<double>(this->VolumeUploads), tableStep,
      static_cast<double>(this->TransferTableSize), texture.GetRange().x, texture.GetRange().y,
      function.OpacityUnitDistance };
    for (const deepshadow::PiecewiseLinear* f : { &function.Opacity, &function.Red, &function.Green, &function.Blue })
    {
      for (const auto& [x, y] : f->GetNodes())
      {
        key.insert(key.end(), { x, y });
      }
      key.push_back(-1.0);
    }
    deepshadow::TransferTableTexture& table = impl.ComponentTables[c];
    if (table.NeedsUpdate(key))
    {
      table.Update(window, function, texture.GetRange(), this->TransferTableSize, tableStep, std::move(key));
      this->LastPasses.emplace_back("component-table");
    }
    deepshadow::ShadowContext::Component component;
    component.Texture = texture.GetTexture();
    component.ScalarMap = texture.GetScalarMap();
    component.ShaderScalar = texture.GetShaderScalar();
    component.Range = texture.GetRange();
    component.Transfer = function;
    context.OtherComponents.push_back(component);
    frame.ComponentTransfers.push_back(table.GetTexture());
  }
  this->UpdateComponentGradients(window, property, frame);
  if (set.Mode != deepshadow::ComponentMode::Independent)
  {
    this->UpdateGradientOpacity(window,
      adapter::MakeDependentGradientOpacity(this, property, impl.Volume.GetRange(),
        context.OtherComponents.back().Range, glm::make_vec3(this->GetImageInput()->GetSpacing())),
      frame);
  }
  return true;
}
