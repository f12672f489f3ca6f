#include "cluster_sets.h"

#include <mid/segmentation/chain_splitting.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <tuple>

namespace mid {

namespace {

/** Sources spanning more than this many steps along the row lie on more than one copy (one
  * copy spans less than a step; the margin absorbs keypoint noise).
  */
constexpr double kMinChainSpan = 1.05;

/** The cut (in chain units) that numbers the copies: point x lies on copy floor(s(x) - cut).
  * `positions` are the chain coordinates of the sources and of the targets moved back by the
  * stride. A cut through the objects puts them on more copies than a cut between copies, so
  * the cut is the middle of an empty interval of the positions modulo 1 that puts them on the
  * fewest copies. (The largest empty interval alone may lie inside every copy, between two
  * printed areas, when copies touch.) Of those, the one with the most `gaps` (the places where
  * the surface shows a gap between copies, for a cut) goes first, then the largest.
  */
double
cutBetweenCopies (const std::vector<double>& positions,
                  const std::function<std::size_t (double)>& gaps)
{
  std::vector<double> phases;
  phases.reserve (positions.size());
  for (const double p : positions)
    phases.push_back (p - std::floor (p));
  std::sort (phases.begin(), phases.end());
  const auto copies = [&positions] (double cut) {
    std::set<long> numbers;
    for (const double p : positions)
      numbers.insert (static_cast<long> (std::floor (p - cut)));
    return numbers.size();
  };
  // (copies, -gaps, -width) of every empty interval's middle; the smallest wins.
  std::vector<std::tuple<std::size_t, long, double, double>> candidates;
  for (std::size_t i = 0; i < phases.size(); ++i) {
    // The gap after phases[i], on the circle.
    const double next = i + 1 < phases.size() ? phases[i + 1] : phases.front() + 1.0;
    const double width = next - phases[i], cut = phases[i] + width / 2;
    if (width > 0.0)
      candidates.emplace_back (copies (cut), 0L, -width, cut);
  }
  if (candidates.empty())
    return 0.0;
  const std::size_t fewest =
      std::get<0> (*std::min_element (candidates.begin(), candidates.end()));
  for (auto& candidate : candidates)
    if (std::get<0> (candidate) == fewest)
      std::get<1> (candidate) = -static_cast<long> (gaps (std::get<3> (candidate)));
  return std::get<3> (*std::min_element (candidates.begin(), candidates.end()));
}

/** How many of the places where the cut `cut` separates two copies show a gap in the surface:
  * at each, the cluster keypoints next to it on either side (within half a step) with the
  * surface between them falling behind (surfaceDropsBetween()). `members` are the cluster's
  * keypoints sorted by their chain coordinate `chain`.
  */
std::size_t
surfaceGapsAt (double cut,
               const pcl::Indices& members,
               const std::function<double (pcl::index_t)>& chain,
               const KeypointSurface& surface)
{
  std::size_t gaps = 0;
  for (std::size_t i = 0; i + 1 < members.size(); ++i) {
    const double below = chain (members[i]), above = chain (members[i + 1]);
    const double boundary = std::floor (above - cut) + cut;
    if (boundary > below && boundary - below < 0.5 && above - boundary < 0.5 &&
        surfaceDropsBetween (surface, members[i], members[i + 1], kMinSurfaceGapDrop))
      ++gaps;
  }
  return gaps;
}

Eigen::Vector3f
sourceCentroid (const TripletCluster& cluster, const KeypointCloud& keypoints)
{
  Eigen::Vector3f centroid = Eigen::Vector3f::Zero();
  for (const auto k : cluster.source_indices)
    centroid += keypoints[static_cast<std::size_t> (k)].getVector3fMap();
  return centroid /
         static_cast<float> (std::max<std::size_t> (1, cluster.source_indices.size()));
}

} // namespace

Eigen::Vector3f
chainStep (const TripletCluster& cluster, const KeypointCloud& keypoints)
{
  if (cluster.source_indices.empty())
    return Eigen::Vector3f::Zero();
  const Eigen::Vector3f centroid = sourceCentroid (cluster, keypoints);
  return cluster.transformation.topLeftCorner<3, 3>() * centroid +
         cluster.transformation.topRightCorner<3, 1>() - centroid;
}

std::vector<std::vector<std::size_t>>
splitChainCluster (const TripletCluster& cluster,
                   const TripletMatches& triplets,
                   const KeypointCloud& keypoints,
                   float max_rotation,
                   const Eigen::Vector3f& row_step,
                   const KeypointSurface* surface)
{
  std::vector<std::size_t> all (cluster.triplets.size());
  std::iota (all.begin(), all.end(), std::size_t{0});
  std::vector<std::vector<std::size_t>> whole{all};
  const Eigen::Matrix3f rotation = cluster.transformation.topLeftCorner<3, 3>();
  if (cluster.source_indices.empty() ||
      Eigen::AngleAxisf (rotation).angle() > max_rotation)
    return whole;

  const Eigen::Vector3f centroid = sourceCentroid (cluster, keypoints);
  const bool known_row = row_step.squaredNorm() > 0.0f;
  // Copies are numbered along the row's step; this cluster links copy k to k + stride.
  const Eigen::Vector3f own_step = chainStep (cluster, keypoints);
  const Eigen::Vector3f step = known_row ? row_step : own_step;
  if (!(step.squaredNorm() > 0.0f))
    return whole;
  const long stride =
      known_row ? std::lround (own_step.dot (step) / step.squaredNorm()) : 1;
  if (stride == 0)
    return whole;
  const auto chain = [&] (pcl::index_t k) {
    return static_cast<double> (
        (keypoints[static_cast<std::size_t> (k)].getVector3fMap() - centroid)
            .dot (step) /
        step.squaredNorm());
  };

  // A chain shows itself by a keypoint that is a target (on copy k + 1) and a source (towards
  // copy k + 2), or by sources that span more than one step along the row (copies cannot
  // interpenetrate, so one copy spans less). A single pair of copies shows neither and is
  // never split: the largest gap of its phases may fall inside the object.
  const pcl::Indices shared =
      detail::sharedKeypoints (cluster.source_indices, cluster.target_indices);
  const auto [lowest, highest] = std::minmax_element (
      cluster.source_indices.begin(),
      cluster.source_indices.end(),
      [&chain] (pcl::index_t a, pcl::index_t b) { return chain (a) < chain (b); });
  if (!known_row && shared.empty() &&
      chain (*highest) - chain (*lowest) <= kMinChainSpan)
    return whole;

  std::vector<double> positions;
  for (const auto k : cluster.source_indices)
    positions.push_back (chain (k));
  for (const auto k : cluster.target_indices)
    positions.push_back (chain (k) - static_cast<double> (stride));
  pcl::Indices along_row =
      detail::allKeypoints (cluster.source_indices, cluster.target_indices);
  std::sort (
      along_row.begin(), along_row.end(), [&chain] (pcl::index_t a, pcl::index_t b) {
        return chain (a) < chain (b);
      });
  const double cut = cutBetweenCopies (positions, [&] (double c) -> std::size_t {
    return surface ? surfaceGapsAt (c, along_row, chain, *surface) : 0;
  });
  const auto copy = [&] (pcl::index_t k) {
    return static_cast<long> (std::floor (chain (k) - cut));
  };
  // Without a shared keypoint, the span is the only evidence: the sources must then lie on
  // consecutive copies of one row. Sources on copies with a gap between them (two pairs of
  // touching copies far apart, 0, 2 -> 1, 3, or a row whose middle link is missing) are left
  // to the compound splitting.
  if (!known_row && shared.empty()) {
    std::set<long> numbers;
    for (const auto k : cluster.source_indices)
      numbers.insert (copy (k));
    if (*numbers.rbegin() - *numbers.begin() + 1 != static_cast<long> (numbers.size()))
      return whole;
  }

  std::map<long, std::vector<std::size_t>> parts;
  for (std::size_t m = 0; m < cluster.triplets.size(); ++m) {
    const auto& correspondences = triplets[cluster.triplets[m]].correspondences;
    const auto source = [&] (const pcl::Correspondence& c) {
      return detail::sourceOf (c, cluster.reversed[m]);
    };
    const auto target = [&] (const pcl::Correspondence& c) {
      return detail::targetOf (c, cluster.reversed[m]);
    };
    const long first = copy (source (correspondences.front()));
    if (std::all_of (correspondences.begin(),
                     correspondences.end(),
                     [&] (const pcl::Correspondence& c) {
                       return copy (source (c)) == first &&
                              copy (target (c)) == first + stride;
                     }))
      parts[first].push_back (m);
  }
  // A known row's multiple may link a single pair of copies; its triplets across copies go.
  if (parts.size() < 2 && !(known_row && parts.size() == 1))
    return whole;
  std::vector<std::vector<std::size_t>> split;
  split.reserve (parts.size());
  for (auto& [copy_number, members] : parts)
    split.push_back (std::move (members));
  return split;
}

} // namespace mid
