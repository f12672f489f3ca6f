#pragma once

#include <Eigen/Core>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/types.h>

#include <cmath>
#include <limits>
#include <vector>

namespace mid {
namespace test {

/** \brief A horizontal rectangle at height y (camera frame, y down): x in [x_min, x_max], z in
  * [z_min, z_max] (metres).
  */
struct Plate
{
  float x_min, x_max, z_min, z_max, y;
};

/** \brief The 640 x 480 pinhole camera of renderPlates() (focal length 525 pixels, principal
  * point at the image centre).
  */
constexpr int kPlateWidth = 640, kPlateHeight = 480;
constexpr float kPlateFocal = 525.0f, kPlateCx = 319.5f, kPlateCy = 239.5f;

/** \brief The pixel (row * width + column) a camera-frame point projects to, or -1 outside the
  * image.
  */
inline pcl::index_t
plateSurfacePixel (const Eigen::Vector3f& point)
{
  const auto u = static_cast<int> (
                 std::lround (kPlateFocal * point.x() / point.z() + kPlateCx)),
             v = static_cast<int> (
                 std::lround (kPlateFocal * point.y() / point.z() + kPlateCy));
  return u < 0 || v < 0 || u >= kPlateWidth || v >= kPlateHeight ? -1
                                                                 : v * kPlateWidth + u;
}

/** \brief The organized frame the camera sees of plates above a floor (the plane y = floor_y),
  * ray cast exactly: each pixel holds the nearest hit along its ray, NaN where nothing is hit.
  */
inline pcl::PointCloud<pcl::PointXYZ>::Ptr
renderPlates (const std::vector<Plate>& plates, float floor_y)
{
  auto cloud =
      pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>> (kPlateWidth, kPlateHeight);
  for (int v = 0; v < kPlateHeight; ++v)
    for (int u = 0; u < kPlateWidth; ++u) {
      const Eigen::Vector3f ray ((static_cast<float> (u) - kPlateCx) / kPlateFocal,
                                 (static_cast<float> (v) - kPlateCy) / kPlateFocal,
                                 1.0f);
      float nearest =
          ray.y() > 0.0f ? floor_y / ray.y() : std::numeric_limits<float>::infinity();
      for (const Plate& plate : plates) {
        const float t = plate.y / ray.y();
        const Eigen::Vector3f hit = t * ray;
        if (ray.y() > 0.0f && t < nearest && hit.x() >= plate.x_min &&
            hit.x() <= plate.x_max && hit.z() >= plate.z_min && hit.z() <= plate.z_max)
          nearest = t;
      }
      pcl::PointXYZ& point =
          (*cloud) (static_cast<std::size_t> (u), static_cast<std::size_t> (v));
      if (std::isfinite (nearest))
        point.getVector3fMap() = nearest * ray;
      else
        point.x = point.y = point.z = std::numeric_limits<float>::quiet_NaN();
    }
  return cloud;
}

} // namespace test
} // namespace mid
