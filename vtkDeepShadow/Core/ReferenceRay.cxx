// The CPU reference's view ray (ReferenceRenderer's per-ray half): where it marches a
// volume, how each sample is classified and lit, the projection blend modes, and the shading
// of a mesh point. ReferenceRenderer.cxx holds the scene's half: preparing the volumes'
// shadows, the meshes' and the other volumes', and compositing the picture.
#include "Core/ReferenceRenderer.h"

#include "Core/Jitter.h"
#include "Core/Mask.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <limits>

namespace deepshadow
{

bool ReferenceRenderer::MarchInterval(const Ray& ray, const VolumeGrid& grid, double tLimit, double& t0, double& t1)
{
  double tEnter = 0.0, tExit = 0.0;
  if (!IntersectBox(ray, grid.GetWorldToIndex(), glm::dvec3(0.0), glm::dvec3(grid.GetDims() - 1), tEnter, tExit))
  {
    return false;
  }
  t0 = std::max(tEnter, 0.0);
  t1 = std::min(tExit, tLimit);
  return true;
}

namespace
{
// A projection blend mode along the ray: every sample inside the bound that a binary mask
// keeps counts, transparent or not, and nothing ends the march early (Features/Projection.glsl).
glm::dvec4 ProjectRay(const VolumeInstance& volume, const TransferTable* table, const ComponentLookup* components,
  const glm::dvec3& indexOrigin, const glm::dvec3& indexDirection, double t0, double t1, double offset, double dt,
  std::optional<BoundRegion::Walker>& bound)
{
  auto colorOpacity = [&](double scalar) {
    if (table)
    {
      return table->Lookup(scalar);
    }
    const double opacity = volume.Transfer.Opacity.Evaluate(scalar);
    return glm::dvec4(volume.Transfer.Color(scalar), volume.Projection.CorrectsOpacity()
        ? CorrectOpacity(opacity, dt, volume.Transfer.OpacityUnitDistance)
        : opacity);
  };
  if (volume.Projection.Mode != BlendMode::Additive)
  {
    offset = std::fmod(offset + 0.5, 1.0); // from the entry, as VTK's (Features/Projection.glsl)
  }
  ProjectionAccumulator projection(volume.Projection);
  std::optional<ComponentProjection> several;
  if (components)
  {
    several.emplace(volume.Projection, *components, dt);
  }
  for (long k = 0;; ++k)
  {
    const double t = t0 + (static_cast<double>(k) + offset) * dt;
    if (!(t < t1))
    {
      break;
    }
    if (bound)
    {
      if (const long skip = bound->SkipSteps(t, dt))
      {
        k += skip - 1;
        continue;
      }
    }
    const glm::dvec3 index = indexOrigin + t * indexDirection;
    if (volume.Mask && !volume.Labels && MaskFactor(volume.Mask.get(), index) <= 0.0)
    {
      continue; // as VTK's: a masked sample is skipped in every blend mode
    }
    if (several)
    {
      several->Add(volume.Components->Sample(*volume.Grid, index, volume.Sampling));
      continue;
    }
    const double scalar = volume.Grid->Sample(index, volume.Sampling);
    projection.Add(scalar, colorOpacity(scalar).a);
  }
  return several ? several->Result() : projection.Result(colorOpacity);
}
}

ReferenceRenderer::ClassifiedSample ReferenceRenderer::Classify(const VolumeInstance& volume,
  const PreparedVolume& prepared, const glm::dvec3& index, double scalar, double dt, double datasetStretch)
{
  const TransferTable* table = prepared.Table.get();
  const VolumeGrid& grid = *volume.Grid;
  const bool isosurface = !volume.IsoValues.empty();
  ClassifiedSample sample;
  glm::dvec3& color = sample.Color;
  double& alpha = sample.Alpha;
  if (prepared.Components)
  {
    sample.ComponentValues = volume.Components->Sample(grid, index, volume.Sampling);
    sample.Colors = prepared.Components->Colors(sample.ComponentValues, dt);
    volume.Components->ApplyGradients(sample.Colors, grid, index, volume.Sampling);
    const glm::dvec4 combined = CombineComponents(*volume.Components, sample.Colors, sample.ComponentValues);
    color = glm::dvec3(combined);
    alpha = combined.a;
  }
  else if (table)
  {
    const glm::dvec4 entry = table->Lookup(scalar);
    color = glm::dvec3(entry);
    alpha = entry.a;
  }
  else
  {
    color = volume.Transfer.Color(scalar);
    const double opacity = volume.Transfer.Opacity.Evaluate(scalar);
    alpha = isosurface ? opacity : CorrectOpacity(opacity, dt, volume.Transfer.OpacityUnitDistance);
  }
  if (volume.Function2D)
  {
    const glm::dvec4 looked = volume.Function2D->At(grid, index, volume.Sampling, scalar);
    color = glm::dvec3(looked);
    alpha = looked.a;
  }
  if (volume.Labels)
  {
    const LabelledSample labelled = volume.Labels->Apply(glm::dvec4(color, alpha), scalar,
      volume.Labels->LabelOf(volume.Mask->Sample(index, Interpolation::Nearest)), 1.0, prepared.LabelTables.get());
    color = glm::dvec3(labelled.Lit);
    alpha = labelled.Lit.a;
    sample.Unlit = labelled.Unlit;
  }
  else
  {
    alpha *= MaskFactor(volume.Mask.get(), index);
  }
  if (volume.Gradient && alpha > 0.0)
  {
    alpha *= volume.Gradient->Factor(grid, index, volume.Sampling);
  }
  if (volume.WorldToDataset)
  {
    alpha = CorrectOpacity(alpha, datasetStretch, 1.0);
  }
  return sample;
}

glm::dvec3 ReferenceRenderer::LitColor(const Scene& scene, const VolumeInstance& volume,
  const PreparedVolume& prepared, const Ray& ray, const glm::dvec3& position, const glm::dvec3& index, double dt,
  ClassifiedSample& sample, bool termOnly, bool wantTerm, std::vector<std::optional<glm::dvec3>>& factors,
  glm::dvec3& term)
{
  const bool shadowed = volume.Shadows.Kind != ShadowKind::None;
  const bool isosurface = !volume.IsoValues.empty();
  const VolumeGrid& grid = *volume.Grid;
  factors.assign(scene.Lights.size(), std::nullopt);
  auto factorOf = [&](size_t l) {
    if (!factors[l])
    {
      const LightShadow* own = shadowed ? prepared.Shadows[l].get() : nullptr;
      const LightShadow* others = l < prepared.OtherShadows.size() ? prepared.OtherShadows[l].get() : nullptr;
      glm::dvec3 factor(1.0);
      if (own || others)
      {
        const glm::dvec3 receiver = isosurface
          ? position + IsoReceiverOffset(volume.Shadows.StepFactor * dt) * scene.Lights[l].At(position).ToLight
          : position;
        glm::dvec3 visibility = own ? own->Visibility(receiver) : glm::dvec3(1.0);
        if (others)
        {
          visibility *= others->Visibility(receiver);
        }
        factor = 1.0 - scene.Lights[l].ShadowAttenuation * (1.0 - visibility);
      }
      factors[l] = factor;
    }
    return *factors[l];
  };
  // What the lights give colour `c` of normal `normal` (Phong) or none (isotropic).
  auto shade = [&](const glm::dvec3& c, const glm::dvec3& normal, const Material& material) {
    if (volume.Shade)
    {
      return ShadeVolumeSample(volume.Shading, c, normal, position, -ray.Direction, scene.Lights,
        material, scene.TwoSidedLighting, factorOf);
    }
    // Isotropic (Light.h): fully lit keeps the colour `c`; Ka A is the shadows' floor.
    const glm::dvec3 ambient = material.Ambient * scene.AmbientLight;
    const glm::dvec3 scattered = glm::max(1.0 - ambient, 0.0) * IsotropicLightScale(scene.Lights) * c;
    glm::dvec3 light = ambient * c;
    for (size_t l = 0; l < scene.Lights.size(); ++l)
    {
      const glm::dvec3 contribution = scattered * scene.Lights[l].VolumeSampleAt(position).Diffuse;
      if (contribution != glm::dvec3(0.0))
      {
        light += contribution * factorOf(l);
      }
    }
    return glm::clamp(light, 0.0, 1.0);
  };
  if (wantTerm)
  {
    for (size_t l = 0; l < scene.Lights.size(); ++l)
    {
      if (scene.Lights[l].VolumeSampleAt(position).Reach > 0.0)
      {
        term *= factorOf(l);
      }
    }
  }
  if (termOnly)
  {
    return glm::clamp(term, 0.0, 1.0);
  }
  if (volume.Components && volume.Components->LitApart(volume.Shade))
  {
    // Each component lit with its own gradient and material, then combined (VTK's).
    for (int i = 0; i < volume.Components->Count(); ++i)
    {
      glm::dvec4& c = sample.Colors[static_cast<size_t>(i)];
      if (c.a > 0.0 && volume.Components->Weights[i] > 0.0)
      {
        const glm::dvec3 normal =
          volume.Shading.Normal(volume.Components->Grid(grid, i).IndexGradient(index, volume.Sampling));
        c = glm::dvec4(shade(glm::dvec3(c), normal, volume.Components->Materials[static_cast<size_t>(i)]), c.a);
      }
    }
    return glm::dvec3(CombineComponents(*volume.Components, sample.Colors, sample.ComponentValues));
  }
  const glm::dvec3 normal =
    volume.Shade ? volume.Shading.Normal(grid.IndexGradient(index, volume.Sampling)) : glm::dvec3(0.0);
  return shade(sample.Color, normal, volume.Surface);
}

glm::dvec4 ReferenceRenderer::MarchRay(const Scene& scene, const VolumeInstance& volume,
  const PreparedVolume& prepared, const Ray& ray, double tLimit, double offset,
  const MarchSettings& settings, glm::dvec4* shadowTerm, std::vector<RaySample>* samples)
{
  const TransferTable* table = prepared.Table.get();
  const bool shadowed = volume.Shadows.Kind != ShadowKind::None;
  const bool termOnly = settings.Output == RenderOutput::ShadowTerm;
  const bool wantTerm = termOnly || shadowTerm || samples;
  const bool lit = volume.Shade || shadowed || termOnly;
  const VolumeGrid& grid = *volume.Grid;
  double t0 = 0.0, t1 = 0.0;
  if (!MarchInterval(ray, grid, tLimit, t0, t1))
  {
    return glm::dvec4(0.0);
  }
  const double dt = settings.SampleDistance;
  const glm::dvec3 indexOrigin = glm::dvec3(grid.GetWorldToIndex() * glm::dvec4(ray.Origin, 1.0));
  const glm::dvec3 indexDirection =
    glm::dvec3(grid.GetWorldToIndex() * glm::dvec4(ray.Direction, 0.0));

  std::optional<BoundRegion::Walker> bound;
  if (volume.Bound)
  {
    bound.emplace(*volume.Bound, indexOrigin, indexDirection);
  }
  if (volume.Projection.Mode != BlendMode::Composite)
  {
    return ProjectRay(
      volume, table, prepared.Components.get(), indexOrigin, indexDirection, t0, t1, offset, dt, bound);
  }

  glm::dvec4 accumulated(0.0);
  glm::dvec4 termAccumulated(0.0);
  const bool isosurface = !volume.IsoValues.empty();
  // Under a prop scaled differently along its axes: this ray's world step in dataset units.
  const double datasetStretch =
    volume.WorldToDataset ? volume.DatasetScale * glm::length(*volume.WorldToDataset * ray.Direction) : 1.0;
  IsoCrossings crossings(isosurface ? &volume.IsoValues : nullptr);
  double previousT = t0; // an isosurface's receiver: the sample before its crossing
  // Each light's shadow factor at the sample at hand, looked up once, when something needs it
  // (held across samples so that the hot loop allocates nothing).
  std::vector<std::optional<glm::dvec3>> factors;
  for (long k = 0;; ++k)
  {
    const double t = t0 + (static_cast<double>(k) + offset) * dt;
    if (!(t < t1) || accumulated.a > settings.TerminationOpacity)
    {
      break;
    }
    if (bound)
    {
      if (const long skip = bound->SkipSteps(t, dt))
      {
        k += skip - 1;
        continue;
      }
    }
    const glm::dvec3 index = indexOrigin + t * indexDirection;
    if (prepared.Empty)
    {
      if (const int skip = prepared.Empty->SkipSteps(index, indexDirection * dt))
      {
        k += skip - 1;
        continue;
      }
    }
    const double scalar = crossings.Next(grid.Sample(index, volume.Sampling));
    double receiverT = t;
    if (isosurface)
    {
      receiverT = previousT;
      previousT = t;
      if (!IsoCrossings::IsCrossing(scalar))
      {
        continue;
      }
    }

    ClassifiedSample sample = Classify(volume, prepared, index, scalar, dt, datasetStretch);
    const double alpha = sample.Alpha;
    if (alpha <= 0.0)
    {
      continue;
    }
    glm::dvec3 color = sample.Color;
    glm::dvec3 termColor(1.0); // nothing shadows an unlit sample
    if (lit)
    {
      glm::dvec3 term(1.0);
      color = LitColor(scene, volume, prepared, ray, ray.Origin + receiverT * ray.Direction, index, dt, sample,
        termOnly, wantTerm, factors, term);
      termColor = glm::clamp(term, 0.0, 1.0);
    }
    if (!termOnly)
    {
      color += sample.Unlit;
    }
    if (shadowTerm)
    {
      CompositeFrontToBack(termAccumulated, termColor, alpha);
    }
    if (samples)
    {
      samples->push_back({ t, glm::dvec4(alpha * color, alpha), glm::dvec4(alpha * termColor, alpha) });
    }
    CompositeFrontToBack(accumulated, color, alpha);
  }
  if (shadowTerm)
  {
    *shadowTerm = termAccumulated;
  }
  return accumulated;
}

glm::dvec3 ReferenceRenderer::ShadeSurface(const Scene& scene, const SurfaceSet& surfaces,
  const SurfaceHit& hit, const Ray& ray, const std::vector<const LightShadow*>& shadows,
  const std::vector<const LightShadow*>& others, double receiverBias, glm::dvec3* term)
{
  const SurfaceMaterial& material = surfaces.GetSurface(hit.Surface).Material;
  const glm::dvec3 color = surfaces.Color(hit);
  // As VTK lights surfaces: two-sided lighting turns a back face's normal to the viewer (the
  // triangle's winding says which face is seen), then each light is one-sided.
  const bool backFace = glm::dot(surfaces.FaceNormal(hit), ray.Direction) > 0.0;
  const glm::dvec3 normal = (scene.TwoSidedLighting && backFace ? -1.0 : 1.0) * surfaces.Normal(hit);
  const glm::dvec3 position = ray.Origin + hit.T * ray.Direction;
  if (term)
  {
    *term = glm::dvec3(1.0);
  }
  glm::dvec3 lit = material.Shading.Ambient * color * scene.AmbientLight;
  for (size_t l = 0; l < scene.Lights.size(); ++l)
  {
    const LightSample sample = scene.Lights[l].At(position);
    glm::dvec3 contribution =
      SurfaceLight(color, normal, -ray.Direction, sample, material.Shading,
      scene.Lights[l].LoneHeadlight, material.SpecularColor);
    const LightShadow* own = l < shadows.size() ? shadows[l] : nullptr;
    const LightShadow* other = l < others.size() ? others[l] : nullptr;
    const bool termReached = term && sample.Reach > 0.0;
    if ((own || other) && (contribution != glm::dvec3(0.0) || termReached))
    {
      const double offset = ReceiverOffset(receiverBias, normal, sample.ToLight);
      const glm::dvec3 at = position + offset * sample.ToLight;
      // Neighbouring texels are compared on the triangle's own plane (its shading normal may
      // be smoothed across edges: MeshNormal.glsl's g_faceNormal).
      glm::dvec3 visibility = own ? own->SurfaceVisibility(at, surfaces.FaceNormal(hit)) : glm::dvec3(1.0);
      if (other)
      {
        visibility *= other->Visibility(at);
      }
      const glm::dvec3 factor = 1.0 - scene.Lights[l].ShadowAttenuation * (1.0 - visibility);
      contribution *= factor;
      if (termReached)
      {
        *term *= factor;
      }
    }
    lit += contribution;
  }
  if (term)
  {
    *term = glm::clamp(*term, 0.0, 1.0);
  }
  return glm::clamp(lit, 0.0, 1.0);
}

}
