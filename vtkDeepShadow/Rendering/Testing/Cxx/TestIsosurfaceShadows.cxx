// Isosurfaces cast and receive shadows with every technique, judged against the closed form.
//
// A ball (radius 12) floats 24 units above a flat box, both the contour 100 of one float
// volume; a directional light shines down at an angle; the camera looks straight down
// (parallel projection) and the mapper shows the shadow term (OutputShadowTerm). The closed
// form: a point of the box's top is in the ball's shadow when its ray towards the light passes
// the ball's centre closer than the radius; the ball's top lets the light in wherever it faces
// it (nothing is above it). Judged pixels keep 1.5 units from the shadow's edge, the ball's
// outline and the box's rim, and must be within 0.15 of the closed form: 1 lit; 0 in shadow
// for grey techniques, 0.09 for coloured ones (they let the surface's colour, 0.3, through at
// each of the light's two crossings of the ball). Coloured stochastic shadow maps are noisy by
// design: a shadowed pixel may be off by 4 more standard errors of their mean of 13 Bernoulli
// tests (as the closed-form test judges them). At most 1% of the judged pixels of each kind
// may fail, and the mean over each kind must be within 0.05 of the closed form. The colour
// picture must match the CPU twin. Shadow structures are rebuilt when the contour values
// change, and only then; without a contour value nothing is drawn.
#include "Core/Camera.h"
#include "DeepShadowTestUtilities.h"
#include "vtkDeepShadowTechnique.h"
#include "vtkDeepShadowTechniqueFactory.h"

#include "vtkContourValues.h"
#include "vtkFloatArray.h"
#include "vtkLight.h"
#include "vtkMatrix4x4.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

using deepshadow::testing::Check;

namespace
{
const glm::dvec3 BallCentre(32.0, 32.0, 40.0);
constexpr double BallRadius = 12.0;
constexpr double BoxTop = 16.0;
constexpr double BoxHalf = 26.0; // in x and y around (32, 32)
constexpr double Margin = 1.5;
constexpr int Size = 160;

vtkSmartPointer<vtkImageData> MakeBallOverBox()
{
  const int n = 64;
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(n, n, n);
  vtkNew<vtkFloatArray> scalars;
  scalars->SetNumberOfTuples(static_cast<vtkIdType>(n) * n * n);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        // Signed distances (positive inside, in units of 12 and 4), as 100 + 100 x, clamped.
        const glm::dvec3 p(i, j, k);
        const double ball = 1.0 - glm::length(p - BallCentre) / BallRadius;
        const double box = 1.0 -
          std::max(std::abs(k - 12.0) / 4.0, (std::max(std::abs(i - 32.0), std::abs(j - 32.0)) - 22.0) / 4.0);
        scalars->SetValue(i + n * (j + n * k), static_cast<float>(100.0 + 100.0 * std::clamp(std::max(ball, box), -1.0, 1.0)));
      }
  image->GetPointData()->SetScalars(scalars);
  return image;
}

struct Scene
{
  vtkNew<vtkDeepShadowRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkDeepShadowVolumeMapper> Mapper;
  vtkNew<vtkVolumeProperty> Property;
  glm::dvec3 ToLight = glm::normalize(glm::dvec3(0.5, 0.2, 1.0));

