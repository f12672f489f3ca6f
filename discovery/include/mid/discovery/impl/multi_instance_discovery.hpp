#pragma once

#include <mid/discovery/discovery_stages.h>
#include <mid/discovery/multi_instance_discovery.h>
#include <mid/features/sift_keypoint_extractor.h>

#include <pcl/common/io.h>
#include <pcl/common/point_tests.h>
#include <pcl/common/time.h>
#include <pcl/features/integral_image_normal.h>

namespace mid {

template <typename PointT>
bool
MultiInstanceDiscovery<PointT>::discover (DiscoveryResult& result)
{
  result = DiscoveryResult();
  pcl::StopWatch total;
  pcl::StopWatch watch;
  SIFTKeypointExtractor<PointT> extractor;
  extractor.setInputCloud (input_);
  if (!fake_indices_)
    extractor.setIndices (indices_);
  extractor.setMaxKeypoints (parameters_.max_keypoints);
  extractor.setContrastThreshold (parameters_.contrast_threshold);
  extractor.setNormalRadius (parameters_.normal_radius);
  result.keypoints = pcl::make_shared<KeypointCloud>();
  result.descriptors = pcl::make_shared<SIFTDescriptorCloud>();
  if (!extractor.compute (*result.keypoints, *result.descriptors)) {
    result = DiscoveryResult();
    return false;
  }
  result.image_keypoints = extractor.getImageKeypoints();
  result.timing_ms.emplace_back ("features", watch.getTime());

  // Only PCL's Hough3D peer needs the surface with normals (for its BOARD reference frames).
  pcl::PointCloud<pcl::PointNormal>::Ptr surface;
  if (parameters_.grouping == Grouping::hough3d) {
    watch.reset();
    pcl::PointCloud<pcl::Normal> normals;
    pcl::IntegralImageNormalEstimation<PointT, pcl::Normal> estimation;
    estimation.setNormalEstimationMethod (estimation.AVERAGE_3D_GRADIENT);
    estimation.setMaxDepthChangeFactor (0.02f);
    estimation.setNormalSmoothingSize (10.0f);
    estimation.setInputCloud (input_);
    estimation.compute (normals);
    surface = pcl::make_shared<pcl::PointCloud<pcl::PointNormal>>();
    for (std::size_t i = 0; i < input_->size(); ++i)
      if (pcl::isXYZFinite ((*input_)[i]) && pcl::isNormalFinite (normals[i])) {
        pcl::PointNormal point;
        point.getVector3fMap() = (*input_)[i].getVector3fMap();
        point.getNormalVector3fMap() = normals[i].getNormalVector3fMap();
        point.curvature = normals[i].curvature;
        surface->push_back (point);
      }
    result.timing_ms.emplace_back ("surface_normals", watch.getTime());
  }
  // The organized frame lets our clustering see the surface between two copies (the peers
  // do not look at it) and the verification compare the look of the copies (every grouping).
  auto organized = pcl::make_shared<pcl::PointCloud<pcl::PointXYZRGB>>();
  pcl::copyPointCloud (*input_, *organized);
  if (!discoverFromKeypoints (parameters_, result, surface, organized)) {
    result = DiscoveryResult();
    return false;
  }
  result.timing_ms.emplace_back ("total", total.getTime());
  return true;
}

} // namespace mid
