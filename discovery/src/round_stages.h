#pragma once

// The rounds of the discovery pipeline: one round of its stages, the round on the keypoints
// left over and the models from patches of keypoints no instance explains.

#include <mid/discovery/discovery_parameters.h>
#include <mid/discovery/discovery_result.h>
#include <mid/segmentation/surface_gap.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

namespace mid {
namespace detail {

/** The stages of one round on result's keypoints and descriptors: the self-matches, their
  * grouping, the models, the detection of more instances and, in the first round, the round on
  * the keypoints left over (which runs these stages again) and the patches; each stage's time
  * goes into result.timing_ms. Defined in discovery_stages.cpp.
  * \return false (with a PCL_ERROR) on unusable input; result's outputs are then partial
  */
bool
runStages (const DiscoveryParameters& p,
           DiscoveryResult& result,
           const pcl::PointCloud<pcl::PointNormal>::ConstPtr& surface,
           const KeypointSurface& frame);

/** The second round on the keypoints left over (DiscoveryParameters::discover_leftovers): its
  * models join result's, merged with them where they match.
  */
bool
discoverLeftovers (const DiscoveryParameters& p,
                   const pcl::PointCloud<pcl::PointNormal>::ConstPtr& surface,
                   const KeypointSurface& keypoint_surface,
                   DiscoveryResult& result);

/** Models from patches of the keypoints no instance explains
  * (DiscoveryParameters::patch_discovery), when the guided search can run; times the
  * "patches" stage either way.
  */
bool
discoverFromPatches (const DiscoveryParameters& p,
                     const KeypointSurface& surface,
                     DiscoveryResult& result);

} // namespace detail
} // namespace mid
