#pragma once

#include <mid/features/sift_keypoint_extractor.h>

#include <opencv2/features2d.hpp>
#include <opencv2/imgproc.hpp>
#include <pcl/common/point_tests.h>
#include <pcl/console/print.h>
#include <pcl/features/normal_3d.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>

namespace mid {
namespace detail {

/** \brief The color image of an organized cloud as an 8-bit gray image. */
template <typename PointT>
cv::Mat
organizedCloudToGray (const pcl::PointCloud<PointT>& cloud)
{
  cv::Mat bgr (
      static_cast<int> (cloud.height), static_cast<int> (cloud.width), CV_8UC3);
  for (int v = 0; v < bgr.rows; ++v) {
    auto* row = bgr.ptr<cv::Vec3b> (v);
    for (int u = 0; u < bgr.cols; ++u) {
      const PointT& point = cloud.at (u, v);
      row[u] = cv::Vec3b (point.b, point.g, point.r);
    }
  }
  cv::Mat gray;
  cv::cvtColor (bgr, gray, cv::COLOR_BGR2GRAY);
  return gray;
}

/** \brief A strict total order on OpenCV keypoints: strongest first, then by position, size and
  * angle, so that the output does not depend on OpenCV's thread scheduling.
  */
inline bool
keypointPrecedes (const cv::KeyPoint& a, const cv::KeyPoint& b)
{
  return std::make_tuple (-a.response, a.pt.y, a.pt.x, a.size, a.angle, a.octave) <
         std::make_tuple (-b.response, b.pt.y, b.pt.x, b.size, b.angle, b.octave);
}

} // namespace detail

template <typename PointT>
bool
SIFTKeypointExtractor<PointT>::checkInputs() const
{
  if (!input_ || input_->empty()) {
    PCL_ERROR ("[mid::SIFTKeypointExtractor::compute] No input cloud given.\n");
    return false;
  }
  if (!input_->isOrganized()) {
    PCL_ERROR ("[mid::SIFTKeypointExtractor::compute] The input cloud is not organized "
               "(height %u); an RGB-D frame is required.\n",
               input_->height);
    return false;
  }
  if (max_keypoints_ < 0 || octave_layers_ < 1 || contrast_threshold_ <= 0.0 ||
      edge_threshold_ <= 0.0 || sigma_ <= 0.0 || !(normal_radius_ > 0.0f) ||
      min_normal_neighbors_ < 3) {
    PCL_ERROR (
        "[mid::SIFTKeypointExtractor::compute] Invalid parameter: max keypoints %d "
        "(>= 0), octave layers %d (>= 1), contrast threshold %g, edge threshold %g, "
        "sigma "
        "%g, normal radius %g (all > 0), min normal neighbors %d (>= 3).\n",
        max_keypoints_,
        octave_layers_,
        contrast_threshold_,
        edge_threshold_,
        sigma_,
        static_cast<double> (normal_radius_),
        min_normal_neighbors_);
    return false;
  }
  return true;
}

template <typename PointT>
bool
SIFTKeypointExtractor<PointT>::estimateNormal (int u,
                                               int v,
                                               pcl::PointNormal& keypoint) const
{
  const int width = static_cast<int> (input_->width);
  const int height = static_cast<int> (input_->height);
  const Eigen::Vector3f center = input_->at (u, v).getVector3fMap();

  // Pixel pitch in metres at this keypoint: the nearest valid 4-neighbour. It turns the metric
  // radius into a pixel window without knowing the camera's focal length.
  float pitch = std::numeric_limits<float>::infinity();
  const int offsets[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  for (const auto& offset : offsets) {
    const int nu = u + offset[0], nv = v + offset[1];
    if (nu < 0 || nv < 0 || nu >= width || nv >= height)
      continue;
    const PointT& neighbor = input_->at (nu, nv);
    if (pcl::isXYZFinite (neighbor))
      pitch = std::min (pitch, (neighbor.getVector3fMap() - center).norm());
  }
  if (!std::isfinite (pitch))
    return false;
  constexpr int kMaxHalfWindow = 25;
  const int half = std::clamp (
      static_cast<int> (std::ceil (normal_radius_ / std::max (pitch, 1e-6f))),
      1,
      kMaxHalfWindow);

  const float squared_radius = normal_radius_ * normal_radius_;
  pcl::Indices neighbors;
  for (int nv = std::max (0, v - half); nv <= std::min (height - 1, v + half); ++nv)
    for (int nu = std::max (0, u - half); nu <= std::min (width - 1, u + half); ++nu) {
      const PointT& neighbor = input_->at (nu, nv);
      if (pcl::isXYZFinite (neighbor) &&
          (neighbor.getVector3fMap() - center).squaredNorm() <= squared_radius)
        neighbors.push_back (nv * width + nu);
    }
  if (static_cast<int> (neighbors.size()) < min_normal_neighbors_)
    return false;

  Eigen::Vector4f plane;
  float curvature = 0.0f;
  if (!pcl::computePointNormal (*input_, neighbors, plane, curvature))
    return false;
  pcl::flipNormalTowardsViewpoint (input_->at (u, v), 0.0f, 0.0f, 0.0f, plane);
  keypoint.getVector3fMap() = center;
  keypoint.getNormalVector3fMap() = plane.head<3>().normalized();
  keypoint.curvature = curvature;
  return keypoint.getNormalVector3fMap().allFinite();
}

template <typename PointT>
bool
SIFTKeypointExtractor<PointT>::compute (KeypointCloud& keypoints,
                                        SIFTDescriptorCloud& descriptors)
{
  keypoints.clear();
  descriptors.clear();
  image_keypoints_.clear();
  if (!checkInputs() || !initCompute())
    return false;

  std::vector<bool> allowed;
  if (!fake_indices_) {
    allowed.assign (input_->size(), false);
    for (const auto index : *indices_)
      allowed[static_cast<std::size_t> (index)] = true;
  }

  const cv::Mat gray = detail::organizedCloudToGray (*input_);
  cv::Ptr<cv::SIFT> sift = cv::SIFT::create (
      0, octave_layers_, contrast_threshold_, edge_threshold_, sigma_);
  std::vector<cv::KeyPoint> cv_keypoints;
  cv::Mat cv_descriptors;
  sift->detectAndCompute (gray, cv::noArray(), cv_keypoints, cv_descriptors);

  std::vector<std::size_t> order (cv_keypoints.size());
  std::iota (order.begin(), order.end(), std::size_t{0});
  std::sort (
      order.begin(), order.end(), [&cv_keypoints] (std::size_t a, std::size_t b) {
        return detail::keypointPrecedes (cv_keypoints[a], cv_keypoints[b]);
      });

  const int width = static_cast<int> (input_->width);
  const int height = static_cast<int> (input_->height);
  for (const std::size_t k : order) {
    if (max_keypoints_ > 0 && static_cast<int> (keypoints.size()) >= max_keypoints_)
      break;
    const cv::KeyPoint& kp = cv_keypoints[k];
    const int u = std::clamp (static_cast<int> (std::lround (kp.pt.x)), 0, width - 1);
    const int v = std::clamp (static_cast<int> (std::lround (kp.pt.y)), 0, height - 1);
    const pcl::index_t pixel = v * width + u;
    if (!allowed.empty() && !allowed[static_cast<std::size_t> (pixel)])
      continue;
    if (!pcl::isXYZFinite (input_->at (u, v)))
      continue;
    pcl::PointNormal keypoint;
    if (!estimateNormal (u, v, keypoint))
      continue;
    keypoints.push_back (keypoint);
    SIFTDescriptor descriptor;
    const float* row = cv_descriptors.ptr<float> (static_cast<int> (k));
    std::copy (row, row + 128, descriptor.histogram);
    descriptors.push_back (descriptor);
    image_keypoints_.push_back (ImageKeypoint{
        kp.pt.x, kp.pt.y, kp.size, kp.angle, kp.response, kp.octave, pixel});
  }
  deinitCompute();
  return true;
}

} // namespace mid
