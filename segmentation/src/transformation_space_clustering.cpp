#include "cluster_sets.h"

#include <mid/registration/rigid_transform.h>
#include <mid/segmentation/chain_splitting.h>
#include <mid/segmentation/compound_splitting.h>
#include <mid/segmentation/dbscan.h>
#include <mid/segmentation/transformation_space_clustering.h>
#include <mid/segmentation/triplet_distance.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <set>

namespace mid {

namespace {

using Geometries =
    std::vector<TripletGeometry, Eigen::aligned_allocator<TripletGeometry>>;

/** The six keypoint indices of a triplet: a total order that does not depend on input order. */
std::array<pcl::index_t, 6>
tripletKey (const TripletMatch& t)
{
  std::array<pcl::index_t, 6> key{};
  for (std::size_t k = 0; k < 3; ++k) {
    key[2 * k] = t.correspondences[k].index_query;
    key[2 * k + 1] = t.correspondences[k].index_match;
  }
  return key;
}

/** Pairs, point sets and pose of a cluster from its member triplets. */
void
estimateCluster (const TripletMatches& triplets,
                 TripletCluster& cluster,
                 const KeypointCloud& source,
                 const KeypointCloud& target)
{
  std::set<std::pair<pcl::index_t, pcl::index_t>> pairs;
  for (std::size_t m = 0; m < cluster.triplets.size(); ++m)
    for (const auto& c : triplets[cluster.triplets[m]].correspondences)
      pairs.insert (cluster.reversed[m]
                        ? std::make_pair (c.index_match, c.index_query)
                        : std::make_pair (c.index_query, c.index_match));
  std::set<pcl::index_t> source_set, target_set;
  Eigen::Matrix3Xf from (3, pairs.size()), to (3, pairs.size());
  cluster.correspondences.clear();
  Eigen::Index column = 0;
  for (const auto& [p, q] : pairs) {
    cluster.correspondences.emplace_back (p, q, 0.0f);
    source_set.insert (p);
    target_set.insert (q);
    // Reversed triplets only exist within one frame, where source and target are one cloud.
    from.col (column) = source[static_cast<std::size_t> (p)].getVector3fMap();
    to.col (column++) = target[static_cast<std::size_t> (q)].getVector3fMap();
  }
  cluster.source_indices.assign (source_set.begin(), source_set.end());
  cluster.target_indices.assign (target_set.begin(), target_set.end());
  cluster.transformation = estimateRigidTransform (from, to, &cluster.rms_error);
  for (auto& c : cluster.correspondences) {
    const Eigen::Vector3f p =
        source[static_cast<std::size_t> (c.index_query)].getVector3fMap();
    const Eigen::Vector3f q =
        target[static_cast<std::size_t> (c.index_match)].getVector3fMap();
    c.distance = ((cluster.transformation.topLeftCorner<3, 3>() * p +
                   cluster.transformation.topRightCorner<3, 1>()) -
                  q)
                     .norm();
  }
}

/** The part of a cluster made of some of its triplets (positions in cluster.triplets). */
TripletCluster
makePart (const TripletCluster& cluster,
          const std::vector<std::size_t>& members,
          const TripletMatches& triplets,
          const KeypointCloud& keypoints)
{
  TripletCluster part;
  for (const std::size_t m : members) {
    part.triplets.push_back (cluster.triplets[m]);
    part.reversed.push_back (cluster.reversed[m]);
  }
  estimateCluster (triplets, part, keypoints, keypoints);
  return part;
}

/** Replace clusters[c] by its parts[c] (positions in its triplets): a single part holding
  * every triplet leaves it as it is, no part removes it.
  */
void
replaceByParts (const std::vector<std::vector<std::vector<std::size_t>>>& parts,
                const TripletMatches& triplets,
                const KeypointCloud& keypoints,
                TripletClusters& clusters)
{
  TripletClusters split;
  split.reserve (clusters.size());
  for (std::size_t c = 0; c < clusters.size(); ++c) {
    if (parts[c].size() == 1 &&
        parts[c].front().size() == clusters[c].triplets.size()) {
      split.push_back (std::move (clusters[c]));
      continue;
    }
    for (const auto& members : parts[c])
      split.push_back (makePart (clusters[c], members, triplets, keypoints));
  }
  clusters.swap (split);
}

/** Largest rotation of a cluster that splitChainCluster() may split: rows of copies are
  * related by translations.
  */
constexpr float kMaxChainRotation = static_cast<float> (20.0 * M_PI / 180.0);

/** True if `step` is k times `row` for an integer |k| >= 2, within a quarter of the row's
  * step.
  */
bool
isMultipleOf (const Eigen::Vector3f& step, const Eigen::Vector3f& row)
{
  const float length = row.norm();
  if (!(length > 0.0f))
    return false;
  const float k = std::round (step.dot (row) / (length * length));
  return std::abs (k) >= 2.0f && (step - k * row).norm() < 0.25f * length;
}

/** Replace every cluster that links a row of copies by its parts (splitChainCluster()): first
  * the chains, then, again and numbered along the row's step, every chain whose step is a
  * multiple of another chain's step (copies k -> k + 2 forming a chain of their own: numbered in
  * its own step, copies k and k + 1 fall into one unit, and its parts link pairs of copies). A
  * multiple that is no chain (copies 1, 2 -> 3, 4) stays whole here: its point sets straddle the
  * neighbour pairs, and splitCompounds() splits it by keypoint membership, which does not need an
  * empty gap between touching copies as the numbering does. `surface` (or null) lets the cuts
  * prefer gaps in the surface.
  */
void
splitChains (const TripletMatches& triplets,
             const KeypointCloud& keypoints,
             const KeypointSurface* surface,
             TripletClusters& clusters)
{
  std::vector<std::vector<std::vector<std::size_t>>> parts (clusters.size());
  std::vector<Eigen::Vector3f> rows;
  for (std::size_t c = 0; c < clusters.size(); ++c) {
    parts[c] = splitChainCluster (clusters[c],
                                  triplets,
                                  keypoints,
                                  kMaxChainRotation,
                                  Eigen::Vector3f::Zero(),
                                  surface);
    if (parts[c].size() > 1)
      rows.push_back (chainStep (clusters[c], keypoints));
  }
  for (std::size_t c = 0; c < clusters.size(); ++c) {
    const Eigen::Vector3f step = chainStep (clusters[c], keypoints);
    const auto found =
        std::find_if (rows.begin(), rows.end(), [&step] (const Eigen::Vector3f& row) {
          return isMultipleOf (step, row);
        });
    if (parts[c].size() > 1 && found != rows.end())
      parts[c] = splitChainCluster (
          clusters[c], triplets, keypoints, kMaxChainRotation, *found, surface);
  }
  replaceByParts (parts, triplets, keypoints, clusters);
}

/** Most splits of straddling clusters in one pass (a frame has a few; a bound on the work). */
constexpr std::size_t kMaxStraddleSplits = 64;

/** True if the two point sets of a cluster share no keypoint (they lie on two copies). */
bool
hasDisjointSets (const TripletCluster& cluster)
{
  return detail::sharedKeypoints (cluster.source_indices, cluster.target_indices)
      .empty();
}

/** Split every cluster with a point set that straddles the two copies of another cluster
  * (splitStraddlingCluster()), until none does or kMaxStraddleSplits splits were made; then
  * drop the clusters none of whose triplets lies on one copy. They go last, as they may be the
  * only evidence that splits another straddler (copies 0, 1 -> 2, 3 across both copies of each
  * pair splits 0, 2 -> 1, 3).
  */
void
splitStraddlers (const TripletMatches& triplets,
                 const KeypointCloud& keypoints,
                 TripletClusters& clusters)
{
  // Whether clusters[o] can split clusters[c]: its point sets must lie on two copies.
  const auto splits_along = [&] (std::size_t c, std::size_t o) {
    return o != c && hasDisjointSets (clusters[o]);
  };
  const auto split = [&] (std::size_t c, std::size_t o) {
    return splitStraddlingCluster (clusters[c], clusters[o], triplets, keypoints);
  };
  std::size_t splits = 0;
  bool again = true;
  while (again && splits < kMaxStraddleSplits) {
    again = false;
    for (std::size_t c = 0; c < clusters.size() && !again; ++c)
      for (std::size_t o = 0; o < clusters.size() && !again; ++o) {
        if (!splits_along (c, o))
          continue;
        // Two parts, or one (untouched) or none (dropped below).
        const auto parts = split (c, o);
        if (parts.size() < 2)
          continue;
        TripletClusters pieces;
        for (const auto& members : parts)
          pieces.push_back (makePart (clusters[c], members, triplets, keypoints));
        clusters.erase (clusters.begin() + static_cast<std::ptrdiff_t> (c));
        clusters.insert (clusters.end(), pieces.begin(), pieces.end());
        again = true;
        ++splits;
      }
  }
  if (again) // the last split may have left more to split
    PCL_DEBUG (
        "[mid::TransformationSpaceClustering] Stopped splitting straddling clusters "
        "after %zu splits.\n",
        kMaxStraddleSplits);
  std::vector<bool> across (clusters.size(), false);
  for (std::size_t c = 0; c < clusters.size(); ++c)
    for (std::size_t o = 0; o < clusters.size() && !across[c]; ++o)
      across[c] = splits_along (c, o) && split (c, o).empty();
  TripletClusters kept;
  for (std::size_t c = 0; c < clusters.size(); ++c)
    if (!across[c])
      kept.push_back (std::move (clusters[c]));
  clusters.swap (kept);
}

/** Orient every half-turn cluster from one copy to the other (orientHalfTurnCluster()), with
  * the point sets of the clusters whose sets are disjoint as anchors.
  */
void
orientHalfTurns (const TripletMatches& triplets,
                 const KeypointCloud& keypoints,
                 const KeypointSurface* surface,
                 TripletClusters& clusters)
{
  std::vector<pcl::Indices> anchors;
  for (const auto& cluster : clusters)
    if (hasDisjointSets (cluster)) {
      anchors.push_back (cluster.source_indices);
      anchors.push_back (cluster.target_indices);
    }
  for (auto& cluster : clusters) {
    const std::vector<TripletOrientation> orientation =
        orientHalfTurnCluster (cluster, anchors, triplets, keypoints, surface);
    TripletCluster oriented;
    for (std::size_t m = 0; m < orientation.size(); ++m)
      if (orientation[m] != TripletOrientation::drop) {
        oriented.triplets.push_back (cluster.triplets[m]);
        oriented.reversed.push_back (cluster.reversed[m] !=
                                     (orientation[m] == TripletOrientation::reverse));
      }
    if (!oriented.triplets.empty()) {
      estimateCluster (triplets, oriented, keypoints, keypoints);
      cluster = oriented;
    }
  }
}

/** Replace every cluster whose point sets lie on objects with a gap between them by its parts
  * (splitClusterAtSurfaceGaps()).
  */
void
splitAtSurfaceGaps (const TripletMatches& triplets,
                    const KeypointCloud& keypoints,
                    const KeypointSurface& surface,
                    TripletClusters& clusters)
{
  std::vector<std::vector<std::vector<std::size_t>>> parts;
  parts.reserve (clusters.size());
  for (const auto& cluster : clusters)
    parts.push_back (splitClusterAtSurfaceGaps (cluster, triplets, surface));
  replaceByParts (parts, triplets, keypoints, clusters);
}

/** Make every cluster's point sets lie on one copy each (compound_splitting.h): clusters
  * straddling another are split, half turns oriented (with the point sets of the others as
  * anchors, which must lie on one copy: hence straddlers first), then the oriented half turns
  * may reveal more straddlers; last, given the surface, clusters whose sets lie on objects
  * with a gap between them are split there.
  */
void
splitCompounds (const TripletMatches& triplets,
                const KeypointCloud& keypoints,
                const KeypointSurface* surface,
                TripletClusters& clusters)
{
  splitStraddlers (triplets, keypoints, clusters);
  orientHalfTurns (triplets, keypoints, surface, clusters);
  splitStraddlers (triplets, keypoints, clusters);
  if (surface)
    splitAtSurfaceGaps (triplets, keypoints, *surface, clusters);
}

/** True if most of `other`'s triplets, used reversed, agree with `cluster`'s pose within eps:
  * sum_k |T(q_k) - p_k| + sum_k |T^-1(p_k) - q_k| <= eps for the reversed pairs (q_k -> p_k).
  */
bool
isInverseOf (const TripletCluster& cluster,
             const TripletCluster& other,
             const Geometries& geometry,
             const std::vector<std::size_t>& canonical_of,
             float eps)
{
  const Eigen::Matrix3f rotation = cluster.transformation.topLeftCorner<3, 3>();
  const Eigen::Vector3f translation = cluster.transformation.topRightCorner<3, 1>();
  std::size_t agreeing = 0;
  for (std::size_t m = 0; m < other.triplets.size(); ++m) {
    const TripletGeometry& g = geometry[canonical_of[other.triplets[m]]];
    const TripletGeometry r = other.reversed[m] ? g : invertTripletGeometry (g);
    const float error =
        ((rotation * r.p).colwise() + translation - r.q).colwise().norm().sum() +
        ((rotation.transpose() * (r.q.colwise() - translation)) - r.p)
            .colwise()
            .norm()
            .sum();
    agreeing += error <= eps ? 1 : 0;
  }
  return 2 * agreeing >= other.triplets.size();
}

/** Calls visit (j, distance) for every j != i within eps of triplet i (paper's distance), after
  * skipping the pairs whose exact centroid lower bound is already beyond eps.
  */
template <typename Visit>
void
forEachNeighbor (const Geometries& geometry,
                 std::size_t i,
                 std::size_t first,
                 float eps,
                 Visit visit)
{
  for (std::size_t j = first; j < geometry.size(); ++j) {
    if (j == i || tripletDistanceLowerBound (geometry[i], geometry[j]) > eps)
      continue;
    const float distance = tripletDistance (geometry[i], geometry[j]);
    if (distance <= eps)
      visit (j, static_cast<double> (distance));
  }
}

/** DBSCAN's region query. The distance is symmetric, so each pair is evaluated once and both
  * neighbour lists are stored, unless they would exceed max_stored entries; then each query
  * scans all triplets (the same result, about four times the work).
  */
DBSCAN::RegionQuery
makeRegionQuery (const Geometries& geometry, float eps, std::size_t max_stored)
{
  auto table =
      std::make_shared<std::vector<std::vector<DBSCAN::Neighbor>>> (geometry.size());
  std::size_t stored = 0;
  for (std::size_t i = 0; i < geometry.size() && stored <= max_stored; ++i)
    forEachNeighbor (geometry, i, i + 1, eps, [&] (std::size_t j, double distance) {
      (*table)[i].emplace_back (j, distance);
      (*table)[j].emplace_back (i, distance);
      stored += 2;
    });
  if (stored <= max_stored)
    return [table] (std::size_t i, std::vector<DBSCAN::Neighbor>& out) {
      out = (*table)[i];
    };
  table.reset();
  return [&geometry, eps] (std::size_t i, std::vector<DBSCAN::Neighbor>& out) {
    out.clear();
    forEachNeighbor (geometry, i, 0, eps, [&out] (std::size_t j, double distance) {
      out.emplace_back (j, distance);
    });
  };
}

} // namespace

void
TransformationSpaceClustering::setInputTriplets (const TripletMatchesConstPtr& triplets)
{
  triplets_ = triplets;
  auto correspondences = pcl::make_shared<pcl::Correspondences>();
  if (triplets)
    for (const auto& t : *triplets)
      correspondences->insert (
          correspondences->end(), t.correspondences.begin(), t.correspondences.end());
  model_scene_corrs_ = correspondences;
}

void
TransformationSpaceClustering::setModelSceneCorrespondences (
    const pcl::CorrespondencesConstPtr& correspondences)
{
  model_scene_corrs_ = correspondences;
  triplets_.reset();
}

bool
TransformationSpaceClustering::checkInputs (const TripletMatches& triplets) const
{
  const char* name = "[mid::TransformationSpaceClustering::cluster]";
  if (!(eps_ > 0.0f) || min_cluster_size_ < 1) {
    PCL_ERROR ("%s Invalid parameter: cluster distance %g (> 0), min cluster size %zu "
               "(>= 1).\n",
               name,
               static_cast<double> (eps_),
               min_cluster_size_);
    return false;
  }
  if (input_->empty() || scene_->empty()) {
    PCL_ERROR ("%s The model or scene keypoint cloud is empty.\n", name);
    return false;
  }
  if (surface_.organized && !isValidKeypointSurface (surface_, input_->size())) {
    PCL_ERROR (
        "%s The keypoint surface is not organized or does not give a pixel inside it "
        "for each of the %zu keypoints (%zu given).\n",
        name,
        input_->size(),
        surface_.keypoint_pixels.size());
    return false;
  }
  for (std::size_t i = 0; i < triplets.size(); ++i) {
    if (!triplets[i].transformation.allFinite()) {
      PCL_ERROR ("%s Triplet %zu has a non-finite pose.\n", name, i);
      return false;
    }
    for (const auto& c : triplets[i].correspondences)
      if (c.index_query < 0 ||
          static_cast<std::size_t> (c.index_query) >= input_->size() ||
          c.index_match < 0 ||
          static_cast<std::size_t> (c.index_match) >= scene_->size() ||
          !(*input_)[static_cast<std::size_t> (c.index_query)]
               .getVector3fMap()
               .allFinite() ||
          !(*scene_)[static_cast<std::size_t> (c.index_match)]
               .getVector3fMap()
               .allFinite()) {
        PCL_ERROR ("%s Triplet %zu refers to keypoint %d -> %d, which is missing or "
                   "not finite.\n",
                   name,
                   i,
                   c.index_query,
                   c.index_match);
        return false;
      }
  }
  return true;
}

void
TransformationSpaceClustering::clusterCorrespondences (
    std::vector<pcl::Correspondences>& clustered_corrs)
{
  clustered_corrs.clear();
  clusters_.clear();
  used_triplets_.clear();
  const bool one_frame = input_ == scene_;
  if (triplets_)
    used_triplets_ = *triplets_;
  else {
    CorrespondenceRejectorPPFTriplet::Ptr rejector =
        rejector_ ? rejector_ : std::make_shared<CorrespondenceRejectorPPFTriplet>();
    rejector->setInputSource (input_);
    rejector->setInputTarget (one_frame ? nullptr : scene_);
    pcl::Correspondences remaining;
    rejector->getRemainingCorrespondences (*model_scene_corrs_, remaining);
    used_triplets_ = rejector->getTripletMatches();
  }
  if (!checkInputs (used_triplets_)) {
    used_triplets_.clear();
    return;
  }

  // Canonical order: sorted by keypoint indices, so the result ignores the input order.
  const std::size_t n = used_triplets_.size();
  std::vector<std::size_t> order (n), canonical_of (n);
  std::iota (order.begin(), order.end(), std::size_t{0});
  std::sort (order.begin(), order.end(), [this] (std::size_t a, std::size_t b) {
    return tripletKey (used_triplets_[a]) < tripletKey (used_triplets_[b]);
  });
  Geometries geometry (n);
  for (std::size_t k = 0; k < n; ++k) {
    canonical_of[order[k]] = k;
    geometry[k] = makeTripletGeometry (used_triplets_[order[k]], *input_, *scene_);
  }

  const DBSCAN::RegionQuery query =
      makeRegionQuery (geometry, eps_, max_stored_neighbors_);
  DBSCAN dbscan;
  dbscan.setMinSamples (min_cluster_size_);
  std::vector<int> labels;
  const std::size_t count = dbscan.cluster (n, query, labels);

  TripletClusters clusters (count);
  for (std::size_t k = 0; k < n; ++k)
    if (labels[k] >= 0) {
      clusters[static_cast<std::size_t> (labels[k])].triplets.push_back (order[k]);
      clusters[static_cast<std::size_t> (labels[k])].reversed.push_back (false);
    }
  for (auto& cluster : clusters)
    estimateCluster (used_triplets_, cluster, *input_, *scene_);

  const auto larger = [&canonical_of] (const TripletCluster& a,
                                       const TripletCluster& b) {
    if (a.triplets.size() != b.triplets.size())
      return a.triplets.size() > b.triplets.size();
    return canonical_of[a.triplets.front()] < canonical_of[b.triplets.front()];
  };
  std::sort (clusters.begin(), clusters.end(), larger);

  if (merge_inverse_ && one_frame) {
    std::vector<bool> merged (clusters.size(), false);
    for (std::size_t i = 0; i < clusters.size(); ++i) {
      if (merged[i])
        continue;
      for (std::size_t j = i + 1; j < clusters.size(); ++j) {
        if (merged[j] ||
            !isInverseOf (clusters[i], clusters[j], geometry, canonical_of, eps_))
          continue;
        for (std::size_t m = 0; m < clusters[j].triplets.size(); ++m) {
          clusters[i].triplets.push_back (clusters[j].triplets[m]);
          clusters[i].reversed.push_back (!clusters[j].reversed[m]);
        }
        estimateCluster (used_triplets_, clusters[i], *input_, *scene_);
        merged[j] = true;
      }
    }
    TripletClusters kept;
    for (std::size_t i = 0; i < clusters.size(); ++i)
      if (!merged[i])
        kept.push_back (clusters[i]);
    clusters.swap (kept);
    std::sort (clusters.begin(), clusters.end(), larger);
  }
  if (split_chains_ && one_frame) {
    splitChains (
        used_triplets_, *input_, surface_.organized ? &surface_ : nullptr, clusters);
    std::sort (clusters.begin(), clusters.end(), larger);
  }
  if (split_compounds_ && one_frame) {
    splitCompounds (
        used_triplets_, *input_, surface_.organized ? &surface_ : nullptr, clusters);
    std::sort (clusters.begin(), clusters.end(), larger);
  }

  clusters_ = clusters;
  for (const auto& cluster : clusters_)
    clustered_corrs.push_back (cluster.correspondences);
}

void
TransformationSpaceClustering::cluster (
    std::vector<pcl::Correspondences>& clustered_corrs)
{
  clusters_.clear();
  used_triplets_.clear();
  pcl::CorrespondenceGrouping<pcl::PointNormal, pcl::PointNormal>::cluster (
      clustered_corrs);
}

void
TransformationSpaceClustering::recognize (
    Transformations& transformations,
    std::vector<pcl::Correspondences>& clustered_corrs)
{
  transformations.clear();
  cluster (clustered_corrs);
  for (const auto& c : clusters_)
    transformations.push_back (c.transformation);
}

void
TransformationSpaceClustering::recognize (Transformations& transformations)
{
  std::vector<pcl::Correspondences> clustered_corrs;
  recognize (transformations, clustered_corrs);
}

} // namespace mid
