#pragma once

#include <Eigen/Core>

namespace mid {

/** \brief The point pair feature of two oriented surface points (Drost et al., CVPR 2010),
  * as used by Abbeloos et al. (3DV 2017) to prune keypoint matches:
  * F(m1, m2) = (|d|, angle(n1, d), angle(n2, d), angle(n1, n2)) with d = m2 - m1.
  * Angles are in radians in [0, pi], the distance in the units of the points (metres).
  */
struct PointPairFeature
{
  float distance = 0.0f;
  float angle_n1_d = 0.0f;
  float angle_n2_d = 0.0f;
  float angle_n1_n2 = 0.0f;
};

/** \brief Angle between two vectors in [0, pi], computed with atan2 so that it stays accurate
  * for nearly parallel vectors. Returns 0 if either vector is zero.
  */
float
angleBetween (const Eigen::Vector3f& a, const Eigen::Vector3f& b);

/** \brief Compute F(m1, m2) for the oriented points (p1, n1) and (p2, n2).
  * \param[in] p1 first point
  * \param[in] n1 normal at the first point (need not be unit length, must be non-zero)
  * \param[in] p2 second point
  * \param[in] n2 normal at the second point
  * \param[out] feature the feature
  * \return false if the points coincide, a normal is zero or any input is not finite
  */
bool
computePointPairFeature (const Eigen::Vector3f& p1,
                         const Eigen::Vector3f& n1,
                         const Eigen::Vector3f& p2,
                         const Eigen::Vector3f& n2,
                         PointPairFeature& feature);

/** \brief Component-wise absolute difference |F(m1, m2) - F(l1, l2)| of two features. */
PointPairFeature
pointPairFeatureDifference (const PointPairFeature& a, const PointPairFeature& b);

/** \brief True if two features agree within the thresholds: the distance difference is at most
  * max_distance_difference and each of the three angle differences at most
  * max_angle_difference (radians). The paper uses 5 mm and 35 degrees.
  */
bool
arePointPairFeaturesSimilar (const PointPairFeature& a,
                             const PointPairFeature& b,
                             float max_distance_difference,
                             float max_angle_difference);

} // namespace mid
