#pragma once

#include <mid/features/keypoint_types.h>
#include <mid/registration/object_model.h>
#include <mid/segmentation/surface_gap.h>

#include <Eigen/Core>

#include <string>

namespace mid {

/** \brief Share of the frame's valid points that its support plane must hold for the steps
  * that measure boxes on it (fitSupportPlane()).
  */
constexpr float kMinSupportPlaneShare = 0.2f;

/** \brief Default largest distance of a point on the support plane from it (metres). */
constexpr float kDefaultPlaneTolerance = 0.01f;

/** \brief What the steps that measure the boxes of objects on the support plane share
  * (ModelSizeMeasurement's steps, RepeatedPrintFilter): the frame's keypoints and keypoint
  * surface, how the surfaces grow (growInstanceSurfaces()) and the support plane; set/get
  * pairs and the shared checks. Only the steps derived from it are made, copied and destroyed.
  */
class SupportPlaneMeasurement
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

  /** \brief The organized frame and each keypoint's pixel in it. Required: the organized
    * frame and the keypoint pixels; grey levels and projection are not read.
    */
  ///@{
  void
  setKeypointSurface (const KeypointSurface& surface)
  {
    surface_ = surface;
  }
  const KeypointSurface&
  getKeypointSurface () const
  {
    return surface_;
  }
  ///@}

  /** \brief Largest distance between two neighbouring pixels' points of one surface (metres,
    * default 0.008, > 0).
    */
  ///@{
  void
  setMaxStep (float step)
  {
    max_step_ = step;
  }
  float
  getMaxStep () const
  {
    return max_step_;
  }
  ///@}

  /** \brief Largest distance of a surface point from the centroid of the keypoints it grew
    * from (metres, default 0.3, > 0): bounds the objects that can be measured.
    */
  ///@{
  void
  setMaxRadius (float radius)
  {
    max_radius_ = radius;
  }
  float
  getMaxRadius () const
  {
    return max_radius_;
  }
  ///@}

  /** \brief Largest distance of a point on the support plane from it (metres, default
    * kDefaultPlaneTolerance, > 0).
    */
  ///@{
  void
  setPlaneTolerance (float tolerance)
  {
    plane_tolerance_ = tolerance;
  }
  float
  getPlaneTolerance () const
  {
    return plane_tolerance_;
  }
  ///@}

  /** \brief The frame's support plane, for a caller that runs several steps on one frame and
    * fits it once (fitSupportPlane() with the step's plane tolerance and
    * kMinSupportPlaneShare): (n, d) with a unit normal n, or zero when the frame has none (the
    * step then measures nothing). Unset (the default, or after resetSupportPlane()), the step
    * fits the plane itself.
    */
  ///@{
  void
  setSupportPlane (const Eigen::Vector4f& plane)
  {
    support_plane_ = plane;
    has_support_plane_ = true;
  }
  /** \return the plane given, zero if none was */
  const Eigen::Vector4f&
  getSupportPlane () const
  {
    return support_plane_;
  }
  void
  resetSupportPlane ()
  {
    support_plane_.setZero();
    has_support_plane_ = false;
  }
  ///@}

  EIGEN_MAKE_ALIGNED_OPERATOR_NEW

protected:
  /** \brief Made, copied, moved and destroyed only as a part of a step derived from it (never
    * deleted through a pointer to this class, which has no virtual destructor).
    */
  ///@{
  SupportPlaneMeasurement() = default;
  SupportPlaneMeasurement (const SupportPlaneMeasurement&) = default;
  SupportPlaneMeasurement (SupportPlaneMeasurement&&) = default;
  SupportPlaneMeasurement&
  operator= (const SupportPlaneMeasurement&) = default;
  SupportPlaneMeasurement&
  operator= (SupportPlaneMeasurement&&) = default;
  ~SupportPlaneMeasurement() = default;
  ///@}

  /** \brief What is wrong with the keypoints, the keypoint surface, the parameters above (a
    * support plane given that is neither zero nor a finite plane with a unit normal) or
    * `models` (observationProblem(): an observation outside the keypoints or the landmarks);
    * empty if nothing.
    */
  std::string
  planeMeasurementProblem (const ObjectModels& models) const;

  /** \brief The frame's support plane: the one given (setSupportPlane()), else fitted
    * (fitSupportPlane(), with the plane tolerance and kMinSupportPlaneShare).
    * \return false if the plane given is zero, or no plane holds that share of the frame
    */
  bool
  fitPlane (Eigen::Vector4f& plane) const;

  KeypointCloud::ConstPtr keypoints_;              ///< see setInputKeypoints()
  KeypointSurface surface_;                        ///< see setKeypointSurface()
  float max_step_ = 0.008f;                        ///< see setMaxStep()
  float max_radius_ = 0.3f;                        ///< see setMaxRadius()
  float plane_tolerance_ = kDefaultPlaneTolerance; ///< see setPlaneTolerance()
  Eigen::Vector4f support_plane_ = Eigen::Vector4f::Zero(); ///< see setSupportPlane()
  bool has_support_plane_ = false;                          ///< see setSupportPlane()
};

} // namespace mid
