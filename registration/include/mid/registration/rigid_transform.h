#pragma once

#include <Eigen/Core>

namespace mid {

/** \brief The rigid transform (rotation + translation, no scale) that maps the columns of
  * `from` onto the columns of `to` in the least-squares sense (Umeyama, PAMI 1991).
  * \param[in] from 3 x N source points, N >= 3, not all collinear
  * \param[in] to 3 x N target points
  * \param[out] rms_error root mean square residual |R from_i + t - to_i| (optional)
  * \return the 4x4 homogeneous transform
  */
Eigen::Matrix4f
estimateRigidTransform (const Eigen::Matrix3Xf& from, const Eigen::Matrix3Xf& to,
                        float* rms_error = nullptr);

} // namespace mid
