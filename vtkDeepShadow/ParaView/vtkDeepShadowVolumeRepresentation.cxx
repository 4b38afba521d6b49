#include "vtkDeepShadowVolumeRepresentation.h"

#include "Core/ShadowParameterText.h"
#include "Core/ShadowTechniques.h"
#include "PassFrame.h"
#include "vtkDeepShadowBrickExchange.h"
#include "vtkDeepShadowCastingMeshes.h"
#include "vtkDeepShadowCompositeSurfaceMapper.h"
#include "vtkDeepShadowLightSpaceTechnique.h"
#include "vtkDeepShadowPolyDataMapper.h"
#include "vtkDeepShadowTechnique.h"
#include "vtkDeepShadowTechniqueFactory.h"
#include "vtkDeepShadowVolumeMapper.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkCommand.h"
#include "vtkCellArray.h"
#include "vtkCommunicator.h"
#include "vtkDataSet.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMultiProcessController.h"
#include "vtkImageData.h"
#include "vtkObjectFactory.h"
#include "vtkPVLODVolume.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkPVRenderView.h"
#include "vtkPVView.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <vector>
#include <sstream>
#include <stdexcept>

vtkStandardNewMacro(vtkDeepShadowVolumeRepresentation);

namespace
{
// ShadowInteractiveLag's default (degrees; the XML's default_values says the same).
constexpr double DefaultInteractiveLag = 10.0;
// ShadowInteractiveSubsampling's default (pixels a coarse ray; the XML's default_values too).
constexpr int DefaultInteractiveSubsampling = 8;

// The bricks of an MPI run: one per rank of ParaView's global controller.
class vtkDeepShadowMPIBrickExchange : public vtkDeepShadowBrickExchange
{
public:
  static vtkDeepShadowMPIBrickExchange* New();
  vtkTypeMacro(vtkDeepShadowMPIBrickExchange, vtkDeepShadowBrickExchange);

  int GetNumberOfBricks() override
  {
    vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
    return controller ? controller->GetNumberOfProcesses() : 1;
  }
  int GetLocalBrick() override
  {
    vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
    return controller ? controller->GetLocalProcessId() : 0;
  }
  bool AllGather(const std::vector<float>& local, std::vector<float>& all) override
  {
    vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
    if (!controller)
    {
      return false;
    }
    all.resize(local.size() * static_cast<size_t>(controller->GetNumberOfProcesses()));
    return controller->AllGather(local.data(), all.data(), static_cast<vtkIdType>(local.size())) != 0;
  }
  bool CanSendReceive() override { return vtkMultiProcessController::GetGlobalController() != nullptr; }
  bool SendReceive(int to, const std::vector<float>& send, int from, std::vector<float>& received, bool sendFirst,
    int tag) override
  {
    vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
    const int messageTag = ScanTag + tag;
    auto sent = [&] {
      return to < 0 || controller->Send(send.data(), static_cast<vtkIdType>(send.size()), to, messageTag) != 0;
    };
    auto arrived = [&] {
      return from < 0 ||
        (controller->Receive(received.data(), static_cast<vtkIdType>(received.size()), from, messageTag) != 0 &&
          controller->GetCommunicator()->GetCount() == static_cast<vtkIdType>(received.size()));
    };
    return sendFirst ? sent() && arrived() : arrived() && sent();
  }

private:
  // Apart from ParaView's own tags on the global controller.
  static constexpr int ScanTag = 0x5D5C00;
};
vtkStandardNewMacro(vtkDeepShadowMPIBrickExchange);

// The registry's names whose technique exchanges bricks between ranks (the light-space ones).
std::string ExchangedTechniques()
{
  std::string names;
  for (const std::string& name : deepshadow::ShadowTechniqueNames())
  {
    if (vtkDeepShadowLightSpaceTechnique::SafeDownCast(vtkDeepShadowTechniqueFactory::New(name)))
    {
      names += (names.empty() ? "" : ", ") + name;
    }
  }
  return names;
}
}

