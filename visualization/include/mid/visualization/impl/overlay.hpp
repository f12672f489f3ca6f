#pragma once

#include <mid/visualization/drawn_boxes.h>
#include <mid/visualization/intrinsics_estimation.h>
#include <mid/visualization/object_colors.h>
#include <mid/visualization/overlay.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <pcl/console/print.h>

#include <algorithm>
#include <limits>

namespace mid {
namespace visualization {
namespace detail {

/** \brief The color image of an organized cloud, 8-bit BGR. */
template <typename PointT>
cv::Mat
organizedCloudToImage (const pcl::PointCloud<PointT>& cloud)
{
  cv::Mat image (
      static_cast<int> (cloud.height), static_cast<int> (cloud.width), CV_8UC3);
  for (int v = 0; v < image.rows; ++v) {
    auto* row = image.ptr<cv::Vec3b> (v);
    for (int u = 0; u < image.cols; ++u) {
      const PointT& point = cloud.at (u, v);
      row[u] = cv::Vec3b (point.b, point.g, point.r);
    }
  }
  return image;
}

/** \brief Draw one instance: keypoint circles, the rectangle around them and its label. */
void
drawInstance (const std::vector<cv::Point2f>& pixels,
              const cv::Scalar& color,
              const std::string& label,
              cv::Mat& image);

/** \brief Draw the 12 edges of a box (edges `size`, frame `box_to_camera`, metres), projected
  * by `intrinsics`, 1 pixel wide; an edge with an end at or behind the camera is left out.
  */
void
drawBox (const Eigen::Matrix4f& box_to_camera,
         const Eigen::Vector3f& size,
         const io::CameraIntrinsics& intrinsics,
         const cv::Scalar& color,
         cv::Mat& image);

} // namespace detail

template <typename PointT>
bool
renderOverlay (const pcl::PointCloud<PointT>& cloud,
               const DiscoveryResult& result,
               cv::Mat& image)
{
  image.release();
  if (!cloud.isOrganized() ||
      cloud.size() != std::size_t (cloud.width) * cloud.height) {
    PCL_ERROR (
        "[mid::visualization::renderOverlay] the cloud is not organized (%u x %u)\n",
        cloud.width,
        cloud.height);
    return false;
  }
  cv::Mat drawn = detail::organizedCloudToImage (cloud);
  // The objects' boxes that enough copies agree on, under the instances; a cloud from a depth
  // image gives its camera.
  io::CameraIntrinsics intrinsics;
  bool boxes = false;
  for (std::size_t m = 0; m < result.models.size(); ++m)
    boxes = boxes || (modelBox (result, m) && isBoxDrawn (*modelBox (result, m)));
  boxes = boxes && estimateIntrinsics (cloud, intrinsics);
  for (std::size_t m = 0; boxes && m < result.models.size(); ++m) {
    const ObjectColor color = objectColor (m);
    const ModelSize* box = modelBox (result, m);
    if (box && isBoxDrawn (*box))
      for (const auto& instance : result.models[m].instances)
        detail::drawBox (instance.pose * box->box_in_model,
                         box->size,
                         intrinsics,
                         cv::Scalar (color.b, color.g, color.r),
                         drawn);
  }
  for (std::size_t m = 0; m < result.models.size(); ++m) {
    const ObjectColor color = objectColor (m);
    const auto& instances = result.models[m].instances;
    for (std::size_t i = 0; i < instances.size(); ++i) {
      std::vector<cv::Point2f> pixels;
      for (const auto k : instances[i].keypoints) {
        if (k < 0 || static_cast<std::size_t> (k) >= result.image_keypoints.size()) {
          PCL_ERROR (
              "[mid::visualization::renderOverlay] keypoint %d of object %zu, instance "
              "%zu has no image position (%zu image keypoints)\n",
              static_cast<int> (k),
              m,
              i,
              result.image_keypoints.size());
          return false;
        }
        const ImageKeypoint& keypoint =
            result.image_keypoints[static_cast<std::size_t> (k)];
        pixels.emplace_back (keypoint.u, keypoint.v);
      }
      detail::drawInstance (pixels,
                            cv::Scalar (color.b, color.g, color.r),
                            std::to_string (m) + "." + std::to_string (i),
                            drawn);
    }
  }
  image = drawn;
  return true;
}

template <typename PointT>
bool
saveOverlay (const std::string& path,
             const pcl::PointCloud<PointT>& cloud,
             const DiscoveryResult& result)
{
  cv::Mat image;
  if (!renderOverlay (cloud, result, image))
    return false;
  bool written = false;
  try {
    written = cv::imwrite (path, image);
  }
  catch (const cv::Exception& error) {
    PCL_ERROR ("[mid::visualization::saveOverlay] cannot write '%s': %s\n",
               path.c_str(),
               error.what());
    return false;
  }
  if (!written) {
    PCL_ERROR ("[mid::visualization::saveOverlay] cannot write '%s'\n", path.c_str());
    return false;
  }
  return true;
}

} // namespace visualization
} // namespace mid
