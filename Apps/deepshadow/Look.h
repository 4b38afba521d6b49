// How the volume looks and is seen, from the command line: the transfer function (--tf, a
// preset or a ParaView file, --window/--level), the lighting coefficients, and the camera
// (--view, --azimuth/--elevation/--roll/--zoom, --camera FILE; render --json writes the
// camera back so that a view can be reproduced exactly).
#ifndef deepshadow_tool_Look_h
#define deepshadow_tool_Look_h

#include "Json.h"
#include "Options.h"

#include <functional>
#include <string>

class vtkCamera;
class vtkImageData;
class vtkRenderer;
class vtkVolume;
class vtkVolumeProperty;

namespace deepshadow
{
namespace tool
{

/** Parses one look option (key, and its value from `next`); false if `key` is not one. */
bool ParseLookOption(Options& o, const std::string& key, const std::function<std::string()>& next);
/** Checks the look options together (--window with --level, --camera alone, ...). */
void ValidateLook(const Options& o, const std::vector<std::string>& args);
/** --help's lines for them. */
std::string LookUsage();

/** The transfer function and lighting options over `property` (the scene's or a file's). */
void ApplyAppearance(const Options& options, vtkImageData* data, vtkVolumeProperty* property);
/** The camera options over the renderer's camera, which shows the whole volume already. */
void ApplyView(const Options& options, vtkRenderer* renderer, vtkVolume* volume);

/**
 * Throws UsageError when the renderer's camera sees nothing of its visible props (their box
 * lies wholly beyond one side of the view frustum at a width x height picture): a picture of
 * nothing is not what a camera file or a turn was meant to give.
 */
void RequireInView(vtkRenderer* renderer, int width, int height);

/** The camera as render --json writes it and --camera reads it. */
Json CameraJson(vtkCamera* camera);

}
}
#endif
