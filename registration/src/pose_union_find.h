#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace mid {
namespace detail {

/** \brief Union-find over nodes that each carry a rigid frame: every class knows where each of
  * its nodes' frames lies in the frame of its root, so a new constraint between two nodes of
  * one class can be checked against the constraints already accepted (a loop closure check).
  */
class PoseUnionFind
{
public:
  explicit PoseUnionFind (std::size_t nodes);

  /** \brief The root of a node's class, and the transform taking the node's frame into the
    * root's frame.
    */
  std::size_t
  find (std::size_t node, Eigen::Matrix4f& to_root) const;

  /** \brief Join the classes of u and v such that x_v = u_to_v x_u (u_to_v maps u's frame into
    * v's frame). Does nothing if they are one class already.
    */
  void
  unite (std::size_t u, std::size_t v, const Eigen::Matrix4f& u_to_v);

private:
  std::vector<std::size_t> parent_;
  /** \brief Per root, the number of nodes in its class. */
  std::vector<std::size_t> size_;
  /** \brief Per node, the transform taking its frame into its parent's frame. */
  std::vector<Eigen::Matrix4f, Eigen::aligned_allocator<Eigen::Matrix4f>> to_parent_;
};

} // namespace detail
} // namespace mid
