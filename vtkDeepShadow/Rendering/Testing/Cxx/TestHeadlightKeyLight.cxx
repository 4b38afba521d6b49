// A lone headlight becomes a key light and a fill when the volume casts shadows
// (vtkDeepShadowVolumeMapper::HeadlightKeyLight): a ball in front of a wall, seen head on.
// - The key's shadow falls on the wall below and to the left of the ball, where the camera
//   sees it (the ambient and the fill stay: 0.81 of the lit side when written); the same check
//   fails on the headlight's picture, whose shadow hides behind the ball.
// - The lit wall keeps at least 0.7 of its brightness under the headlight without shadows
//   (0.77 when written; 0.52 with a key and fill summing to the headlight). The rest is the
//   key's light lost in the wall's own outer layers: a dense medium lit from 60 degrees off
//   its normal keeps a third of it (the emission-absorption model has no scattering).
// - GPU against its CPU twin; HeadlightKeyLight off, no technique, or any other light: the
//   headlight's picture, pixel for pixel.
#include "DeepShadowTestUtilities.h"
#include "vtkDeepShadowRenderWindow.h"
#include "vtkDeepShadowTechniqueFactory.h"
#include "vtkDeepShadowVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkLight.h"
#include "vtkPiecewiseFunction.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

using deepshadow::testing::Check;
using deepshadow::testing::Grab;
using deepshadow::Image;
using deepshadow::testing::Reference;
using deepshadow::testing::WithinTolerance;

namespace
{
const int N = 48; // points a side; the volume spans [-47, 47] (spacing 2)

// A wall facing +z (value 90) and a ball (200) in front of it, centred on the z axis; both
// rise over three voxels, as scanned surfaces do (a step of one voxel draws the sampling
// pattern's rings into the self-shadowing).
vtkSmartPointer<vtkImageData> MakeWallAndBall()
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(N, N, N);
  image->SetSpacing(2.0, 2.0, 2.0);
  image->SetOrigin(-(N - 1.0), -(N - 1.0), -(N - 1.0));
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  auto* v = static_cast<unsigned char*>(image->GetScalarPointer());
  const double rise = 3.0 * 2.0 / (N - 1); // three voxels
  auto ramp = [rise](double inside) { return std::min(1.0, std::max(0.0, inside / rise)); };
  for (int k = 0; k < N; ++k)
    for (int j = 0; j < N; ++j)
      for (int i = 0; i < N; ++i)
      {
        const double x = 2.0 * i / (N - 1) - 1.0, y = 2.0 * j / (N - 1) - 1.0, z = 2.0 * k / (N - 1) - 1.0;
        const double wall = (std::abs(x) < 0.95 && std::abs(y) < 0.95 && z > -0.95) ? ramp(-0.6 - z) : 0.0;
        const double ball = ramp(0.25 - std::sqrt(x * x + y * y + (z + 0.3) * (z + 0.3)));
        v[i + N * (j + N * k)] = static_cast<unsigned char>(std::max(90.0 * wall, 200.0 * ball) + 0.5);
      }
  return image;
}

// Mean brightness (sum of channels) of the wall's front face around (u, v) (fractions of the
// volume's half width), over the pixels within 4 of its projection.
double WallAround(vtkRenderer* renderer, const Image& image, double u, double v)
{
  renderer->SetWorldPoint(u * (N - 1.0), v * (N - 1.0), -0.6 * (N - 1.0), 1.0);
  renderer->WorldToDisplay();
  double display[3];
  renderer->GetDisplayPoint(display);
  const int cx = static_cast<int>(display[0]), cy = static_cast<int>(display[1]);
  double sum = 0.0;
  int count = 0;
  for (int y = cy - 4; y <= cy + 4; ++y)
    for (int x = cx - 4; x <= cx + 4; ++x)
    {
      const glm::dvec3 c = image.At(x, y);
      sum += c.x + c.y + c.z;
      ++count;
    }
  return sum / count;
}
}

int TestHeadlightKeyLight(int, char*[])
{
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0, 1.0, 1.0, 1.0);
  color->AddRGBPoint(90, 0.85, 0.85, 0.8);
  color->AddRGBPoint(200, 1.0, 0.5, 0.3);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0, 0.0);
  opacity->AddPoint(40, 0.0);
  opacity->AddPoint(90, 0.8);
  opacity->AddPoint(200, 0.95);
  vtkNew<vtkVolumeProperty> property;
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->ShadeOn();
  property->SetAmbient(0.2);
  property->SetDiffuse(0.8);

  vtkNew<vtkDeepShadowRenderWindow> window;
  window->SetSize(160, 160);
  vtkNew<vtkRenderer> renderer; // no lights: VTK adds its headlight at the first render
  renderer->SetBackground(0.05, 0.05, 0.08);
  window->AddRenderer(renderer);
  vtkNew<vtkDeepShadowVolumeMapper> mapper;
  mapper->SetInputData(MakeWallAndBall());
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  renderer->AddVolume(volume);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, 0.0, 1.0);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  renderer->ResetCamera();
  renderer->ResetCameraClippingRange();

  auto draw = [&](bool technique, bool key) {
    mapper->SetShadowTechnique(technique ? vtkDeepShadowTechniqueFactory::New("dsm") : nullptr);
    mapper->SetHeadlightKeyLight(key);
    window->Render();
    return Grab(window);
  };
  // Where the key's shadow falls (below left of the ball) and its mirror image (above right).
  auto shadowSide = [&](const Image& image) { return WallAround(renderer, image, -0.35, -0.35); };
  auto litSide = [&](const Image& image) { return WallAround(renderer, image, 0.35, 0.35); };

  bool ok = true;
  const Image headlight = draw(false, true);
  const Image keyed = draw(true, true);
  const Image twin = Reference(renderer, true);
  const Image headlightShadows = draw(true, false);
  std::printf("wall below left / above right: key %.3f / %.3f, headlight with shadows %.3f / %.3f, "
              "no shadows %.3f / %.3f\n",
    shadowSide(keyed), litSide(keyed), shadowSide(headlightShadows), litSide(headlightShadows),
    shadowSide(headlight), litSide(headlight));

  ok = Check("key light: the ball's shadow below left on the wall", shadowSide(keyed) < 0.9 * litSide(keyed)) && ok;
  ok = Check("the check fails on the headlight's shadows (hidden behind the ball)",
         !(shadowSide(headlightShadows) < 0.9 * litSide(headlightShadows))) && ok;
  ok = Check("key light: the lit wall keeps 0.7 of the headlight's brightness",
         litSide(keyed) >= 0.7 * litSide(headlight)) && ok;
  ok = WithinTolerance("key light vs CPU twin", keyed, twin, 2.0 / 255.0, 12.0 / 255.0, 0.01) && ok;

  // Without a technique the key is not made: the headlight's picture exactly.
  ok = WithinTolerance("no technique, key on vs off", draw(false, true), draw(false, false), 0.0, 0.0, 0.0) && ok;
  // Any light beside the headlight: the scene's lighting is kept as it is.
  vtkNew<vtkLight> scene;
  scene->SetLightTypeToSceneLight();
  scene->SetPosition(-1.0, 1.0, 1.0);
  scene->SetFocalPoint(0.0, 0.0, 0.0);
  scene->SetIntensity(0.5);
  renderer->AddLight(scene);
  ok = WithinTolerance("headlight and a scene light, key on vs off", draw(true, true), draw(true, false), 0.0, 0.0,
         0.0) && ok;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
