// Links the installed mid::io, mid::features and mid::discovery and checks that they work: a tiny RGB-D frame
// is turned into a cloud, and the point pair feature of two points is computed.
#include <mid/discovery/multi_instance_discovery.h>
#include <mid/features/point_pair_feature.h>
#include <mid/features/self_matcher.h>
#include <mid/io/organized_cloud_io.h>

#include <opencv2/core.hpp>
#include <pcl/point_types.h>

#include <cmath>
#include <iostream>

int
main ()
{
  const cv::Mat color (4, 4, CV_8UC3, cv::Scalar (10, 20, 30));
  const cv::Mat depth (4, 4, CV_16UC1, cv::Scalar (1000));
  pcl::PointCloud<pcl::PointXYZRGB> cloud;
  if (!mid::io::rgbdToCloud (color, depth, {500.0, 500.0, 1.5, 1.5, 0.001}, cloud) ||
      cloud.width != 4 || std::abs (cloud.at (0, 0).z - 1.0f) > 1e-6f)
    return 1;
  mid::PointPairFeature feature;
  if (!mid::computePointPairFeature (
          {0, 0, 0}, {0, 0, 1}, {0.1f, 0, 0}, {0, 0, 1}, feature) ||
      std::abs (feature.distance - 0.1f) > 1e-6f)
    return 1;
  std::string problem;
  if (!mid::validateDiscoveryParameters (mid::DiscoveryParameters(), problem))
    return 1;
  mid::MultiInstanceDiscovery<pcl::PointXYZRGB>
      discovery; // links the explicit instantiation
  mid::SelfMatcher matcher;
  std::cout << "consumer ok: " << cloud.size()
            << " points, default max descriptor distance "
            << matcher.getMaxDescriptorDistance() << "\n";
  return 0;
}
