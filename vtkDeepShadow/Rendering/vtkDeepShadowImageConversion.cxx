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

std::string EncodePNG(vtkImageData* image)
{
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(image);
  writer->WriteToMemoryOn();
  writer->Write();
  vtkUnsignedCharArray* bytes = writer->GetResult();
  if (writer->GetErrorCode() != 0 || !bytes || bytes->GetNumberOfValues() == 0)
  {
    return std::string();
  }
  return std::string(reinterpret_cast<const char*>(bytes->GetPointer(0)),
    static_cast<size_t>(bytes->GetNumberOfValues()));
}

bool WritePNG(vtkImageData* image, const std::string& path)
{
  const std::string bytes = EncodePNG(image);
  std::ofstream file(path, std::ios::binary);
  file.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  file.close();
  return !bytes.empty() && file.good();
}

bool WritePNG(const Image& image, const std::string& path)
{
  return WritePNG(ToImageData(image), path);
}

}
