// Drop-in shading: under every kind of light VTK has, a shaded volume drawn by our mapper
// (ShadingModel VTK, the default) is VTK's picture (VTK 9.1's lighting or 9.2's, as built),
// drawn in the same run by vtkOpenGLGPUVolumeRayCastMapper: a lone headlight (two- and
// one-sided), a dimmed headlight, a scene light, a key and a fill, a light with an ambient
// colour, a light kit (ParaView's lighting), positional lights with and without attenuation,
// spots of 25 and 90 degrees, positional and directional lights together; on a cube-shaped
// volume and on a flat one of anisotropic spacing and a direction matrix (where VTK's normals
// lean, Core/VolumeShading.h), and under a vtkVolume's rotation and scale. Each GPU picture
// also matches its CPU twin. A mapper keeps the path it reached, as VTK 9.1's does (9.2's
// follows the lights). The check can fail: the same scenes under Blinn-Phong differ from
// VTK's, and so do two paths of VTK 9.1's.
//
// Stated tolerances: against VTK, RMSE <= 0.01 and at most 3 % of pixels off by more than
// 8/255 (VTK's own noise: its picture at another sample distance differs by about 0.005);
// against the twin, RMSE <= 1.5/255.
#include "DeepShadowTestUtilities.h"
#include "vtkDeepShadowRenderWindow.h"
#include "vtkDeepShadowVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkLight.h"
#include "vtkLightKit.h"
#include "vtkMatrix3x3.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkTransform.h"
#include "vtkVersionMacros.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <functional>
#include <string>
#include <vector>

using deepshadow::testing::Check;
using deepshadow::testing::Grab;
using deepshadow::testing::Reference;
using deepshadow::testing::WithinTolerance;

namespace
{
// A bumpy ball filling most of its box: surfaces facing every way, for diffuse and specular.
vtkSmartPointer<vtkImageData> MakeBumpyBall(int nx, int ny, int nz, const double spacing[3])
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(nx, ny, nz);
  image->SetSpacing(spacing[0], spacing[1], spacing[2]);
  image->AllocateScalars(VTK_FLOAT, 1);
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  const double cx = 0.5 * (nx - 1), cy = 0.5 * (ny - 1), cz = 0.5 * (nz - 1);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
      {
        const double x = (i - cx) / (0.45 * nx), y = (j - cy) / (0.45 * ny), z = (k - cz) / (0.45 * nz);
        const double r = std::sqrt(x * x + y * y + z * z) + 0.06 * std::sin(0.5 * i) * std::sin(0.4 * j) +
          0.04 * std::sin(0.6 * k);
        scalars->SetComponent(i + nx * (j + ny * k), 0, 255.0 * std::clamp((1.0 - r) * 5.0, 0.0, 1.0));
      }
  return image;
}

vtkSmartPointer<vtkVolumeProperty> MakeProperty()
{
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0, 0.2, 0.2, 0.8);
  color->AddRGBPoint(120, 0.9, 0.6, 0.3);
  color->AddRGBPoint(255, 1.0, 1.0, 0.9);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0, 0.0);
  opacity->AddPoint(60, 0.0);
  opacity->AddPoint(128, 0.8);
  opacity->AddPoint(255, 0.95);
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetInterpolationTypeToLinear();
  property->ShadeOn();
  property->SetAmbient(0.2);
  property->SetDiffuse(0.7);
  property->SetSpecular(0.4);
  property->SetSpecularPower(12.0);
  return property;
}

vtkSmartPointer<vtkLight> SceneLight(double x, double y, double z, double intensity = 1.0)
{
  auto light = vtkSmartPointer<vtkLight>::New();
  light->SetLightTypeToSceneLight();
  light->SetPosition(x, y, z);
  light->SetFocalPoint(0.0, 0.0, 0.0);
  light->SetIntensity(intensity);
  return light;
}

// A positional scene light above the volume's centre `c`, `cone` degrees (180: no spot).
vtkSmartPointer<vtkLight> PointLight(const double c[3], double cone, double constant = 1.0, double linear = 0.0)
{
  auto light = vtkSmartPointer<vtkLight>::New();
  light->SetLightTypeToSceneLight();
  light->SetPositional(true);
  light->SetPosition(c[0] + 36.0, c[1] + 56.0, c[2] + 66.0);
  light->SetFocalPoint(c);
  light->SetConeAngle(cone);
  light->SetExponent(cone < 180.0 ? 3.0 : 1.0);
  light->SetAttenuationValues(constant, linear, 0.0);
  return light;
}

struct Lighting
{
  std::string Name;
  std::function<void(vtkRenderer*, const double centre[3])> Apply; // adds lights (none: VTK's headlight)
  bool TwoSided = true;
};

