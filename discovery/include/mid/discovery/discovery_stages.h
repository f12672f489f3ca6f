#pragma once

#include <mid/discovery/discovery_parameters.h>
#include <mid/discovery/discovery_result.h>

namespace mid {

/** \brief The stages of MultiInstanceDiscovery after keypoint extraction: self-matching,
  * triplets, clustering, model building and additional instance detection. For users who bring
  * their own keypoints and descriptors (result.keypoints / result.descriptors must be set).
  * Appends the stages' times to result.timing_ms.
  * \return false (with a PCL_ERROR) if a stage refuses its input or parameters
  */
bool
discoverFromKeypoints (const DiscoveryParameters& parameters, DiscoveryResult& result);

} // namespace mid
