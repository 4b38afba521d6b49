#include "vtkDeepShadowPass.h"

#include "PassFrame.h"
#include "Shadows/OtherVolumeShadows.h"
#include "Sampling/ShadowContext.h"
#include "Core/Geometry/SurfaceSet.h"
#include "Translucency/TranslucentLayers.h"
#include "vtkDeepShadowCastingMeshes.h"
#include "vtkDeepShadowPolyDataMapper.h"
#include "vtkDeepShadowVolumeMapper.h"

#include "vtkActor.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPolyData.h"
#include "vtkProp.h"
#include "vtkProperty.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <vector>

vtkStandardNewMacro(vtkDeepShadowPass);

namespace
{
using VolumeEntries = std::vector<std::pair<vtkVolume*, vtkDeepShadowVolumeMapper*>>;
using MeshEntries = std::vector<std::pair<vtkActor*, vtkDeepShadowPolyDataMapper*>>;

// The visible props this pass drives: volumes and meshes drawn by our mappers.
void CollectProps(const vtkRenderState* state, VolumeEntries& volumes, MeshEntries& meshes)
{
  for (int i = 0; i < state->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = state->GetPropArray()[i];
    if (!prop->GetVisibility())
    {
      continue;
    }
    if (auto* volume = vtkVolume::SafeDownCast(prop))
    {
      if (auto* mapper = vtkDeepShadowVolumeMapper::SafeDownCast(volume->GetMapper()))
      {
        volumes.emplace_back(volume, mapper);
      }
    }
    else if (auto* actor = vtkActor::SafeDownCast(prop))
    {
      if (auto* mapper = vtkDeepShadowPolyDataMapper::SafeDownCast(actor->GetMapper()))
      {
        meshes.emplace_back(actor, mapper);
      }
    }
  }
}

// Hands every mapper the frame (null: takes it back).
void HandFrame(const VolumeEntries& volumes, const MeshEntries& meshes, deepshadow::PassFrame* frame)
{
  for (const auto& entry : volumes)
  {
    entry.second->SetPassFrame(frame);
  }
  for (const auto& entry : meshes)
  {
    entry.second->SetPassFrame(frame);
  }
}
}

class vtkDeepShadowPass::Internals
{
public:
  vtkNew<vtkDeepShadowCastingMeshes> Casting; // the casting meshes, gathered again on change
  // What the mappers read this frame; empty between frames.
  deepshadow::PassFrame Frame;
  deepshadow::TranslucentLayers Layers;
  std::string SegmentError; // the last one said (once per change)

  // What the other volumes cast, per receiver: volumes by mapper, meshes by actor (with the
  // grid's frame over the mesh's points, found again only when the mesh changed).
  std::map<vtkDeepShadowVolumeMapper*, deepshadow::OtherVolumeShadows> VolumeGrids;
  struct MeshGrid
  {
    std::vector<double> Key;
    deepshadow::GridFrame Frame;
    deepshadow::OtherVolumeShadows Grid;
  };
  std::map<vtkActor*, MeshGrid> MeshGrids;

  void ReleaseGrids(vtkWindow* window)
  {
    for (auto& entry : this->VolumeGrids)
    {
      entry.second.Release(window);
    }
    for (auto& entry : this->MeshGrids)
    {
      entry.second.Grid.Release(window);
    }
    this->VolumeGrids.clear();
    this->MeshGrids.clear();
  }
};

vtkDeepShadowPass::vtkDeepShadowPass()
  : Impl(new Internals)
{
}

vtkDeepShadowPass::~vtkDeepShadowPass() = default;

