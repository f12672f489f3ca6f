#include "cluster_sets.h"
#include "disjoint_sets.h"

#include <mid/segmentation/compound_splitting.h>

#include <Eigen/Geometry>
#include <Eigen/SVD>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <numeric>
#include <utility>

namespace mid {

namespace {

/** A half turn rotates by 180 degrees; poses rotating less are not checked. */
constexpr float kMinHalfTurnAngle = static_cast<float> (150.0 * M_PI / 180.0);

/** Fraction of the smaller point set that the two sets of a half-turn cluster must share. */
constexpr double kMinSharedFraction = 0.25;

/** A point set straddles another cluster's two copies if at least this many of its keypoints,
  * and this fraction of them, lie within kMaxStraddleDistance of each of the other's sets.
  */
constexpr std::size_t kMinStraddlingPoints = 3;
constexpr double kMinStraddlingFraction = 0.2;
constexpr float kMaxStraddleDistance = 0.015f;

/** Fewest keypoints of a group on one side of the surface gaps, and fewest triplets of a part
  * of a cluster split at the gaps.
  */
constexpr std::size_t kMinGroupPoints = 3;
constexpr std::size_t kMinPartTriplets = 3;

/** Nearest keypoints (3D) each keypoint of a point set is first linked to when grouping it by
  * the surface's gaps; more pieces than kMaxSurfaceGroups left after that leave the set
  * unjudged (a walk per pair of pieces is the cost of joining them).
  */
constexpr std::size_t kGroupNeighbours = 8;
constexpr std::size_t kMaxSurfaceGroups = 16;

/** Keypoints closer than this (metres) to the plane between two half-turn copies take no
  * side (their triplets are dropped).
  */
constexpr float kMinPlaneDistance = 0.001f;

/** Keypoints closer than this (metres) are neighbours on one surface. */
constexpr float kNeighbourRadius = 0.02f;

/** A keypoint of a half-turn cluster this close (metres) to a keypoint of an anchor set is on
  * the anchor's copy.
  */
constexpr float kAnchorRadius = 0.005f;

/** Weight of a link between two keypoints on one anchor, against 1 for neighbours. */
constexpr int kAnchorWeight = 4;

/** The plane may cut at most this fraction of the anchor links (keypoints near a copy's
  * border may be near an anchor on the twin).
  */
constexpr double kMaxAnchorCut = 0.1;

/** Planes through the half turn's axis tried, evenly spaced over half a turn. */
constexpr int kPlaneCandidates = 180;

Eigen::Vector3f
position (const KeypointCloud& keypoints, pcl::index_t k)
{
  return keypoints[static_cast<std::size_t> (k)].getVector3fMap();
}

/** Two keypoints (positions in a list) that should lie on one side of the plane. */
struct Link
{
  std::size_t a, b;
  bool anchor; ///< both near one anchor set, else neighbours on one surface
};

/** Links between the listed keypoints: neighbours on one surface, and keypoints near one
  * anchor set, which lies on a single copy.
  */
std::vector<Link>
sameCopyLinks (const pcl::Indices& points,
               const std::vector<pcl::Indices>& anchors,
               const KeypointCloud& keypoints)
{
  std::vector<Link> links;
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t j = i + 1; j < points.size(); ++j)
      if ((position (keypoints, points[i]) - position (keypoints, points[j])).norm() <
          kNeighbourRadius)
        links.push_back ({i, j, false});
  for (const auto& anchor : anchors) {
    std::vector<std::size_t> near;
    for (std::size_t i = 0; i < points.size(); ++i)
      if (std::any_of (anchor.begin(), anchor.end(), [&] (pcl::index_t k) {
            return (position (keypoints, k) - position (keypoints, points[i])).norm() <
                   kAnchorRadius;
          }))
        near.push_back (i);
    for (std::size_t i = 0; i < near.size(); ++i)
      for (std::size_t j = i + 1; j < near.size(); ++j)
        links.push_back ({near[i], near[j], true});
  }
  return links;
}

/** True if the surface falls behind the segment between the closest two keypoints on either
  * side of the plane (normal through center): a gap between two objects.
  */
bool
gapBetweenSides (const pcl::Indices& points,
                 const std::vector<Eigen::Vector3f>& offsets,
                 const Eigen::Vector3f& normal,
                 const KeypointCloud& keypoints,
                 const KeypointSurface& surface)
{
  float closest = std::numeric_limits<float>::infinity();
  std::pair<pcl::index_t, pcl::index_t> pair{-1, -1};
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t j = 0; j < points.size(); ++j)
      if (offsets[i].dot (normal) > 0.0f && offsets[j].dot (normal) <= 0.0f) {
        const float d =
            (position (keypoints, points[i]) - position (keypoints, points[j])).norm();
        if (d < closest) {
          closest = d;
          pair = {points[i], points[j]};
        }
      }
  return pair.first >= 0 &&
         surfaceDropsBetween (surface, pair.first, pair.second, kMinSurfaceGapDrop);
}

