#pragma once

#include <mid/discovery/discovery_result.h>

#include <opencv2/core/mat.hpp>
#include <pcl/point_cloud.h>

#include <string>

namespace mid {
namespace visualization {

/** \brief Draw a discovery result on the frame's color image.
  *
  * The image is the organized cloud's color (also where the depth is missing). Each instance is
  * drawn in its object's color (objectColor(), object = index in result.models): a small circle
  * (radius 3 pixels) on each of its keypoints, the rectangle around them (the `bbox` of the
  * result JSON, 2 pixels wide, rounded to whole pixels) and a label "object.instance" above it.
  * Under them, where the result gives an object's box on the table (DiscoveryResult::model_sizes)
  * that two or more measured copies agree on (one copy alone is often measured joined with a
  * neighbour), its 12 edges at each instance's pose, projected by the camera the cloud's own
  * points give (estimateIntrinsics()), 1 pixel wide. Every other pixel keeps the scene's color.
  * \param[in] cloud the organized cloud the result was computed on
  * \param[in] result the result; its instances' keypoints index result.image_keypoints
  * \param[out] image 8-bit BGR image of the cloud's size (OpenCV's channel order); empty when
  * false is returned
  * \return false (with a PCL_ERROR naming the problem) if the cloud is not organized or an
  * instance's keypoint has no image position
  */
template <typename PointT>
bool
renderOverlay (const pcl::PointCloud<PointT>& cloud,
               const DiscoveryResult& result,
               cv::Mat& image);

/** \brief Draw a discovery result with renderOverlay() and write it with cv::imwrite.
  * \param[in] path the image file; its extension chooses the format (PNG: .png)
  * \param[in] cloud the organized cloud the result was computed on
  * \param[in] result the result
  * \return false (with a PCL_ERROR naming the problem) if the overlay cannot be drawn or written
  */
template <typename PointT>
bool
saveOverlay (const std::string& path,
             const pcl::PointCloud<PointT>& cloud,
             const DiscoveryResult& result);

} // namespace visualization
} // namespace mid

#ifdef MID_NO_PRECOMPILE
#include <mid/visualization/impl/overlay.hpp>
#endif