  Scene()
  {
    this->Window->SetSize(Size, Size);
    this->Window->AddRenderer(this->Renderer);
    this->Renderer->SetBackground(0.0, 0.0, 0.0);
    this->Renderer->AutomaticLightCreationOff();
    vtkNew<vtkLight> light;
    light->SetLightTypeToSceneLight();
    light->SetPositional(false);
    light->SetFocalPoint(32.0, 32.0, 32.0);
    light->SetPosition(32.0 + this->ToLight.x, 32.0 + this->ToLight.y, 32.0 + this->ToLight.z);
    this->Renderer->AddLight(light);
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->ParallelProjectionOn();
    camera->SetFocalPoint(32.0, 32.0, 20.0);
    camera->SetPosition(32.0, 32.0, 200.0);
    camera->SetViewUp(0.0, 1.0, 0.0);
    camera->SetParallelScale(31.0);
    camera->SetClippingRange(1.0, 400.0);
    vtkNew<vtkColorTransferFunction> color;
    color->AddRGBPoint(0.0, 0.3, 0.3, 0.3);
    color->AddRGBPoint(200.0, 0.3, 0.3, 0.3);
    vtkNew<vtkPiecewiseFunction> opacity;
    opacity->AddPoint(0.0, 1.0);
    opacity->AddPoint(200.0, 1.0);
    this->Property->SetColor(color);
    this->Property->SetScalarOpacity(opacity);
    this->Property->SetInterpolationTypeToLinear();
    this->Property->SetShade(1);
    this->Property->GetIsoSurfaceValues()->SetValue(0, 100.0);
    this->Mapper->SetInputData(MakeBallOverBox());
    this->Mapper->SetBlendModeToIsoSurface();
    this->Mapper->SetSampleDistance(0.5f);
    vtkNew<vtkVolume> volume;
    volume->SetMapper(this->Mapper);
    volume->SetProperty(this->Property);
    this->Renderer->AddVolume(volume);
  }

  /** Where pixel (x, y)'s ray (straight down) meets the plane z = `z`. */
  glm::dvec3 OnPlane(int x, int y, double z)
  {
    vtkMatrix4x4* m = this->Renderer->GetActiveCamera()->GetCompositeProjectionTransformMatrix(1.0, -1.0, 1.0);
    glm::dmat4 viewProjection;
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c)
        viewProjection[c][r] = m->GetElement(r, c);
    const deepshadow::Ray ray = deepshadow::Camera(viewProjection, Size, Size).PixelRay(x, y);
    return ray.Origin + (z - ray.Origin.z) / ray.Direction.z * ray.Direction;
  }
};

// Distance from `centre` to the ray from `p` along unit `direction` (the whole line behind p
// counts as far).
double RayDistance(const glm::dvec3& p, const glm::dvec3& direction, const glm::dvec3& centre)
{
  const double along = glm::dot(centre - p, direction);
  return along < 0.0 ? glm::length(centre - p) : glm::length(centre - p - along * direction);
}

struct Tally
{
  double Expected = 1.0; // the closed form's term
  double Tolerance = 0.15;
  int Judged = 0, Failed = 0;
  double Sum = 0.0;
  void Add(double got)
  {
    ++this->Judged;
    this->Failed += std::abs(got - this->Expected) <= this->Tolerance ? 0 : 1;
    this->Sum += got;
  }
  double Mean() const { return this->Judged > 0 ? this->Sum / this->Judged : 0.0; }
  bool Passed() const
  {
    return this->Failed <= this->Judged / 100 && std::abs(this->Mean() - this->Expected) <= 0.05;
  }
};

// Judges the shadow term picture against the closed form: {lit, shadowed} tallies.
std::pair<Tally, Tally> Judge(Scene& scene, const deepshadow::Image& term, const deepshadow::ShadowParameters& p)
{
  Tally lit, shadowed;
  // A coloured technique lets the surface's colour (0.3) through at each of two crossings.
  shadowed.Expected = p.IsColored() ? 0.3 * 0.3 : 0.0;
  if (p.Kind == deepshadow::ShadowKind::Stochastic)
  {
    const double e = shadowed.Expected;
    shadowed.Tolerance += 4.0 * std::sqrt(e * (1.0 - e) / (p.Offsets * p.Photons));
  }
  for (int y = 0; y < Size; ++y)
    for (int x = 0; x < Size; ++x)
    {
      const double got = std::max({ term.At(x, y).x, term.At(x, y).y, term.At(x, y).z });
      const glm::dvec3 top = scene.OnPlane(x, y, BoxTop);
      const double fromAxis = glm::length(glm::dvec2(top) - glm::dvec2(BallCentre));
      if (fromAxis < BallRadius - Margin)
      {
        // The ball's upper half: lit where it faces the light.
        const double z = BallCentre.z + std::sqrt(BallRadius * BallRadius - fromAxis * fromAxis);
        const glm::dvec3 normal = (glm::dvec3(top.x, top.y, z) - BallCentre) / BallRadius;
        if (glm::dot(normal, scene.ToLight) > 0.3)
        {
          lit.Add(got);
        }
        continue;
      }
      const bool onBox = std::abs(top.x - 32.0) < BoxHalf - Margin && std::abs(top.y - 32.0) < BoxHalf - Margin;
      if (fromAxis < BallRadius + Margin || !onBox)
      {
        continue;
      }
      const double d = RayDistance(top, scene.ToLight, BallCentre);
      if (d < BallRadius - Margin)
      {
        shadowed.Add(got);
      }
      else if (d > BallRadius + Margin)
      {
        lit.Add(got);
      }
    }
  return { lit, shadowed };
}
}