void vtkDeepShadowPass::Render(const vtkRenderState* state)
{
  Internals& impl = *this->Impl;
  vtkRenderer* renderer = state->GetRenderer();
  // What vtkCameraPass and vtkLightsPass do: camera (which clears), then the lights, which the
  // shadow structures are built for.
  this->UpdateCamera(renderer);
  this->UpdateLightGeometry(renderer);
  this->UpdateLights(renderer);
  VolumeEntries volumes;
  MeshEntries meshes;
  CollectProps(state, volumes, meshes);

  if (impl.Casting->Update(meshes))
  {
    this->LastError = impl.Casting->GetLastError();
  }
  this->SurfaceSetBuilds = impl.Casting->GetBuilds();
  this->CastingMeshes = impl.Casting->GetCount();

  // Every volume with a technique casts shadows onto the others and onto the meshes. The
  // first one is the meshes' shadow source and holds the casting meshes (so that they count
  // once); the others reach each receiver through a grid (deepshadow::OtherVolumeShadows).
  VolumeEntries shadowing;
  for (const auto& entry : volumes)
  {
    if (entry.second->GetShadowTechnique())
    {
      shadowing.push_back(entry);
    }
  }
  // One frame object for all our mappers, handed over now and taken back at the end. (A
  // volume takes its casting surfaces from it at once: a replaced set marks it modified.)
  impl.Frame = deepshadow::PassFrame();
  impl.Frame.Surfaces = impl.Casting->GetSurfaces();
  impl.Frame.SurfaceHolder = shadowing.empty() ? nullptr : shadowing.front().second;
  HandFrame(volumes, meshes, &impl.Frame);
  std::vector<deepshadow::VolumeCaster> casters(shadowing.size());
  if (!meshes.empty() || shadowing.size() > 1)
  {
    for (size_t v = 0; v < shadowing.size(); ++v)
    {
      casters[v].Context = shadowing[v].second->PrepareShadows(renderer, shadowing[v].first);
      casters[v].Technique = shadowing[v].second->GetShadowTechnique();
    }
  }
  impl.Frame.Source = casters.empty() ? nullptr : casters.front().Context;
  impl.Frame.SourceTechnique = impl.Frame.Source ? casters.front().Technique : nullptr;
  this->UpdateOtherVolumeShadows(renderer, shadowing, casters, meshes);

  // Translucent meshes go into layers, and the volumes after the first into segments, when
  // the first volume will merge them into its march.
  const bool glWindow = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow()) != nullptr;
  MeshEntries peeled;
  if (this->TranslucentLayers > 0 && !volumes.empty() && glWindow)
  {
    for (const auto& entry : meshes)
    {
      if (entry.first->HasTranslucentPolygonalGeometry())
      {
        peeled.push_back(entry);
      }
    }
  }
  VolumeEntries guests;
  if (this->VolumeSegments > 0 && glWindow && volumes.size() > 1)
  {
    guests.assign(volumes.begin() + 1, volumes.end());
  }
  this->PeeledLayers = 0;
  this->TranslucentLayersOverflowed = false;
  this->MergedVolumes = 0;
  if (peeled.empty() && guests.empty())
  {
    this->Superclass::Render(state);
  }
  else
  {
    this->RenderMerged(state, volumes.front().second, guests, peeled);
  }
  if (guests.empty())
  {
    impl.Layers.GetSegments().Release(renderer->GetRenderWindow());
  }
  this->VolumeSegmentBytes = impl.Layers.GetSegments().GetBytes();
  this->TranslucentLayerBytes = impl.Layers.GetBytes();

  // The frame ends: the mappers let go of it, and it lets go of the contexts.
  HandFrame(volumes, meshes, nullptr);
  impl.Frame = deepshadow::PassFrame();
}

