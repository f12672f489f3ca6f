#pragma once

#include <mid/registration/object_model.h>

#include <Eigen/Core>

namespace mid {

/** \brief Where a model's landmarks lie, as a box in the model frame: centred on the landmarks,
  * along their principal axes, between a low and a high percentile of their coordinates along
  * each axis, so that a stray landmark does not widen it (it still takes part in the
  * covariance that gives the axes, so it may tilt them).
  *
  * The landmarks are points of the object's surface, so the box is a lower bound of the space
  * the object fills: a face, or the part of the body between the faces the landmarks cover.
  */
struct LandmarkBox
{
  /** \brief The principal axes as columns (largest spread first), in the model frame. */
  Eigen::Matrix3f axes = Eigen::Matrix3f::Identity();
  /** \brief Centre of the box in the model frame (metres). */
  Eigen::Vector3f center = Eigen::Vector3f::Zero();
  /** \brief Half of the box's extent along each axis (metres). */
  Eigen::Vector3f half_extent = Eigen::Vector3f::Zero();
  /** \brief False when there is no box (fewer than 3 finite landmarks). */
  bool valid = false;

  /** \brief How far `point` (model frame) lies outside the box: the length of the shortest
    * segment from the box to it (metres; 0 inside the box).
    * \param[in] point a point in the model frame (metres)
    * \return the distance; infinity if the box is not valid
    */
  float
  distanceTo (const Eigen::Vector3f& point) const;

  EIGEN_MAKE_ALIGNED_OPERATOR_NEW
};

/** \brief The box of a model's landmarks (see LandmarkBox).
  * \param[in] model the model (its landmarks, model frame)
  * \param[in] trim share of the landmarks left out at each end of every axis (in [0, 0.5);
  * default 0.05: the box spans the 5th to the 95th percentile)
  * \return the box; not valid if the model has fewer than 3 finite landmarks or trim is out of
  * its range
  */
LandmarkBox
computeLandmarkBox (const ObjectModel& model, float trim = 0.05f);

} // namespace mid
