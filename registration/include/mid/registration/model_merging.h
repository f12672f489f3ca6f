#pragma once

#include <mid/registration/object_model.h>

#include <utility>
#include <vector>

namespace mid {

/** \brief Merge model `from` into model `into`, given where `from` sits in `into`'s frame.
  *
  * \param[in,out] into the model that absorbs the other
  * \param[in] from the model to absorb
  * \param[in] into_to_from rigid transform mapping `into`'s model frame onto `from`'s
  * \param[in] same_landmarks pairs (landmark of into, landmark of from) that are one point
  * \param[in] max_angle, max_distance instances of both models whose poses coincide within
  *            these (radians, metres) are one instance, and their observations are joined
  *
  * \param[out] landmark_map if given, for every landmark of `from` its index in `into`
  *
  * `from`'s other landmarks are appended (moved into `into`'s frame), its descriptors appended,
  * and its instances re-expressed as instances of `into`.
  */
void
mergeModel (ObjectModel& into,
            const ObjectModel& from,
            const Eigen::Matrix4f& into_to_from,
            const std::vector<std::pair<int, int>>& same_landmarks,
            float max_angle,
            float max_distance,
            std::vector<int>* landmark_map = nullptr);

/** \brief Add a detected instance to a model and extend the model with its observations'
  * descriptors; an instance whose pose coincides with an existing one is joined to it.
  * \param[in,out] model the model that gains the instance and the descriptors
  * \param[in] instance the detected instance (ModelInstanceDetector::detect()); its indices
  *            must be valid for the model and the frame (not checked)
  * \param[in] frame_descriptors the descriptors of the frame's keypoints
  * \param[in] max_angle, max_distance an existing instance whose pose coincides with the new
  *            one within these (radians, metres) is the same instance
  */
void
addInstance (ObjectModel& model,
             const ModelInstance& instance,
             const SIFTDescriptorCloud& frame_descriptors,
             float max_angle,
             float max_distance);

} // namespace mid
