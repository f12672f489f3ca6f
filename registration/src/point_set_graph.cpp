#include "point_set_graph.h"

#include "pose_union_find.h"

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/connected_components.hpp>
#include <boost/graph/dijkstra_shortest_paths.hpp>

#include <algorithm>
#include <map>
#include <numeric>
#include <set>

namespace mid {
namespace detail {

namespace {

using Graph = boost::adjacency_list<
    boost::vecS,
    boost::vecS,
    boost::undirectedS,
    boost::no_property,
    boost::property<boost::edge_weight_t,
                    double,
                    boost::property<boost::edge_index_t, std::size_t>>>;

} // namespace

PointSetGraph::PointSetGraph (const TripletClusters& clusters,
                              const KeypointCloud& keypoints,
                              double shared_point_weight,
                              float link_tolerance)
: points_ (2 * clusters.size()), importance_ (2 * clusters.size(), 0)
{
  for (std::size_t c = 0; c < clusters.size(); ++c) {
    points_[2 * c] = clusters[c].source_indices;
    points_[2 * c + 1] = clusters[c].target_indices;
    edges_.push_back ({2 * c,
                       2 * c + 1,
                       static_cast<double> (clusters[c].rms_error),
                       false,
                       0,
                       false,
                       clusters[c].transformation});
    importance_[2 * c] = importance_[2 * c + 1] = clusters[c].correspondences.size();
  }
  // Nodes holding each keypoint; every two such nodes (of different clusters) share it.
  std::map<pcl::index_t, std::vector<std::size_t>> holders;
  for (std::size_t n = 0; n < points_.size(); ++n)
    for (const auto k : points_[n])
      holders[k].push_back (n);
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> shared;
  for (const auto& entry : holders)
    for (std::size_t i = 0; i < entry.second.size(); ++i)
      for (std::size_t j = i + 1; j < entry.second.size(); ++j) {
        const std::size_t a = entry.second[i], b = entry.second[j];
        if (a / 2 == b / 2)
          continue; // one cluster's own two sets: joined by its pose, not by identity
        ++importance_[a];
        ++importance_[b];
        ++shared[{a, b}];
      }
  for (const auto& [nodes, count] : shared)
    edges_.push_back ({nodes.first,
                       nodes.second,
                       shared_point_weight,
                       true,
                       count,
                       false,
                       Eigen::Matrix4f::Identity()});
  rejectInconsistentSharedEdges (keypoints, link_tolerance);
}

void
PointSetGraph::rejectInconsistentSharedEdges (const KeypointCloud& keypoints,
                                              float link_tolerance)
{
  PoseUnionFind frames (points_.size());
  std::vector<std::size_t> order;
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    if (edges_[e].shared)
      order.push_back (e);
    else
      frames.unite (edges_[e].u, edges_[e].v, edges_[e].u_to_v);
  }
  std::stable_sort (order.begin(), order.end(), [this] (std::size_t a, std::size_t b) {
    return edges_[a].shared_count > edges_[b].shared_count;
  });
  for (const std::size_t e : order) {
    Edge& edge = edges_[e];
    Eigen::Matrix4f u_to_root, v_to_root;
    if (frames.find (edge.u, u_to_root) != frames.find (edge.v, v_to_root)) {
      frames.unite (edge.u, edge.v, edge.u_to_v);
      continue;
    }
    Eigen::Vector3f center = Eigen::Vector3f::Zero();
    for (const std::size_t n : {edge.u, edge.v})
      for (const auto k : points_[n])
        center += keypoints[static_cast<std::size_t> (k)].getVector3fMap();
    center /= static_cast<float> (points_[edge.u].size() + points_[edge.v].size());
    const Eigen::Vector3f in_u = (u_to_root * center.homogeneous()).head<3>();
    const Eigen::Vector3f in_v = (v_to_root * center.homogeneous()).head<3>();
    edge.rejected = !((in_u - in_v).norm() < link_tolerance);
    if (edge.rejected) {
      const std::set<pcl::index_t> of_u (points_[edge.u].begin(),
                                         points_[edge.u].end());
      for (const auto k : points_[edge.v])
        if (of_u.count (k) > 0)
          contested_.insert (k);
    }
  }
}

std::vector<std::vector<std::size_t>>
PointSetGraph::components() const
{
  Graph graph (points_.size());
  for (const auto& e : edges_)
    if (!e.rejected)
      boost::add_edge (e.u, e.v, graph);
  std::vector<int> component (points_.size());
  const int count = boost::connected_components (graph, component.data());
  std::vector<std::vector<std::size_t>> result (static_cast<std::size_t> (count));
  for (std::size_t n = 0; n < points_.size(); ++n)
    result[static_cast<std::size_t> (component[n])].push_back (n);
  std::sort (result.begin(), result.end());
  return result;
}

std::size_t
PointSetGraph::solveComponent (const std::vector<std::size_t>& component,
                               std::size_t& reference,
                               Transforms& to_reference,
                               std::vector<int>& group) const
{
  reference = *std::max_element (
      component.begin(), component.end(), [this] (std::size_t a, std::size_t b) {
        return importance_[a] < importance_[b] ||
               (importance_[a] == importance_[b] && a > b);
      });
  Graph graph (points_.size());
  for (std::size_t e = 0; e < edges_.size(); ++e)
    if (!edges_[e].rejected)
      boost::add_edge (edges_[e].u,
                       edges_[e].v,
                       Graph::edge_property_type (edges_[e].weight, e),
                       graph);
  std::vector<Graph::vertex_descriptor> predecessor (points_.size());
  std::vector<double> distance (points_.size());
  boost::dijkstra_shortest_paths (
      graph,
      reference,
      boost::predecessor_map (predecessor.data()).distance_map (distance.data()));

  // Compose along the tree, nearest nodes first so that each predecessor is done.
  to_reference.assign (points_.size(), Eigen::Matrix4f::Identity());
  std::vector<std::size_t> order = component;
  std::sort (order.begin(), order.end(), [&distance] (std::size_t a, std::size_t b) {
    return distance[a] < distance[b] || (distance[a] == distance[b] && a < b);
  });
  const auto index_map = boost::get (boost::edge_index, graph);
  for (const std::size_t n : order) {
    if (n == reference)
      continue;
    const std::size_t p = predecessor[n];
    // The cheapest edge between p and n is the one Dijkstra relaxed.
    const Edge* best = nullptr;
    for (auto [it, end] = boost::out_edges (p, graph); it != end; ++it)
      if (boost::target (*it, graph) == n) {
        const Edge& candidate = edges_[index_map[*it]];
        if (best == nullptr || candidate.weight < best->weight)
          best = &candidate;
      }
    // x_n = E x_p  =>  to_reference(n) = to_reference(p) * E^-1
    const Eigen::Matrix4f p_to_n =
        best->u == p ? best->u_to_v : Eigen::Matrix4f (best->u_to_v.inverse());
    to_reference[n] = to_reference[p] * p_to_n.inverse();
  }

  // Groups: nodes joined by shared-keypoint edges.
  std::vector<std::size_t> parent (points_.size());
  std::iota (parent.begin(), parent.end(), std::size_t{0});
  const auto find = [&parent] (std::size_t i) {
    while (parent[i] != i)
      i = parent[i] = parent[parent[i]];
    return i;
  };
  for (const auto& e : edges_)
    if (e.shared && !e.rejected)
      parent[std::max (find (e.u), find (e.v))] = std::min (find (e.u), find (e.v));
  group.assign (points_.size(), -1);
  std::map<std::size_t, int> group_of_root;
  for (const std::size_t n : component) {
    const auto inserted =
        group_of_root.emplace (find (n), static_cast<int> (group_of_root.size()));
    group[n] = inserted.first->second;
  }
  return group_of_root.size();
}

} // namespace detail
} // namespace mid
