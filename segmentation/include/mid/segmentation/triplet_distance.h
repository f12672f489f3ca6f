#pragma once

#include <mid/features/keypoint_types.h>
#include <mid/registration/triplet_match.h>

#include <Eigen/Core>

namespace mid {

/** \brief A triplet match's two triangles and rigid pose, ready for distance computations. */
struct TripletGeometry
{
  /** \brief Triangle P (columns p_1..p_3) and triangle Q (q_1..q_3). */
  Eigen::Matrix3f p;
  Eigen::Matrix3f q;
  /** \brief T_pq: q_i ~= rotation p_i + translation. */
  Eigen::Matrix3f rotation;
  Eigen::Vector3f translation;
  /** \brief Centroids of P and Q. */
  Eigen::Vector3f p_centroid;
  Eigen::Vector3f q_centroid;

  EIGEN_MAKE_ALIGNED_OPERATOR_NEW
};

/** \brief Gather the positions of a triplet's keypoints (P from source, Q from target). The
  * indices must be valid for the clouds.
  */
TripletGeometry
makeTripletGeometry (const TripletMatch& triplet, const KeypointCloud& source,
                     const KeypointCloud& target);

/** \brief The same triplet used the other way round: Q -> P with the inverse pose. */
TripletGeometry
invertTripletGeometry (const TripletGeometry& geometry);

/** \brief The distance of Abbeloos et al. (3DV 2017, eq. 2) between triplet matches (P, Q) and
  * (A, B): sum_i |T_pq(a_i) - b_i| + sum_i |T_ab(p_i) - q_i| (metres).
  */
float
tripletDistance (const TripletGeometry& pq, const TripletGeometry& ab);

/** \brief A lower bound of tripletDistance() from the centroids only:
  * 3 |T_pq(mean a) - mean b| + 3 |T_ab(mean p) - mean q| (the triangle inequality on the sums).
  * It is exact to use it to skip pairs: if the bound exceeds eps, so does the distance.
  */
float
tripletDistanceLowerBound (const TripletGeometry& pq, const TripletGeometry& ab);

} // namespace mid
