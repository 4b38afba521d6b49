// Shared by the two halves of the stiff cases (TestStiffCases.cxx, TestStiffCasesLights.cxx):
// grids, the techniques by name and their tolerances, and the checks every case uses.
#ifndef deepshadow_testing_StiffCases_h
#define deepshadow_testing_StiffCases_h

#include "ClosedFormScenes.h"
#include "Core/Shadows/DeepShadowMap.h"
#include "Core/Shadows/LightSpace.h"
#include "Core/ReferenceRenderer.h"
#include "Core/Shadows.h"
#include "Core/ShadowTechniques.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <string>

using namespace deepshadow;

namespace
{
constexpr int Threads = 2;

std::shared_ptr<VolumeGrid> Grid(const glm::ivec3& dims, const glm::dvec3& spacing,
  const std::function<float(int, int, int)>& value)
{
  std::vector<float> values;
  values.reserve(static_cast<size_t>(dims.x) * dims.y * dims.z);
  for (int k = 0; k < dims.z; ++k)
    for (int j = 0; j < dims.y; ++j)
      for (int i = 0; i < dims.x; ++i)
        values.push_back(value(i, j, k));
  return std::make_shared<VolumeGrid>(dims, std::move(values), glm::scale(glm::dmat4(1.0), spacing));
}

std::shared_ptr<VolumeGrid> Uniform(int n, float value = 1.0f)
{
  return Grid(glm::ivec3(n), glm::dvec3(1.0), [=](int, int, int) { return value; });
}

// Scalars in [0, 1]: opacity 0 at 0 and `alpha` from `from` up; grey colour `grey` (< 1, so
// that a coloured technique's medium lets through only part of the light).
TransferFunction Medium(double alpha, double from = 0.5, double grey = 0.5)
{
  TransferFunction tf = TransferFunction::Grey({ { 0.0, 0.0 }, { from, alpha }, { 1.0, alpha } });
  tf.Red = tf.Green = tf.Blue = PiecewiseLinear({ { 0.0, grey } });
  return tf;
}

Light Directional(const glm::dvec3& toLight)
{
  Light light;
  light.Position = toLight;
  return light;
}

Light Positional(const glm::dvec3& position)
{
  Light light;
  light.Positional = true;
  light.Position = position;
  return light;
}

ShadowParameters Technique(ShadowKind kind, bool colored = false, bool cached = false, bool opaque = false)
{
  ShadowParameters p;
  p.Kind = kind;
  p.Colored = colored;
  p.Cached = cached;
  p.Opaque = opaque;
  p.MapSize = 32;
  p.VolumeSize = 128; // as many nodes as voxels: cache nodes sit on the voxels
  p.Seed = 3;
  return p;
}

// Every technique the registry offers, cached or not, at small maps (a new one is in every
// stiff case without an edit here); the ground truth (no early termination) first.
std::vector<ShadowParameters> EveryTechnique()
{
  std::vector<ShadowParameters> all{ ShadowParameters::GroundTruth(false, 1.0) };
  for (const std::string& name : ShadowTechniqueNames())
  {
    bool cached = false;
    const ShadowTechniqueInfo* info = FindShadowTechnique(name, &cached);
    if (info->Kind == ShadowKind::None)
    {
      continue;
    }
    ShadowParameters p = info->DefaultParameters(cached);
    p.MapSize = 32;
    p.VolumeSize = 128; // as many nodes as voxels: cache nodes sit on the voxels
    p.Seed = 3;
    all.push_back(p);
  }
  return all;
}

std::string NameOf(const ShadowParameters& p)
{
  return p.Kind == ShadowKind::Rays && !p.EarlyTermination ? "ground truth" : p.Name();
}

using closedform::DarkTolerance;

// No technique takes light below the ambient-only value: every visibility is in [0, 1]
// (deep shadow map nodes included, see DeepShadowMapNodesAreNeverNegative).
double NegativeAllowance(const ShadowParameters&)
{
  return 0.0;
}

// A volume that casts, kept alive with its transfer function.
struct Caster
{
  std::shared_ptr<VolumeGrid> G;
  TransferFunction Transfer;
  Interpolation Sampling = Interpolation::Linear;
  ShadowCaster Get() const
  {
    ShadowCaster c;
    c.Grid = this->G.get();
    c.Transfer = &this->Transfer;
    c.Sampling = this->Sampling;
    return c;
  }
  std::unique_ptr<LightShadow> Shadow(const ShadowParameters& p, const Light& light, double step = 0.5) const
  {
    return MakeLightShadow(p, this->Get(), light, step, Threads);
  }
};

// A size x size orthographic view of the box [0, extent]^2 x [0, depth] from below (-z),
// unshaded (lit isotropically because it receives shadows).
Scene ViewFromBelow(std::shared_ptr<VolumeGrid> grid, const TransferFunction& tf, const ShadowParameters& p,
  const std::vector<Light>& lights, int size = 24)
{
  const glm::dvec3 top = glm::dvec3(grid->GetIndexToWorld() * glm::dvec4(glm::dvec3(grid->GetDims() - 1), 1.0));
  const glm::dvec3 centre = 0.5 * top;
  const double half = 0.6 * std::max({ top.x, top.y, 1.0 });
  Scene scene;
  const glm::dmat4 view = glm::lookAt(glm::dvec3(centre.x, centre.y, -40.0 - top.z), centre, glm::dvec3(0, 1, 0));
  scene.View = Camera(glm::ortho(-half, half, -half, half, 1.0, 100.0 + 2.0 * top.z) * view, size, size);
  scene.Lights = lights;
  scene.Background = { 0.2, 0.3, 0.4 };
  VolumeInstance volume;
  volume.Grid = std::move(grid);
  volume.Transfer = tf;
  volume.Shadows = p;
  scene.Volumes.push_back(volume);
  return scene;
}

MarchSettings Exact(double sampleDistance = 0.5)
{
  MarchSettings settings;
  settings.SampleDistance = sampleDistance;
  return settings;
}

// Every channel finite, and ambient-only <= shadowed <= unshadowed: shadows never add light
// and never take away more than the direct light. Returns the shadowed image.
Image ExpectLightBounded(const Scene& scene, const MarchSettings& settings, const std::string& what)
{
  const double allowance = NegativeAllowance(scene.Volumes[0].Shadows);
  Scene unshadowed = scene, ambient = scene;
  for (Light& light : unshadowed.Lights)
  {
    light.ShadowAttenuation = 0.0;
  }
  for (Light& light : ambient.Lights)
  {
    light.Diffuse = light.Specular = glm::dvec3(0.0);
  }
  const Image shadowed = ReferenceRenderer::Render(scene, settings, Threads);
  const Image upper = ReferenceRenderer::Render(unshadowed, settings, Threads);
  const Image lower = ReferenceRenderer::Render(ambient, settings, Threads);
  size_t nonFinite = 0, outside = 0;
  for (size_t i = 0; i < shadowed.RGB.size(); ++i)
  {
    nonFinite += std::isfinite(shadowed.RGB[i]) ? 0 : 1;
    const double floor = lower.RGB[i] - allowance * (upper.RGB[i] - lower.RGB[i]) - 1e-12;
    outside += (shadowed.RGB[i] >= floor && shadowed.RGB[i] <= upper.RGB[i] + 1e-12) ? 0 : 1;
  }
  EXPECT_EQ(nonFinite, 0u) << what;
  EXPECT_EQ(outside, 0u) << what << ": channels outside [ambient only, unshadowed]";
  return shadowed;
}

void ExpectVisibilityInUnitRange(const glm::dvec3& v, const std::string& what, double allowance = 0.0)
{
  for (int c = 0; c < 3; ++c)
  {
    ASSERT_TRUE(std::isfinite(v[c]) && v[c] >= -allowance && v[c] <= 1.0) << what << ": " << v[c];
  }
}
}

#endif
