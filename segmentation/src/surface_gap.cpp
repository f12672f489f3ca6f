#include <mid/segmentation/surface_gap.h>

#include <pcl/common/point_tests.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace mid {

namespace {

/** Distance from the camera, along the unit ray `ray`, of the point of the line through `from`
  * with direction `step` that comes closest to the ray (infinity if they are parallel).
  */
double
lineDepthAlongRay (const Eigen::Vector3d& from,
                   const Eigen::Vector3d& step,
                   const Eigen::Vector3d& ray)
{
  // Closest points of ray r * d and line from + s * e: r = ((e.e)(d.w) - (e.d)(e.w)) / den,
  // with w = from and den = (e.e) - (e.d)^2 for a unit d.
  const double ee = step.squaredNorm(), ed = step.dot (ray);
  const double den = ee - ed * ed;
  if (!(den > 1e-12 * ee))
    return std::numeric_limits<double>::infinity();
  return (ee * ray.dot (from) - ed * step.dot (from)) / den;
}

} // namespace

bool
isValidKeypointSurface (const KeypointSurface& surface, std::size_t keypoints)
{
  if (!surface.organized || !surface.organized->isOrganized() ||
      surface.keypoint_pixels.size() != keypoints)
    return false;
  const auto pixels = static_cast<pcl::index_t> (surface.organized->size());
  return std::all_of (surface.keypoint_pixels.begin(),
                      surface.keypoint_pixels.end(),
                      [pixels] (pcl::index_t p) { return p >= 0 && p < pixels; });
}

bool
surfaceDropsBetween (const KeypointSurface& surface,
                     pcl::index_t a,
                     pcl::index_t b,
                     float min_drop,
                     int min_pixels)
{
  const pcl::PointCloud<pcl::PointXYZ>& cloud = *surface.organized;
  const auto width = static_cast<int> (cloud.width);
  const pcl::index_t pa = surface.keypoint_pixels[static_cast<std::size_t> (a)],
                     pb = surface.keypoint_pixels[static_cast<std::size_t> (b)];
  if (!pcl::isXYZFinite (cloud[pa]) || !pcl::isXYZFinite (cloud[pb]))
    return false;
  const Eigen::Vector3d from = cloud[pa].getVector3fMap().cast<double>(),
                        step = cloud[pb].getVector3fMap().cast<double>() - from;
  const int u0 = pa % width, v0 = pa / width, u1 = pb % width, v1 = pb / width;
  const int n = std::max (std::abs (u1 - u0), std::abs (v1 - v0));
  // Valid pixels in a row behind the segment (pixels without depth skipped).
  int run = 0;
  for (int i = 1; i < n; ++i) {
    const int u = u0 + static_cast<int> (
                           std::lround (static_cast<double> (i * (u1 - u0)) / n)),
              v = v0 + static_cast<int> (
                           std::lround (static_cast<double> (i * (v1 - v0)) / n));
    const pcl::PointXYZ& p =
        cloud (static_cast<std::size_t> (u), static_cast<std::size_t> (v));
    if (!pcl::isXYZFinite (p))
      continue;
    const Eigen::Vector3d point = p.getVector3fMap().cast<double>();
    const double range = point.norm();
    const bool behind =
        range > 0.0 && range - lineDepthAlongRay (from, step, point / range) > min_drop;
    run = behind ? run + 1 : 0;
    if (run >= std::max (min_pixels, 1))
      return true;
  }
  return false;
}

bool
surfacePinhole (const KeypointSurface& surface, FramePinhole& pinhole)
{
  if (surface.pinhole) {
    pinhole = *surface.pinhole;
    return pinhole.isValid();
  }
  return surface.organized && fitFramePinhole (*surface.organized, pinhole);
}

} // namespace mid