vtkDeepShadowVolumeRepresentation::vtkDeepShadowVolumeRepresentation()
{
  // The superclass keeps its mapper in VolumeMapper and drives it with vtkVolumeMapper's API
  // only (input, array selection, blend mode, cropping): ours takes its place.
  auto mapper = vtkSmartPointer<vtkDeepShadowVolumeMapper>::New();
  // Blinn-Phong: our model of VTK's shading is VTK 9.1's, ParaView's VTK 9.2 shades otherwise,
  // and VTK's shading depends on each rank's box (seams between the pieces of MPI ranks).
  mapper->SetShadingModelToBlinnPhong();
  mapper->SetInteractiveShadowLag(DefaultInteractiveLag);
  mapper->SetInteractiveShadowSubsampling(DefaultInteractiveSubsampling);
  this->VolumeMapper = mapper;
  this->Exchange = vtkSmartPointer<vtkDeepShadowMPIBrickExchange>::New();
  this->Casting = vtkSmartPointer<vtkDeepShadowCastingMeshes>::New();
  this->Ground = vtkSmartPointer<vtkActor>::New();
  vtkNew<vtkDeepShadowPolyDataMapper> groundMapper;
  groundMapper->CastShadowsOff();
  groundMapper->SetShadowingVolume(this->Actor);
  this->Ground->SetMapper(groundMapper);
  this->Ground->SetVisibility(false);
  this->Ground->PickableOff();
  this->ApplyTechnique();
}

vtkDeepShadowVolumeRepresentation::~vtkDeepShadowVolumeRepresentation() = default;

void vtkDeepShadowVolumeRepresentation::SetShadowTechnique(const char* name)
{
  const std::string text = name ? name : "";
  if (text != this->TechniqueName)
  {
    this->TechniqueName = text;
    this->TechniqueChanged = true;
    this->Modified();
  }
}