std::vector<Lighting> Lightings()
{
  return {
    { "headlight", [](vtkRenderer*, const double*) {} },
    { "headlight one-sided", [](vtkRenderer*, const double*) {}, false },
    { "headlight of intensity 0.8",
      [](vtkRenderer* r, const double*) {
        vtkNew<vtkLight> head;
        head->SetLightTypeToHeadlight();
        head->SetIntensity(0.8);
        r->AddLight(head);
      } },
    { "scene light", [](vtkRenderer* r, const double*) { r->AddLight(SceneLight(1.0, 1.5, 2.0)); } },
    { "scene light one-sided", [](vtkRenderer* r, const double*) { r->AddLight(SceneLight(1.0, 1.5, 2.0)); },
      false },
    { "key and fill",
      [](vtkRenderer* r, const double*) {
        r->AddLight(SceneLight(1.0, 1.5, 2.0));
        r->AddLight(SceneLight(-2.0, -0.5, 1.0, 0.4));
      } },
    { "a light's ambient colour",
      [](vtkRenderer* r, const double*) {
        auto light = SceneLight(1.0, 1.5, 2.0);
        light->SetAmbientColor(0.5, 0.4, 0.3);
        r->AddLight(light);
      } },
    { "light kit",
      [](vtkRenderer* r, const double*) {
        vtkNew<vtkLightKit> kit;
        kit->AddLightsToRenderer(r);
      } },
    { "positional", [](vtkRenderer* r, const double* c) { r->AddLight(PointLight(c, 180.0)); } },
    { "positional, attenuated", [](vtkRenderer* r, const double* c) { r->AddLight(PointLight(c, 180.0, 0.5, 0.005)); } },
    { "spot of 25 degrees", [](vtkRenderer* r, const double* c) { r->AddLight(PointLight(c, 25.0)); } },
    { "spot of 90 degrees", [](vtkRenderer* r, const double* c) { r->AddLight(PointLight(c, 90.0)); } },
    { "positional and directional",
      [](vtkRenderer* r, const double* c) {
        r->AddLight(PointLight(c, 180.0));
        r->AddLight(SceneLight(1.0, 1.5, 2.0));
        r->AddLight(SceneLight(-2.0, -0.5, 1.0, 0.4));
      } },
  };
}

struct Drawn
{
  deepshadow::Image Picture, Twin;
};

Drawn Draw(vtkRenderWindow* window, vtkVolumeMapper* mapper, vtkImageData* data, vtkTransform* transform,
  const Lighting& lighting, bool twin)
{
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.0, 0.0, 0.0);
  renderer->SetTwoSidedLighting(lighting.TwoSided);
  window->GetRenderers()->RemoveAllItems();
  window->AddRenderer(renderer);
  mapper->SetInputData(data);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(MakeProperty());
  if (transform)
  {
    volume->SetUserTransform(transform);
  }
  renderer->AddVolume(volume);
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Azimuth(30.0);
  renderer->GetActiveCamera()->Elevation(20.0);
  renderer->ResetCamera();
  lighting.Apply(renderer, volume->GetCenter());
  window->Render();
  Drawn drawn;
  drawn.Picture = Grab(window);
  if (twin)
  {
    drawn.Twin = Reference(renderer, true);
  }
  return drawn;
}
}

