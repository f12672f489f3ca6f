#include "compatible_match_graph.h"

#include <mid/features/point_pair_feature.h>

#include <pcl/kdtree/kdtree_flann.h>

#include <algorithm>
#include <cmath>

namespace mid {
namespace detail {

namespace {

/** Position and normal of a keypoint. */
struct Oriented
{
  Eigen::Vector3f point;
  Eigen::Vector3f normal;
};

Oriented
oriented (const KeypointCloud& cloud, pcl::index_t index)
{
  const auto& k = cloud[static_cast<std::size_t> (index)];
  return {k.getVector3fMap(), k.getNormalVector3fMap()};
}

bool
edgeWithin (const Eigen::Vector3f& a,
            const Eigen::Vector3f& b,
            const PairCriteria& criteria)
{
  const float squared = (a - b).squaredNorm();
  return squared >= criteria.min_edge_length * criteria.min_edge_length &&
         squared <= criteria.max_edge_length * criteria.max_edge_length;
}

/** The pair test: edges of both triangles in range, then the point pair features agree. */
bool
compatible (const Oriented& pa,
            const Oriented& qa,
            const Oriented& pb,
            const Oriented& qb,
            const PairCriteria& criteria)
{
  if (!edgeWithin (pa.point, pb.point, criteria) ||
      !edgeWithin (qa.point, qb.point, criteria))
    return false;
  // The distance component first: it is cheap and rejects most pairs before any angle.
  if (std::abs ((pa.point - pb.point).norm() - (qa.point - qb.point).norm()) >
      criteria.max_distance_difference)
    return false;
  PointPairFeature fp, fq;
  return computePointPairFeature (pa.point, pa.normal, pb.point, pb.normal, fp) &&
         computePointPairFeature (qa.point, qa.normal, qb.point, qb.normal, fq) &&
         arePointPairFeaturesSimilar (
             fp, fq, criteria.max_distance_difference, criteria.max_angle_difference);
}

} // namespace

CompatibleMatchGraph::CompatibleMatchGraph (const std::vector<UniqueMatch>& matches,
                                            const KeypointCloud::ConstPtr& source,
                                            const KeypointCloud& target,
                                            const PairCriteria& criteria,
                                            bool allow_reversal)
: successors_ (matches.size())
{
  // For each source keypoint, the matches that have it on their P side when used as given, and
  // (in one frame) the matches that have it on their P side when reversed.
  std::vector<std::vector<std::uint32_t>> forward (source->size()),
      reversed (source->size());
  for (std::size_t b = 0; b < matches.size(); ++b) {
    forward[static_cast<std::size_t> (matches[b].p)].push_back (
        static_cast<std::uint32_t> (2 * b));
    if (allow_reversal)
      reversed[static_cast<std::size_t> (matches[b].q)].push_back (
          static_cast<std::uint32_t> (2 * b + 1));
  }
  pcl::KdTreeFLANN<pcl::PointNormal> tree (false);
  tree.setInputCloud (source);

  pcl::Indices nearby;
  std::vector<float> squared_distances;
  std::vector<std::uint32_t> candidates;
  for (std::size_t a = 0; a < matches.size(); ++a) {
    const UniqueMatch& ma = matches[a];
    const Oriented pa = oriented (*source, ma.p), qa = oriented (target, ma.q);
    tree.radiusSearch ((*source)[static_cast<std::size_t> (ma.p)],
                       criteria.max_edge_length,
                       nearby,
                       squared_distances);
    candidates.clear();
    for (const pcl::index_t k : nearby) {
      for (const std::uint32_t encoded : forward[static_cast<std::size_t> (k)])
        if (encoded / 2 > a)
          candidates.push_back (encoded);
      for (const std::uint32_t encoded : reversed[static_cast<std::size_t> (k)])
        if (encoded / 2 > a)
          candidates.push_back (encoded);
    }
    std::sort (candidates.begin(), candidates.end());
    for (const std::uint32_t encoded : candidates) {
      const UniqueMatch& mb = matches[encoded / 2];
      // Two matches sharing a keypoint give a degenerate edge; in one frame, a keypoint on both
      // sides would also put the two triangles onto each other.
      const bool shared = mb.p == ma.p || mb.q == ma.q;
      const bool crossed = mb.q == ma.p || mb.p == ma.q;
      if (shared || (allow_reversal && crossed))
        continue;
      const bool reverse = encoded % 2 == 1;
      const Oriented pb = oriented (*source, reverse ? mb.q : mb.p);
      const Oriented qb = oriented (target, reverse ? mb.p : mb.q);
      if (compatible (pa, qa, pb, qb, criteria))
        successors_[a].push_back (encoded);
    }
  }
}

bool
CompatibleMatchGraph::hasEdge (std::size_t a, std::uint32_t encoded_b) const
{
  return std::binary_search (successors_[a].begin(), successors_[a].end(), encoded_b);
}

std::size_t
CompatibleMatchGraph::size() const
{
  std::size_t edges = 0;
  for (const auto& list : successors_)
    edges += list.size();
  return edges;
}

} // namespace detail
} // namespace mid
