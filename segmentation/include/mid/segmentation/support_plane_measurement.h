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

/** \brief What the steps that measure the boxes of objects on the support plane share
  * (ModelSizeMeasurement's steps, RepeatedPrintFilter): the frame's keypoints and keypoint
  * surface and how the surfaces grow (growInstanceSurfaces()); set/get pairs and the shared
  * checks.
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

  /** \brief Largest distance of a point on the support plane from it (metres, default 0.01,
    * > 0).
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

protected:
  /** \brief What is wrong with the keypoints, the keypoint surface, the parameters above or
    * `models` (an observation outside the keypoints); empty if nothing.
    */
  std::string
  planeMeasurementProblem (const ObjectModels& models) const;

  /** \brief Fit the frame's support plane (fitSupportPlane(), with the plane tolerance and
    * kMinSupportPlaneShare).
    * \return false if no plane holds that share of the frame
    */
  bool
  fitPlane (Eigen::Vector4f& plane) const;

  KeypointCloud::ConstPtr keypoints_; ///< see setInputKeypoints()
  KeypointSurface surface_;           ///< see setKeypointSurface()
  float max_step_ = 0.008f;           ///< see setMaxStep()
  float max_radius_ = 0.3f;           ///< see setMaxRadius()
  float plane_tolerance_ = 0.01f;     ///< see setPlaneTolerance()
};

} // namespace mid
