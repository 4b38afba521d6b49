// The smallest vtkDeepShadow program: an ordinary VTK volume pipeline, rendered on a machine
// with no display and no GPU, written to a PNG.
//
//   HeadlessVolume [volume.vti|.mhd|.nrrd] [out.png]
//
// Nothing here is headless-specific: linked with DeepShadow::Rendering and run without a
// display, vtkRenderWindow::New() returns the headless vtkDeepShadowRenderWindow.
#include "vtkDeepShadowStandardScene.h"
#include "vtkDeepShadowVolumeMapper.h"
#include "vtkDeepShadowVolumeReader.h"

#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkWindowToImageFilter.h"

#include <iostream>

int main(int argc, char* argv[])
{
  // A standard scene gives the volume and a good transfer function...
  vtkNew<vtkDeepShadowStandardScene> scene;
  scene->SetScene("head");
  vtkNew<vtkDeepShadowVolumeMapper> mapper;
  mapper->SetInputData(scene->GetVolume());

  // ...or read a file (the transfer function stays the head's).
  vtkNew<vtkDeepShadowVolumeReader> reader;
  if (argc > 1 && argv[1][0] != '\0')
  {
    reader->SetFileName(argv[1]);
    mapper->SetInputConnection(reader->GetOutputPort());
  }

  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(scene->GetVolumeProperty());

  vtkNew<vtkRenderer> renderer;
  renderer->AddVolume(volume);
  scene->ApplyCamera(renderer->GetActiveCamera());
  renderer->ResetCameraClippingRange();

  vtkNew<vtkRenderWindow> window;
  window->SetSize(512, 512);
  window->AddRenderer(renderer);
  window->Render();
  if (!mapper->GetLastError().empty())
  {
    std::cerr << "cannot render: " << mapper->GetLastError() << "\n";
    return 2;
  }

  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(grab->GetOutputPort());
  writer->SetFileName(argc > 2 ? argv[2] : "HeadlessVolume.png");
  writer->Write();
  std::cout << "rendered with " << window->GetClassName() << " -> " << writer->GetFileName() << "\n";
  return 0;
}
