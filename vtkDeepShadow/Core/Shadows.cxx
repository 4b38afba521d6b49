#include "Core/Shadows.h"

#include "Core/Bound/BoundRegion.h"
#include "Core/Geometry/SurfaceSet.h"
#include "Core/Camera.h"
#include "Core/Components.h"
#include "Core/GradientOpacity.h"
#include "Core/Isosurface.h"
#include "Core/Mask.h"
#include "Core/Transfer2D.h"
#include "Core/Shadows/LightSpace.h"
#include "Core/OpticalModel.h"
#include "Core/Parallel.h"
#include "Core/Shadows/ShadowGrid.h"
#include "Core/ShadowTechniques.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <limits>
#include <stdexcept>
#include <utility>

namespace deepshadow
{

ShadowParameters ShadowParameters::GroundTruth(bool colored, double stepFactor)
{
  ShadowParameters p;
  p.Kind = ShadowKind::Rays;
  p.Colored = colored;
  p.StepFactor = stepFactor;
  p.EarlyTermination = false;
  return p;
}

// One validation: each key's range as the registry declares it (ShadowTechniques.cxx).
std::string ShadowParameters::Validate() const
{
  for (const ShadowParameterInfo& parameter : ShadowParameterInfos())
  {
    const std::string problem = parameter.Check(parameter.Get(*this));
    if (!problem.empty())
    {
      return problem;
    }
  }
  return std::string();
}

std::string ShadowParameters::Name() const
{
  return ShadowTechniqueOf(*this).Name + (this->Cached && this->Kind != ShadowKind::None ? "-cached" : "");
}

glm::ivec3 ShadowVolumeDims(const glm::ivec3& dataDims, int size)
{
  // Never finer than the data: a feeler per voxel is all the data can tell.
  const int longest = std::max({ dataDims.x, dataDims.y, dataDims.z });
  size = std::min(size, longest);
  glm::ivec3 dims;
  for (int axis = 0; axis < 3; ++axis)
  {
    dims[axis] = std::max(2, static_cast<int>(std::lround(
                               static_cast<double>(dataDims[axis]) * size / longest)));
  }
  return dims;
}

CastSample ShadowCaster::Read(const glm::dvec3& index, IsoCrossings& crossings) const
{
  // A label map keeps every sample (its label decides how it casts); a binary mask clears.
  const double kept = this->Labels ? 1.0 : MaskFactor(this->Mask, index);
  CastSample sample(crossings.Next(this->Grid->Sample(index, this->Sampling)),
    kept * (this->Gradient && kept > 0.0 ? this->Gradient->Factor(*this->Grid, index, this->Sampling) : 1.0));
  if (this->Labels)
  {
    sample.Label = this->Labels->LabelOf(this->Mask->Sample(index, Interpolation::Nearest));
  }
  if (this->Function2D)
  {
    sample.Magnitude = this->Function2D->Gradient.Magnitude(*this->Grid, index, this->Sampling);
  }
  if (this->Components)
  {
    const ComponentSet& set = this->Components->GetSet();
    sample.Values = set.Sample(*this->Grid, index, this->Sampling);
    if (set.HasGradients())
    {
      sample.ComponentGradientFactors = set.GradientFactors(*this->Grid, index, this->Sampling);
    }
  }
  return sample;
}

glm::dvec4 ShadowCaster::Sample(const CastSample& sample, double step) const
{
  const double scalar = sample.Scalar;
  if (this->IsoValues)
  {
    if (!IsoCrossings::IsCrossing(scalar))
    {
      return glm::dvec4(0.0);
    }
    // A surface's opacity is the function's own: its table is sampled for a unit step.
    step = this->Transfer->OpacityUnitDistance;
  }
  if (this->Components)
  {
    glm::dvec4 rgba = this->Components->Combined(sample.Values, step, sample.ComponentGradientFactors);
    rgba.a *= sample.OpacityScale;
    return rgba;
  }
  glm::dvec4 rgba;
  if (this->Function2D)
  {
    rgba = this->Function2D->Lookup(scalar, sample.Magnitude);
    rgba.a = CorrectOpacity(rgba.a, step / this->ViewStep, 1.0); // it holds for one view step
  }
  else
  {
    rgba = this->FeelerTable ? this->FeelerTable->Lookup(scalar)
                             : glm::dvec4(this->Transfer->Color(scalar),
                                 CorrectOpacity(this->Transfer->Opacity.Evaluate(scalar), step,
                                   this->Transfer->OpacityUnitDistance));
  }
  if (this->Labels)
  {
    rgba = this->Labels->Apply(rgba, scalar, sample.Label, step / this->ViewStep, this->LabelTables).Whole();
  }
  rgba.a *= sample.OpacityScale;
  return rgba;
}

bool ShadowCaster::AboveThreshold(const CastSample& sample, double step, const ShadowParameters& parameters) const
{
  const double scalar = sample.Scalar;
  if (this->IsoValues)
  {
    if (!IsoCrossings::IsCrossing(scalar))
    {
      return false;
    }
    step = this->Transfer->OpacityUnitDistance;
  }
  if (parameters.Mode == ThresholdMode::Scalar)
  {
    const glm::dvec2 range = this->Grid->GetRange();
    const double width = range.y > range.x ? range.y - range.x : 1.0;
    return (scalar - range.x) / width > parameters.Threshold;
  }
  if (this->Components || this->Function2D || (this->Labels && sample.Label > 0))
  {
    // The sample's combined (or labelled) opacity, corrected for the step: against the
    // corrected threshold.
    return this->Sample(sample, step).a >
      CorrectOpacity(parameters.Threshold, step, this->Transfer->OpacityUnitDistance);
  }
  if (this->FeelerTable)
  {
    // The table holds corrected opacity: compare with the corrected threshold.
    return this->FeelerTable->Lookup(scalar).a * sample.OpacityScale >
      CorrectOpacity(parameters.Threshold, step, this->Transfer->OpacityUnitDistance);
  }
  return this->Transfer->Opacity.Evaluate(scalar) * sample.OpacityScale > parameters.Threshold;
}

bool OccluderTest::Sample(const CastSample& sample)
{
  if (this->Parameters.Mode == ThresholdMode::Accumulated)
  {
    return this->Transmission(1.0 - this->Caster.Sample(sample, this->Step).a);
  }
  return this->Caster.AboveThreshold(sample, this->Step, this->Parameters);
}

bool OccluderTest::Surface(int surface)
{
  const SurfaceMaterial& material = this->Caster.Surfaces->GetSurface(surface).Material;
  if (this->Parameters.Mode == ThresholdMode::Accumulated)
  {
    return this->Transmission(SurfaceTransmission(material, false).r);
  }
  return material.Opacity > this->Parameters.Threshold;
}

bool OccluderTest::Transmission(double transmission)
{
  this->Transmittance *= transmission;
  return 1.0 - this->Transmittance > this->Parameters.Threshold;
}

double DistanceToLight(const Light& light, const glm::dvec3& p)
{
  return light.Positional ? glm::length(light.Position - p) : std::numeric_limits<double>::infinity();
}

glm::dvec3 FeelerVisibility(const ShadowCaster& caster, const glm::dvec3& from,
  const glm::dvec3& toLight, double maxDistance, double step, const ShadowParameters& parameters)
{
  glm::dvec3 transmittance(1.0);
  OccluderTest occluder(caster, parameters, step);
  if (caster.Surfaces && !caster.Surfaces->Empty())
  {
    if (parameters.Opaque)
    {
      const bool blocked = parameters.Mode == ThresholdMode::Accumulated
        ? occluder.Transmission(caster.Surfaces->Transmittance(from, toLight, 0.0, maxDistance, false).r)
        : caster.Surfaces->Occludes(from, toLight, 0.0, maxDistance, parameters.Threshold);
      if (blocked)
      {
        return glm::dvec3(0.0);
      }
    }
    else
    {
      transmittance = caster.Surfaces->Transmittance(from, toLight, 0.0, maxDistance, parameters.Colored);
      if (transmittance == glm::dvec3(0.0))
      {
        return transmittance;
      }
    }
  }
  const VolumeGrid& grid = *caster.Grid;
  double tEnter = 0.0, tExit = 0.0;
  if (!IntersectBox(Ray{ from, toLight }, grid.GetWorldToIndex(), glm::dvec3(0.0),
        glm::dvec3(grid.GetDims() - 1), tEnter, tExit))
  {
    return transmittance;
  }
  const double tEnd = std::min(tExit, maxDistance);
  // Samples before the box's entry (a point outside the volume) are left out.
  const long firstSample = tEnter > 0.0 ? static_cast<long>(std::ceil(tEnter / step - 0.5)) : 0;
  const glm::dvec3 indexOrigin = glm::dvec3(grid.GetWorldToIndex() * glm::dvec4(from, 1.0));
  const glm::dvec3 indexDirection = glm::dvec3(grid.GetWorldToIndex() * glm::dvec4(toLight, 0.0));
  // Zero-opacity blocks cannot stop a feeler, unless the threshold is on the scalar.
  const EmptySpaceMap* empty =
    parameters.Opaque && parameters.Mode == ThresholdMode::Scalar ? nullptr : caster.Empty;
  const glm::dvec3 indexStep = indexDirection * step;
  std::optional<BoundRegion::Walker> bound;
  if (caster.Bound)
  {
    bound.emplace(*caster.Bound, indexOrigin, indexDirection);
  }
  IsoCrossings crossings(caster.IsoValues);
  for (long j = firstSample;; ++j)
  {
    const double t = (static_cast<double>(j) + 0.5) * step;
    if (!(t < tEnd))
    {
      break;
    }
    if (bound)
    {
      if (const long skip = bound->SkipSteps(t, step))
      {
        j += skip - 1;
        continue;
      }
    }
    const glm::dvec3 index = indexOrigin + t * indexDirection;
    if (empty)
    {
      if (const int skip = empty->SkipSteps(index, indexStep))
      {
        j += skip - 1;
        continue;
      }
    }
    const CastSample scalar = caster.Read(index, crossings);
    if (parameters.Opaque)
    {
      if (occluder.Sample(scalar))
      {
        return glm::dvec3(0.0);
      }
      continue;
    }
    const glm::dvec4 sample = caster.Sample(scalar, step);
    // A coloured medium lets through its colour of what it stops: 1 - alpha (1 - c).
    transmittance *= parameters.Colored ? 1.0 - sample.a * (1.0 - glm::dvec3(sample))
                                        : glm::dvec3(1.0 - sample.a);
    if (parameters.EarlyTermination &&
      std::max({ transmittance.r, transmittance.g, transmittance.b }) < ShadowTerminationTransmittance)
    {
      break;
    }
  }
  return transmittance;
}

namespace
{
class RayShadow : public LightShadow
{
public:
  RayShadow(const ShadowParameters& parameters, const ShadowCaster& caster, const Light& light,
    double step)
    : Parameters(parameters)
    , Caster(caster)
    , TheLight(light)
    , Step(step)
  {
  }
  glm::dvec3 Visibility(const glm::dvec3& p) const override
  {
    return FeelerVisibility(this->Caster, p, this->TheLight.At(p).ToLight,
      DistanceToLight(this->TheLight, p), this->Step, this->Parameters);
  }

private:
  ShadowParameters Parameters;
  ShadowCaster Caster;
  Light TheLight;
  double Step;
};

}

std::unique_ptr<LightShadow> MakeRayShadow(const ShadowParameters& parameters,
  const ShadowCaster& caster, const Light& light, double step, int)
{
  return std::make_unique<RayShadow>(parameters, caster, light, step);
}

std::unique_ptr<LightShadow> MakeLightShadow(const ShadowParameters& parameters,
  const ShadowCaster& caster, const Light& light, double viewStep, int threads)
{
  const std::string problem = parameters.Validate();
  if (!problem.empty())
  {
    throw std::invalid_argument("shadow parameters: " + problem);
  }
  const ShadowTechniqueInfo& technique = ShadowTechniqueOf(parameters);
  if (!technique.MakeShadow)
  {
    return nullptr; // none
  }
  const double step = parameters.StepFactor * viewStep;
  std::unique_ptr<LightShadow> shadow = technique.MakeShadow(parameters, caster, light, step, threads);
  if (parameters.Cached)
  {
    // Once per node of a grid over the volume's box, then trilinear (the GPU's 3D texture).
    const LightShadow& inner = *shadow;
    return std::make_unique<ShadowGrid>([&inner](const glm::dvec3& p) { return inner.Visibility(p); },
      GridFrame::OverVolume(caster.Grid->GetDims(), caster.Grid->GetIndexToWorld(), parameters.VolumeSize),
      parameters.IsColored(), threads);
  }
  return shadow;
}

}
