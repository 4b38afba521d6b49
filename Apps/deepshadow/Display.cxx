#include "Display.h"

#include <X11/Xlib.h>

namespace deepshadow
{
namespace tool
{

bool DisplayAnswers()
{
  ::Display* display = XOpenDisplay(nullptr);
  if (!display)
  {
    return false;
  }
  XCloseDisplay(display);
  return true;
}

}
}
