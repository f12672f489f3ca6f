#pragma once

#include <mid/discovery/discovery_parameters.h>
#include <mid/features/keypoint_types.h>
#include <mid/registration/triplet_cluster.h>

#include <pcl/correspondence.h>

namespace mid {
namespace detail {

/** \brief Group the self-matches with one of PCL's correspondence grouping classes (the model
  * and the scene are both the frame's keypoints), and express each group as a TripletCluster
  * (no triplets) so that the same model building follows.
  * \param[in] p the parameters (grouping method and its settings)
  * \param[in] keypoints the frame's keypoints
  * \param[in] surface the frame's points with normals (BOARD frames for Hough3D), may be null
  *            for geometric consistency
  * \param[in] matches the self-matches
  * \param[out] clusters one per group, largest first
  * \return false (with a PCL_ERROR) if the input is unusable
  */
bool
groupWithPeer (const DiscoveryParameters& p,
               const KeypointCloud::ConstPtr& keypoints,
               const pcl::PointCloud<pcl::PointNormal>::ConstPtr& surface,
               const pcl::Correspondences& matches,
               TripletClusters& clusters);

} // namespace detail
} // namespace mid
