// The scalar types render the same volume alike when the transfer function is scaled with the
// data: unsigned char, short (HU-like, negative values), unsigned short (exact 8/16-bit
// textures); signed char, int, unsigned int, long long, double and float (kept in single
// precision). Each is also compared with its CPU twin.
//
// Stated tolerances: type vs type RMSE <= 1/255 and <= 0.5% of pixels off by more than
// 4/255 (16-bit unorm and float textures filter alike to about 1e-5 of the range); type vs
// CPU twin as in TestVolumeMapperMatchesReference.
#include "DeepShadowTestUtilities.h"
#include "vtkDeepShadowRenderWindow.h"
#include "vtkDeepShadowVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkPiecewiseFunction.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

using deepshadow::testing::Grab;
using deepshadow::testing::WithinTolerance;

int TestScalarTypes(int argc, char* argv[])
{
  struct Type
  {
    int VTKType;
    double Scale, Offset;
  };
  // Float last: its picture is the baseline.
  const Type types[] = { { VTK_UNSIGNED_CHAR, 255.0, 0.0 }, { VTK_SHORT, 4000.0, -1000.0 },
    { VTK_UNSIGNED_SHORT, 65535.0, 0.0 }, { VTK_SIGNED_CHAR, 250.0, -125.0 },
    { VTK_INT, 2.0e7, -1.0e7 }, { VTK_UNSIGNED_INT, 4.0e9, 0.0 }, { VTK_LONG_LONG, 1.0e15, -5.0e14 },
    { VTK_DOUBLE, 1.0e30, -2.0e29 }, { VTK_FLOAT, 1.0e6, -5.0e5 } };
  vtkNew<vtkDeepShadowRenderWindow> window;
  window->SetSize(160, 160);
  bool ok = true;
  deepshadow::Image first;
  for (const Type& type : types)
  {
    auto data = deepshadow::testing::MakeTestVolume(type.VTKType, 40, type.Scale, type.Offset);
    auto at = [&](double u) { return type.Offset + type.Scale * u; };
    vtkNew<vtkColorTransferFunction> color;
    color->AddRGBPoint(at(0.0), 0.1, 0.1, 0.3);
    color->AddRGBPoint(at(0.4), 1.0, 0.6, 0.2);
    color->AddRGBPoint(at(1.0), 1.0, 1.0, 0.9);
    vtkNew<vtkPiecewiseFunction> opacity;
    opacity->AddPoint(at(0.0), 0.0);
    opacity->AddPoint(at(0.1), 0.0);
    opacity->AddPoint(at(1.0), 0.5);
    vtkNew<vtkVolumeProperty> property;
    property->SetColor(color);
    property->SetScalarOpacity(opacity);
    property->ShadeOn();

    vtkNew<vtkRenderer> renderer;
    renderer->SetBackground(0.0, 0.0, 0.0);
    window->GetRenderers()->RemoveAllItems();
    window->AddRenderer(renderer);
    vtkNew<vtkDeepShadowVolumeMapper> mapper;
    mapper->SetInputData(data);
    vtkNew<vtkVolume> volume;
    volume->SetMapper(mapper);
    volume->SetProperty(property);
    renderer->AddVolume(volume);
    renderer->GetActiveCamera()->SetPosition(1.0, 0.7, 1.5);
    renderer->ResetCamera();
    window->Render();
    const deepshadow::Image image = Grab(window);
    const std::string name = data->GetPointData()->GetScalars()->GetDataTypeAsString();
    if (!mapper->GetLastError().empty())
    {
      std::printf("%s: %s\n", name.c_str(), mapper->GetLastError().c_str());
      return EXIT_FAILURE;
    }
    ok = WithinTolerance((name + " vs CPU twin").c_str(), image,
           deepshadow::testing::Reference(renderer, true), 1.5 / 255.0, 6.0 / 255.0, 0.005) && ok;
    if (first.Width == 0)
    {
      first = image;
      ok = deepshadow::testing::CoveredFraction(image, { 0.0, 0.0, 0.0 }) > 0.1 && ok;
    }
    else
    {
      ok = WithinTolerance((name + " vs unsigned char").c_str(), image, first, 1.0 / 255.0,
             4.0 / 255.0, 0.005) && ok;
    }
  }
  const int result = deepshadow::testing::RegressionTestImage(window, argc, argv);
  return ok && result != vtkTesting::FAILED ? EXIT_SUCCESS : EXIT_FAILURE;
}
