#pragma once

#include <Eigen/Geometry>
#include <opencv2/core/mat.hpp>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

namespace mid {
namespace test {

/** \brief An organized 640x480 cloud in which one random texture patch appears twice on
  * fronto-parallel planes at the same depth: copy A as is, copy B turned by 90 degrees in the
  * image. The background is a flat untextured wall. Since fx == fy, copy B is copy A under an
  * exactly known rigid motion (a rotation about the optical axis plus a translation).
  */
struct TwoCopiesScene
{
  pcl::PointCloud<pcl::PointXYZRGB>::Ptr cloud;
  /** \brief Maps copy A's 3D points onto copy B's. */
  Eigen::Isometry3f a_to_b;
  /** \brief The image rectangles of the two copies. */
  cv::Rect rect_a, rect_b;
};

/** \brief Build the scene; the texture is random but seeded. */
TwoCopiesScene
makeTwoCopiesScene (unsigned seed = 7);

} // namespace test
} // namespace mid