/** Side (+1 / -1, 0 on the plane) of every keypoint of a half-turn cluster; empty when
  * nothing confirms the plane.
  */
std::map<pcl::index_t, int>
halfTurnSides (const TripletCluster& cluster,
               const std::vector<pcl::Indices>& anchors,
               const KeypointCloud& keypoints,
               const KeypointSurface* surface)
{
  const Eigen::Matrix3f rotation = cluster.transformation.topLeftCorner<3, 3>();
  const Eigen::Vector3f translation = cluster.transformation.topRightCorner<3, 1>();
  const Eigen::Vector3f axis = Eigen::AngleAxisf (rotation).axis();
  // A point of the axis: (I - R) c = t minus its part along the axis (least squares; I - R is
  // singular along the axis).
  const Eigen::Matrix3f about = Eigen::Matrix3f::Identity() - rotation;
  const Eigen::Vector3f center =
      about.jacobiSvd (Eigen::ComputeFullU | Eigen::ComputeFullV)
          .solve (translation - translation.dot (axis) * axis);
  const Eigen::Vector3f e1 = axis.unitOrthogonal(), e2 = axis.cross (e1);

  pcl::Indices points;
  std::set_union (cluster.source_indices.begin(),
                  cluster.source_indices.end(),
                  cluster.target_indices.begin(),
                  cluster.target_indices.end(),
                  std::back_inserter (points));
  std::vector<Eigen::Vector3f> offsets;
  for (const auto k : points)
    offsets.emplace_back (position (keypoints, k) - center);
  // Each candidate plane contains the axis; keep the one that cuts the fewest same-copy links.
  const std::vector<Link> links = sameCopyLinks (points, anchors, keypoints);
  const auto anchor_links = static_cast<std::size_t> (std::count_if (
      links.begin(), links.end(), [] (const Link& link) { return link.anchor; }));
  Eigen::Vector3f normal = e1;
  long fewest_cut = std::numeric_limits<long>::max();
  float widest_margin = 0.0f;
  std::size_t anchors_cut = 0;
  for (int step = 0; step < kPlaneCandidates; ++step) {
    const double angle = M_PI * step / kPlaneCandidates;
    const Eigen::Vector3f candidate = static_cast<float> (std::cos (angle)) * e1 +
                                      static_cast<float> (std::sin (angle)) * e2;
    long cut = 0;
    std::size_t cut_anchor_links = 0;
    for (const Link& link : links)
      if ((offsets[link.a].dot (candidate) > 0.0f) !=
          (offsets[link.b].dot (candidate) > 0.0f)) {
        cut += link.anchor ? kAnchorWeight : 1;
        cut_anchor_links += link.anchor ? 1 : 0;
      }
    // Among planes cutting as few links, the one farthest from every keypoint: between two
    // copies lying apart, the plane through the middle of the gap, not one through an
    // unprinted band of both.
    float margin = std::numeric_limits<float>::infinity();
    for (const auto& offset : offsets)
      margin = std::min (margin, std::abs (offset.dot (candidate)));
    if (cut < fewest_cut || (cut == fewest_cut && margin > widest_margin)) {
      fewest_cut = cut;
      widest_margin = margin;
      anchors_cut = cut_anchor_links;
      normal = candidate;
    }
  }
  std::map<pcl::index_t, int> sides;
  // A plane that cuts anchors may cross both copies, or the copies may be the two halves of
  // one symmetric object: leave the cluster as it is. Without anchors, only a plane through
  // a gap free of keypoints where the surface shows two objects is trusted.
  const bool confirmed =
      anchor_links > 0
          ? static_cast<double> (anchors_cut) <=
                kMaxAnchorCut * static_cast<double> (anchor_links)
          : fewest_cut == 0 && surface != nullptr &&
                gapBetweenSides (points, offsets, normal, keypoints, *surface);
  if (!confirmed)
    return sides;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const float d = offsets[i].dot (normal);
    sides[points[i]] = std::abs (d) < kMinPlaneDistance ? 0 : (d > 0.0f ? 1 : -1);
  }
  return sides;
}

