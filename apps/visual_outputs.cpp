#include "visual_outputs.h"

#include <mid/visualization/discovery_viewer.h>
#include <mid/visualization/display.h>
#include <mid/visualization/overlay.h>

#include <pcl/console/parse.h>
#include <pcl/console/print.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace mid {
namespace apps {

namespace {

using pcl::console::print_error;
using pcl::console::print_info;

/** The `count` numbers after `option`: 0 if the option is absent, 1 if they were read, -1
  * after a one-line error.
  */
int
parseNumbers (int argc,
              char** argv,
              const char* option,
              std::size_t count,
              std::vector<double>& values)
{
  const int index = pcl::console::find_argument (argc, argv, option);
  if (index < 0)
    return 0;
  values.clear();
  double value = 0.0;
  for (int i = index + 1;
       i < argc && values.size() < count && toNumber (std::string (argv[i]), value);
       ++i)
    values.push_back (value);
  if (values.size() != count) {
    print_error ("%s needs %zu numbers.\n", option, count);
    return -1;
  }
  return 1;
}

bool
endsWithPng (const std::string& path)
{
  return path.size() > 4 && path.compare (path.size() - 4, 4, ".png") == 0;
}

} // namespace

void
VisualOutputs::printHelp()
{
  print_info ("Pictures (none by default; without -screenshot and -view no display is "
              "needed):\n");
  print_info ("  -overlay FILE.png   the color image with each instance's keypoints, "
              "box and label\n");
  print_info ("                      in its object's color, and the object's box where "
              "2+ copies agree\n");
  print_info ("  -screenshot FILE.png  3D view rendered off-screen: scene, model "
              "landmarks at each\n");
  print_info ("                      instance's pose, 5 cm frames, the object's box as "
              "on the overlay,\n");
  print_info ("                      models on the right (needs an X display: run "
              "under xvfb-run -a\n");
  print_info ("                      on a headless machine)\n");
  print_info (
      "  -size W H           screenshot and window size in pixels (default 640 480)\n");
  print_info ("  -viewpoint X Y Z    look from this point (camera frame, metres) at "
              "the instances\n");
  print_info ("                      (default: through the RGB-D camera)\n");
  print_info ("  -draw_matches       also draw the self-matches as lines\n");
  print_info ("  -view               open an interactive 3D window after the work "
              "(needs a display)\n");
}

OptionSpecs
VisualOutputs::options()
{
  return {{"-screenshot", 1},
          {"-overlay", 1},
          {"-size", 2},
          {"-viewpoint", 3},
          {"-view", 0},
          {"-draw_matches", 0}};
}

bool
VisualOutputs::parse (int argc, char** argv)
{
  pcl::console::parse_argument (argc, argv, "-screenshot", screenshot_path_);
  pcl::console::parse_argument (argc, argv, "-overlay", overlay_path_);
  view_ = pcl::console::find_switch (argc, argv, "-view");
  draw_matches_ = pcl::console::find_switch (argc, argv, "-draw_matches");
  for (const std::string* path : {&screenshot_path_, &overlay_path_})
    if (!path->empty() && !endsWithPng (*path)) {
      print_error ("'%s' must end in .png.\n", path->c_str());
      return false;
    }
  std::vector<double> values;
  const int size = parseNumbers (argc, argv, "-size", 2, values);
  if (size < 0)
    return false;
  if (size > 0) {
    constexpr double kSmallest = 16.0, kLargest = 8192.0;
    if (!(values[0] >= kSmallest && values[0] <= kLargest && values[1] >= kSmallest &&
          values[1] <= kLargest && values[0] == std::floor (values[0]) &&
          values[1] == std::floor (values[1]))) {
      print_error (
          "Invalid parameter: -size %g %g, each must be a whole number in [16, 8192] "
          "pixels.\n",
          values[0],
          values[1]);
      return false;
    }
    width_ = static_cast<int> (values[0]);
    height_ = static_cast<int> (values[1]);
  }
  const int viewpoint = parseNumbers (argc, argv, "-viewpoint", 3, values);
  if (viewpoint < 0)
    return false;
  has_viewpoint_ = viewpoint > 0;
  if (has_viewpoint_)
    viewpoint_ = Eigen::Vector3d (values[0], values[1], values[2]).cast<float>();
  if ((!screenshot_path_.empty() || view_) && !visualization::displayAvailable()) {
    print_error (
        "%s needs an X display, and DISPLAY is unset or unreachable (headless: run "
        "under xvfb-run -a).\n",
        view_ ? "-view" : "-screenshot");
    return false;
  }
  return true;
}

bool
VisualOutputs::stage (ResultFiles& files)
{
  if (!screenshot_path_.empty() &&
      (screenshot_temporary_ = files.stageFile (screenshot_path_)).empty())
    return false;
  return overlay_path_.empty() ||
         !(overlay_temporary_ = files.stageFile (overlay_path_)).empty();
}

bool
VisualOutputs::write (const pcl::PointCloud<PointT>::ConstPtr& cloud,
                      const DiscoveryResult& result) const
{
  if (!overlay_temporary_.empty() &&
      !visualization::saveOverlay (overlay_temporary_, *cloud, result))
    return false;
  if (screenshot_temporary_.empty())
    return true;
  visualization::DiscoveryViewer<PointT> viewer;
  viewer.setInputCloud (cloud);
  viewer.setResult (result);
  viewer.setShowMatches (draw_matches_);
  if (has_viewpoint_)
    viewer.setViewpoint (viewpoint_);
  return viewer.saveScreenshot (screenshot_temporary_, width_, height_);
}

bool
VisualOutputs::show (const pcl::PointCloud<PointT>::ConstPtr& cloud,
                     const DiscoveryResult& result) const
{
  if (!view_)
    return true;
  visualization::DiscoveryViewer<PointT> viewer;
  viewer.setInputCloud (cloud);
  viewer.setResult (result);
  viewer.setShowMatches (draw_matches_);
  if (has_viewpoint_)
    viewer.setViewpoint (viewpoint_);
  return viewer.spin (width_, height_);
}

} // namespace apps
} // namespace mid
