#include "rigid_motion.h"

#include <mid/segmentation/triplet_distance.h>

#include <gtest/gtest.h>

#include <random>

namespace {

/** A triplet geometry with triangle p and pose T (q = T p exactly), plus an optional extra
  * displacement of q.
  */
mid::TripletGeometry
makeGeometry (const Eigen::Matrix3f& p,
              const Eigen::Isometry3f& motion,
              const Eigen::Vector3f& q_offset = Eigen::Vector3f::Zero())
{
  mid::TripletGeometry g;
  g.p = p;
  g.q = (motion * p).colwise() + q_offset;
  g.rotation = motion.linear();
  g.translation = motion.translation() + q_offset;
  g.p_centroid = g.p.rowwise().mean();
  g.q_centroid = g.q.rowwise().mean();
  return g;
}

Eigen::Matrix3f
triangle (float scale, float z)
{
  Eigen::Matrix3f p;
  p << 0.0f, scale, 0.0f, 0.0f, 0.0f, scale, z, z, z + 0.01f;
  return p;
}

} // namespace

TEST (TripletDistance, IsZeroForTheSameMotionAndSixTimesAPureOffset)
{
  const Eigen::Isometry3f motion =
      mid::test::rigidMotion ({0.3f, 0.0f, 0.1f}, 0.7f, {0, 1, 0});
  const auto a = makeGeometry (triangle (0.05f, 0.8f), motion);
  const auto b = makeGeometry (triangle (0.04f, 0.9f), motion);
  EXPECT_NEAR (mid::tripletDistance (a, b), 0.0f, 1e-6f);
  // Same rotation, translation off by d: every one of the six transferred points is off by |d|.
  const Eigen::Vector3f d (0.003f, -0.004f, 0.0f); // |d| = 5 mm
  const auto c = makeGeometry (triangle (0.04f, 0.9f), motion, d);
  EXPECT_NEAR (mid::tripletDistance (a, c), 6.0f * 0.005f, 1e-6f);
  EXPECT_NEAR (mid::tripletDistance (c, a), 6.0f * 0.005f, 1e-6f);
  EXPECT_NEAR (mid::tripletDistanceLowerBound (a, c), 6.0f * 0.005f, 1e-6f);
}

TEST (TripletDistance, LowerBoundNeverExceedsTheDistance)
{
  std::mt19937 rng (5);
  std::uniform_real_distribution<float> unit (-1.0f, 1.0f);
  for (int trial = 0; trial < 2000; ++trial) {
    auto random_geometry = [&] () {
      Eigen::Matrix3f p =
          Eigen::Matrix3f::NullaryExpr ([&] () { return 0.1f * unit (rng); });
      p.row (2).array() += 0.8f;
      const auto motion =
          mid::test::rigidMotion ({unit (rng), unit (rng), unit (rng)},
                                  3.0f * unit (rng),
                                  {unit (rng), unit (rng), unit (rng) + 2.0f});
      const Eigen::Vector3f noise (
          0.01f * unit (rng), 0.01f * unit (rng), 0.01f * unit (rng));
      return makeGeometry (p, motion, noise);
    };
    const auto a = random_geometry(), b = random_geometry();
    EXPECT_LE (mid::tripletDistanceLowerBound (a, b),
               mid::tripletDistance (a, b) * (1.0f + 1e-5f) + 1e-6f);
  }
}

TEST (TripletDistance, InversionSwapsTheTrianglesAndInvertsThePose)
{
  const Eigen::Isometry3f motion =
      mid::test::rigidMotion ({0.2f, -0.1f, 0.05f}, 1.3f, {1, 2, 3});
  const auto g = makeGeometry (triangle (0.05f, 0.8f), motion);
  const auto inverse = mid::invertTripletGeometry (g);
  EXPECT_EQ (inverse.p, g.q);
  EXPECT_EQ (inverse.q, g.p);
  const Eigen::Matrix3f mapped =
      (inverse.rotation * inverse.p).colwise() + inverse.translation;
  EXPECT_LT ((mapped - inverse.q).cwiseAbs().maxCoeff(), 1e-6f);
  EXPECT_NEAR (
      mid::tripletDistance (inverse, mid::invertTripletGeometry (g)), 0.0f, 1e-6f);
  // A triplet and its inverse do not cluster together: far apart in transformation space.
  EXPECT_GT (mid::tripletDistance (g, inverse), 0.1f);
}