/** The side of a keypoint (0, no side, for a keypoint missing from the cluster's point sets). */
int
sideOf (const std::map<pcl::index_t, int>& sides, pcl::index_t k)
{
  const auto found = sides.find (k);
  return found == sides.end() ? 0 : found->second;
}

/** A keypoint's nearest keypoint of another cluster's point sets: which set (0: source, 1:
  * target) and how far (metres).
  */
struct NearestSide
{
  int side = 0;
  float distance = std::numeric_limits<float>::infinity();
};

/** The nearest side of `other` (see NearestSide) of every keypoint in `points`. */
std::map<pcl::index_t, NearestSide>
nearestSides (const pcl::Indices& points,
              const TripletCluster& other,
              const KeypointCloud& keypoints)
{
  std::map<pcl::index_t, NearestSide> sides;
  for (const auto k : points) {
    const Eigen::Vector3f x = position (keypoints, k);
    NearestSide& nearest = sides[k];
    for (const int side : {0, 1})
      for (const auto o : side == 0 ? other.source_indices : other.target_indices) {
        const float d = (position (keypoints, o) - x).norm();
        if (d < nearest.distance)
          nearest = {side, d};
      }
  }
  return sides;
}

/** True if enough keypoints of a point set lie close to each of `other`'s two sets. */
bool
straddles (const std::map<pcl::index_t, NearestSide>& sides)
{
  std::array<std::size_t, 2> close{0, 0};
  for (const auto& entry : sides)
    if (entry.second.distance < kMaxStraddleDistance)
      ++close[static_cast<std::size_t> (entry.second.side)];
  const double needed =
      std::max (static_cast<double> (kMinStraddlingPoints),
                kMinStraddlingFraction * static_cast<double> (sides.size()));
  return static_cast<double> (close[0]) >= needed &&
         static_cast<double> (close[1]) >= needed;
}

/** The groups of a point set that the surface's gaps separate (surfaceGroups()). */
struct SurfaceGroups
{
  /** Group of each keypoint, from 0; -1 for a keypoint without depth at its pixel or in a
    * group of fewer than kMinGroupPoints keypoints.
    */
  std::map<pcl::index_t, int> group_of;
  /** How many groups (of kMinGroupPoints keypoints or more); 0 when the set is not judged
    * (no such group, or more than kMaxSurfaceGroups pieces).
    */
  int count = 0;
};

/** Groups of a point set: keypoints joined by links over which the surface does not fall
  * behind (single linkage). Each keypoint is linked to its kGroupNeighbours nearest ones (3D);
  * the groups still apart are then joined, closest first, where the surface does not fall
  * behind their closest pair across, which costs a walk per pair of groups: a set falling
  * into more than kMaxSurfaceGroups pieces is not judged. Groups are numbered in the order of
  * their first keypoint.
  */