void vtkDeepShadowPass::UpdateOtherVolumeShadows(vtkRenderer* renderer,
  const std::vector<std::pair<vtkVolume*, vtkDeepShadowVolumeMapper*>>& shadowing,
  const std::vector<deepshadow::VolumeCaster>& casters,
  const std::vector<std::pair<vtkActor*, vtkDeepShadowPolyDataMapper*>>& meshes)
{
  Internals& impl = *this->Impl;
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  this->OtherVolumeShadowBytes = 0;
  // Casters other than `skip` whose structures are ready.
  const auto othersThan = [&casters](size_t skip) {
    std::vector<deepshadow::VolumeCaster> others;
    for (size_t u = 0; u < casters.size(); ++u)
    {
      if (u != skip && casters[u].Context)
      {
        others.push_back(casters[u]);
      }
    }
    return others;
  };
  const auto update = [&](deepshadow::OtherVolumeShadows& grid, const deepshadow::GridFrame& frame,
                        const std::vector<deepshadow::VolumeCaster>& others) {
    const int before = grid.GetBuildCount();
    std::string error;
    if (!grid.Update(window, frame, others, error))
    {
      vtkErrorMacro(<< error);
    }
    this->OtherVolumeShadowBuilds += grid.GetBuildCount() - before;
    this->OtherVolumeShadowBytes += grid.GetBytes();
    return grid.Any() ? &grid : nullptr;
  };

  std::map<vtkDeepShadowVolumeMapper*, deepshadow::OtherVolumeShadows> volumeGrids;
  std::map<vtkActor*, Internals::MeshGrid> meshGrids;
  for (size_t v = 0; v < shadowing.size() && window; ++v)
  {
    const std::vector<deepshadow::VolumeCaster> others = othersThan(v);
    vtkDeepShadowVolumeMapper* mapper = shadowing[v].second;
    if (others.empty() || !casters[v].Context)
    {
      continue;
    }
    deepshadow::OtherVolumeShadows& grid = volumeGrids[mapper];
    if (auto found = impl.VolumeGrids.find(mapper); found != impl.VolumeGrids.end())
    {
      grid = std::move(found->second);
      impl.VolumeGrids.erase(found);
    }
    const deepshadow::ShadowContext& context = *casters[v].Context;
    impl.Frame.Others[mapper] = update(grid,
      deepshadow::GridFrame::OverVolume(context.Dims, context.IndexToWorld, this->OtherVolumeShadowSize),
      others);
  }
  const std::vector<deepshadow::VolumeCaster> others = othersThan(0); // the source aside
  for (const auto& [actor, mapper] : meshes)
  {
    if (others.empty() || !casters.front().Context || !mapper->GetReceiveShadows() || !window)
    {
      continue;
    }
    Internals::MeshGrid& entry = meshGrids[actor];
    if (auto found = impl.MeshGrids.find(actor); found != impl.MeshGrids.end())
    {
      entry = std::move(found->second);
      impl.MeshGrids.erase(found);
    }
    vtkPolyData* input = mapper->GetInput();
    std::vector<double> key{ static_cast<double>(mapper->GetMTime()),
      static_cast<double>(input ? input->GetMTime() : 0), static_cast<double>(this->OtherVolumeShadowSize) };
    const double* m = actor->GetMatrix()->GetData();
    key.insert(key.end(), m, m + 16);
    if (key != entry.Key)
    {
      deepshadow::SurfaceMesh mesh;
      std::string error;
      if (!mapper->GetSurfaceMesh(actor, mesh, error))
      {
        continue; // the mapper says why when it draws
      }
      glm::dvec3 lo, hi;
      deepshadow::MeshBounds(mesh, lo, hi);
      entry.Frame = deepshadow::GridFrame::OverBox(lo, hi, this->OtherVolumeShadowSize);
      entry.Key = key;
    }
    impl.Frame.Others[mapper] = update(entry.Grid, entry.Frame, others);
  }
  // Receivers gone from the scene give their grids back.
  impl.ReleaseGrids(window);
  impl.VolumeGrids = std::move(volumeGrids);
  impl.MeshGrids = std::move(meshGrids);
}

