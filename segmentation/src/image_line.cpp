#include "image_line.h"

#include <limits>

namespace mid {
namespace detail {

double
behindLineAlongRay (const Eigen::Vector3d& point,
                    const Eigen::Vector3d& from,
                    const Eigen::Vector3d& step)
{
  const double range = point.norm();
  if (!(range > 0.0))
    return std::numeric_limits<double>::quiet_NaN();
  const Eigen::Vector3d ray = point / range;
  // Closest points of ray r * d and line from + s * e: r = ((e.e)(d.w) - (e.d)(e.w)) / den,
  // with w = from and den = (e.e) - (e.d)^2 for a unit d.
  const double ee = step.squaredNorm(), ed = step.dot (ray);
  const double den = ee - ed * ed;
  if (!(den > 1e-12 * ee))
    return std::numeric_limits<double>::quiet_NaN();
  return range - (ee * ray.dot (from) - ed * step.dot (from)) / den;
}

} // namespace detail
} // namespace mid