SurfaceGroups
surfaceGroups (const pcl::Indices& points, const KeypointSurface& surface)
{
  // Keypoints with depth at their pixel (the positions the surface test walks between).
  std::vector<pcl::index_t> seen;
  std::vector<Eigen::Vector3f> at;
  for (const pcl::index_t k : points) {
    const auto& p = (*surface.organized)[static_cast<std::size_t> (
        surface.keypoint_pixels[static_cast<std::size_t> (k)])];
    if (std::isfinite (p.x) && std::isfinite (p.y) && std::isfinite (p.z)) {
      seen.push_back (k);
      at.emplace_back (p.getVector3fMap());
    }
  }
  const std::size_t n = seen.size();
  detail::DisjointSets sets (n);
  const auto join = [&] (std::size_t a, std::size_t b) {
    if (sets.find (a) != sets.find (b) &&
        !surfaceDropsBetween (surface, seen[a], seen[b], kMinSurfaceGapDrop))
      sets.unite (a, b);
  };
  std::vector<std::size_t> order (n);
  for (std::size_t a = 0; a < n; ++a) {
    std::iota (order.begin(), order.end(), std::size_t{0});
    const std::size_t nearest = std::min (n, kGroupNeighbours + 1);
    std::partial_sort (order.begin(),
                       order.begin() + static_cast<std::ptrdiff_t> (nearest),
                       order.end(),
                       [&] (std::size_t b, std::size_t c) {
                         return (at[b] - at[a]).squaredNorm() <
                                (at[c] - at[a]).squaredNorm();
                       });
    for (std::size_t m = 0; m < nearest; ++m)
      if (order[m] != a)
        join (a, order[m]);
  }
  SurfaceGroups groups;
  for (const pcl::index_t k : points)
    groups.group_of[k] = -1;
  // The pieces left, numbered; joined, closest first, across their closest pair.
  std::map<std::size_t, std::size_t> piece_of_root;
  std::vector<std::size_t> piece (n);
  for (std::size_t a = 0; a < n; ++a)
    piece[a] =
        piece_of_root.emplace (sets.find (a), piece_of_root.size()).first->second;
  const std::size_t pieces = piece_of_root.size();
  if (pieces > kMaxSurfaceGroups)
    return groups;
  using Pair = std::pair<float, std::pair<std::size_t, std::size_t>>;
  std::vector<Pair> closest (pieces * pieces,
                             {std::numeric_limits<float>::infinity(), {0, 0}});
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b) {
      if (piece[a] == piece[b])
        continue;
      Pair& best = closest[std::min (piece[a], piece[b]) * pieces +
                           std::max (piece[a], piece[b])];
      const float d = (at[a] - at[b]).squaredNorm();
      if (d < best.first)
        best = {d, {a, b}};
    }
  std::sort (closest.begin(), closest.end());
  for (const Pair& pair : closest)
    if (std::isfinite (pair.first))
      join (pair.second.first, pair.second.second);

  std::vector<std::size_t> size (n, 0);
  for (std::size_t a = 0; a < n; ++a)
    ++size[sets.find (a)];
  std::map<std::size_t, int> number;
  for (std::size_t a = 0; a < n; ++a) {
    const std::size_t root = sets.find (a);
    if (size[root] >= kMinGroupPoints)
      groups.group_of[seen[a]] =
          number.emplace (root, static_cast<int> (number.size())).first->second;
  }
  groups.count = static_cast<int> (number.size());
  return groups;
}

} // namespace

std::vector<TripletOrientation>
orientHalfTurnCluster (const TripletCluster& cluster,
                       const std::vector<pcl::Indices>& anchors,
                       const TripletMatches& triplets,
                       const KeypointCloud& keypoints,
                       const KeypointSurface* surface)
{
  const std::size_t smaller =
      std::min (cluster.source_indices.size(), cluster.target_indices.size());
  const float angle =
      Eigen::AngleAxisf (cluster.transformation.topLeftCorner<3, 3>()).angle();
  if (smaller == 0 || !(angle >= kMinHalfTurnAngle) ||
      static_cast<double> (
          detail::sharedKeypoints (cluster.source_indices, cluster.target_indices)
              .size()) < kMinSharedFraction * static_cast<double> (smaller))
    return {};
  const std::map<pcl::index_t, int> sides =
      halfTurnSides (cluster, anchors, keypoints, surface);
  if (sides.empty())
    return {};

  std::vector<TripletOrientation> orientation;
  orientation.reserve (cluster.triplets.size());
  for (std::size_t m = 0; m < cluster.triplets.size(); ++m) {
    const bool reversed = cluster.reversed[m];
    int source_side = 0, target_side = 0;
    bool consistent = true;
    for (const auto& c : triplets[cluster.triplets[m]].correspondences) {
      const int s = sideOf (sides, detail::sourceOf (c, reversed)),
                t = sideOf (sides, detail::targetOf (c, reversed));
      if (source_side == 0)
        source_side = s;
      if (target_side == 0)
        target_side = t;
      consistent =
          consistent && s != 0 && s == source_side && t == target_side && t == -s;
    }
    orientation.push_back (!consistent       ? TripletOrientation::drop
                           : source_side > 0 ? TripletOrientation::keep
                                             : TripletOrientation::reverse);
  }
  return orientation;
}

