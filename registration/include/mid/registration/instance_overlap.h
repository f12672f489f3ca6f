#pragma once

#include <mid/registration/object_model.h>

namespace mid {

/** \brief True if two instances lie on one physical object: the centroid of their observed
  * keypoints are closer than the larger of their RMS radii (the RMS distance of an instance's
  * keypoints from their centroid).
  *
  * Copies of an object cannot interpenetrate, so two instances of one object (or of two
  * models) whose keypoints intermix describe one physical object. On one face of a box, two
  * sets of keypoints have nearby centroids (a fraction of the face); on two copies side by
  * side the centroids are about an object's width apart, more than the radius of either set
  * (about 0.4 widths for keypoints spread over a face).
  * \param[in] keypoints the frame's keypoints, which the instances index
  * \param[in] a one instance (its keypoints)
  * \param[in] b the other instance
  * \return false if either instance observes no keypoint
  */
bool
instancesOverlap (const KeypointCloud& keypoints,
                  const ModelInstance& a,
                  const ModelInstance& b);

/** \brief Remove the instances of a model that lie on the same physical object as an instance
  * observing at least as many keypoints (on a tie the earlier instance stays) (an object with a repeated pattern on one face, such as two
  * copies of a logo, gives such pairs); the remaining instances keep their order.
  * \param[in] keypoints the frame's keypoints, which the instances index
  * \param[in,out] model the model whose instances are checked
  * \return the number of instances removed
  */
std::size_t
removeOverlappingInstances (const KeypointCloud& keypoints, ObjectModel& model);

/** \brief Merge models of which an instance lies on an instance of another model: both then
  * describe the same object, seen on one physical copy, and the pose of each instance gives
  * the transform between the two model frames.
  *
  * Models are visited largest first (most observations); a smaller model B that overlaps a
  * larger model A (some instance pair overlaps, see instancesOverlap()) is brought into A's
  * frame by the overlapping pair with the most observations, landmarks of B observed by a
  * keypoint that also observes a landmark of A become that landmark, B's instances that overlap an
  * instance of A join it (their keypoints are added to it), the others become new instances of
  * A. Complements appearance-based merging: the two models may share no descriptor at all when
  * they were built from different keypoints of the same face.
  * \param[in] keypoints the frame's keypoints, which the instances index
  * \param[in,out] models the models; merged ones are removed
  * \return the number of models merged into others
  */
std::size_t
mergeOverlappingModels (const KeypointCloud& keypoints, ObjectModels& models);

} // namespace mid
