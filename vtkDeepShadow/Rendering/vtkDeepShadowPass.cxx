#include "vtkDeepShadowPass.h"

#include "SurfaceSet.h"
#include "Translucency/TranslucentLayers.h"
#include "vtkDeepShadowPolyDataMapper.h"
#include "vtkDeepShadowVolumeMapper.h"

#include "vtkActor.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPolyData.h"
#include "vtkProp.h"
#include "vtkProperty.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"

#include <algorithm>
#include <stdexcept>
#include <vector>

vtkStandardNewMacro(vtkDeepShadowPass);

class vtkDeepShadowPass::Internals
{
public:
  std::vector<double> SurfaceKey;
  std::shared_ptr<const deepshadow::SurfaceSet> Surfaces;
  std::vector<vtkDeepShadowPolyDataMapper*> Receivers;
  deepshadow::TranslucentLayers Layers;
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
  std::vector<std::pair<vtkVolume*, vtkDeepShadowVolumeMapper*>> volumes;
  std::vector<std::pair<vtkActor*, vtkDeepShadowPolyDataMapper*>> meshes;
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

  // The casting meshes in world coordinates: gathered again only when one of them changed.
  std::vector<double> key;
  for (const auto& [actor, mapper] : meshes)
  {
    if (!mapper->GetCastShadows())
    {
      continue;
    }
    vtkPolyData* input = mapper->GetInput();
    key.insert(key.end(), { static_cast<double>(reinterpret_cast<uintptr_t>(actor)),
      static_cast<double>(mapper->GetMTime()), static_cast<double>(input ? input->GetMTime() : 0),
      static_cast<double>(actor->GetProperty()->GetMTime()) });
    const double* m = actor->GetMatrix()->GetData();
    key.insert(key.end(), m, m + 16);
  }
  if (key != impl.SurfaceKey || (impl.Surfaces == nullptr) != key.empty())
  {
    impl.SurfaceKey = key;
    impl.Surfaces.reset();
    this->LastError.clear();
    std::vector<deepshadow::SurfaceMesh> casting;
    for (const auto& [actor, mapper] : meshes)
    {
      deepshadow::SurfaceMesh mesh;
      std::string error;
      if (!mapper->GetCastShadows())
      {
        continue;
      }
      if (mapper->GetSurfaceMesh(actor, mesh, error))
      {
        casting.push_back(std::move(mesh));
      }
      else
      {
        vtkWarningMacro("a mesh casts no shadow: " << error);
      }
    }
    try
    {
      if (!casting.empty())
      {
        impl.Surfaces = std::make_shared<const deepshadow::SurfaceSet>(std::move(casting));
        this->CastingMeshes = impl.Surfaces->GetSurfaceCount();
      }
      else
      {
        this->CastingMeshes = 0;
      }
    }
    catch (const std::invalid_argument& e)
    {
      this->LastError = std::string("meshes cast no shadows: ") + e.what();
      this->CastingMeshes = 0;
      vtkErrorMacro(<< this->LastError);
    }
    ++this->SurfaceSetBuilds;
  }

  // Every shadowing volume sees the meshes; the first one's structures light the meshes.
  const deepshadow::ShadowContext* source = nullptr;
  vtkDeepShadowTechnique* technique = nullptr;
  for (const auto& [volume, mapper] : volumes)
  {
    mapper->SetCastingSurfaces(impl.Surfaces);
    if (!source && mapper->GetShadowTechnique() && !meshes.empty())
    {
      source = mapper->PrepareShadows(renderer, volume);
      technique = source ? mapper->GetShadowTechnique() : nullptr;
    }
  }
  for (const auto& [actor, mapper] : meshes)
  {
    mapper->SetShadowSource(source, technique);
  }
  impl.Receivers.clear();
  for (const auto& entry : meshes)
  {
    impl.Receivers.push_back(entry.second);
  }

  // Translucent meshes go into layers when a volume will merge them.
  std::vector<std::pair<vtkActor*, vtkDeepShadowPolyDataMapper*>> peeled;
  if (this->TranslucentLayers > 0 && !volumes.empty() &&
    vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow()))
  {
    for (const auto& entry : meshes)
    {
      if (entry.first->HasTranslucentPolygonalGeometry())
      {
        peeled.push_back(entry);
      }
    }
  }
  this->PeeledLayers = 0;
  this->TranslucentLayersOverflowed = false;
  if (peeled.empty())
  {
    this->Superclass::Render(state);
  }
  else
  {
    this->RenderWithLayers(state, volumes.front().second, peeled);
  }
  this->TranslucentLayerBytes = impl.Layers.GetBytes();

  // The source is valid for this frame only.
  for (vtkDeepShadowPolyDataMapper* mapper : impl.Receivers)
  {
    mapper->SetShadowSource(nullptr, nullptr);
  }
}

void vtkDeepShadowPass::RenderWithLayers(const vtkRenderState* state, vtkDeepShadowVolumeMapper* merging,
  const std::vector<std::pair<vtkActor*, vtkDeepShadowPolyDataMapper*>>& peeled)
{
  Internals& impl = *this->Impl;
  vtkRenderer* renderer = state->GetRenderer();
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  this->NumberOfRenderedProps = 0;
  this->RenderOpaqueGeometry(state);

  int width = 0, height = 0, x0 = 0, y0 = 0;
  renderer->GetTiledSizeAndOrigin(&width, &height, &x0, &y0);
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
  impl.Layers.Composite(window, x0, y0, width, height);
  this->NumberOfRenderedProps += static_cast<int>(peeled.size());

  // Other translucent props (not ours) as vtkDefaultPass draws them.
  for (int i = 0; i < state->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = state->GetPropArray()[i];
    const bool isPeeled = std::any_of(
      peeled.begin(), peeled.end(), [prop](const auto& entry) { return entry.first == prop; });
    if (!isPeeled)
    {
      this->NumberOfRenderedProps += prop->RenderTranslucentPolygonalGeometry(renderer);
    }
  }

  merging->SetTranslucentLayers(&impl.Layers);
  this->RenderVolumetricGeometry(state);
  merging->SetTranslucentLayers(nullptr);
  this->RenderOverlay(state);
}

void vtkDeepShadowPass::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Impl->Layers.Release(window);
  this->Superclass::ReleaseGraphicsResources(window);
}

void vtkDeepShadowPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SurfaceSetBuilds: " << this->SurfaceSetBuilds << "\n";
  os << indent << "CastingMeshes: " << this->CastingMeshes << "\n";
  os << indent << "TranslucentLayers: " << this->TranslucentLayers << "\n";
  os << indent << "PeeledLayers: " << this->PeeledLayers << "\n";
}
