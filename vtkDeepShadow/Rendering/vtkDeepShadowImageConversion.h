/**
 * Conversions between the Core's linear-RGB images (deepshadow::Image, what errors are
 * measured on) and VTK: a render window's pixels, vtkImageData, PNG files.
 */
#ifndef vtkDeepShadowImageConversion_h
#define vtkDeepShadowImageConversion_h

#include "Core/Image.h"                        // For deepshadow::Image
#include "vtkDeepShadowRenderingModule.h" // For export macro
#include "vtkSmartPointer.h"              // For vtkSmartPointer

#include <string> // For std::string

class vtkImageData;
class vtkRenderWindow;

namespace deepshadow
{

/** The window's current pixels (back buffer, RGB) as an Image. */
VTKDEEPSHADOWRENDERING_EXPORT Image CaptureWindow(vtkRenderWindow* window);

/** An 8-bit RGB vtkImageData of the image (values rounded and clamped). */
VTKDEEPSHADOWRENDERING_EXPORT vtkSmartPointer<vtkImageData> ToImageData(const Image& image);

/**
 * The PNG file's bytes (encoded in memory: libpng then has no file error to print on
 * stderr); empty if the image cannot be encoded.
 */
VTKDEEPSHADOWRENDERING_EXPORT std::string EncodePNG(vtkImageData* image);

/** Writes a PNG; returns false if the file cannot be written whole. */
VTKDEEPSHADOWRENDERING_EXPORT bool WritePNG(const Image& image, const std::string& path);
VTKDEEPSHADOWRENDERING_EXPORT bool WritePNG(vtkImageData* image, const std::string& path);

}
#endif
