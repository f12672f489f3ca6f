#pragma once

#include <mid/io/camera_intrinsics.h>

#include <pcl/point_cloud.h>

namespace mid {
namespace visualization {

/** \brief Estimate the pinhole intrinsics of an organized cloud from its own points.
  *
  * A finite point at column u and row v lies on that pixel's ray: u = fx * x / z + cx and
  * v = fy * y / z + cy. mid::fitFramePinhole() fits both lines by least squares. Exact (to float
  * precision) for a cloud made from a depth image, such as those of mid::io::loadRGBD() or an
  * organized PCD saved from one; depth_scale is left at its default.
  * \param[in] cloud organized cloud, metres
  * \param[out] intrinsics the estimate; reset to CameraIntrinsics() when false is returned
  * \return false (with a PCL_ERROR naming the problem) if the cloud is not organized, its finite
  * points do not cover two columns and two rows or do not lie on their pixels' rays (within a
  * pixel), or the fit gives no positive focal length (a cloud looking down -z)
  */
template <typename PointT>
bool
estimateIntrinsics (const pcl::PointCloud<PointT>& cloud,
                    io::CameraIntrinsics& intrinsics);

} // namespace visualization
} // namespace mid

#ifdef MID_NO_PRECOMPILE
#include <mid/visualization/impl/intrinsics_estimation.hpp>
#endif
