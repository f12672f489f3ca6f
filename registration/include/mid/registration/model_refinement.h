#pragma once

#include <mid/registration/object_model.h>

#include <vector>

namespace mid {

/** \brief Jointly refine a model's landmarks and its instances' poses: least squares over all
  * observations, sum over (instance n, keypoint k observing landmark l) of
  * |pose_n * landmark_l - keypoint_k|^2, by alternating the two closed-form block minimizations:
  * each landmark becomes the mean of its observations mapped into the model frame, and each pose
  * the Umeyama fit of its landmarks onto its keypoints. Each step cannot increase the cost, so
  * the cost decreases monotonically to a (local) minimum; the pose of `fixed_instance` is kept
  * to fix the gauge (the model frame).
  *
  * \param[in,out] model landmarks and instance poses (observations unchanged)
  * \param[in] keypoints the frame's keypoints the observations index
  * \param[in] max_iterations most alternations (default 20); it stops earlier once an
  *            iteration lowers the cost by less than 1e-6 of it; 0 or less only recomputes the
  *            instances' rms errors
  * \param[in] fixed_instance the instance whose pose stays fixed (default 0); an index past the
  *            last instance leaves every pose free
  * \param[out] costs the mean squared residual before the first and after each iteration
  *             (optional)
  * \return the final root mean square residual over all observations (metres). The
  *         observations' indices must be valid for the model and keypoints (not checked); an
  *         instance with fewer than three distinct landmarks keeps its pose
  */
float
refineModel (ObjectModel& model,
             const KeypointCloud& keypoints,
             int max_iterations = 20,
             std::size_t fixed_instance = 0,
             std::vector<float>* costs = nullptr);

/** \brief The landmark step of refineModel() on its own: each landmark becomes the mean of its
  * observations mapped into the model frame by the observing instances' poses (a landmark no
  * instance observes stays). For a step that moves the poses by other evidence
  * (SurfacePoseRefinement) and must keep the landmarks consistent with them.
  * \param[in,out] model its instances' poses and observations are read, its landmarks written
  * \param[in] keypoints the frame's keypoints the observations index (indices not checked)
  */
void
updateModelLandmarks (ObjectModel& model, const KeypointCloud& keypoints);

} // namespace mid
