#include <mid/features/point_pair_feature.h>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>

namespace {

constexpr float kPi = static_cast<float> (M_PI);

mid::PointPairFeature
feature (const Eigen::Vector3f& p1,
         const Eigen::Vector3f& n1,
         const Eigen::Vector3f& p2,
         const Eigen::Vector3f& n2)
{
  mid::PointPairFeature f;
  EXPECT_TRUE (mid::computePointPairFeature (p1, n1, p2, n2, f));
  return f;
}

} // namespace

TEST (PointPairFeature, MatchesHandComputedGeometry)
{
  // d = (2, 0, 0); n1 along +z (90 deg to d), n2 along (1, 0, 1) (45 deg to d, 45 deg to n1).
  const auto f = feature ({1, 1, 1}, {0, 0, 1}, {3, 1, 1}, {1, 0, 1});
  EXPECT_FLOAT_EQ (f.distance, 2.0f);
  EXPECT_NEAR (f.angle_n1_d, kPi / 2, 1e-6f);
  EXPECT_NEAR (f.angle_n2_d, kPi / 4, 1e-6f);
  EXPECT_NEAR (f.angle_n1_n2, kPi / 4, 1e-6f);

  // Anti-parallel normals along d: angles 0 and pi; distance 5 (3-4-5 triangle).
  const auto g = feature ({0, 0, 0}, {3, 4, 0}, {3, 4, 0}, {-3, -4, 0});
  EXPECT_FLOAT_EQ (g.distance, 5.0f);
  EXPECT_NEAR (g.angle_n1_d, 0.0f, 1e-6f);
  EXPECT_NEAR (g.angle_n2_d, kPi, 1e-6f);
  EXPECT_NEAR (g.angle_n1_n2, kPi, 1e-6f);
}

TEST (PointPairFeature, IsInvariantToRigidMotionAndNormalLength)
{
  const Eigen::Vector3f p1 (0.1f, -0.2f, 0.9f), n1 (0.3f, 0.2f, -1.0f);
  const Eigen::Vector3f p2 (0.14f, -0.17f, 0.93f), n2 (-0.4f, 0.1f, -1.0f);
  const Eigen::Isometry3f motion =
      Eigen::Translation3f (0.3f, -0.1f, 0.2f) *
      Eigen::AngleAxisf (1.1f, Eigen::Vector3f (1, 2, 3).normalized());
  const auto a = feature (p1, n1, p2, n2);
  const auto b = feature (
      motion * p1, 2.0f * (motion.linear() * n1), motion * p2, motion.linear() * n2);
  const auto d = mid::pointPairFeatureDifference (a, b);
  EXPECT_NEAR (d.distance, 0.0f, 1e-6f);
  EXPECT_NEAR (d.angle_n1_d, 0.0f, 1e-5f);
  EXPECT_NEAR (d.angle_n2_d, 0.0f, 1e-5f);
  EXPECT_NEAR (d.angle_n1_n2, 0.0f, 1e-5f);
}

TEST (PointPairFeature, RefusesDegenerateInput)
{
  mid::PointPairFeature f;
  const Eigen::Vector3f p (1, 2, 3), n (0, 0, 1);
  EXPECT_FALSE (mid::computePointPairFeature (p, n, p, n, f));
  EXPECT_FALSE (mid::computePointPairFeature (p, Eigen::Vector3f::Zero(), p + n, n, f));
  EXPECT_FALSE (mid::computePointPairFeature (p, n, Eigen::Vector3f (NAN, 0, 0), n, f));
}

TEST (PointPairFeature, SimilarityAppliesEachThreshold)
{
  const float max_distance = 0.005f, max_angle = 35.0f * kPi / 180.0f;
  const mid::PointPairFeature base{0.05f, 1.0f, 1.5f, 0.5f};
  EXPECT_TRUE (mid::arePointPairFeaturesSimilar (base, base, max_distance, max_angle));

  auto off = base;
  off.distance += 0.0049f;
  EXPECT_TRUE (mid::arePointPairFeaturesSimilar (base, off, max_distance, max_angle));
  off.distance = base.distance - 0.0051f;
  EXPECT_FALSE (mid::arePointPairFeaturesSimilar (base, off, max_distance, max_angle));

  for (float mid::PointPairFeature::*angle : {&mid::PointPairFeature::angle_n1_d,
                                              &mid::PointPairFeature::angle_n2_d,
                                              &mid::PointPairFeature::angle_n1_n2}) {
    off = base;
    off.*angle += 0.99f * max_angle;
    EXPECT_TRUE (mid::arePointPairFeaturesSimilar (base, off, max_distance, max_angle));
    off.*angle = base.*angle - 1.01f * max_angle;
    EXPECT_FALSE (
        mid::arePointPairFeaturesSimilar (base, off, max_distance, max_angle));
  }
}
