#pragma once

#include <Eigen/Core>
#include <pcl/correspondence.h>
#include <pcl/types.h>

#include <cstddef>
#include <vector>

namespace mid {

/** \brief A group of triplet matches that share one relative pose: the same pair of object
  * instances, seen as two point sets, and the rigid motion between them.
  */
struct TripletCluster
{
  /** \brief The distinct keypoint pairs of the cluster's triplets: index_query on the source
    * side (set P), index_match on the target side (set Q), sorted.
    */
  pcl::Correspondences correspondences;
  /** \brief Rigid transform mapping set P onto set Q, least squares over all pairs. */
  Eigen::Matrix4f transformation = Eigen::Matrix4f::Identity();
  /** \brief Root mean square residual of the pairs under the transform (metres). */
  float rms_error = 0.0f;
  /** \brief The keypoints of set P and of set Q (sorted, distinct). */
  ///@{
  pcl::Indices source_indices;
  pcl::Indices target_indices;
  ///@}
  /** \brief The input triplets in the cluster, and for each whether it was used reversed (Q->P)
    * because it came from the merged inverse cluster.
    */
  ///@{
  std::vector<std::size_t> triplets;
  std::vector<bool> reversed;
  ///@}

  EIGEN_MAKE_ALIGNED_OPERATOR_NEW
};

/** \brief Clusters of one frame (Eigen-aligned, as TripletCluster holds a fixed-size matrix). */
using TripletClusters =
    std::vector<TripletCluster, Eigen::aligned_allocator<TripletCluster>>;

} // namespace mid
