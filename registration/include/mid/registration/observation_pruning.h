#pragma once

#include <mid/features/keypoint_types.h>
#include <mid/registration/object_model.h>

#include <cstddef>

namespace mid {

/** \brief Drop the observations that an instance's pose does not explain (not in the paper).
  *
  * Joint refinement makes every landmark the mean of its observations, so a keypoint that
  * joined an instance without lying on its copy (a keypoint of a touching copy, brought in by
  * a cluster that spans two copies, or a landmark built from two places of one print) stays
  * far from where the pose puts its landmark, or outside the model's box. Such a keypoint is
  * not the instance's: the instance's keypoints and its image box (what a result reports, and
  * what the paper's scoring counts: 90 % of an instance's keypoints on one copy) should not
  * hold it.
  *
  * An observation (keypoint k of an instance at pose T, observing landmark l) is kept when
  * both hold:
  * - |T^-1 k - l| <= max_residual (a non-finite keypoint or landmark fails);
  * - T^-1 k lies within box_margin of the model's landmark box (computeLandmarkBox(), taken
  *   before anything is dropped), or l is observed by this instance alone: such a landmark
  *   shows the instance's own surface (a face no other copy shows, as a copy found by its
  *   size may), which the box of the other copies' landmarks does not bound. With fewer than
  *   3 landmarks there is no box and only the residual counts.
  *
  * An instance that would keep none of its observations, or whose pose is not finite, keeps
  * them all: its pose rests on other evidence (the depth, a box measured on the table). A
  * landmark that loses every observation here is removed with its descriptors (the others
  * are renumbered); a landmark that no instance observed before stays. Poses do not change.
  *
  * \param[in] keypoints the frame's keypoints that the observations index (camera frame,
  * metres)
  * \param[in] max_residual largest distance of a kept observation from its landmark, in the
  * model frame (metres, > 0)
  * \param[in] box_margin largest distance of a kept observation outside the landmark box
  * (metres, >= 0)
  * \param[in,out] model its instances' observations, landmarks and descriptors are pruned,
  * its diameter updated; its frame is not centred again (centerModelFrame())
  * \param[out] dropped how many observations were dropped (0 on failure)
  * \return false, with a PCL_ERROR and the model unchanged, for a bound out of its range, an
  * observation whose keypoint or landmark does not exist, an instance with unequal numbers of
  * keypoints and landmarks, or descriptors that do not match their landmark list (in number,
  * or naming a landmark that does not exist)
  */
bool
pruneUnexplainedObservations (const KeypointCloud& keypoints,
                              float max_residual,
                              float box_margin,
                              ObjectModel& model,
                              std::size_t& dropped);

/** \brief Drop the observations of an instance that lie among the keypoints of another
  * instance of the same model (not in the paper).
  *
  * Copies cannot interpenetrate: a keypoint amid another copy's keypoints is that copy's. A
  * model whose copies lie in one arrangement twice (two touching copies, each beside a third
  * copy of the product) holds a landmark of the neighbour, and each instance keeps a keypoint
  * on the neighbour's face, explained by its pose (pruneUnexplainedObservations() keeps it)
  * but not on its copy; where that neighbour is itself an instance of the model, its own
  * keypoints surround the stray one.
  *
  * An observation of instance A (keypoint k) is dropped when another instance B of the model,
  * observing keypoints at 3 or more distinct places, has
  * - k within B's radius of B's centroid (the RMS distance of B's keypoints from their
  *   centroid; as instancesOverlap() tells two instances on one object), and
  * - a keypoint nearer to k than every other place of A's keypoints (keypoints at k's own
  *   place, the other orientations of one SIFT keypoint, are no other place).
  * Instances are judged as they were before anything is dropped. An instance that would keep
  * no observation keeps them all. A landmark that loses every observation is removed with its
  * descriptors (the others are renumbered). Poses do not change.
  *
  * \param[in] keypoints the frame's keypoints that the observations index (camera frame,
  * metres)
  * \param[in,out] model its instances' observations, landmarks and descriptors are pruned,
  * its diameter updated
  * \param[out] dropped how many observations were dropped (0 on failure)
  * \return false, with a PCL_ERROR and the model unchanged, for an observation whose keypoint
  * or landmark does not exist, an instance with unequal numbers of keypoints and landmarks,
  * or descriptors that do not match their landmark list
  */
bool
pruneObservationsOnOtherCopies (const KeypointCloud& keypoints,
                                ObjectModel& model,
                                std::size_t& dropped);

} // namespace mid