int TestShadingMatchesVTK(int, char*[])
{
  const double cubic[3] = { 1.0, 1.0, 1.0 }, flat[3] = { 1.0, 1.0, 2.0 };
  auto cube = MakeBumpyBall(48, 48, 48, cubic);
  auto slab = MakeBumpyBall(64, 48, 24, flat);
  vtkNew<vtkMatrix3x3> direction; // 30 degrees about z
  direction->SetElement(0, 0, 0.8660254037844387);
  direction->SetElement(0, 1, -0.5);
  direction->SetElement(1, 0, 0.5);
  direction->SetElement(1, 1, 0.8660254037844387);
  slab->SetDirectionMatrix(direction);
  vtkNew<vtkTransform> placed; // rotated and scaled differently along its axes
  placed->RotateZ(25.0);
  placed->RotateX(-15.0);
  placed->Scale(1.3, 0.8, 1.1);

  struct Volume
  {
    std::string Name;
    vtkImageData* Data;
    vtkTransform* Transform;
  };
  const std::vector<Volume> volumes = { { "cube", cube, nullptr }, { "flat, rotated by its direction", slab, nullptr },
    { "cube, placed by a vtkVolume transform", cube, placed } };

  vtkNew<vtkDeepShadowRenderWindow> window;
  window->SetSize(160, 160);
  // Fresh mappers for each picture: VTK 9.1's mapper never lowers its lighting complexity.
  struct Mappers
  {
    vtkNew<vtkGPUVolumeRayCastMapper> Theirs;
    vtkNew<vtkDeepShadowVolumeMapper> Ours;
    Mappers()
    {
      this->Theirs->SetAutoAdjustSampleDistances(false);
      this->Theirs->SetSampleDistance(0.5f);
      this->Ours->SetSampleDistance(0.5f);
    }
  };
  auto lighting = [](const std::string& name) {
    for (const Lighting& l : Lightings())
    {
      if (l.Name == name)
      {
        return l;
      }
    }
    return Lighting();
  };

  bool ok = true;
  for (const Volume& v : volumes)
  {
    for (const Lighting& l : Lightings())
    {
      // The placed volume: one light of each path.
      if (v.Transform && l.Name != "headlight" && l.Name != "scene light" && l.Name != "positional")
      {
        continue;
      }
      const std::string what = v.Name + ", " + l.Name;
      Mappers m;
      const Drawn vtks = Draw(window, m.Theirs, v.Data, v.Transform, l, false);
      const Drawn drawn = Draw(window, m.Ours, v.Data, v.Transform, l, true);
      ok &= Check(what + ": VTK's picture is not empty",
        deepshadow::testing::CoveredFraction(vtks.Picture, glm::dvec3(0.0)) > 0.05 || l.Name == "headlight one-sided");
      ok &= WithinTolerance((what + ": ours against VTK's").c_str(), drawn.Picture, vtks.Picture, 0.01, 8.0 / 255.0, 0.03);
      ok &= WithinTolerance((what + ": GPU against its twin").c_str(), drawn.Picture, drawn.Twin, 1.5 / 255.0, 8.0 / 255.0, 0.01);
    }
  }

  // As VTK's: built with VTK 9.1, a mapper that has shaded under a positional light keeps
  // VTK's positional path when the scene light comes back, and a fresh one takes the
  // directional path; with VTK 9.2 onwards both take the directional path.
  {
    Mappers m;
    Draw(window, m.Theirs, slab, nullptr, lighting("positional"), false);
    Draw(window, m.Ours, slab, nullptr, lighting("positional"), false);
    const Drawn vtks = Draw(window, m.Theirs, slab, nullptr, lighting("scene light"), false);
    const Drawn drawn = Draw(window, m.Ours, slab, nullptr, lighting("scene light"), true);
    ok &= WithinTolerance("scene light after a positional one: ours against VTK's", drawn.Picture, vtks.Picture, 0.01,
      8.0 / 255.0, 0.03);
    ok &= WithinTolerance("scene light after a positional one: GPU against its twin", drawn.Picture, drawn.Twin,
      1.5 / 255.0, 8.0 / 255.0, 0.01);
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 2, 0)
    ok &= Check("a mapper that saw a positional light follows the lights to the directional path",
      m.Ours->GetVTKLightingComplexity() == 2);
#else
    ok &= Check("a mapper that saw a positional light stays on VTK's positional path", m.Ours->GetVTKLightingComplexity() == 3);
    Mappers fresh;
    const Drawn directional = Draw(window, fresh.Ours, slab, nullptr, lighting("scene light"), false);
    const deepshadow::ImageDifference d = deepshadow::Compare(directional.Picture, vtks.Picture, 8.0 / 255.0);
    std::printf("a fresh mapper's directional path against the positional one: RMSE %.5f\n", d.RMSE);
    ok &= Check("a fresh mapper under the scene light takes the directional path",
      fresh.Ours->GetVTKLightingComplexity() == 2 && d.RMSE > 0.01);
#endif
  }

  // The comparison tells shadings apart: Blinn-Phong (the true normal, the half vector
  // normalize(L + V), the renderer's ambient light) is not VTK's picture.
  for (const char* name : { "scene light", "positional" })
  {
    Mappers m;
    m.Ours->SetShadingModelToBlinnPhong();
    const Drawn vtks = Draw(window, m.Theirs, slab, nullptr, lighting(name), false);
    const Drawn drawn = Draw(window, m.Ours, slab, nullptr, lighting(name), true);
    const deepshadow::ImageDifference d = deepshadow::Compare(drawn.Picture, vtks.Picture, 8.0 / 255.0);
    std::printf("Blinn-Phong against VTK, flat volume, %s: RMSE %.5f\n", name, d.RMSE);
    ok &= Check(std::string("Blinn-Phong is not VTK's picture under a ") + name, d.RMSE > 0.015);
    ok &= WithinTolerance((std::string("Blinn-Phong, ") + name + ": GPU against its twin").c_str(), drawn.Picture,
      drawn.Twin, 1.5 / 255.0, 8.0 / 255.0, 0.01);
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
