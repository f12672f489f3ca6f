#pragma once

namespace mid {
namespace visualization {

/** \brief A connection to the X display named by DISPLAY, for VTK's render windows.
  *
  * VTK's render windows here are X windows, also when they render off-screen, and VTK aborts the
  * program when it cannot open the display itself. Give it this connection instead
  * (vtkRenderWindow::SetDisplayId (connection.get ())), and keep the connection until the window
  * is gone. Opening retries for up to a second: a virtual X server (Xvfb) resets when its last
  * client leaves and refuses connections meanwhile.
  */
class DisplayConnection
{
public:
  /** \brief Open the display (see isOpen()). */
  DisplayConnection();
  /** \brief Close it. */
  ~DisplayConnection();
  DisplayConnection (const DisplayConnection&) = delete;
  DisplayConnection&
  operator= (const DisplayConnection&) = delete;

  /** \brief True if the display could be opened. */
  bool
  isOpen () const
  {
    return display_ != nullptr;
  }

  /** \brief The Xlib Display*, null if not open. */
  void*
  get () const
  {
    return display_;
  }

private:
  void* display_ = nullptr;
};

/** \brief True if an X display can be opened (DisplayConnection); headless machines can render
  * under a virtual one (`xvfb-run -a PROGRAM ...`).
  */
bool
displayAvailable ();

} // namespace visualization
} // namespace mid
