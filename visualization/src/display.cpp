#include <mid/visualization/display.h>

#include <X11/Xlib.h>

#include <chrono>
#include <cstdlib>
#include <thread>

namespace mid {
namespace visualization {

DisplayConnection::DisplayConnection()
{
  // XOpenDisplay returns null, without exiting, if DISPLAY is unset or names no reachable server.
  if (std::getenv ("DISPLAY") == nullptr)
    return;
  constexpr int kAttempts = 50;
  for (int attempt = 0; attempt < kAttempts && display_ == nullptr; ++attempt) {
    if (attempt > 0)
      std::this_thread::sleep_for (std::chrono::milliseconds (20));
    display_ = XOpenDisplay (nullptr);
  }
}

DisplayConnection::~DisplayConnection()
{
  if (display_ != nullptr)
    XCloseDisplay (static_cast<Display*> (display_));
}

bool
displayAvailable ()
{
  return DisplayConnection().isOpen();
}

} // namespace visualization
} // namespace mid
