#include "vtkDeepShadowVolumeRepresentation.h"

#include "Core/ShadowTechniques.h"
#include "vtkDeepShadowTechnique.h"
#include "vtkDeepShadowTechniqueFactory.h"
#include "vtkDeepShadowVolumeMapper.h"

#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkPVRenderView.h"
#include "vtkPVView.h"
#include "vtkRenderer.h"

#include <sstream>
#include <stdexcept>

vtkStandardNewMacro(vtkDeepShadowVolumeRepresentation);

vtkDeepShadowVolumeRepresentation::vtkDeepShadowVolumeRepresentation()
{
  // The superclass keeps its mapper in VolumeMapper and drives it with vtkVolumeMapper's API
  // only (input, array selection, blend mode, cropping): ours takes its place.
  this->VolumeMapper = vtkSmartPointer<vtkDeepShadowVolumeMapper>::New();
  this->ApplyTechnique();
}

vtkDeepShadowVolumeRepresentation::~vtkDeepShadowVolumeRepresentation() = default;

void vtkDeepShadowVolumeRepresentation::SetShadowTechnique(const char* name)
{
  const std::string text = name ? name : "";
  if (text != this->TechniqueName)
  {
    this->TechniqueName = text;
    this->ApplyTechnique();
    this->Modified();
  }
}

void vtkDeepShadowVolumeRepresentation::SetShadowParameters(const char* text)
{
  const std::string value = text ? text : "";
  if (value != this->ParameterText)
  {
    this->ParameterText = value;
    this->ApplyTechnique();
    this->Modified();
  }
}

bool vtkDeepShadowVolumeRepresentation::ApplyTechnique()
{
  auto* mapper = vtkDeepShadowVolumeMapper::SafeDownCast(this->VolumeMapper);
  this->Error.clear();
  bool cached = false;
  const deepshadow::ShadowTechniqueInfo* technique = deepshadow::FindShadowTechnique(this->TechniqueName, &cached);
  if (!technique)
  {
    this->Error = "unknown shadow technique '" + this->TechniqueName + "'";
  }
  deepshadow::ShadowParameters parameters;
  if (technique)
  {
    parameters = technique->DefaultParameters(cached);
    // KEY=VALUE pairs, separated by spaces or commas (a value's own commas, as in
    // levels=0.1,0.5,0.9, stay with it: a piece without '=' continues the previous value).
    std::string text = this->ParameterText;
    for (char& c : text)
    {
      c = c == '\t' || c == '\n' ? ' ' : c;
    }
    std::istringstream words(text);
    std::string word;
    std::vector<std::pair<std::string, std::string>> pairs;
    while (words >> word)
    {
      std::istringstream pieces(word);
      std::string piece;
      while (std::getline(pieces, piece, ','))
      {
        const size_t equals = piece.find('=');
        if (equals != std::string::npos)
        {
          pairs.emplace_back(piece.substr(0, equals), piece.substr(equals + 1));
        }
        else if (!pairs.empty() && !piece.empty())
        {
          pairs.back().second += "," + piece;
        }
        else if (!piece.empty())
        {
          this->Error = "shadow parameter '" + piece + "' has no value (KEY=VALUE)";
        }
      }
    }
    for (const auto& [key, value] : pairs)
    {
      const deepshadow::ShadowParameterInfo* info = deepshadow::FindShadowParameter(key);
      if (!info || !technique->Reads(key))
      {
        this->Error = "the shadow technique '" + technique->Name + "' has no parameter '" + key + "'";
        break;
      }
      try
      {
        info->Set(parameters, info->Parse(value));
      }
      catch (const std::invalid_argument& e)
      {
        this->Error = e.what();
        break;
      }
    }
  }
  if (!this->Error.empty())
  {
    vtkErrorMacro(<< this->Error << "; the shadows drawn stay as they were");
    return false;
  }
  mapper->SetShadowTechnique(
    technique->Kind == deepshadow::ShadowKind::None ? nullptr : vtkDeepShadowTechniqueFactory::New(parameters));
  return true;
}

bool vtkDeepShadowVolumeRepresentation::AddToView(vtkView* view)
{
  if (auto* renderView = vtkPVRenderView::SafeDownCast(view))
  {
    this->Renderer = renderView->GetRenderer();
  }
  return this->Superclass::AddToView(view);
}

bool vtkDeepShadowVolumeRepresentation::RemoveFromView(vtkView* view)
{
  this->Renderer = nullptr;
  return this->Superclass::RemoveFromView(view);
}

int vtkDeepShadowVolumeRepresentation::ProcessViewRequest(
  vtkInformationRequestKey* request, vtkInformation* in, vtkInformation* out)
{
  if (request == vtkPVView::REQUEST_RENDER())
  {
    this->ChooseShadowLights();
    // Under MPI each rank draws its piece, and its shadow structures see that piece only.
    vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
    if (!this->SaidPiecesAlone && controller && controller->GetNumberOfProcesses() > 1 &&
      this->TechniqueName != "none" && controller->GetLocalProcessId() == 0)
    {
      this->SaidPiecesAlone = true;
      vtkWarningMacro(<< "shadows across " << controller->GetNumberOfProcesses()
                      << " ranks: each rank's piece casts shadows onto itself only (the other "
                         "pieces' shadows are not exchanged yet)");
    }
  }
  return this->Superclass::ProcessViewRequest(request, in, out);
}

void vtkDeepShadowVolumeRepresentation::ChooseShadowLights()
{
  if (!this->Renderer)
  {
    return;
  }
  vtkLightCollection* lights = this->Renderer->GetLights();
  vtkLight* brightest = nullptr;
  lights->InitTraversal();
  while (vtkLight* light = lights->GetNextItem())
  {
    if (light->GetSwitch() && (!brightest || light->GetIntensity() > brightest->GetIntensity()))
    {
      brightest = light;
    }
  }
  lights->InitTraversal();
  while (vtkLight* light = lights->GetNextItem())
  {
    const double attenuation = this->ShadowLights == 1 || light == brightest ? 1.0 : 0.0;
    if (light->GetShadowAttenuation() != attenuation) // a change would rebuild the shadows
    {
      light->SetShadowAttenuation(attenuation);
    }
  }
}

void vtkDeepShadowVolumeRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ShadowTechnique: " << this->TechniqueName << "\n";
  os << indent << "ShadowParameters: " << this->ParameterText << "\n";
  os << indent << "ShadowLights: " << (this->ShadowLights ? "all" : "the brightest") << "\n";
}
