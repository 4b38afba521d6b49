#include "vtkDeepShadowImageConversion.h"

#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

#include <fstream>

namespace deepshadow
{

Image CaptureWindow(vtkRenderWindow* window)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ShouldRerenderOff(); // the pixels of the last render, not of a new one
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkImageData* pixels = grab->GetOutput();
  const int* dims = pixels->GetDimensions();
  return Image::FromBytes(
    static_cast<const uint8_t*>(pixels->GetScalarPointer()), dims[0], dims[1], 3);
}

vtkSmartPointer<vtkImageData> ToImageData(const Image& image)
{
  auto data = vtkSmartPointer<vtkImageData>::New();
  data->SetDimensions(image.Width, image.Height, 1);
  data->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  const std::vector<uint8_t> bytes = image.ToBytes();
  std::copy(bytes.begin(), bytes.end(),
    vtkUnsignedCharArray::SafeDownCast(data->GetPointData()->GetScalars())->GetPointer(0));
  return data;
}

bool WritePNG(vtkImageData* image, const std::string& path)
{
  if (!std::ofstream(path, std::ios::binary))
  {
    return false;
  }
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(path.c_str());
  writer->Write();
  return writer->GetErrorCode() == 0;
}

bool WritePNG(const Image& image, const std::string& path)
{
  return WritePNG(ToImageData(image), path);
}

}
