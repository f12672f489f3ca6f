#pragma once

#include <mid/registration/triplet_cluster.h>

#include <Eigen/Core>
#include <Eigen/StdVector>

#include <vector>

namespace mid {
namespace detail {

using Transforms =
    std::vector<Eigen::Matrix4f, Eigen::aligned_allocator<Eigen::Matrix4f>>;

/** \brief The graph of point sets of the paper's "Initial Model Creation": node 2c is cluster
  * c's source set and 2c+1 its target set; a cluster edge carries its pose and its rms as weight,
  * a shared-keypoint edge the identity and the weight delta.
  */
class PointSetGraph
{
public:
  PointSetGraph (const TripletClusters& clusters, double shared_point_weight);

  /** \brief The connected components, each a sorted list of nodes, ordered by first node. */
  std::vector<std::vector<std::size_t>>
  components () const;

  /** \brief Solve one component.
    * \param[in] component its nodes
    * \param[out] reference the node with the most matches and shared points
    * \param[out] to_reference for each node of the component, the transform taking its points
    *             into the reference set's frame (composed along the Dijkstra shortest path)
    * \param[out] group for each node of the component, its group of nodes joined by shared
    *             keypoints (one instance); groups are numbered from 0 within the component
    * \return the number of groups
    */
  std::size_t
  solveComponent (const std::vector<std::size_t>& component,
                  std::size_t& reference,
                  Transforms& to_reference,
                  std::vector<int>& group) const;

  /** \brief The keypoints of a node. */
  const pcl::Indices&
  points (std::size_t node) const
  {
    return points_[node];
  }

  std::size_t
  size () const
  {
    return points_.size();
  }

private:
  struct Edge
  {
    std::size_t u, v;
    double weight;
    bool shared; // a shared-keypoint edge (identity), else a cluster edge
    Eigen::Matrix4f u_to_v;
    EIGEN_MAKE_ALIGNED_OPERATOR_NEW
  };

  std::vector<pcl::Indices> points_;
  std::vector<Edge, Eigen::aligned_allocator<Edge>> edges_;
  /** \brief Matches of each node's cluster plus the keypoints it shares with other nodes. */
  std::vector<std::size_t> importance_;
};

} // namespace detail
} // namespace mid