int TestIsosurfaceShadows(int, char*[])
{
  bool ok = true;
  Scene scene;
  const std::vector<std::string> techniques = { "rays", "rays-opaque", "shadowmap", "dsm", "dsm-color", "dsm3",
    "cssm", "rays-cached", "dsm-cached" };
  for (const std::string& name : techniques)
  {
    vtkSmartPointer<vtkDeepShadowTechnique> technique = vtkDeepShadowTechniqueFactory::New(name);
    scene.Mapper->SetShadowTechnique(technique);
    scene.Mapper->SetOutputModeToShadowTerm();
    scene.Window->Render();
    const deepshadow::Image term = deepshadow::testing::Grab(scene.Window);
    const auto [lit, shadowed] = Judge(scene, term, technique->GetParameters());
    std::printf("%s: lit %d of %d judged pixels wrong (mean %.4f), shadowed %d of %d (mean %.4f, closed "
                "form %.2f, tolerance %.3f)\n",
      name.c_str(), lit.Failed, lit.Judged, lit.Mean(), shadowed.Failed, shadowed.Judged, shadowed.Mean(),
      shadowed.Expected, shadowed.Tolerance);
    ok = Check(name + ": the closed form's light and shadow", lit.Judged > 2000 && shadowed.Judged > 500 &&
           lit.Passed() && shadowed.Passed()) && ok;
    if (const char* directory = std::getenv("DEEPSHADOW_TEST_IMAGES"))
    {
      deepshadow::WritePNG(term, std::string(directory) + "/isosurface-term-" + name + ".png");
    }
    scene.Mapper->SetOutputModeToColor();
    scene.Window->Render();
    ok = deepshadow::testing::WithinTolerance(("isosurface, " + name + " vs CPU twin").c_str(),
           deepshadow::testing::Grab(scene.Window), deepshadow::testing::Reference(scene.Renderer, true),
           2.0 / 255.0, 12.0 / 255.0, 0.01) && ok;
    ok = Check(name + ": composed with Isosurface", deepshadow::testing::HasFeature(scene.Mapper, "Isosurface")) && ok;
  }

  // The structures follow the contour values: kept while they stay, rebuilt when they change.
  vtkSmartPointer<vtkDeepShadowTechnique> dsm = vtkDeepShadowTechniqueFactory::New("dsm");
  scene.Mapper->SetShadowTechnique(dsm);
  scene.Window->Render();
  const int built = dsm->GetBuildCount();
  scene.Window->Render();
  ok = Check("unchanged contour values: nothing rebuilt", dsm->GetBuildCount() == built) && ok;
  scene.Property->GetIsoSurfaceValues()->SetValue(0, 120.0);
  scene.Window->Render();
  ok = Check("a changed contour value: rebuilt", dsm->GetBuildCount() == built + 1) && ok;
  scene.Property->GetIsoSurfaceValues()->SetNumberOfContours(0);
  scene.Window->Render();
  ok = Check("no contour value: nothing drawn",
         deepshadow::testing::CoveredFraction(deepshadow::testing::Grab(scene.Window), { 0.0, 0.0, 0.0 }) == 0.0) && ok;
  scene.Mapper->SetBlendModeToComposite();
  scene.Window->Render();
  ok = Check("composite blending: no Isosurface in the shader",
         !deepshadow::testing::HasFeature(scene.Mapper, "Isosurface")) && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
