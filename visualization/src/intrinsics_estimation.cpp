#include <mid/visualization/impl/intrinsics_estimation.hpp>

#include <pcl/point_types.h>

template bool
mid::visualization::estimateIntrinsics<pcl::PointXYZRGB> (
    const pcl::PointCloud<pcl::PointXYZRGB>&, mid::io::CameraIntrinsics&);
template bool
mid::visualization::estimateIntrinsics<pcl::PointXYZRGBA> (
    const pcl::PointCloud<pcl::PointXYZRGBA>&, mid::io::CameraIntrinsics&);
