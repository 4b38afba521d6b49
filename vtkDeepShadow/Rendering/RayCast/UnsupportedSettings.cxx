#include "RayCast/UnsupportedSettings.h"

#include "CoreAdapter.h"

#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkVolumeProperty.h"

#include <sstream>
#include <string>

namespace deepshadow
{
namespace
{
const char* BlendModeName(int mode)
{
  switch (mode)
  {
    case vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND:
      return "maximum intensity projection";
    case vtkVolumeMapper::MINIMUM_INTENSITY_BLEND:
      return "minimum intensity projection";
    case vtkVolumeMapper::AVERAGE_INTENSITY_BLEND:
      return "average intensity projection";
    case vtkVolumeMapper::ADDITIVE_BLEND:
      return "additive";
    case vtkVolumeMapper::ISOSURFACE_BLEND:
      return "isosurface";
    case vtkVolumeMapper::SLICE_BLEND:
      return "slice";
    default:
      return "unknown";
  }
}

// Several components, and the blend modes: what is drawn composite or without shadows.
void SayBlendModes(std::vector<std::string>& said, vtkGPUVolumeRayCastMapper* mapper, int components,
  vtkVolumeProperty* property, bool shadowed)
{
  const int blend = mapper->GetBlendMode();
  if (components > 1)
  {
    // Several components (Core/Components.h) are composited or projected, without these.
    if (blend == vtkVolumeMapper::ISOSURFACE_BLEND || blend == vtkVolumeMapper::SLICE_BLEND)
    {
      said.push_back(std::string("several components are drawn with composite blending or projected: ") +
        BlendModeName(blend) + " is drawn composite");
    }
    else if (blend != vtkVolumeMapper::COMPOSITE_BLEND && shadowed)
    {
      said.push_back(std::string("shadows do not apply to ") + BlendModeName(blend) +
        ": it is drawn exactly, without shadows");
    }
    if (!adapter::MakeComponentGradients(mapper, property,
          std::vector<glm::dvec2>(static_cast<size_t>(components), glm::dvec2(0.0, 1.0)), glm::dvec3(1.0))
           .empty())
    {
      said.push_back("gradient opacity over independent components: each component's opacity is multiplied by its "
                     "own function at its own gradient (VTK 9.1's mapper multiplies every component's function and "
                     "weight into each, and applies none unless component 0 has one)");
    }
    if (mapper->GetMaskInput())
    {
      said.push_back("masks are not drawn with several components: the volume is drawn without the mask");
    }
  }
  else if (blend == vtkVolumeMapper::SLICE_BLEND)
  {
    said.push_back(std::string("blend mode ") + BlendModeName(blend) +
      " is not supported: the volume is drawn with composite blending");
  }
  else if (blend == vtkVolumeMapper::ISOSURFACE_BLEND)
  {
    int given = 0;
    adapter::MakeIsoValues(mapper, property, &given);
    if (given == 0)
    {
      said.push_back("isosurface blending without contour values "
                     "(vtkVolumeProperty::GetIsoSurfaceValues): nothing is drawn");
    }
    else if (given > MaxIsoValues)
    {
      said.push_back("isosurface blending draws at most " + std::to_string(MaxIsoValues) +
        " contour values: the lowest " + std::to_string(MaxIsoValues) + " of " + std::to_string(given) +
        " are drawn");
    }
  }
  else if (blend != vtkVolumeMapper::COMPOSITE_BLEND && shadowed)
  {
    said.push_back(std::string("shadows do not apply to ") + BlendModeName(blend) +
      ": it is drawn exactly, without shadows");
  }
}

// A 2D transfer function where it cannot apply as set.
void SayTransfer2D(std::vector<std::string>& said, vtkGPUVolumeRayCastMapper* mapper, int components,
  vtkVolumeProperty* property)
{
  const int blend = mapper->GetBlendMode();
  if (property && property->GetTransferFunctionMode() == vtkVolumeProperty::TF_2D)
  {
    // Drawn under composite blending over one component (Core/Transfer2D.h).
    if (mapper->GetTransfer2DYAxisArray())
    {
      said.push_back("a 2D transfer function's Y axis array (SetTransfer2DYAxisArray) is not read: its Y axis is "
                     "the gradient magnitude");
    }
    if (components > 1)
    {
      said.push_back("2D transfer functions are not drawn over several components (VTK 9.1's shader does "
                     "not compile them): the 1D functions are used");
    }
    else if (blend != vtkVolumeMapper::COMPOSITE_BLEND)
    {
      said.push_back(std::string("2D transfer functions apply to composite blending: ") + BlendModeName(blend) +
        " uses the 1D functions");
    }
    else if (property->GetInterpolationType() == VTK_NEAREST_INTERPOLATION)
    {
      said.push_back("a 2D transfer function is read with linear interpolation (VTK's mapper reads it nearest "
                     "under nearest interpolation)");
    }
  }
}

// A mask or label map that is not drawn, or not drawn as set.
void SayMask(std::vector<std::string>& said, vtkGPUVolumeRayCastMapper* mapper, vtkImageData* volume,
  bool fromCells, int components, vtkVolumeProperty* property)
{
  const int blend = mapper->GetBlendMode();
  // What vtkGPUVolumeRayCastMapper adds to vtkVolumeMapper.
  vtkImageData* mask = mapper->GetMaskInput();
  if (mask && components == 1)
  {
    const bool binary = mapper->GetMaskType() == vtkGPUVolumeRayCastMapper::BinaryMaskType;
    if (blend == vtkVolumeMapper::ISOSURFACE_BLEND || blend == vtkVolumeMapper::SLICE_BLEND)
    {
      said.push_back(std::string("masks apply to composite blending and projections only: ") +
        BlendModeName(blend) + " is drawn without the mask");
    }
    else if (blend != vtkVolumeMapper::COMPOSITE_BLEND && !binary)
    {
      said.push_back(std::string("a label map colours composite blending only, as in VTK's mapper: ") +
        BlendModeName(blend) + " is drawn without it (SetMaskTypeToBinary to skip what it clears)");
    }
    else if (fromCells)
    {
      said.push_back("masks are not drawn over cell scalars: the volume is drawn without the mask");
    }
    else if (!adapter::UsableMask(mapper, volume))
    {
      int maskDims[3] = { 0, 0, 0 }, dims[3] = { 0, 0, 0 };
      mask->GetDimensions(maskDims);
      if (volume)
      {
        volume->GetDimensions(dims);
      }
      std::ostringstream text;
      if (!mask->GetPointData()->GetScalars())
      {
        text << "the mask has no point scalars: the volume is drawn without it";
      }
      else
      {
        text << "the mask's dimensions " << maskDims[0] << "x" << maskDims[1] << "x" << maskDims[2]
             << " differ from the volume's " << dims[0] << "x" << dims[1] << "x" << dims[2]
             << ": the volume is drawn without it";
      }
      said.push_back(text.str());
    }
    else if (mapper->GetMaskType() == vtkGPUVolumeRayCastMapper::LabelMapMaskType)
    {
      if (!property || property->GetLabelMapLabels().empty())
      {
        said.push_back("a label-map mask (the mask type by default) without label functions "
                       "(vtkVolumeProperty::SetLabelColor/SetLabelScalarOpacity) changes nothing, as in VTK's "
                       "mapper: SetMaskTypeToBinary for a binary mask");
      }
      else
      {
        if (property->HasLabelGradientOpacity())
        {
          said.push_back("label gradient opacity (SetLabelGradientOpacity) is not drawn: labelled samples are "
                         "drawn without it");
        }
        if (adapter::MakeGradientOpacity(mapper, property, { 0.0, 1.0 }, glm::dvec3(1.0)))
        {
          said.push_back("gradient opacity with a label map applies to labelled samples too (VTK 9.1's mapper "
                         "applies it to label 0 only)");
        }
      }
    }
  }
}

// vtkGPUVolumeRayCastMapper's own settings that are not supported, and a prop scaled unevenly.
void SayMapperSettings(std::vector<std::string>& said, vtkGPUVolumeRayCastMapper* mapper,
  const vtkMatrix4x4* propMatrix, bool shadowed)
{
  if (mapper->GetImageSampleDistance() != 1.0f)
  {
    std::ostringstream text;
    text << "image sample distance " << mapper->GetImageSampleDistance()
         << " is not supported: one ray per pixel is cast";
    said.push_back(text.str());
  }
  if (mapper->GetFinalColorWindow() != 1.0f || mapper->GetFinalColorLevel() != 0.5f)
  {
    said.push_back("final colour window/level (SetFinalColorWindow/Level) is not supported: "
                   "colours are drawn as composited");
  }
  if (mapper->GetRenderToImage())
  {
    said.push_back("RenderToImage is not supported: the volume is drawn into the window");
  }
  if (mapper->GetUseDepthPass())
  {
    said.push_back("UseDepthPass is not supported: the volume is drawn without it");
  }
  for (int port = 1; port < mapper->GetNumberOfInputPorts(); ++port)
  {
    if (mapper->GetNumberOfInputConnections(port) > 0)
    {
      said.push_back("volumes on input ports 1 and up (vtkMultiVolume) are not supported: "
                     "the volume on port 0 is drawn");
      break;
    }
  }
  // The view integrates opacity per dataset unit along each ray (Features/DatasetOpacity.glsl);
  // light rays do not.
  bool anisotropic = false;
  adapter::DatasetLengthScale(propMatrix, &anisotropic);
  if (anisotropic && shadowed)
  {
    said.push_back("a vtkVolume scaled differently along its axes: light rays integrate opacity at its mean "
                   "scale, so shadows are lighter or darker along its longer or shorter axes than the view");
  }
}
}

std::vector<std::string> UnsupportedSettings(vtkGPUVolumeRayCastMapper* mapper, vtkImageData* volume,
  bool fromCells, int components, vtkVolumeProperty* property, const vtkMatrix4x4* propMatrix, bool shadowed)
{
  std::vector<std::string> said;
  SayBlendModes(said, mapper, components, property, shadowed);
  SayTransfer2D(said, mapper, components, property);
  SayMask(said, mapper, volume, fromCells, components, property);
  SayMapperSettings(said, mapper, propMatrix, shadowed);
  return said;
}

}