void vtkDeepShadowVolumeRepresentation::SetShadowParameters(const char* text)
{
  const std::string value = text ? text : "";
  if (value != this->ParameterText)
  {
    this->ParameterText = value;
    this->TechniqueChanged = true;
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
    std::vector<std::pair<std::string, std::string>> pairs;
    try
    {
      pairs = deepshadow::SplitShadowParameterText(this->ParameterText);
    }
    catch (const std::invalid_argument& e)
    {
      this->Error = e.what();
    }
    for (const auto& [key, value] : pairs)
    {
      const deepshadow::ShadowParameterInfo* info = deepshadow::FindShadowParameter(key);
      if (!info || !technique->Reads(key))
      {
        // The name selected (dsm-cached), not the registry entry's (dsm).
        this->Error = "the shadow technique '" + this->TechniqueName + "' has no parameter '" + key + "'";
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
    this->Renderer->AddActor(this->Ground);
    this->RenderObserver = this->Renderer->AddObserver(
      vtkCommand::StartEvent, this, &vtkDeepShadowVolumeRepresentation::GatherCastingSurfaces);
  }
  return this->Superclass::AddToView(view);
}

bool vtkDeepShadowVolumeRepresentation::RemoveFromView(vtkView* view)
{
  // A view being destroyed is no render view any more (its renderer is gone already).
  if (auto* renderView = vtkPVRenderView::SafeDownCast(view))
  {
    renderView->GetRenderer()->RemoveActor(this->Ground);
    renderView->GetRenderer()->RemoveObserver(this->RenderObserver);
  }
  this->Renderer = nullptr;
  return this->Superclass::RemoveFromView(view);
}

vtkDeepShadowCastingMeshes* vtkDeepShadowVolumeRepresentation::GetCastingMeshes()
{
  return this->Casting;
}

void vtkDeepShadowVolumeRepresentation::GatherCastingSurfaces()
{
  // Here, after every representation's REQUEST_RENDER (the surfaces' data is delivered) and
  // before anything is drawn: the surfaces' own renders prepare these structures first.
  std::vector<std::pair<vtkActor*, vtkDeepShadowPolyDataMapper*>> meshes;
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  const bool ranks = controller && controller->GetNumberOfProcesses() > 1;
  if (this->Renderer && this->GetVisibility() && !ranks)
  {
    vtkActorCollection* actors = this->Renderer->GetActors();
    vtkCollectionSimpleIterator it;
    actors->InitTraversal(it);
    while (vtkActor* actor = actors->GetNextActor(it))
    {
      auto* mapper = vtkDeepShadowCompositeSurfaceMapper::SafeDownCast(actor->GetMapper());
      if (mapper && actor->GetVisibility())
      {
        mapper->Join();
        meshes.emplace_back(actor, mapper->GetSurfaceMapper());
      }
    }
  }
  this->Casting->Update(meshes);
  // The set stays with the mapper after the frame (vtkDeepShadowVolumeMapper::SetPassFrame);
  // handing the same set again changes nothing.
  auto* mapper = vtkDeepShadowVolumeMapper::SafeDownCast(this->VolumeMapper);
  deepshadow::PassFrame frame;
  frame.Surfaces = this->Casting->GetSurfaces();
  frame.SurfaceHolder = mapper;
  mapper->SetPassFrame(&frame);
  mapper->SetPassFrame(nullptr);
}

void vtkDeepShadowVolumeRepresentation::UpdateGround()
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  const bool ranks = controller && controller->GetNumberOfProcesses() > 1;
  auto* image = vtkImageData::SafeDownCast(this->Cache);
  const bool wanted = this->ShadowGround > 0 && this->GetVisibility() && image;
  if (wanted && ranks && !this->SaidGroundAlone && controller->GetLocalProcessId() == 0)
  {
    vtkWarningMacro(<< "the shadow ground is not drawn under MPI: a rank's lookups see its own brick and "
                       "those in front of it, not every brick between the light and the ground");
  }
  this->SaidGroundAlone = this->SaidGroundAlone || (wanted && ranks);
  this->Ground->SetVisibility(wanted && !ranks);
  if (!this->Ground->GetVisibility())
  {
    return;
  }
  // The volume's whole box (every rank's piece together), from its extent and placement.
  double box[6];
  const double* origin = image->GetOrigin();
  const double* spacing = image->GetSpacing();
  for (int a = 0; a < 3; ++a)
  {
    box[2 * a] = origin[a] + spacing[a] * this->WholeExtent[2 * a];
    box[2 * a + 1] = origin[a] + spacing[a] * this->WholeExtent[2 * a + 1];
  }
  const int axis = (this->ShadowGround - 1) / 2;
  const bool high = (this->ShadowGround - 1) % 2 == 1;
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const double extent = box[2 * axis + 1] - box[2 * axis];
  const double level = high ? box[2 * axis + 1] + 0.05 * extent : box[2 * axis] - 0.05 * extent;
  const double du = 0.5 * (box[2 * u + 1] - box[2 * u]), dv = 0.5 * (box[2 * v + 1] - box[2 * v]);
  vtkNew<vtkPoints> points;
  for (int corner = 0; corner < 4; ++corner)
  {
    double p[3];
    p[axis] = level;
    p[u] = corner & 1 ? box[2 * u + 1] + du : box[2 * u] - du;
    p[v] = corner & 2 ? box[2 * v + 1] + dv : box[2 * v] - dv;
    points->InsertNextPoint(p);
  }
  vtkNew<vtkCellArray> quad;
  const vtkIdType ids[4] = { 0, 1, 3, 2 };
  quad->InsertNextCell(4, ids);
  vtkNew<vtkPolyData> plane;
  plane->SetPoints(points);
  plane->SetPolys(quad);
  auto* mapper = vtkDeepShadowPolyDataMapper::SafeDownCast(this->Ground->GetMapper());
  vtkPolyData* drawn = vtkPolyData::SafeDownCast(mapper->GetInput());
  double was[6] = { 0, -1, 0, -1, 0, -1 };
  if (drawn)
  {
    drawn->GetBounds(was);
  }
  double now[6];
  plane->GetBounds(now);
  if (!drawn || !std::equal(now, now + 6, was)) // the same plane keeps its upload
  {
    mapper->SetInputData(plane);
  }
  this->Ground->GetProperty()->SetColor(this->ShadowGroundColor);
}

int vtkDeepShadowVolumeRepresentation::ProcessViewRequest(
  vtkInformationRequestKey* request, vtkInformation* in, vtkInformation* out)
{
  if (request == vtkPVView::REQUEST_UPDATE())
  {
    this->CountPieces();
  }
  if (request == vtkPVView::REQUEST_RENDER())
  {
    this->GatherExchangeStatistics();
    // The technique and its parameters are checked together, once both are set: the panel
    // sets the technique, then drops the parameters the new one does not read.
    if (this->TechniqueChanged)
    {
      this->TechniqueChanged = false;
      this->ApplyTechnique();
    }
    this->ChooseShadowLights();
    this->ShareShadowsAcrossRanks();
    this->UpdateGround();
  }
  return this->Superclass::ProcessViewRequest(request, in, out);
}

void vtkDeepShadowVolumeRepresentation::CountPieces()
{
  // Every rank takes part in a view's update, so this is where the ranks agree on whether
  // every one of them holds a piece: the exchange is collective inside the mapper's render,
  // which a rank without a piece never reaches.
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (!controller || controller->GetNumberOfProcesses() <= 1)
  {
    this->RanksWithoutPiece = 0;
    return;
  }
  vtkDataSet* piece = vtkDataSet::SafeDownCast(this->Cache);
  const int mine = piece && piece->GetNumberOfPoints() > 0 ? 0 : 1;
  int without = 0;
  controller->AllReduce(&mine, &without, 1, vtkCommunicator::SUM_OP);
  this->RanksWithoutPiece = without;
}

void vtkDeepShadowVolumeRepresentation::ShareShadowsAcrossRanks()
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  auto* mapper = vtkDeepShadowVolumeMapper::SafeDownCast(this->VolumeMapper);
  vtkDeepShadowTechnique* technique = mapper->GetShadowTechnique();
  auto* lightSpace = vtkDeepShadowLightSpaceTechnique::SafeDownCast(technique);
  const int ranks = controller ? controller->GetNumberOfProcesses() : 1;
  std::string alone; // why the pieces shadow themselves only
  if (ranks > 1 && technique && !lightSpace)
  {
    alone = "the technique '" + this->TechniqueName +
      "' is not exchanged between ranks (the light-space ones are: " + ExchangedTechniques() + ")";
  }
  else if (ranks > 1 && technique && this->RanksWithoutPiece > 0)
  {
    alone = std::to_string(this->RanksWithoutPiece) + " of " + std::to_string(ranks) + " ranks hold no piece";
  }
  if (lightSpace)
  {
    lightSpace->SetBrickExchange(ranks > 1 && alone.empty() ? this->Exchange.Get() : nullptr);
  }
  if (!alone.empty() && alone != this->SaidAlone && controller->GetLocalProcessId() == 0)
  {
    vtkWarningMacro(<< "shadows across " << ranks << " ranks: each rank's piece casts shadows onto itself only: "
                    << alone);
  }
  this->SaidAlone = alone;
}

