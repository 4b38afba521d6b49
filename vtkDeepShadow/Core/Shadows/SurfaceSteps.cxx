#include "Core/Shadows/SurfaceSteps.h"

#include "Core/Geometry/SurfaceSet.h"

namespace deepshadow
{

void SurfaceStepsBuilder::Add(double depth, double transmission)
{
  this->Depth[this->Count] = depth;
  this->Own[this->Count] = transmission;
  if (++this->Count < 3)
  {
    return;
  }
  // Fold the more transparent of the last two into the one before it (ties: the later).
  const int folded = this->Own[1] > this->Own[2] ? 1 : 2;
  this->Own[folded - 1] *= this->Own[folded];
  if (folded == 1)
  {
    this->Depth[1] = this->Depth[2];
    this->Own[1] = this->Own[2];
  }
  this->Count = 2;
}

double SurfaceStepsBuilder::Transmittance() const
{
  double t = 1.0;
  for (int k = 0; k < this->Count; ++k)
  {
    t *= this->Own[k];
  }
  return t;
}

SurfaceSteps SurfaceStepsBuilder::Finish() const
{
  SurfaceSteps steps;
  double t = 1.0;
  for (int k = 0; k < this->Count; ++k)
  {
    t *= this->Own[k];
    steps.Depths[k] = static_cast<float>(this->Depth[k]);
    steps.Transmittance[k] = static_cast<float>(t);
  }
  return steps;
}

double EvaluateSurfaceSteps(const SurfaceSteps& steps, double depth)
{
  return depth < steps.Depths[0] ? 1.0
    : depth < steps.Depths[1]    ? static_cast<double>(steps.Transmittance[0])
                                 : static_cast<double>(steps.Transmittance[1]);
}

void MarchBesideSurfaceSteps(const ShadowCaster& march, const ShadowCaster& caster,
  const glm::dvec3& origin, const glm::dvec3& direction, double step, SurfaceStepsBuilder& steps,
  const std::function<void(double t, double opacity, bool skipped, double volume)>& visit)
{
  double volume = 1.0;
  auto more = [&] { return volume * steps.Transmittance() > ShadowTerminationTransmittance; };
  MarchTexelRay(
    march, origin, direction, step, march.Empty,
    [&](long, double t, const CastSample& scalar, bool skipped) {
      const double opacity = skipped ? 0.0 : caster.Sample(scalar, step).a;
      if (!skipped)
      {
        volume *= 1.0 - opacity;
      }
      visit(t, opacity, skipped, volume);
      return more();
    },
    [&](double t, int surface) {
      steps.Add(t, SurfaceTransmission(caster.Surfaces->GetSurface(surface).Material, false).r);
      return more();
    });
}

}
