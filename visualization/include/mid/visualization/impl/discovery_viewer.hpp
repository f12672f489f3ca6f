#pragma once

#include <mid/visualization/camera_view.h>
#include <mid/visualization/discovery_viewer.h>
#include <mid/visualization/drawn_boxes.h>
#include <mid/visualization/intrinsics_estimation.h>
#include <mid/visualization/object_colors.h>

#include <pcl/console/print.h>
#include <pcl/visualization/pcl_visualizer.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

namespace mid {
namespace visualization {
namespace detail {

/** \brief Landmarks moved by `pose` (model -> camera), then `shift` metres towards the camera
  * along their ray.
  */
pcl::PointCloud<pcl::PointXYZ>::Ptr
posedPoints (const KeypointCloud& points, const Eigen::Matrix4f& pose, float shift);

/** \brief Add the rows of the model panel, one per object, on the right of the window. */
void
addModelPanel (pcl::visualization::PCLVisualizer& viewer,
               const ObjectModels& models,
               double left,
               int height);

/** \brief Add a box as its 12 edges, unlit lines of `color` (kBoxLineWidth pixels wide).
  * \param[in] box_to_camera the box's frame: origin at its centre, axes along its edges
  * \param[in] size its edges along those axes (metres)
  */
void
addBox (pcl::visualization::PCLVisualizer& viewer,
        const Eigen::Matrix4f& box_to_camera,
        const Eigen::Vector3f& size,
        const ObjectColor& color,
        const std::string& id,
        int viewport);

/** \brief A renderer drawn over the viewport (VTK layer 1, same extent and camera), for what
  * must stay visible in front of the scene; its index in the viewer's renderer collection.
  */
int
addOverlayLayer (pcl::visualization::PCLVisualizer& viewer, int viewport);

/** \brief Look from `position` at `target` (camera frame), -y up, in the viewport. */
bool
lookAt (pcl::visualization::PCLVisualizer& viewer,
        const Eigen::Vector3f& position,
        const Eigen::Vector3f& target,
        int viewport);

/** \brief Open the display, create a PCLVisualizer on it (off-screen, or with an interactor),
  * let `populate` fill it, then write it as a PNG or run it until the window is closed. False
  * (with a PCL_ERROR naming `caller`) if there is no display, `populate` fails, or the file
  * cannot be written. VTK's deprecation warnings (from inside VTK) are not printed meanwhile.
  */
bool
renderOffScreen (
    const char* caller,
    const std::string& path,
    const std::function<bool (pcl::visualization::PCLVisualizer&)>& populate);
bool
renderInteractive (
    const char* caller,
    const std::function<bool (pcl::visualization::PCLVisualizer&)>& populate);

/** \brief Size of the landmark points for a picture `scale` times the image's size. */
inline double
landmarkPointSize (double scale)
{
  return std::max (4.0, std::round (7.0 * scale));
}

/** \brief Landmarks and match lines are drawn this much (metres) closer to the camera. */
constexpr float kTowardsCamera = 0.01f;
/** \brief Length of the axes of each coordinate frame (metres). */
constexpr double kFrameAxes = 0.05;
/** \brief Width of the lines of the objects' boxes (pixels). */
constexpr double kBoxLineWidth = 2.0;

} // namespace detail

template <typename PointT>
bool
DiscoveryViewer<PointT>::saveScreenshot (const std::string& path,
                                         int width,
                                         int height) const
{
  return detail::renderOffScreen (
      "mid::visualization::DiscoveryViewer::saveScreenshot",
      path,
      [this, width, height] (pcl::visualization::PCLVisualizer& viewer) {
        return populate (viewer, width, height);
      });
}

template <typename PointT>
bool
DiscoveryViewer<PointT>::spin (int width, int height) const
{
  return detail::renderInteractive (
      "mid::visualization::DiscoveryViewer::spin",
      [this, width, height] (pcl::visualization::PCLVisualizer& viewer) {
        return populate (viewer, width, height);
      });
}

template <typename PointT>
bool
DiscoveryViewer<PointT>::populate (pcl::visualization::PCLVisualizer& viewer,
                                   int width,
                                   int height) const
{
  if (!cloud_ || !cloud_->isOrganized() ||
      cloud_->size() != std::size_t (cloud_->width) * cloud_->height) {
    PCL_ERROR (
        "[mid::visualization::DiscoveryViewer] no organized input cloud given\n");
    return false;
  }
  if (width <= 0 || height <= 0) {
    PCL_ERROR ("[mid::visualization::DiscoveryViewer] the picture size %d x %d is not "
               "positive\n",
               width,
               height);
    return false;
  }
  io::CameraIntrinsics intrinsics = intrinsics_;
  if (!has_intrinsics_ && !estimateIntrinsics (*cloud_, intrinsics))
    return false;

  viewer.setShowFPS (false);
  viewer.getRenderWindow()->SetSize (width, height);
  const bool panel = show_model_panel_ && !result_.models.empty();
  const double scene_right = panel ? 1.0 - MODEL_PANEL_WIDTH : 1.0;
  int viewport = 0;
  viewer.createViewPort (0.0, 0.0, scene_right, 1.0, viewport);
  viewer.createViewPortCamera (viewport);
  const ImageFit fit = fitImage (static_cast<int> (cloud_->width),
                                 static_cast<int> (cloud_->height),
                                 static_cast<int> (std::lround (scene_right * width)),
                                 height);
  if (!populateScene (viewer, viewport, intrinsics, fit.scale))
    return false;
  if (panel)
    detail::addModelPanel (viewer, result_.models, scene_right, height);
  return true;
}

template <typename PointT>
bool
DiscoveryViewer<PointT>::populateScene (pcl::visualization::PCLVisualizer& viewer,
                                        int viewport,
                                        const io::CameraIntrinsics& intrinsics,
                                        double scale) const
{
  using pcl::visualization::PCL_VISUALIZER_POINT_SIZE;
  viewer.setBackgroundColor (0.05, 0.05, 0.05, viewport);
  const pcl::visualization::PointCloudColorHandlerRGBField<PointT> scene_colors (
      cloud_);
  viewer.addPointCloud<PointT> (cloud_, scene_colors, "scene", viewport);
  viewer.setPointCloudRenderingProperties (
      PCL_VISUALIZER_POINT_SIZE, std::max (1.0, std::ceil (scale)), "scene");

  // Frames and boxes (those the overlay draws too) stay visible in front of the scene.
  const int frames_viewport = detail::addOverlayLayer (viewer, viewport);
  Eigen::Vector3f instances_sum = Eigen::Vector3f::Zero();
  std::size_t instances = 0;
  for (std::size_t m = 0; m < result_.models.size(); ++m) {
    const ObjectColor color = objectColor (m);
    const ObjectModel& model = result_.models[m];
    for (std::size_t i = 0; i < model.instances.size(); ++i) {
      const Eigen::Matrix4f& pose = model.instances[i].pose;
      const std::string suffix = std::to_string (m) + "_" + std::to_string (i);
      const auto points =
          detail::posedPoints (model.landmarks, pose, detail::kTowardsCamera);
      const pcl::visualization::PointCloudColorHandlerCustom<pcl::PointXYZ> colors (
          points, color.r, color.g, color.b);
      viewer.addPointCloud<pcl::PointXYZ> (
          points, colors, "landmarks_" + suffix, viewport);
      viewer.setPointCloudRenderingProperties (PCL_VISUALIZER_POINT_SIZE,
                                               detail::landmarkPointSize (scale),
                                               "landmarks_" + suffix);
      viewer.addCoordinateSystem (detail::kFrameAxes,
                                  Eigen::Affine3f (pose),
                                  "frame_" + suffix,
                                  frames_viewport);
      if (const ModelSize* box = modelBox (result_, m); box && isBoxDrawn (*box))
        detail::addBox (viewer,
                        pose * box->box_in_model,
                        box->size,
                        color,
                        "box_" + suffix,
                        frames_viewport);
      instances_sum += pose.topRightCorner<3, 1>();
      ++instances;
    }
  }
  if (show_matches_ && result_.keypoints && !result_.matches.empty()) {
    const auto keypoints = detail::posedPoints (
        *result_.keypoints, Eigen::Matrix4f::Identity(), detail::kTowardsCamera);
    viewer.addCorrespondences<pcl::PointXYZ> (
        keypoints, keypoints, result_.matches, "matches", viewport);
    viewer.setShapeRenderingProperties (
        pcl::visualization::PCL_VISUALIZER_COLOR, 1.0, 1.0, 0.6, "matches", viewport);
  }

  if (!setCameraView (viewer,
                      intrinsics,
                      static_cast<int> (cloud_->width),
                      static_cast<int> (cloud_->height),
                      viewport))
    return false;
  if (!has_viewpoint_)
    return true;
  Eigen::Vector3f target = Eigen::Vector3f::Zero();
  if (instances > 0)
    target = instances_sum / static_cast<float> (instances);
  else {
    std::size_t finite = 0;
    for (const auto& point : cloud_->points)
      if (pcl::isFinite (point)) {
        target += point.getVector3fMap();
        ++finite;
      }
    target /= static_cast<float> (std::max<std::size_t> (finite, 1));
  }
  return detail::lookAt (viewer, viewpoint_, target, viewport);
}

} // namespace visualization
} // namespace mid
