#pragma once

#include <mid/discovery/discovery_stages.h>
#include <mid/discovery/multi_instance_discovery.h>
#include <mid/features/sift_keypoint_extractor.h>

#include <pcl/common/time.h>

namespace mid {

template <typename PointT>
bool
MultiInstanceDiscovery<PointT>::discover (DiscoveryResult& result)
{
  result = DiscoveryResult ();
  pcl::StopWatch total;
  pcl::StopWatch watch;
  SIFTKeypointExtractor<PointT> extractor;
  extractor.setInputCloud (input_);
  if (!fake_indices_)
    extractor.setIndices (indices_);
  extractor.setMaxKeypoints (parameters_.max_keypoints);
  extractor.setContrastThreshold (parameters_.contrast_threshold);
  extractor.setNormalRadius (parameters_.normal_radius);
  result.keypoints = pcl::make_shared<KeypointCloud> ();
  result.descriptors = pcl::make_shared<SIFTDescriptorCloud> ();
  if (!extractor.compute (*result.keypoints, *result.descriptors)) {
    result = DiscoveryResult ();
    return false;
  }
  result.image_keypoints = extractor.getImageKeypoints ();
  result.timing_ms.emplace_back ("features", watch.getTime ());
  if (!discoverFromKeypoints (parameters_, result)) {
    result = DiscoveryResult ();
    return false;
  }
  result.timing_ms.emplace_back ("total", total.getTime ());
  return true;
}

} // namespace mid