std::vector<std::vector<std::size_t>>
splitStraddlingCluster (const TripletCluster& cluster,
                        const TripletCluster& other,
                        const TripletMatches& triplets,
                        const KeypointCloud& keypoints)
{
  std::vector<std::size_t> all (cluster.triplets.size());
  std::iota (all.begin(), all.end(), std::size_t{0});
  std::vector<std::vector<std::size_t>> whole{all};
  // Split along the straddling set: its keypoints are the sources, or else the targets.
  const auto source_sides = nearestSides (cluster.source_indices, other, keypoints);
  const bool on_source = straddles (source_sides);
  const auto sides = on_source
                         ? source_sides
                         : nearestSides (cluster.target_indices, other, keypoints);
  if (!on_source && !straddles (sides))
    return whole;

  std::vector<std::vector<std::size_t>> parts (2);
  for (std::size_t m = 0; m < cluster.triplets.size(); ++m) {
    const auto& correspondences = triplets[cluster.triplets[m]].correspondences;
    const auto side = [&] (const pcl::Correspondence& c) {
      const bool reversed = cluster.reversed[m];
      const auto found = sides.find (on_source ? detail::sourceOf (c, reversed)
                                               : detail::targetOf (c, reversed));
      return found == sides.end() ? -1 : found->second.side;
    };
    const int first = side (correspondences.front());
    if (first >= 0 &&
        std::all_of (correspondences.begin(),
                     correspondences.end(),
                     [&] (const pcl::Correspondence& c) { return side (c) == first; }))
      parts[static_cast<std::size_t> (first)].push_back (m);
  }
  // Every triplet across both copies: nothing of the cluster lies on one copy. Whole triplets
  // on one side only: the set may be one object with a repeated print, left alone.
  if (parts[0].empty() && parts[1].empty())
    return {};
  if (parts[0].empty() || parts[1].empty())
    return whole;
  return parts;
}

std::vector<std::vector<std::size_t>>
splitClusterAtSurfaceGaps (const TripletCluster& cluster,
                           const TripletMatches& triplets,
                           const KeypointSurface& surface)
{
  std::vector<std::size_t> all (cluster.triplets.size());
  std::iota (all.begin(), all.end(), std::size_t{0});
  std::vector<std::vector<std::size_t>> whole{all};
  const SurfaceGroups source_groups = surfaceGroups (cluster.source_indices, surface);
  const SurfaceGroups target_groups = surfaceGroups (cluster.target_indices, surface);
  // A set that is not judged (no group of kMinGroupPoints keypoints, or too many pieces) gives
  // no side to any triplet: the cluster stays whole.
  if ((source_groups.count < 2 && target_groups.count < 2) ||
      source_groups.count == 0 || target_groups.count == 0)
    return whole;
  const std::map<pcl::index_t, int>& sources = source_groups.group_of;
  const std::map<pcl::index_t, int>& targets = target_groups.group_of;

  // The part of each (source group, target group) pair, in the order of its first triplet.
  std::map<std::pair<int, int>, std::size_t> part_of;
  std::vector<std::vector<std::size_t>> parts;
  const auto groupOf = [] (const std::map<pcl::index_t, int>& groups, pcl::index_t k) {
    const auto found = groups.find (k);
    return found == groups.end() ? -1 : found->second;
  };
  for (std::size_t m = 0; m < cluster.triplets.size(); ++m) {
    const bool reversed = cluster.reversed[m];
    const auto& correspondences = triplets[cluster.triplets[m]].correspondences;
    const int s = groupOf (sources,
                           detail::sourceOf (correspondences.front(), reversed)),
              t = groupOf (targets,
                           detail::targetOf (correspondences.front(), reversed));
    const bool one_pair =
        s >= 0 && t >= 0 &&
        std::all_of (
            correspondences.begin(), correspondences.end(), [&] (const auto& c) {
              return groupOf (sources, detail::sourceOf (c, reversed)) == s &&
                     groupOf (targets, detail::targetOf (c, reversed)) == t;
            });
    if (!one_pair)
      continue;
    const auto entry = part_of.emplace (std::make_pair (s, t), parts.size());
    if (entry.second)
      parts.emplace_back();
    parts[entry.first->second].push_back (m);
  }
  parts.erase (std::remove_if (parts.begin(),
                               parts.end(),
                               [] (const std::vector<std::size_t>& part) {
                                 return part.size() < kMinPartTriplets;
                               }),
               parts.end());
  return parts;
}

} // namespace mid
