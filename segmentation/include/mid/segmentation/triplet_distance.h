#pragma once

#include <mid/features/keypoint_types.h>
#include <mid/registration/triplet_match.h>

#include <Eigen/Core>

namespace mid {

/** \brief A triplet match's two triangles and rigid pose, ready for distance computations. */
struct TripletGeometry
{
  /** \brief Triangle P (columns p_1..p_3) and triangle Q (q_1..q_3), metres. */
  ///@{
  Eigen::Matrix3f p;
  Eigen::Matrix3f q;
  ///@}
  /** \brief T_pq: q_i ~= rotation p_i + translation (metres). */
  ///@{
  Eigen::Matrix3f rotation;
  Eigen::Vector3f translation;
  ///@}
  /** \brief Centroids of P and Q (metres). */
  ///@{
  Eigen::Vector3f p_centroid;
  Eigen::Vector3f q_centroid;
  ///@}

  EIGEN_MAKE_ALIGNED_OPERATOR_NEW
};

/** \brief Gather the positions of a triplet's keypoints (P from source, Q from target). The
  * indices must be valid for the clouds (not checked).
  * \param[in] triplet the triplet match, with its pose
  * \param[in] source the keypoints index_query refers to
  * \param[in] target the keypoints index_match refers to (the same cloud for one frame)
  * \return the triangles, the pose and the centroids
  */
TripletGeometry
makeTripletGeometry (const TripletMatch& triplet,
                     const KeypointCloud& source,
                     const KeypointCloud& target);

/** \brief The same triplet used the other way round: Q -> P with the inverse pose.
  * \param[in] geometry the triplet P -> Q
  * \return the triplet Q -> P
  */
TripletGeometry
invertTripletGeometry (const TripletGeometry& geometry);

/** \brief The distance of Abbeloos et al. (3DV 2017, eq. 2) between triplet matches (P, Q) and
  * (A, B): sum_i |T_pq(a_i) - b_i| + sum_i |T_ab(p_i) - q_i| (metres).
  * \param[in] pq the triplet match (P, Q)
  * \param[in] ab the triplet match (A, B)
  * \return the distance D (metres); symmetric in its arguments
  */
float
tripletDistance (const TripletGeometry& pq, const TripletGeometry& ab);

/** \brief A lower bound of tripletDistance() from the centroids only:
  * 3 |T_pq(mean a) - mean b| + 3 |T_ab(mean p) - mean q| (the triangle inequality on the sums).
  * It is exact to use it to skip pairs: if the bound exceeds eps, so does the distance.
  * \param[in] pq the triplet match (P, Q)
  * \param[in] ab the triplet match (A, B)
  * \return the lower bound (metres)
  */
float
tripletDistanceLowerBound (const TripletGeometry& pq, const TripletGeometry& ab);

} // namespace mid
