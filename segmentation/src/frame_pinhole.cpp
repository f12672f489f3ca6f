#include "paired_sums.h"

#include <mid/segmentation/frame_pinhole.h>

#include <pcl/common/point_tests.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace mid {

namespace {

/** The least-squares line pixel = scale * ratio + offset, from the sums of its samples
  * (x: ratio, y: pixel).
  */
struct LineFit : detail::PairedSums
{
  /** False if fewer than 3 samples or the ratios do not vary; rms is the residual's. */
  bool
  solve (double& scale, double& offset, double& rms) const
  {
    const double den = n * sxx - sx * sx;
    if (n < 3.0 || !(den > 1e-12 * n * n))
      return false;
    scale = (n * sxy - sx * sy) / den;
    offset = (sy - scale * sx) / n;
    const double sse = syy - 2.0 * scale * sxy - 2.0 * offset * sy +
                       scale * scale * sxx + 2.0 * scale * offset * sx +
                       n * offset * offset;
    rms = std::sqrt (std::max (sse, 0.0) / n);
    return std::isfinite (scale) && std::isfinite (offset);
  }
};

} // namespace

bool
FramePinhole::isValid() const
{
  return std::isfinite (fx) && std::isfinite (fy) && std::isfinite (cx) &&
         std::isfinite (cy) && fx != 0.0 && fy != 0.0;
}

bool
FramePinhole::project (
    const Eigen::Vector3f& point, int width, int height, int& u, int& v) const
{
  if (!(std::abs (point.z()) > 1e-6f) || !point.allFinite())
    return false;
  const double pu = fx * point.x() / point.z() + cx,
               pv = fy * point.y() / point.z() + cy;
  if (!(pu > -0.5 && pv > -0.5 && pu < width - 0.5 && pv < height - 0.5))
    return false;
  u = static_cast<int> (std::lround (pu));
  v = static_cast<int> (std::lround (pv));
  return true;
}

bool
fitFramePinhole (const pcl::PointCloud<pcl::PointXYZ>& organized, FramePinhole& pinhole)
{
  pinhole = FramePinhole();
  if (!organized.isOrganized())
    return false;
  LineFit columns, rows;
  for (std::uint32_t v = 0; v < organized.height; ++v)
    for (std::uint32_t u = 0; u < organized.width; ++u) {
      const pcl::PointXYZ& p = organized (u, v);
      if (!pcl::isXYZFinite (p) || !(std::abs (p.z) > 1e-6f))
        continue;
      columns.add (p.x / p.z, u);
      rows.add (p.y / p.z, v);
    }
  FramePinhole fit;
  double rms_u = 0.0, rms_v = 0.0;
  if (!columns.solve (fit.fx, fit.cx, rms_u) || !rows.solve (fit.fy, fit.cy, rms_v) ||
      !(rms_u < 1.0 && rms_v < 1.0))
    return false;
  pinhole = fit;
  return true;
}

} // namespace mid
