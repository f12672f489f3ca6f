#include <mid/io/camera_intrinsics.h>

#include <gtest/gtest.h>

#include <limits>

TEST (CameraIntrinsics, AcceptsATypicalKinect)
{
  const mid::io::CameraIntrinsics intrinsics{525.0, 525.0, 319.5, 239.5, 0.001};
  std::string problem;
  EXPECT_TRUE (mid::io::validateIntrinsics (intrinsics, problem));
  EXPECT_TRUE (problem.empty());
}

TEST (CameraIntrinsics, NamesEachProblem)
{
  std::string problem;
  EXPECT_FALSE (
      mid::io::validateIntrinsics ({0.0, 525.0, 319.5, 239.5, 0.001}, problem));
  EXPECT_NE (problem.find ("focal"), std::string::npos);
  EXPECT_FALSE (
      mid::io::validateIntrinsics ({525.0, 525.0, 319.5, 239.5, 0.0}, problem));
  EXPECT_NE (problem.find ("depth scale"), std::string::npos);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE (
      mid::io::validateIntrinsics ({525.0, 525.0, nan, 239.5, 0.001}, problem));
  EXPECT_NE (problem.find ("non-finite"), std::string::npos);
}
