#pragma once

#include <mid/discovery/discovery_result.h>
#include <mid/io/camera_intrinsics.h>

#include <Eigen/Core>
#include <pcl/point_cloud.h>

#include <memory>
#include <string>

namespace pcl {
namespace visualization {
class PCLVisualizer;
} // namespace visualization
} // namespace pcl

namespace mid {
namespace visualization {

/** \brief Fraction of the window's width that the model panel of DiscoveryViewer takes (on the
  * right) when the result has objects and the panel is on.
  */
constexpr double MODEL_PANEL_WIDTH = 0.25;

/** \brief A 3D view of a discovery result, built on pcl::visualization::PCLVisualizer.
  *
  * The scene viewport (left) shows the colored scene cloud and, for every instance, the model's
  * landmarks moved by the instance's pose (model -> camera) as large points in the object's
  * color (objectColor()), with a coordinate frame (5 cm axes: x red, y green, z blue) at the
  * model origin. The landmarks are drawn 1 cm closer to the camera than they are, along their
  * ray, so that the surface they lie on does not hide them; seen from the camera this changes
  * nothing. Optionally the self-matches are drawn as lines between their keypoints.
  *
  * Its default camera is the RGB-D camera itself (setCameraView()): at the origin, looking along
  * +z, y down, with the view angle of the cloud's intrinsics (estimated from the cloud with
  * estimateIntrinsics() unless set), so the picture matches the color image. The model panel
  * (right, MODEL_PANEL_WIDTH of the window, one row per object) shows each model alone in its own
  * frame, with its coordinate frame and a caption.
  *
  * Rendering needs an X display (displayAvailable()); headless, run under `xvfb-run -a`.
  * \code
  * mid::visualization::DiscoveryViewer<pcl::PointXYZRGBA> viewer;
  * viewer.setInputCloud (cloud);
  * viewer.setResult (result);
  * viewer.saveScreenshot ("scene.png", 1280, 720);   // off-screen
  * viewer.spin (1280, 720);                          // interactive, until the window is closed
  * \endcode
  */
template <typename PointT>
class DiscoveryViewer
{
public:
  /** \brief The scene: an organized cloud with x, y, z (metres) and r, g, b. */
  using PointCloud = pcl::PointCloud<PointT>;
  /** \brief Shared pointer to a const scene. */
  using PointCloudConstPtr = typename PointCloud::ConstPtr;

  /** \brief The organized scene cloud the result was computed on (metres). */
  ///@{
  void
  setInputCloud (const PointCloudConstPtr& cloud)
  {
    cloud_ = cloud;
  }
  const PointCloudConstPtr&
  getInputCloud () const
  {
    return cloud_;
  }
  ///@}

  /** \brief The result to show (copied). */
  ///@{
  void
  setResult (const DiscoveryResult& result)
  {
    result_ = result;
  }
  const DiscoveryResult&
  getResult () const
  {
    return result_;
  }
  ///@}

  /** \brief The camera's intrinsics (fx, fy, cx, cy); without them they are estimated from the
    * cloud.
    */
  void
  setIntrinsics (const io::CameraIntrinsics& intrinsics)
  {
    intrinsics_ = intrinsics;
    has_intrinsics_ = true;
  }

  /** \brief Draw the self-matches as lines (default: off). */
  ///@{
  void
  setShowMatches (bool show)
  {
    show_matches_ = show;
  }
  bool
  getShowMatches () const
  {
    return show_matches_;
  }
  ///@}

  /** \brief Show the model panel on the right (default: on; it appears only if the result has
    * objects).
    */
  ///@{
  void
  setShowModelPanel (bool show)
  {
    show_model_panel_ = show;
  }
  bool
  getShowModelPanel () const
  {
    return show_model_panel_;
  }
  ///@}

  /** \brief Look at the scene from `position` (camera frame, metres) instead of through the
    * camera: towards the mean of the instances' positions (the cloud's centroid if there are
    * none), with -y up.
    */
  void
  setViewpoint (const Eigen::Vector3f& position)
  {
    viewpoint_ = position;
    has_viewpoint_ = true;
  }

  /** \brief Go back to the default camera (the RGB-D camera's view). */
  void
  resetViewpoint ()
  {
    has_viewpoint_ = false;
  }

  /** \brief Render off-screen at the given size and write a PNG (VTK's vtkWindowToImageFilter
    * and vtkPNGWriter).
    * \param[in] path the PNG file
    * \param[in] width window width, pixels
    * \param[in] height window height, pixels
    * \return false (with a PCL_ERROR naming the problem) if there is no display, no usable
    * input, a size is not positive, or the file cannot be written
    */
  bool
  saveScreenshot (const std::string& path, int width, int height) const;

  /** \brief Open an interactive window (PCL's mouse and key bindings; h prints them) and return
    * when it is closed.
    * \param[in] width window width, pixels
    * \param[in] height window height, pixels
    * \return false (with a PCL_ERROR naming the problem) if there is no display or no usable input
    */
  bool
  spin (int width, int height) const;

private:
  /** \brief Check the inputs, create the viewports and add everything to `viewer`. */
  bool
  populate (pcl::visualization::PCLVisualizer& viewer, int width, int height) const;

  /** \brief The scene viewport: cloud, posed landmarks, frames, matches, camera. */
  bool
  populateScene (pcl::visualization::PCLVisualizer& viewer,
                 int viewport,
                 const io::CameraIntrinsics& intrinsics,
                 double scale) const;

  PointCloudConstPtr cloud_;
  DiscoveryResult result_;
  io::CameraIntrinsics intrinsics_;
  bool has_intrinsics_ = false;
  bool show_matches_ = false;
  bool show_model_panel_ = true;
  Eigen::Vector3f viewpoint_ = Eigen::Vector3f::Zero();
  bool has_viewpoint_ = false;
};

} // namespace visualization
} // namespace mid

#ifdef MID_NO_PRECOMPILE
#include <mid/visualization/impl/discovery_viewer.hpp>
#endif
