#include <mid/visualization/display.h>

#include <X11/Xlib.h>

namespace mid {
namespace visualization {

bool
displayAvailable ()
{
  // Opening the display named by DISPLAY is exactly what VTK does first; XOpenDisplay returns
  // null (without exiting) if DISPLAY is unset or names no reachable server.
  Display* display = XOpenDisplay (nullptr);
  if (display == nullptr)
    return false;
  XCloseDisplay (display);
  return true;
}

} // namespace visualization
} // namespace mid
