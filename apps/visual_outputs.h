#pragma once

// The pictures of a result that the apps make on request: a screenshot of the 3D view, the 2D
// overlay on the color image, and an interactive window. Without these options no window is
// opened and no display is needed.

#include "app_support.h"

#include <Eigen/Core>

#include <string>

namespace mid {
namespace apps {

/** \brief The picture options of a command line, the files they stage and the pictures. */
class VisualOutputs
{
public:
  /** \brief Print the help lines of the picture options. */
  static void
  printHelp ();

  /** \brief The picture options (for onlyKnownArguments). */
  static OptionSpecs
  options ();

  /** \brief Read the picture options; false after a one-line error if they are unusable, or if
    * a screenshot or a window is asked for and there is no X display.
    */
  bool
  parse (int argc, char** argv);

  /** \brief Stage the picture files with the app's other outputs; false after a one-line error
    * if a folder is unusable.
    */
  bool
  stage (ResultFiles& files);

  /** \brief Draw the staged pictures of a result (committed later with the other outputs);
    * false after a one-line error.
    */
  bool
  write (const pcl::PointCloud<PointT>::ConstPtr& cloud,
         const DiscoveryResult& result) const;

  /** \brief Open the interactive window if -view was given; returns when it is closed. False
    * after a one-line error.
    */
  bool
  show (const pcl::PointCloud<PointT>::ConstPtr& cloud,
        const DiscoveryResult& result) const;

private:
  std::string screenshot_path_;
  std::string overlay_path_;
  std::string screenshot_temporary_;
  std::string overlay_temporary_;
  int width_ = 640;
  int height_ = 480;
  bool view_ = false;
  bool draw_matches_ = false;
  bool has_viewpoint_ = false;
  Eigen::Vector3f viewpoint_ = Eigen::Vector3f::Zero();
};

} // namespace apps
} // namespace mid
