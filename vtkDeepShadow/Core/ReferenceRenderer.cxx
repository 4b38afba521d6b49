#include "Core/ReferenceRenderer.h"

#include "Core/Jitter.h"
#include "Core/Mask.h"
#include "Core/Parallel.h"
#include "Core/Shadows/ShadowGrid.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <limits>
#include <stdexcept>

namespace deepshadow
{

namespace
{
// A mesh crossing, or a volume's sample (or segment), along a view ray.
struct Fragment
{
  RaySample Sample;
  bool FirstVolume;
};

// The surface term of Render(): the shadow term of the first fragment with which the view
// ray's opacity (`opacity`, this fragment composited) reaches ReceiverOpacity (kept in
// `surface` once found).
void FollowReceiver(double opacity, const RaySample& sample, glm::dvec3& surface, bool& found)
{
  if (!found && opacity >= ReferenceRenderer::ReceiverOpacity && sample.Term.a > 0.0)
  {
    surface = glm::dvec3(sample.Term) / sample.Term.a;
    found = true;
  }
}

// Scene::VolumeSegments: a volume's samples along `ray` (as MarchRay gives them, up to
// `tEnd`) grouped into `count` segments of equal length over its march interval, each
// composited on its own and placed at its opacity-weighted mean depth. Empty segments are
// left out.
std::vector<RaySample> Segments(
  const std::vector<RaySample>& samples, const Ray& ray, const VolumeGrid& grid, double tEnd, int count)
{
  double t0 = 0.0, t1 = 0.0;
  if (samples.empty() || !ReferenceRenderer::MarchInterval(ray, grid, tEnd, t0, t1))
  {
    return {};
  }
  std::vector<RaySample> segments(static_cast<size_t>(count));
  std::vector<double> weightedT(segments.size(), 0.0);
  for (const RaySample& sample : samples)
  {
    const int s = std::clamp(static_cast<int>((sample.T - t0) / (t1 - t0) * count), 0, count - 1);
    RaySample& segment = segments[static_cast<size_t>(s)];
    weightedT[static_cast<size_t>(s)] += (1.0 - segment.Color.a) * sample.Color.a * sample.T;
    CompositeFrontToBack(segment.Color, sample.Color);
    CompositeFrontToBack(segment.Term, sample.Term);
  }
  std::vector<RaySample> kept;
  for (size_t s = 0; s < segments.size(); ++s)
  {
    if (segments[s].Color.a > 0.0)
    {
      segments[s].T = weightedT[s] / segments[s].Color.a;
      kept.push_back(segments[s]);
    }
  }
  return kept;
}
}

MarchSettings MarchSettings::GpuTwin(
  double sampleDistance, int tableSize, bool jitter, uint32_t seed, double terminationOpacity)
{
  MarchSettings settings;
  settings.SampleDistance = sampleDistance;
  settings.Jitter = jitter;
  settings.JitterSeed = seed;
  settings.TerminationOpacity = terminationOpacity;
  settings.TransferTableSize = tableSize;
  return settings;
}

const LightShadow* ReferenceRenderer::PreparedVolume::ReceiverLookup(size_t light) const
{
  const auto& lookups = this->DirectShadows.empty() ? this->Shadows : this->DirectShadows;
  return light < lookups.size() ? lookups[light].get() : nullptr;
}

ReferenceRenderer::PreparedVolume ReferenceRenderer::Prepare(const Scene& scene,
  const VolumeInstance& volume, const MarchSettings& settings, int threads, bool castSurfaces)
{
  PreparedVolume prepared;
  const glm::dvec2 range = volume.Grid->GetRange();
  const bool projection = volume.Projection.Mode != BlendMode::Composite;
  const bool isosurface = !volume.IsoValues.empty();
  if (settings.TransferTableSize > 0)
  {
    // Projections but additive, and isosurfaces, look opacity up uncorrected: a step of one
    // unit distance corrects nothing.
    const bool uncorrected = isosurface || (projection && !volume.Projection.CorrectsOpacity());
    prepared.Table = std::make_unique<TransferTable>(TransferTable::Sample(volume.Transfer,
      range.x, range.y, settings.TransferTableSize,
      uncorrected ? volume.Transfer.OpacityUnitDistance : settings.SampleDistance));
  }
  if (volume.Labels && settings.TransferTableSize > 0)
  {
    // Each label's function over the volume's range, uncorrected (a step of its unit distance).
    prepared.LabelTables = std::make_unique<std::vector<TransferTable>>();
    for (const TransferFunction& function : volume.Labels->Functions)
    {
      prepared.LabelTables->push_back(TransferTable::Sample(
        function, range.x, range.y, settings.TransferTableSize, function.OpacityUnitDistance));
    }
  }
  if (volume.Components)
  {
    prepared.Components = std::make_unique<ComponentLookup>(*volume.Components, *volume.Grid, volume.Transfer,
      settings.SampleDistance, settings.TransferTableSize, projection && !volume.Projection.CorrectsOpacity());
  }
  // A projection counts transparent samples too; an isosurface's crossings lie anywhere;
  // the block map knows one component's 1D opacity only, and not the labels'.
  if (settings.EmptySpaceSkipping && !projection && !isosurface && !volume.Components && !volume.Labels &&
    !volume.Function2D)
  {
    prepared.Empty = std::make_unique<EmptySpaceMap>(*volume.Grid, volume.Transfer.Opacity);
  }
  prepared.Shadows.resize(scene.Lights.size());
  if (volume.Shadows.Kind == ShadowKind::None)
  {
    return prepared;
  }
  const TransferFunction& casting = volume.ShadowTransfer ? *volume.ShadowTransfer : volume.Transfer;
  ShadowCaster caster;
  caster.Grid = volume.Grid.get();
  caster.Transfer = &casting;
  caster.Sampling = volume.Sampling;
  caster.Empty = prepared.Empty.get();
  caster.Bound = volume.Bound.get();
  caster.Surfaces = castSurfaces ? scene.CastingSurfaces.get() : nullptr;
  caster.IsoValues = isosurface ? &volume.IsoValues : nullptr;
  caster.Gradient = volume.Gradient ? &*volume.Gradient : nullptr;
  caster.Mask = volume.Mask.get();
  caster.Labels = volume.Labels.get();
  caster.Function2D = volume.Function2D.get();
  caster.ViewStep = settings.SampleDistance;
  caster.LabelTables = prepared.LabelTables.get();
  caster.Eye = scene.View.Unproject(0.5 * scene.View.GetWidth(), 0.5 * scene.View.GetHeight(), 0.0);
  caster.View = &scene.View;
  if (volume.ShadowTransfer && settings.EmptySpaceSkipping && !isosurface && !volume.Components && !volume.Labels &&
    !volume.Function2D)
  {
    prepared.ShadowEmpty = std::make_unique<EmptySpaceMap>(*volume.Grid, casting.Opacity);
    caster.Empty = prepared.ShadowEmpty.get();
  }
  if (settings.TransferTableSize > 0)
  {
    prepared.FeelerTable = std::make_unique<TransferTable>(TransferTable::Sample(casting,
      range.x, range.y, settings.TransferTableSize,
      isosurface ? casting.OpacityUnitDistance : volume.Shadows.StepFactor * settings.SampleDistance));
    caster.FeelerTable = prepared.FeelerTable.get();
  }
  if (volume.Components)
  {
    prepared.FeelerComponents = std::make_unique<ComponentLookup>(*volume.Components, *volume.Grid, casting,
      volume.Shadows.StepFactor * settings.SampleDistance, settings.TransferTableSize);
    caster.Components = prepared.FeelerComponents.get();
  }
  for (size_t l = 0; l < scene.Lights.size(); ++l)
  {
    if (scene.Lights[l].ShadowAttenuation > 0.0)
    {
      prepared.Shadows[l] =
        MakeLightShadow(volume.Shadows, caster, scene.Lights[l], settings.SampleDistance, threads);
      // A cache's grid covers its own box only: receivers elsewhere need the technique itself.
      const bool receiversElsewhere = (scene.Surfaces && !scene.Surfaces->Empty()) ||
        std::count_if(scene.Volumes.begin(), scene.Volumes.end(),
          [](const VolumeInstance& v) { return v.Shadows.Kind != ShadowKind::None; }) > 1;
      if (volume.Shadows.Cached && receiversElsewhere)
      {
        ShadowParameters direct = volume.Shadows;
        direct.Cached = false;
        prepared.DirectShadows.resize(scene.Lights.size());
        prepared.DirectShadows[l] =
          MakeLightShadow(direct, caster, scene.Lights[l], settings.SampleDistance, threads);
      }
    }
  }
  return prepared;
}

namespace
{
using PreparedVolume = ReferenceRenderer::PreparedVolume;

// Refuses the scene before any work, as the GPU mapper does: nothing that would take hours
// (the GPU's bound on samples a ray, MaxRayIterations).
void CheckVolumeSamples(const Scene& scene, const MarchSettings& settings)
{
  for (const VolumeInstance& volume : scene.Volumes)
  {
    const double longest = LongestPath(volume.Grid->GetIndexToWorld(), volume.Grid->GetDims());
    std::string problem = CheckRaySamples(longest, settings.SampleDistance, "the sample distance");
    if (problem.empty() && volume.Shadows.Kind != ShadowKind::None)
    {
      problem = CheckRaySamples(longest, volume.Shadows.StepFactor * settings.SampleDistance, "the shadow step");
    }
    if (!problem.empty())
    {
      throw std::invalid_argument(problem);
    }
  }
}

// The first shadowing volume is the meshes' shadow source and holds the casting meshes;
// scene.Volumes.size() when no volume shadows.
size_t ShadowSource(const Scene& scene)
{
  size_t source = scene.Volumes.size();
  for (size_t v = 0; v < scene.Volumes.size() && source == scene.Volumes.size(); ++v)
  {
    if (scene.Volumes[v].Shadows.Kind != ShadowKind::None)
    {
      source = v;
    }
  }
  return source;
}

// What the shadowing volumes other than `skip` cast for light l: their product, exact or
// on the pass's grid over `frame`.
std::unique_ptr<LightShadow> OthersCast(const Scene& scene, const std::vector<PreparedVolume>& prepared,
  int threads, size_t skip, size_t l, const GridFrame* frame)
{
  std::vector<const LightShadow*> factors;
  for (size_t u = 0; u < prepared.size(); ++u)
  {
    const LightShadow* lookup = u == skip ? nullptr : prepared[u].ReceiverLookup(l);
    if (lookup)
    {
      factors.push_back(lookup);
    }
  }
  if (factors.empty())
  {
    return nullptr;
  }
  auto product = std::make_unique<ProductShadow>(std::move(factors));
  if (!frame)
  {
    return product;
  }
  const bool colored = std::any_of(scene.Volumes.begin(), scene.Volumes.end(),
    [](const VolumeInstance& v) { return v.Shadows.IsColored(); });
  const ProductShadow& evaluate = *product;
  return std::make_unique<ShadowGrid>(
    [&evaluate](const glm::dvec3& p) { return evaluate.Visibility(p); }, *frame, colored, threads);
}

// Fills each shadow-receiving volume's OtherShadows: what the other volumes cast onto it.
void CastOtherVolumeShadows(const Scene& scene, std::vector<PreparedVolume>& prepared, int threads)
{
  const bool onGrids = scene.OtherVolumeShadowSize > 0;
  for (size_t v = 0; v < prepared.size(); ++v)
  {
    if (scene.Volumes[v].Shadows.Kind == ShadowKind::None)
    {
      continue; // a volume receives shadows when it has a technique
    }
    const VolumeGrid& grid = *scene.Volumes[v].Grid;
    const GridFrame frame =
      GridFrame::OverVolume(grid.GetDims(), grid.GetIndexToWorld(), scene.OtherVolumeShadowSize);
    prepared[v].OtherShadows.resize(scene.Lights.size());
    for (size_t l = 0; l < scene.Lights.size(); ++l)
    {
      prepared[v].OtherShadows[l] = OthersCast(scene, prepared, threads, v, l, onGrids ? &frame : nullptr);
    }
  }
}

// Per drawn mesh and light: the source's lookups, and what the other volumes cast onto it.
// Owns the shadows it points to, so it must outlive the image's shading.
struct MeshShadows
{
  std::vector<const LightShadow*> SourceLookups;
  std::vector<std::vector<const LightShadow*>> Others; // per mesh; empty if it receives none
  std::vector<std::unique_ptr<LightShadow>> ExactOthers; // per light, exact casts
  std::vector<std::unique_ptr<LightShadow>> OthersStore; // per mesh and light, on grids
  const std::vector<const LightShadow*> None;
};

void GatherMeshShadows(const Scene& scene, const std::vector<PreparedVolume>& prepared, int threads,
  size_t source, MeshShadows& meshes)
{
  const bool onGrids = scene.OtherVolumeShadowSize > 0;
  const size_t meshCount = scene.Surfaces ? static_cast<size_t>(scene.Surfaces->GetSurfaceCount()) : 0;
  meshes.SourceLookups.assign(scene.Lights.size(), nullptr);
  meshes.Others.resize(meshCount);
  if (source >= prepared.size())
  {
    return;
  }
  for (size_t l = 0; l < scene.Lights.size(); ++l)
  {
    meshes.SourceLookups[l] = prepared[source].ReceiverLookup(l);
    if (!onGrids)
    {
      meshes.ExactOthers.push_back(OthersCast(scene, prepared, threads, source, l, nullptr));
    }
  }
  for (size_t s = 0; s < meshCount; ++s)
  {
    const SurfaceMesh& mesh = scene.Surfaces->GetSurface(static_cast<int>(s));
    if (!mesh.ReceivesShadows)
    {
      continue;
    }
    glm::dvec3 lo, hi;
    MeshBounds(mesh, lo, hi);
    const GridFrame frame = onGrids ? GridFrame::OverBox(lo, hi, scene.OtherVolumeShadowSize) : GridFrame();
    for (size_t l = 0; l < scene.Lights.size(); ++l)
    {
      if (onGrids)
      {
        meshes.OthersStore.push_back(OthersCast(scene, prepared, threads, source, l, &frame));
      }
      meshes.Others[s].push_back(onGrids ? meshes.OthersStore.back().get() : meshes.ExactOthers[l].get());
    }
  }
}

// Mesh crossings in depth order, up to the first opaque one (which ends the ray), shaded and
// appended to `fragments`; returns where the ray ends (infinity if no opaque crossing).
double CollectMeshFragments(const Scene& scene, const MarchSettings& settings, const MeshShadows& meshes,
  double receiverBias, const Ray& ray, std::vector<Fragment>& fragments)
{
  double tEnd = std::numeric_limits<double>::infinity();
  int translucent = 0;
  for (SurfaceHit hit = scene.Surfaces ? scene.Surfaces->NextHit(ray.Origin, ray.Direction, 0.0) : SurfaceHit();
       hit.Found; hit = scene.Surfaces->NextHit(ray.Origin, ray.Direction, hit.T))
  {
    const SurfaceMesh& mesh = scene.Surfaces->GetSurface(hit.Surface);
    const bool opaque = mesh.Material.Opacity >= 1.0;
    // Behind the last peeled layer: left out, as on the GPU.
    if (opaque || scene.TranslucentLayers == 0 || translucent < scene.TranslucentLayers)
    {
      glm::dvec3 term;
      const glm::dvec3 color = ReferenceRenderer::ShadeSurface(scene, *scene.Surfaces, hit, ray,
        mesh.ReceivesShadows ? meshes.SourceLookups : meshes.None,
        mesh.ReceivesShadows ? meshes.Others[hit.Surface] : meshes.None, receiverBias, &term);
      const double alpha = std::clamp(mesh.Material.Opacity, 0.0, 1.0);
      const glm::dvec3 shown = settings.Output == RenderOutput::ShadowTerm ? term : color;
      fragments.push_back({ { hit.T, glm::dvec4(alpha * shown, alpha), glm::dvec4(alpha * term, alpha) }, false });
      translucent += opaque ? 0 : 1;
    }
    if (opaque)
    {
      tEnd = hit.T;
      break;
    }
  }
  return tEnd;
}

// Meshes and every volume along one view ray, composited in depth order over `pixel` and
// `termPixel` (the GPU twin's merge of meshes, peeled layers and further volumes).
void CompositeMeshesAndVolumes(const Scene& scene, const MarchSettings& settings,
  const std::vector<PreparedVolume>& prepared, const MeshShadows& meshes, double receiverBias,
  const Ray& ray, double offset, glm::dvec3& pixel, glm::dvec3& termPixel, glm::dvec3& surfacePixel)
{
  std::vector<Fragment> fragments;
  const double tEnd = CollectMeshFragments(scene, settings, meshes, receiverBias, ray, fragments);
  // Every volume's samples before it: the first's one by one, the others' one by one
  // (exact) or in segments (the GPU twin).
  std::vector<RaySample> samples;
  for (size_t v = 0; v < scene.Volumes.size(); ++v)
  {
    samples.clear();
    ReferenceRenderer::MarchRay(scene, scene.Volumes[v], prepared[v], ray, tEnd, offset, settings, nullptr, &samples);
    if (v > 0 && scene.VolumeSegments > 0)
    {
      samples = Segments(samples, ray, *scene.Volumes[v].Grid, tEnd, scene.VolumeSegments);
    }
    for (const RaySample& sample : samples)
    {
      fragments.push_back({ sample, v == 0 });
    }
  }
  // Stable: a mesh crossing and a sample at the same depth keep the crossing first.
  std::stable_sort(fragments.begin(), fragments.end(),
    [](const Fragment& a, const Fragment& b) { return a.Sample.T < b.Sample.T; });
  glm::dvec4 front(0.0);
  glm::dvec4 termFront(0.0);
  bool terminated = false, found = false;
  for (const Fragment& fragment : fragments)
  {
    // The first volume's march stops once the ray, all it merged included, is nearly
    // opaque (GPU twin); each volume's own march stopped in MarchRay already.
    terminated = terminated || (fragment.FirstVolume && front.a > settings.TerminationOpacity);
    if (fragment.FirstVolume && terminated)
    {
      continue;
    }
    CompositeFrontToBack(front, fragment.Sample.Color);
    CompositeFrontToBack(termFront, fragment.Sample.Term);
    FollowReceiver(front.a, fragment.Sample, surfacePixel, found);
  }
  pixel = glm::dvec3(front) + (1.0 - front.a) * pixel;
  termPixel = glm::dvec3(termFront) + (1.0 - termFront.a) * termPixel;
}
}

Image ReferenceRenderer::Render(const Scene& scene, const MarchSettings& settings, int threads,
  Image* shadowTerm, Image* surfaceTerm)
{
  CheckVolumeSamples(scene, settings);
  const int width = scene.View.GetWidth();
  const int height = scene.View.GetHeight();
  Image image(width, height);
  if (shadowTerm)
  {
    *shadowTerm = Image(width, height);
  }
  if (surfaceTerm)
  {
    *surfaceTerm = Image(width, height);
  }

  const size_t source = ShadowSource(scene);
  std::vector<PreparedVolume> prepared;
  for (size_t v = 0; v < scene.Volumes.size(); ++v)
  {
    prepared.push_back(Prepare(scene, scene.Volumes[v], settings, threads, v == source));
  }
  double receiverBias = scene.ReceiverBias;
  if (source < scene.Volumes.size() && !(receiverBias > 0.0))
  {
    receiverBias = DefaultReceiverBias(scene.Volumes[source].Shadows.StepFactor * settings.SampleDistance);
  }
  CastOtherVolumeShadows(scene, prepared, threads);
  MeshShadows meshes;
  GatherMeshShadows(scene, prepared, threads, source, meshes);

  ParallelFor(
    height,
    [&](int y) {
      for (int x = 0; x < width; ++x)
      {
        const Ray ray = scene.View.PixelRay(x, y);
        const double offset = settings.Jitter
          ? JitterOffset(static_cast<uint32_t>(x), static_cast<uint32_t>(y), settings.JitterSeed)
          : UnjitteredOffset;
        glm::dvec3 pixel = scene.Background;
        glm::dvec3 termPixel = scene.Background;
        glm::dvec3 surfacePixel(-1.0);
        if ((scene.Surfaces && !scene.Surfaces->Empty()) || scene.Volumes.size() > 1)
        {
          CompositeMeshesAndVolumes(
            scene, settings, prepared, meshes, receiverBias, ray, offset, pixel, termPixel, surfacePixel);
        }
        else if (!scene.Volumes.empty())
        {
          glm::dvec4 term(0.0);
          std::vector<RaySample> samples;
          const glm::dvec4 rgba = MarchRay(scene, scene.Volumes[0], prepared[0], ray,
            std::numeric_limits<double>::infinity(), offset, settings, shadowTerm ? &term : nullptr,
            surfaceTerm ? &samples : nullptr);
          glm::dvec4 front(0.0);
          bool found = false;
          for (const RaySample& sample : samples)
          {
            CompositeFrontToBack(front, sample.Color);
            FollowReceiver(front.a, sample, surfacePixel, found);
          }
          // The GPU writes the volume to an 8-bit target, which clamps its colour (above 1 where
          // independent components overlap, as in VTK's) before it is blended.
          pixel = glm::clamp(glm::dvec3(rgba), 0.0, 1.0) + (1.0 - rgba.a) * pixel;
          termPixel = glm::dvec3(term) + (1.0 - term.a) * termPixel;
        }
        image.Set(x, y, pixel);
        if (shadowTerm)
        {
          shadowTerm->Set(x, y, termPixel);
        }
        if (surfaceTerm)
        {
          surfaceTerm->Set(x, y, surfacePixel);
        }
      }
    },
    threads);
  return image;
}

}
