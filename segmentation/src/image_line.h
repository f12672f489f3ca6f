#pragma once

#include <Eigen/Core>
#include <pcl/common/point_tests.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/types.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdlib>

namespace mid {
namespace detail {

/** \brief How far `point` (camera frame) lies behind the line through `from` with direction
  * `step`, along its own viewing ray: its distance from the camera less that of the line's
  * point closest to the ray (metres; negative in front of the line). NaN if the ray runs
  * parallel to the line or `point` is the camera's centre.
  */
double
behindLineAlongRay (const Eigen::Vector3d& point,
                    const Eigen::Vector3d& from,
                    const Eigen::Vector3d& step);

/** \brief Walks the image line between pixels `p` and `q` of `organized` (both left out) and
  * calls `visit (pixel, behind)` at each pixel with a point, in order from p: `pixel` is its
  * index (row * width + column), `behind` how far its point lies behind the straight segment
  * between p's and q's points (behindLineAlongRay()). The walk stops early when `visit`
  * returns false. What lies between two points of the frame, for the steps that tell two
  * objects from one by the surface seen between them: the floor or the background seen behind
  * (surfaceDropsBetween()), an occluder in front (the ends of one hidden box).
  * \param[in] organized an organized frame (camera frame, metres; NaN where the depth is
  * missing)
  * \param[in] p, q two pixels of `organized` (not checked)
  * \param[in] visit called as `bool visit (pcl::index_t pixel, double behind)`
  * \return false if p or q has no point (nothing visited), else true
  */
template <typename Visit>
bool
walkImageLine (const pcl::PointCloud<pcl::PointXYZ>& organized,
               pcl::index_t p,
               pcl::index_t q,
               Visit visit)
{
  const pcl::PointXYZ &at_p = organized[static_cast<std::size_t> (p)],
                      &at_q = organized[static_cast<std::size_t> (q)];
  if (!pcl::isXYZFinite (at_p) || !pcl::isXYZFinite (at_q))
    return false;
  const Eigen::Vector3d from = at_p.getVector3fMap().cast<double>(),
                        step = at_q.getVector3fMap().cast<double>() - from;
  const auto width = static_cast<int> (organized.width);
  const int u0 = p % width, v0 = p / width, u1 = q % width, v1 = q / width;
  const int n = std::max (std::abs (u1 - u0), std::abs (v1 - v0));
  for (int i = 1; i < n; ++i) {
    const auto u = u0 + static_cast<int> (
                            std::lround (static_cast<double> (i * (u1 - u0)) / n)),
               v = v0 + static_cast<int> (
                            std::lround (static_cast<double> (i * (v1 - v0)) / n));
    const auto pixel = static_cast<pcl::index_t> (v * width + u);
    const pcl::PointXYZ& point = organized[static_cast<std::size_t> (pixel)];
    if (pcl::isXYZFinite (point) &&
        !visit (pixel,
                behindLineAlongRay (point.getVector3fMap().cast<double>(), from, step)))
      break;
  }
  return true;
}

} // namespace detail
} // namespace mid
