#pragma once

// The discovery pipeline's stages on the models: merges through shared landmarks or regions,
// more instances by RANSAC and by the guided search, the split by appearance.

#include <mid/discovery/discovery_parameters.h>
#include <mid/discovery/discovery_result.h>
#include <mid/segmentation/surface_gap.h>

#include <vector>

namespace mid {
namespace detail {

/** Merge the models whose instances show a common surface around their landmarks
  * (RegionModelMerger), with the pipeline's RANSAC settings; when the frame can tell, only
  * through copies whose common surface looks alike (DiscoveryParameters::verify_joins).
  */
bool
mergeThroughRegions (const DiscoveryParameters& p,
                     const KeypointSurface& surface,
                     DiscoveryResult& result);

/** Look for each model's instances among the keypoints no model uses yet; when the frame can
  * tell, an instance whose surface does not look like that of the model's copy that observes
  * most of its landmarks is not added (DiscoveryParameters::verify_joins).
  */
bool
detectAdditionalInstances (const DiscoveryParameters& p,
                           const KeypointSurface& surface,
                           DiscoveryResult& result);

/** Look for more instances of each model from single matches
  * (DiscoveryParameters::guided_search) among the keypoints outside every instance's box and
  * not `excluded` (one flag per keypoint, or empty), when the frame, its grey levels and the
  * image keypoints are known. The copies whose neighbourhoods disagree
  * (DiscoveryParameters::guided_max_disagreeing) join with landmarks of their own (which a
  * retraction of the box search's extension keeps, as a new copy observes them).
  */
bool
searchGuidedInstances (const DiscoveryParameters& p,
                       const KeypointSurface& surface,
                       DiscoveryResult& result,
                       const std::vector<bool>& excluded = {});

/** Split each model whose instances fall into groups that do not look alike
  * (DiscoveryParameters::split_by_appearance), when the frame, its grey levels and the image
  * keypoints are known; each split part is refined.
  */
bool
splitByAppearance (const DiscoveryParameters& p,
                   const KeypointSurface& surface,
                   DiscoveryResult& result);

} // namespace detail
} // namespace mid
