#pragma once

#include <mid/features/keypoint_types.h>
#include <mid/registration/triplet_cluster.h>

#include <Eigen/Core>
#include <Eigen/StdVector>

#include <set>
#include <vector>

namespace mid {
namespace detail {

using Transforms =
    std::vector<Eigen::Matrix4f, Eigen::aligned_allocator<Eigen::Matrix4f>>;

/** \brief The graph of point sets of the paper's "Initial Model Creation": node 2c is cluster
  * c's source set and 2c+1 its target set; a cluster edge carries its pose and its rms as weight,
  * a shared-keypoint edge the identity and the weight delta.
  *
  * A shared keypoint says that two sets lie on one instance, but one stray keypoint can tie
  * sets on two copies together (in a row of copies, a cluster k -> k + 3 that also holds a
  * keypoint of copy k + 1). So the shared-keypoint edges are checked against the poses before
  * they are used (not in the paper): the cluster edges are taken first, then the shared-keypoint
  * edges from the most shared keypoints down; an edge that closes a loop is kept only if the
  * poses its two sets already have put the sets' centroid less than the link tolerance apart.
  * The rejected edges take part in nothing: not in the shortest paths, not in the groups.
  */
class PointSetGraph
{
public:
  /** \param[in] clusters the clusters of triplet matches
    * \param[in] keypoints the keypoints the clusters index
    * \param[in] shared_point_weight weight delta of a shared-keypoint edge
    * \param[in] link_tolerance a shared-keypoint edge closing a loop is rejected if the poses
    *            of its two sets put their centroid this far apart or farther (metres)
    */
  PointSetGraph (const TripletClusters& clusters,
                 const KeypointCloud& keypoints,
                 double shared_point_weight,
                 float link_tolerance);

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

  /** \brief The keypoints shared by the two sets of a rejected shared-keypoint edge: each lies
    * on one of two instances, not on both.
    */
  const std::set<pcl::index_t>&
  contestedKeypoints () const
  {
    return contested_;
  }

private:
  struct Edge
  {
    std::size_t u, v;
    double weight;
    bool shared;              // a shared-keypoint edge (identity), else a cluster edge
    std::size_t shared_count; // keypoints the two sets share (shared edges)
    bool rejected;            // a shared edge whose sets' poses disagree
    Eigen::Matrix4f u_to_v;
    EIGEN_MAKE_ALIGNED_OPERATOR_NEW
  };

  /** \brief Mark the shared-keypoint edges that contradict the poses (see the class). */
  void
  rejectInconsistentSharedEdges (const KeypointCloud& keypoints, float link_tolerance);

  std::vector<pcl::Indices> points_;
  std::set<pcl::index_t> contested_;
  std::vector<Edge, Eigen::aligned_allocator<Edge>> edges_;
  /** \brief Matches of each node's cluster plus the keypoints it shares with other nodes. */
  std::vector<std::size_t> importance_;
};

} // namespace detail
} // namespace mid