void vtkDeepShadowVolumeRepresentation::SetShadowInteractiveLag(double degrees)
{
  auto* mapper = vtkDeepShadowVolumeMapper::SafeDownCast(this->VolumeMapper);
  if (degrees != mapper->GetInteractiveShadowLag())
  {
    mapper->SetInteractiveShadowLag(degrees);
    this->Modified();
  }
}

double vtkDeepShadowVolumeRepresentation::GetShadowInteractiveLag()
{
  return vtkDeepShadowVolumeMapper::SafeDownCast(this->VolumeMapper)->GetInteractiveShadowLag();
}

void vtkDeepShadowVolumeRepresentation::SetShadowInteractiveSubsampling(int pixels)
{
  auto* mapper = vtkDeepShadowVolumeMapper::SafeDownCast(this->VolumeMapper);
  if (pixels != mapper->GetInteractiveShadowSubsampling())
  {
    mapper->SetInteractiveShadowSubsampling(pixels);
    this->Modified();
  }
}

int vtkDeepShadowVolumeRepresentation::GetShadowInteractiveSubsampling()
{
  return vtkDeepShadowVolumeMapper::SafeDownCast(this->VolumeMapper)->GetInteractiveShadowSubsampling();
}

int vtkDeepShadowVolumeRepresentation::GetShadowBuilds()
{
  return vtkDeepShadowVolumeMapper::SafeDownCast(this->VolumeMapper)->GetShadowBuilds();
}

