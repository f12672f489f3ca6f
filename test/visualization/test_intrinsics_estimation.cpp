// estimateIntrinsics recovers the pinhole camera a cloud was made with.

#include "two_copies_scene.h"

#include <mid/visualization/intrinsics_estimation.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>

TEST (IntrinsicsEstimation, RecoversTheCameraOfADepthImage)
{
  // makeTwoCopiesScene back-projects with fx = fy = 525, cx = 319.5, cy = 239.5.
  const auto scene = mid::test::makeTwoCopiesScene();
  mid::io::CameraIntrinsics intrinsics;
  ASSERT_TRUE (mid::visualization::estimateIntrinsics (*scene.cloud, intrinsics));
  EXPECT_NEAR (intrinsics.fx, 525.0, 1e-2);
  EXPECT_NEAR (intrinsics.fy, 525.0, 1e-2);
  EXPECT_NEAR (intrinsics.cx, 319.5, 1e-2);
  EXPECT_NEAR (intrinsics.cy, 239.5, 1e-2);
}

TEST (IntrinsicsEstimation, RefusesCloudsWithoutACamera)
{
  mid::io::CameraIntrinsics intrinsics;
  intrinsics.fx = 1.0;
  EXPECT_FALSE (mid::visualization::estimateIntrinsics (
      pcl::PointCloud<pcl::PointXYZRGBA> (100, 1), intrinsics));
  EXPECT_EQ (intrinsics.fx, 0.0);

  auto cloud = mid::test::makeTwoCopiesScene().cloud;
  for (auto& point : *cloud)
    point.z = std::numeric_limits<float>::quiet_NaN();
  EXPECT_FALSE (mid::visualization::estimateIntrinsics (*cloud, intrinsics));
  cloud->at (10, 10).getVector3fMap() = Eigen::Vector3f (0.1f, 0.1f, 1.0f);
  EXPECT_FALSE (mid::visualization::estimateIntrinsics (*cloud, intrinsics));

  // Points that do not lie on their pixels' rays (shuffled over the pixels).
  auto shuffled = mid::test::makeTwoCopiesScene().cloud;
  std::mt19937 random (5);
  std::shuffle (shuffled->begin(), shuffled->end(), random);
  EXPECT_FALSE (mid::visualization::estimateIntrinsics (*shuffled, intrinsics));

  // A frame looking down -z (as PCL's milk scene): no positive focal length.
  auto turned = mid::test::makeTwoCopiesScene().cloud;
  for (auto& point : *turned) {
    point.y = -point.y;
    point.z = -point.z;
  }
  EXPECT_FALSE (mid::visualization::estimateIntrinsics (*turned, intrinsics));
  EXPECT_EQ (intrinsics.fx, 0.0);
}
