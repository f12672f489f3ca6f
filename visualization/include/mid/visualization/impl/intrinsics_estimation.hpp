#pragma once

#include <mid/visualization/intrinsics_estimation.h>

#include <pcl/common/point_tests.h>
#include <pcl/console/print.h>

#include <cmath>

namespace mid {
namespace visualization {
namespace detail {

/** \brief Least-squares line pixel = slope * ratio + offset, from running sums. */
struct LineFit
{
  double n = 0.0, sum_r = 0.0, sum_p = 0.0, sum_rr = 0.0, sum_rp = 0.0;

  /** \brief Add one (ratio, pixel) pair. */
  void
  add (double ratio, double pixel)
  {
    n += 1.0;
    sum_r += ratio;
    sum_p += pixel;
    sum_rr += ratio * ratio;
    sum_rp += ratio * pixel;
  }

  /** \brief Solve; false if the ratios do not vary. */
  bool
  solve (double& slope, double& offset) const
  {
    const double variance = n * sum_rr - sum_r * sum_r;
    if (n < 2.0 || !(variance > 1e-12 * n * n))
      return false;
    slope = (n * sum_rp - sum_r * sum_p) / variance;
    offset = (sum_p - slope * sum_r) / n;
    return std::isfinite (slope) && std::isfinite (offset);
  }
};

} // namespace detail

template <typename PointT>
bool
estimateIntrinsics (const pcl::PointCloud<PointT>& cloud,
                    io::CameraIntrinsics& intrinsics)
{
  intrinsics = io::CameraIntrinsics();
  if (!cloud.isOrganized() ||
      cloud.size() != std::size_t (cloud.width) * cloud.height) {
    PCL_ERROR ("[mid::visualization::estimateIntrinsics] the cloud is not organized "
               "(%u x %u)\n",
               cloud.width,
               cloud.height);
    return false;
  }
  detail::LineFit columns, rows;
  for (unsigned v = 0; v < cloud.height; ++v)
    for (unsigned u = 0; u < cloud.width; ++u) {
      const PointT& point = cloud.at (u, v);
      if (!pcl::isFinite (point) || !(point.z > 0.0f))
        continue;
      columns.add (static_cast<double> (point.x / point.z), static_cast<double> (u));
      rows.add (static_cast<double> (point.y / point.z), static_cast<double> (v));
    }
  io::CameraIntrinsics estimate;
  if (!columns.solve (estimate.fx, estimate.cx) ||
      !rows.solve (estimate.fy, estimate.cy) || !(estimate.fx > 0.0) ||
      !(estimate.fy > 0.0)) {
    PCL_ERROR (
        "[mid::visualization::estimateIntrinsics] the finite points give no pinhole "
        "camera (too few, or not spread over several columns and rows)\n");
    return false;
  }
  intrinsics = estimate;
  return true;
}

} // namespace visualization
} // namespace mid
