#include "pose_union_find.h"

#include <Eigen/Geometry>

#include <numeric>

namespace mid {
namespace detail {

PoseUnionFind::PoseUnionFind (std::size_t nodes)
: parent_ (nodes), size_ (nodes, 1), to_parent_ (nodes, Eigen::Matrix4f::Identity())
{
  std::iota (parent_.begin(), parent_.end(), std::size_t{0});
}

std::size_t
PoseUnionFind::find (std::size_t node, Eigen::Matrix4f& to_root) const
{
  to_root.setIdentity();
  while (parent_[node] != node) {
    to_root = to_parent_[node] * to_root;
    node = parent_[node];
  }
  return node;
}

void
PoseUnionFind::unite (std::size_t u, std::size_t v, const Eigen::Matrix4f& u_to_v)
{
  Eigen::Matrix4f u_to_root_u, v_to_root_v;
  const std::size_t root_u = find (u, u_to_root_u);
  const std::size_t root_v = find (v, v_to_root_v);
  if (root_u == root_v)
    return;
  // A point x_u is x_v = u_to_v x_u; in root_u's frame it is u_to_root_u x_u. So root_v's frame
  // goes into root_u's by u_to_root_u u_to_v^-1 v_to_root_v^-1.
  const Eigen::Matrix4f root_v_to_root_u =
      u_to_root_u * Eigen::Isometry3f (u_to_v).inverse (Eigen::Isometry).matrix() *
      Eigen::Isometry3f (v_to_root_v).inverse (Eigen::Isometry).matrix();
  // The smaller class goes under the larger one's root, so that find() stays short.
  if (size_[root_v] <= size_[root_u]) {
    parent_[root_v] = root_u;
    to_parent_[root_v] = root_v_to_root_u;
    size_[root_u] += size_[root_v];
  }
  else {
    parent_[root_u] = root_v;
    to_parent_[root_u] =
        Eigen::Isometry3f (root_v_to_root_u).inverse (Eigen::Isometry).matrix();
    size_[root_v] += size_[root_u];
  }
}

} // namespace detail
} // namespace mid
