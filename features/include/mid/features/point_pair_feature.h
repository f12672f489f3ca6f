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
  /** \brief |d| = |m2 - m1|, in the units of the points (metres). */
  float distance = 0.0f;
  /** \brief Angle between n1 and d, in radians [0, pi]. */
  float angle_n1_d = 0.0f;
  /** \brief Angle between n2 and d, in radians [0, pi]. */
  float angle_n2_d = 0.0f;
  /** \brief Angle between n1 and n2, in radians [0, pi]. */
  float angle_n1_n2 = 0.0f;
};

/** \brief Angle between two vectors in [0, pi], computed with atan2 so that it stays accurate
  * for nearly parallel vectors. Returns 0 if either vector is zero.
  * \param[in] a first vector (any length)
  * \param[in] b second vector (any length)
  * \return the angle in radians, in [0, pi]
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

/** \brief Component-wise absolute difference |F(m1, m2) - F(l1, l2)| of two features.
  * \param[in] a first feature
  * \param[in] b second feature
  * \return the four absolute differences (metres, radians)
  */
PointPairFeature
pointPairFeatureDifference (const PointPairFeature& a, const PointPairFeature& b);

/** \brief True if two features agree within the thresholds: the distance difference is at most
  * max_distance_difference and each of the three angle differences at most
  * max_angle_difference (radians). The paper uses 5 mm and 35 degrees.
  * \param[in] a first feature
  * \param[in] b second feature
  * \param[in] max_distance_difference largest distance difference, in the units of the points
  * (metres)
  * \param[in] max_angle_difference largest difference of each angle, in radians
  * \return true if all four differences are within the thresholds (false for a NaN component)
  */
bool
arePointPairFeaturesSimilar (const PointPairFeature& a,
                             const PointPairFeature& b,
                             float max_distance_difference,
                             float max_angle_difference);

} // namespace mid
