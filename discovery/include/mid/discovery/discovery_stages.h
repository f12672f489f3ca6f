#pragma once

#include <mid/discovery/discovery_parameters.h>
#include <mid/discovery/discovery_result.h>

namespace mid {

/** \brief The stages of MultiInstanceDiscovery after keypoint extraction: self-matching,
  * triplets, clustering, model building and additional instance detection. For users who bring
  * their own keypoints and descriptors (result.keypoints / result.descriptors must be set).
  * Appends the stages' times to result.timing_ms. With a peer grouping (PCL's classes) the
  * "triplets" stage is empty and "clustering" times the peer.
  * \param[in] parameters the parameters
  * \param[in,out] result keypoints and descriptors in; matches, counts, models and times out
  * \param[in] surface the frame's points with normals; needed by Grouping::hough3d only
  * \return false (with a PCL_ERROR) if a stage refuses its input or parameters
  */
bool
discoverFromKeypoints (
    const DiscoveryParameters& parameters,
    DiscoveryResult& result,
    const pcl::PointCloud<pcl::PointNormal>::ConstPtr& surface = nullptr);

} // namespace mid
