#pragma once

#include <mid/features/keypoint_types.h>
#include <mid/registration/object_model.h>
#include <mid/segmentation/surface_gap.h>

#include <string>

namespace mid {

/** \brief Refines the poses of a model's instances on the frame's depth: each instance's
  * surface is aligned with the surface the other instances show of the same object, together
  * with its landmark observations (not in the paper).
  *
  * The paper refines landmarks and poses on the keypoints alone (refineModel()). An instance
  * seen by five to ten keypoints, often along one line of printed text, then gets a rotation
  * that is off by 10 to 20 deg about that line, although its faces are plainly visible in the
  * depth. This step adds that depth, as a multi-view ICP between the copies:
  *
  * 1. **Samples.** The pixels (every `sample step` pixels) whose points fall inside the box of
  *    the model's landmarks (computeLandmarkBox()), placed by the instance's pose and grown by
  *    the box margin, with a surface normal, are the instance's surface samples.
  * 2. **Correspondences.** A sample of instance j is carried into every other instance i by
  *    their relative pose and projected into the frame (projective association, as in
  *    KinectFusion); the point seen at that pixel is its partner if it lies within the largest
  *    correspondence distance and its normal within 45 deg of the carried sample's.
  * 3. **Pose step.** Each instance's pose in turn but the first one's (which keeps the model
  *    frame, as in refineModel()), the others fixed, takes Gauss-Newton steps
  *    on the sum of the squared point-to-plane distances to its partners (each weighted by the
  *    surface weight) and of its landmark residuals |pose^-1 * keypoint - landmark|^2, both
  *    with Huber weights (2 mm and 5 mm) so that another object in the box, or a wrong
  *    observation, pulls only linearly. The surface's terms count only along the motions it
  *    constrains (a plane slides along itself, a box along its edge): the landmark terms
  *    decide the others.
  * 4. **Landmark step.** Each landmark becomes the mean of its observations under the new
  *    poses (updateModelLandmarks()); steps 1 to 4 repeat for the given number of iterations.
  *
  * A model with one instance is left as it is; an instance without partners on the surface
  * takes the landmark steps only, as in refineModel().
  * Deterministic: no random draws.
  */
class SurfacePoseRefinement
{
public:
  /** \brief The frame's keypoints that the models' observations index (camera frame, metres).
    * Required.
    */
  ///@{
  void
  setInputKeypoints (const KeypointCloud::ConstPtr& keypoints)
  {
    keypoints_ = keypoints;
  }
  const KeypointCloud::ConstPtr&
  getInputKeypoints () const
  {
    return keypoints_;
  }
  ///@}

  /** \brief The organized frame and its projection (given, or fitted to the frame). Required:
    * the organized frame; keypoint pixels and grey levels are not read.
    */
  void
  setKeypointSurface (const KeypointSurface& surface);

  /** \brief Every how many pixels, along rows and columns, a surface sample is taken (default
    * 3, >= 1).
    */
  ///@{
  void
  setSampleStep (int step)
  {
    sample_step_ = step;
  }
  int
  getSampleStep () const
  {
    return sample_step_;
  }
  ///@}

  /** \brief How far outside the landmarks' box a point may lie and still be a sample (metres,
    * default 0.005, >= 0).
    */
  ///@{
  void
  setBoxMargin (float margin)
  {
    box_margin_ = margin;
  }
  float
  getBoxMargin () const
  {
    return box_margin_;
  }
  ///@}

  /** \brief Largest distance between a carried sample and its partner (metres, default 0.01,
    * > 0).
    */
  ///@{
  void
  setMaxCorrespondenceDistance (float distance)
  {
    max_distance_ = distance;
  }
  float
  getMaxCorrespondenceDistance () const
  {
    return max_distance_;
  }
  ///@}

  /** \brief Weight of one point-to-plane residual against one landmark residual (default 1,
    * >= 0; 0 leaves only the landmarks, as refineModel()).
    */
  ///@{
  void
  setSurfaceWeight (float weight)
  {
    surface_weight_ = weight;
  }
  float
  getSurfaceWeight () const
  {
    return surface_weight_;
  }
  ///@}

  /** \brief Rounds of samples, pose steps and landmark step (default 4, >= 1). */
  ///@{
  void
  setMaxIterations (int iterations)
  {
    max_iterations_ = iterations;
  }
  int
  getMaxIterations () const
  {
    return max_iterations_;
  }
  ///@}

  /** \brief Refine the poses of `model`'s instances, and its landmarks with them.
    * \param[in,out] model its instances' poses and rms errors, and its landmarks, are written;
    * its observations must index the input keypoints
    * \return false (with a PCL_ERROR, model unchanged) on missing or inconsistent input, a
    * parameter out of range, or an observation outside the model or the keypoints
    */
  bool
  refine (ObjectModel& model) const;

private:
  /** \brief What is wrong with the input or parameters for `model`; empty if nothing. */
  std::string
  inputProblem (const ObjectModel& model) const;

  KeypointCloud::ConstPtr keypoints_;
  KeypointSurface surface_;
  FramePinhole pinhole_;
  bool has_pinhole_ = false;
  int sample_step_ = 3;
  float box_margin_ = 0.005f;
  float max_distance_ = 0.01f;
  float surface_weight_ = 1.0f;
  int max_iterations_ = 4;
};

} // namespace mid
