#pragma once

namespace mid {
namespace visualization {

/** \brief True if an X display can be opened.
  *
  * VTK's render windows here are X windows, also when they render off-screen: without a display
  * VTK aborts the program. Check this first; a headless machine can render under a virtual
  * display (`xvfb-run -a PROGRAM ...`).
  */
bool
displayAvailable ();

} // namespace visualization
} // namespace mid
