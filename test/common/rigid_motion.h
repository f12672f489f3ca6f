#pragma once

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <utility>

namespace mid {
namespace test {

/** \brief The rigid motion x -> R x + t with R a rotation by `angle` (radians) about `axis`. */
inline Eigen::Isometry3f
rigidMotion (const Eigen::Vector3f& translation,
             float angle = 0.0f,
             const Eigen::Vector3f& axis = Eigen::Vector3f::UnitZ())
{
  Eigen::Isometry3f motion = Eigen::Isometry3f::Identity();
  motion.linear() = Eigen::AngleAxisf (angle, axis.normalized()).toRotationMatrix();
  motion.translation() = translation;
  return motion;
}

/** \brief Rotation error (radians, angle of the relative rotation, computed in double so that
  * tiny angles are not lost to acos near 1) and translation error (metres) between two poses.
  */
inline std::pair<double, double>
poseError (const Eigen::Matrix4f& a, const Eigen::Matrix4f& b)
{
  const Eigen::Matrix3d relative =
      (a.topLeftCorner<3, 3>().transpose() * b.topLeftCorner<3, 3>()).cast<double>();
  const double angle =
      Eigen::AngleAxisd (Eigen::Quaterniond (relative).normalized()).angle();
  const double translation =
      (a.topRightCorner<3, 1>() - b.topRightCorner<3, 1>()).cast<double>().norm();
  return {std::min (angle, 2.0 * M_PI - angle), translation};
}

} // namespace test
} // namespace mid
