#include <mid/simulation/bop_ground_truth.h>
#include <mid/simulation/scene_renderer.h>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>

namespace mid {
namespace simulation {

namespace {

/** The image window that holds a shape's projection: the projected corners of the cube around
  * its bounding sphere, one pixel wider on each side; the whole image if the cube reaches
  * behind the camera or the shape is unbounded.
  */
cv::Rect
projectionWindow (const PinholeCamera& camera, const SceneObject& object)
{
  const cv::Rect image (0, 0, camera.width, camera.height);
  const double radius = object.shape->getBoundingRadius();
  if (!std::isfinite (radius))
    return image;
  const Eigen::Vector3d center = object.pose.translation();
  double min_u = camera.width, min_v = camera.height, max_u = -1.0, max_v = -1.0;
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d point =
        center + radius * Eigen::Vector3d ((corner & 1) ? 1.0 : -1.0,
                                           (corner & 2) ? 1.0 : -1.0,
                                           (corner & 4) ? 1.0 : -1.0);
    Eigen::Vector2d pixel;
    if (point.z() <= 1e-6 || !projectPoint (camera, point, pixel))
      return image;
    min_u = std::min (min_u, pixel.x());
    min_v = std::min (min_v, pixel.y());
    max_u = std::max (max_u, pixel.x());
    max_v = std::max (max_v, pixel.y());
  }
  const cv::Rect window (cv::Point (static_cast<int> (std::floor (min_u)) - 1,
                                    static_cast<int> (std::floor (min_v)) - 1),
                         cv::Point (static_cast<int> (std::ceil (max_u)) + 2,
                                    static_cast<int> (std::ceil (max_v)) + 2));
  return window & image;
}

/** Silhouette of one object alone (CV_8UC1, 255 inside), full image size. */
bool
renderSilhouette (const PinholeCamera& camera,
                  const SceneObject& object,
                  cv::Mat& silhouette)
{
  silhouette = cv::Mat::zeros (camera.height, camera.width, CV_8UC1);
  const cv::Rect window = projectionWindow (camera, object);
  if (window.empty())
    return true;
  // The window as a camera of its own: same rays through the same pixel centres.
  PinholeCamera cropped = camera;
  cropped.width = window.width;
  cropped.height = window.height;
  cropped.cx = camera.cx - window.x;
  cropped.cy = camera.cy - window.y;
  Scene alone;
  alone.addObject (object.shape, object.pose);
  SceneRenderer renderer;
  renderer.setCamera (cropped);
  RenderedFrame frame;
  if (!renderer.render (alone, frame))
    return false;
  silhouette (window).setTo (255, frame.instances == 0);
  return true;
}

} // namespace

bool
computeBopInstanceInfo (const Scene& scene,
                        const RenderedFrame& frame,
                        std::vector<BopInstanceInfo>& info)
{
  info.clear();
  const PinholeCamera& camera = frame.camera;
  const cv::Size size (camera.width, camera.height);
  if (frame.instances.size() != size || frame.instances.type() != CV_32SC1 ||
      frame.depth.size() != size || frame.depth.type() != CV_32FC1 ||
      frame.instance_stats.size() != scene.getObjects().size()) {
    PCL_ERROR (
        "[mid::simulation::computeBopInstanceInfo] the frame was not rendered from "
        "this scene\n");
    return false;
  }
  const cv::Mat valid = frame.depth > 0.0f;
  for (std::size_t id = 0; id < scene.getObjects().size(); ++id) {
    cv::Mat silhouette;
    if (!renderSilhouette (camera, scene.getObjects()[id], silhouette)) {
      info.clear();
      return false;
    }
    BopInstanceInfo entry;
    entry.px_count_all = cv::countNonZero (silhouette);
    entry.px_count_valid = cv::countNonZero (silhouette & valid);
    entry.px_count_visib = frame.instance_stats[id].visible_pixels;
    if (entry.px_count_all > 0) {
      entry.bbox_obj = cv::boundingRect (silhouette);
      entry.visib_fract =
          static_cast<double> (entry.px_count_visib) / entry.px_count_all;
    }
    if (entry.px_count_visib > 0)
      entry.bbox_visib = frame.instance_stats[id].bbox;
    info.push_back (entry);
  }
  return true;
}

} // namespace simulation
} // namespace mid
