#pragma once

#include <mid/segmentation/frame_pinhole.h>
#include <mid/visualization/intrinsics_estimation.h>

#include <pcl/common/io.h>
#include <pcl/console/print.h>

namespace mid {
namespace visualization {

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
  pcl::PointCloud<pcl::PointXYZ> points;
  pcl::copyPointCloud (cloud, points);
  FramePinhole pinhole;
  if (!fitFramePinhole (points, pinhole) || !(pinhole.fx > 0.0) ||
      !(pinhole.fy > 0.0)) {
    PCL_ERROR (
        "[mid::visualization::estimateIntrinsics] the finite points give no pinhole "
        "camera looking down +z (too few, not spread over several columns and rows, or "
        "not on their pixels' rays)\n");
    return false;
  }
  intrinsics.fx = pinhole.fx;
  intrinsics.fy = pinhole.fy;
  intrinsics.cx = pinhole.cx;
  intrinsics.cy = pinhole.cy;
  return true;
}

} // namespace visualization
} // namespace mid