void vtkDeepShadowPass::RenderMerged(const vtkRenderState* state, vtkDeepShadowVolumeMapper* merging,
  const std::vector<std::pair<vtkVolume*, vtkDeepShadowVolumeMapper*>>& guests,
  const std::vector<std::pair<vtkActor*, vtkDeepShadowPolyDataMapper*>>& peeled)
{
  Internals& impl = *this->Impl;
  vtkRenderer* renderer = state->GetRenderer();
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  this->NumberOfRenderedProps = 0;
  this->RenderOpaqueGeometry(state);

  int width = 0, height = 0, x0 = 0, y0 = 0;
  renderer->GetTiledSizeAndOrigin(&width, &height, &x0, &y0);
  if (peeled.empty())
  {
    impl.Layers.CaptureOpaque(window, x0, y0, width, height);
  }
  else
  {
    impl.Layers.Peel(window, x0, y0, width, height, this->TranslucentLayers,
      [&](const deepshadow::PeelStep& step) {
        for (const auto& [actor, mapper] : peeled)
        {
          mapper->SetPeelStep(&step);
          actor->RenderTranslucentPolygonalGeometry(renderer);
          mapper->SetPeelStep(nullptr);
        }
      });
    this->PeeledLayers = impl.Layers.GetLayerCount();
    this->TranslucentLayersOverflowed = impl.Layers.GetOverflowed();
  }

  // The other volumes, each into its slices of the segments.
  deepshadow::VolumeSegments& segments = impl.Layers.GetSegments();
  std::string error;
  if (!guests.empty() &&
    !segments.Allocate(window, width, height, static_cast<int>(guests.size()), this->VolumeSegments, error))
  {
    if (error != impl.SegmentError)
    {
      vtkErrorMacro(<< error); // once, until it changes; the guests are blended instead
    }
    impl.SegmentError = error;
    segments.Release(window);
  }
  else if (!guests.empty())
  {
    impl.SegmentError.clear();
    segments.Clear(window); // a guest not drawn this frame (bad input) leaves no old picture
    // The guests are drawn here only (into their slices); the loop below skips them.
    impl.Frame.Segments = &segments;
    for (size_t g = 0; g < guests.size(); ++g)
    {
      impl.Frame.Guests[guests[g].first] = static_cast<int>(g);
    }
    for (const auto& guest : guests)
    {
      this->NumberOfRenderedProps += guest.first->RenderVolumetricGeometry(renderer);
    }
    this->MergedVolumes = static_cast<int>(guests.size());
  }
  impl.Layers.Composite(window, x0, y0, width, height);
  this->NumberOfRenderedProps += static_cast<int>(peeled.size());

  // Other translucent props (not ours) as vtkDefaultPass draws them.
  const auto isOneOf = [](vtkProp* prop, const auto& list) {
    return std::any_of(list.begin(), list.end(), [prop](const auto& entry) { return entry.first == prop; });
  };
  for (int i = 0; i < state->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = state->GetPropArray()[i];
    if (!isOneOf(prop, peeled))
    {
      this->NumberOfRenderedProps += prop->RenderTranslucentPolygonalGeometry(renderer);
    }
  }

  // The merging volume, and volumes that are not ours, as vtkDefaultPass draws them; the
  // merged ones are drawn already.
  impl.Frame.Merging = merging;
  impl.Frame.Layers = &impl.Layers;
  for (int i = 0; i < state->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = state->GetPropArray()[i];
    if (this->MergedVolumes == 0 || !isOneOf(prop, guests))
    {
      this->NumberOfRenderedProps += prop->RenderVolumetricGeometry(renderer);
    }
  }
  this->RenderOverlay(state);
}

void vtkDeepShadowPass::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Impl->Layers.Release(window);
  this->Impl->ReleaseGrids(window);
  this->Superclass::ReleaseGraphicsResources(window);
}

void vtkDeepShadowPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SurfaceSetBuilds: " << this->SurfaceSetBuilds << "\n";
  os << indent << "CastingMeshes: " << this->CastingMeshes << "\n";
  os << indent << "TranslucentLayers: " << this->TranslucentLayers << "\n";
  os << indent << "PeeledLayers: " << this->PeeledLayers << "\n";
  os << indent << "OtherVolumeShadowSize: " << this->OtherVolumeShadowSize << "\n";
  os << indent << "OtherVolumeShadowBuilds: " << this->OtherVolumeShadowBuilds << "\n";
  os << indent << "VolumeSegments: " << this->VolumeSegments << "\n";
  os << indent << "MergedVolumes: " << this->MergedVolumes << "\n";
}
