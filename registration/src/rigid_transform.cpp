#include <mid/registration/rigid_transform.h>

#include <Eigen/Geometry>

#include <cmath>

namespace mid {

Eigen::Matrix4f
estimateRigidTransform (const Eigen::Matrix3Xf& from,
                        const Eigen::Matrix3Xf& to,
                        float* rms_error)
{
  Eigen::Matrix4f transform = Eigen::umeyama (from, to, false);
  if (rms_error != nullptr) {
    const Eigen::Matrix3Xf residual =
        (transform.topLeftCorner<3, 3>() * from).colwise() +
        transform.topRightCorner<3, 1>() - to;
    *rms_error =
        from.cols() > 0 ? std::sqrt (residual.colwise().squaredNorm().mean()) : 0.0f;
  }
  return transform;
}

} // namespace mid
