#pragma once

#include <Eigen/Core>
#include <Eigen/StdVector>
#include <pcl/correspondence.h>

#include <array>
#include <vector>

namespace mid {

/** \brief Two matched triangles of keypoints, P and Q, in one frame (or in a source and a
  * target cloud), with the rigid motion that maps P onto Q.
  *
  * correspondences[k].index_query is the k-th keypoint of P and index_match the k-th of Q; the
  * orientation may be the reverse of the self-match the correspondence came from (a match a->b
  * may be used as b->a). This is the unit the transformation-space clustering works on.
  */
struct TripletMatch
{
  /** \brief The three keypoint pairs (P_k, Q_k). */
  std::array<pcl::Correspondence, 3> correspondences;
  /** \brief Rigid transform with Q_k ~= R P_k + t (least squares over the three pairs). */
  Eigen::Matrix4f transformation = Eigen::Matrix4f::Identity();
  /** \brief Root mean square of |R P_k + t - Q_k| over the three pairs (metres). */
  float rms_error = 0.0f;

  EIGEN_MAKE_ALIGNED_OPERATOR_NEW
};

/** \brief Triplet matches (Eigen-aligned, as TripletMatch holds a fixed-size matrix). */
using TripletMatches =
    std::vector<TripletMatch, Eigen::aligned_allocator<TripletMatch>>;

} // namespace mid