void vtkDeepShadowVolumeRepresentation::GatherExchangeStatistics()
{
  // Collective (every rank's REQUEST_RENDER): the largest of what each rank's last frame
  // moved, which differs between ranks under the scan (the first brick along the light
  // receives nothing); the client reads rank 0's properties.
  const double mine[3] = { static_cast<double>(this->Exchange->GetLastBytes()),
    static_cast<double>(this->Exchange->GetLastMessages()), this->Exchange->GetLastMilliseconds() };
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (controller && controller->GetNumberOfProcesses() > 1)
  {
    controller->AllReduce(mine, this->ExchangeLargest, 3, vtkCommunicator::MAX_OP);
  }
  else
  {
    std::copy(mine, mine + 3, this->ExchangeLargest);
  }
}

double vtkDeepShadowVolumeRepresentation::GetShadowExchangeBytes()
{
  return this->ExchangeLargest[0];
}

int vtkDeepShadowVolumeRepresentation::GetShadowExchangeMessages()
{
  return static_cast<int>(this->ExchangeLargest[1]);
}

double vtkDeepShadowVolumeRepresentation::GetShadowExchangeMilliseconds()
{
  return this->ExchangeLargest[2];
}

void vtkDeepShadowVolumeRepresentation::SetShadowExchangeScan(int scan)
{
  if ((scan != 0) != this->Exchange->GetScan())
  {
    this->Exchange->SetScan(scan != 0);
    this->Modified();
  }
}

int vtkDeepShadowVolumeRepresentation::GetShadowExchangeScan()
{
  return this->Exchange->GetScan() ? 1 : 0;
}

const char* vtkDeepShadowVolumeRepresentation::GetShadowStatistics()
{
  std::ostringstream text;
  auto* mapper = vtkDeepShadowVolumeMapper::SafeDownCast(this->VolumeMapper);
  if (vtkDeepShadowTechnique* technique = mapper ? mapper->GetShadowTechnique() : nullptr)
  {
    for (const auto& statistic : technique->GetStatistics())
    {
      text << (text.tellp() > 0 ? " " : "") << statistic.first << "=" << statistic.second;
    }
  }
  this->StatisticsText = text.str();
  return this->StatisticsText.c_str();
}

void vtkDeepShadowVolumeRepresentation::ChooseShadowLights()
{
  if (!this->Renderer)
  {
    return;
  }
  // The lights that are on, brightest first (stable: equal intensities keep their order).
  std::vector<vtkLight*> lit;
  vtkLightCollection* lights = this->Renderer->GetLights();
  lights->InitTraversal();
  while (vtkLight* light = lights->GetNextItem())
  {
    if (light->GetSwitch())
    {
      lit.push_back(light);
    }
  }
  std::stable_sort(lit.begin(), lit.end(),
    [](vtkLight* a, vtkLight* b) { return a->GetIntensity() > b->GetIntensity(); });
  // The key light alone, or the brightest four: the mapper shadows at most four, and
  // ParaView's light kit has five (choosing here keeps the technique from warning each frame).
  const size_t casting = std::min<size_t>(this->ShadowLights == 1 ? 4 : 1, lit.size());
  lights->InitTraversal();
  while (vtkLight* light = lights->GetNextItem())
  {
    const bool casts = std::find(lit.begin(), lit.begin() + static_cast<std::ptrdiff_t>(casting), light) !=
      lit.begin() + static_cast<std::ptrdiff_t>(casting);
    const double attenuation = casts ? 1.0 : 0.0;
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
  os << indent << "ShadowGround: " << this->ShadowGround << "\n";
  os << indent << "ShadowInteractiveLag: " << this->GetShadowInteractiveLag() << " degrees\n";
  os << indent << "ShadowInteractiveSubsampling: " << this->GetShadowInteractiveSubsampling() << "\n";
}
