// Whether an X server answers at $DISPLAY: asked with Xlib before VTK's X11 window, which
// crashes (SIGSEGV) on a display that does not open. Its own file, so that Xlib's macros
// (None, Status, Bool, ...) meet no VTK header.
#ifndef deepshadow_tool_Display_h
#define deepshadow_tool_Display_h

namespace deepshadow
{
namespace tool
{

/** True if XOpenDisplay opens $DISPLAY (closed again at once). */
bool DisplayAnswers();

}
}
#endif
