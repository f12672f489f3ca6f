#include "rigid_motion.h"

#include <mid/registration/rigid_transform.h>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

TEST (RigidTransform, RecoversAKnownMotionFromThreePoints)
{
  const Eigen::Isometry3f motion =
      mid::test::rigidMotion ({0.3f, -0.2f, 0.1f}, 2.0f, {1, 1, -1});
  Eigen::Matrix3Xf from (3, 3);
  from << 0.0f, 0.05f, 0.01f, 0.0f, 0.0f, 0.06f, 0.8f, 0.82f, 0.79f;
  const Eigen::Matrix3Xf to = motion * from;
  float rms = 1.0f;
  const Eigen::Matrix4f estimate = mid::estimateRigidTransform (from, to, &rms);
  EXPECT_LT ((estimate - motion.matrix()).cwiseAbs().maxCoeff(), 1e-5f);
  EXPECT_LT (rms, 1e-6f);
  const Eigen::Matrix3f rotation = estimate.topLeftCorner<3, 3>();
  EXPECT_NEAR (rotation.determinant(), 1.0f, 1e-5f);
}

TEST (RigidTransform, ReportsTheResidualOfInconsistentPairs)
{
  Eigen::Matrix3Xf from (3, 4), to (3, 4);
  from << 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1;
  to = from;
  to (2, 3) += 0.4f; // one point moved: no rigid motion explains it exactly
  float rms = 0.0f;
  mid::estimateRigidTransform (from, to, &rms);
  EXPECT_GT (rms, 0.05f);
}
