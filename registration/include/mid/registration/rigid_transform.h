#pragma once

#include <Eigen/Core>

namespace mid {

/** \brief The rigid transform (rotation + translation, no scale) that maps the columns of
  * `from` onto the columns of `to` in the least-squares sense (Umeyama, PAMI 1991).
  * \param[in] from 3 x N source points, N >= 3, not all collinear
  * \param[in] to 3 x N target points
  * \param[out] rms_error root mean square residual |R from_i + t - to_i| in the units of the
  * points (optional; 0 when N = 0)
  * \return the 4x4 homogeneous transform; with fewer than three points, or collinear ones, the
  * rotation is not unique and one of the solutions is returned (no error is reported)
  */
Eigen::Matrix4f
estimateRigidTransform (const Eigen::Matrix3Xf& from,
                        const Eigen::Matrix3Xf& to,
                        float* rms_error = nullptr);

} // namespace mid
