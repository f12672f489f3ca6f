#pragma once

#include <mid/features/keypoint_types.h>

#include <pcl/types.h>

#include <cstddef>
#include <vector>

namespace mid {

/** \brief The densest patch of free keypoints: the free keypoint with the most free
  * keypoints within `radius` of it (itself included), and those keypoints.
  *
  * A patch of keypoints that no instance explains is where an object whose copies share too
  * little surface for the triplets may still be: taken as a model with one instance, the
  * guided search (GuidedInstanceSearch) looks for a second copy of it from single matches.
  * Ties go to the lowest index, so the patch depends on nothing but the input.
  *
  * \param[in] keypoints the frame's keypoints (camera frame, metres)
  * \param[in] free which keypoints may join the patch (one flag per keypoint)
  * \param[in] radius how far from its centre a keypoint of the patch may lie (metres, > 0)
  * \param[in] min_keypoints the fewest keypoints of a patch (>= 1)
  * \param[out] patch the centre's index first, then the other keypoints within the radius in
  * index order; empty when there is no patch of min_keypoints or on bad input
  * \return false (with a PCL_ERROR, patch cleared) if free is not one flag per keypoint, the
  * radius is not positive or min_keypoints is 0; true otherwise, also when there is no patch
  */
bool
densestKeypointPatch (const KeypointCloud& keypoints,
                      const std::vector<bool>& free,
                      float radius,
                      std::size_t min_keypoints,
                      pcl::Indices& patch);

} // namespace mid
