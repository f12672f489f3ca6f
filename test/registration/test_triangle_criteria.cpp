#include "rigid_motion.h"

#include <mid/registration/triangle_criteria.h>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>

namespace {

constexpr float kDegree = static_cast<float> (M_PI / 180.0);

mid::Triangle
transformed (const Eigen::Isometry3f& motion,
             const mid::Triangle& t,
             bool is_normal = false)
{
  mid::Triangle out;
  for (int k = 0; k < 3; ++k)
    out[k] = is_normal ? Eigen::Vector3f (motion.linear() * t[k])
                       : Eigen::Vector3f (motion * t[k]);
  return out;
}

const mid::Triangle kRight{
    Eigen::Vector3f (0, 0, 0),
    Eigen::Vector3f (0.03f, 0, 0),
    Eigen::Vector3f (0, 0.04f, 0)}; // 3-4-5 cm, angles 90, 53.1, 36.9
const mid::Triangle kUp{
    Eigen::Vector3f::UnitZ(), Eigen::Vector3f::UnitZ(), Eigen::Vector3f::UnitZ()};

} // namespace

TEST (TriangleCriteria, EdgeLengthsAreCheckedOnEveryEdge)
{
  EXPECT_TRUE (mid::hasEdgeLengthsWithin (kRight, 0.010f, 0.125f));
  EXPECT_FALSE (mid::hasEdgeLengthsWithin (kRight, 0.035f, 0.125f)); // the 3 cm edge
  EXPECT_FALSE (mid::hasEdgeLengthsWithin (kRight, 0.010f, 0.049f)); // the 5 cm edge
  mid::Triangle small = kRight;
  for (auto& p : small)
    p *= 0.2f; // 6-8-10 mm
  EXPECT_FALSE (mid::hasEdgeLengthsWithin (small, 0.010f, 0.125f));
}

TEST (TriangleCriteria, EveryAngleMustExceedTheMinimum)
{
  EXPECT_TRUE (mid::hasAnglesAbove (kRight, 36.8f * kDegree));
  EXPECT_FALSE (mid::hasAnglesAbove (kRight, 36.9f * kDegree));
  // An isosceles sliver with an apex angle of 8 degrees.
  const float half = std::tan (4.0f * kDegree) * 0.1f;
  const mid::Triangle sliver{Eigen::Vector3f (0, 0, 0),
                             Eigen::Vector3f (0.1f, half, 0),
                             Eigen::Vector3f (0.1f, -half, 0)};
  EXPECT_FALSE (mid::hasAnglesAbove (sliver, 10.0f * kDegree));
  EXPECT_TRUE (mid::hasAnglesAbove (sliver, 7.9f * kDegree));
}

TEST (TriangleCriteria, SidednessSurvivesRigidMotionAndFlipsUnderAMirror)
{
  const float side = mid::triangleSidedness (kRight, kUp);
  EXPECT_NEAR (side, 1.0f, 1e-6f); // counter-clockwise seen from +z
  const Eigen::Isometry3f motion =
      mid::test::rigidMotion ({0.2f, -0.1f, 0.7f}, 2.5f, {1, -2, 0.5f});
  EXPECT_NEAR (mid::triangleSidedness (transformed (motion, kRight),
                                       transformed (motion, kUp, true)),
               side,
               1e-5f);
  Eigen::Isometry3f mirror = Eigen::Isometry3f::Identity();
  mirror.linear() = Eigen::Vector3f (-1, 1, 1).asDiagonal();
  const mid::Triangle mirrored = transformed (motion * mirror, kRight);
  const mid::Triangle mirrored_normals = transformed (motion * mirror, kUp, true);
  EXPECT_NEAR (mid::triangleSidedness (mirrored, mirrored_normals), -side, 1e-5f);
  // Degenerate: a triangle whose vertices are collinear has no side.
  const mid::Triangle line{
      Eigen::Vector3f (0, 0, 0), Eigen::Vector3f (1, 0, 0), Eigen::Vector3f (2, 0, 0)};
  EXPECT_EQ (mid::triangleSidedness (line, kUp), 0.0f);
}

TEST (TriangleCriteria, DistanceBetweenTriangles)
{
  const Eigen::Isometry3f up = mid::test::rigidMotion ({0.01f, 0.005f, 0.02f});
  EXPECT_NEAR (mid::triangleDistance (kRight, transformed (up, kRight)), 0.02f, 1e-6f);

  // Side by side in one plane: the gap between the 4 cm edge at x = 0 and a copy moved to
  // x = -0.05 whose nearest part is its vertex (0.03 - 0.05) = -0.02: 2 cm.
  const Eigen::Isometry3f left = mid::test::rigidMotion ({-0.05f, 0.0f, 0.0f});
  EXPECT_NEAR (
      mid::triangleDistance (kRight, transformed (left, kRight)), 0.02f, 1e-6f);

  // Coplanar and overlapping, touching at a vertex, and piercing: all 0.
  const Eigen::Isometry3f shift = mid::test::rigidMotion ({0.005f, 0.005f, 0.0f});
  EXPECT_EQ (mid::triangleDistance (kRight, transformed (shift, kRight)), 0.0f);
  const Eigen::Isometry3f corner = mid::test::rigidMotion ({0.03f, 0.0f, 0.0f});
  EXPECT_NEAR (
      mid::triangleDistance (kRight, transformed (corner, kRight)), 0.0f, 1e-7f);
  const mid::Triangle piercing{Eigen::Vector3f (0.01f, 0.01f, -0.01f),
                               Eigen::Vector3f (0.01f, 0.01f, 0.01f),
                               Eigen::Vector3f (0.05f, 0.05f, 0.01f)};
  EXPECT_EQ (mid::triangleDistance (kRight, piercing), 0.0f);
  // Symmetric.
  EXPECT_FLOAT_EQ (mid::triangleDistance (transformed (left, kRight), kRight),
                   mid::triangleDistance (kRight, transformed (left, kRight)));
}
