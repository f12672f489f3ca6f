#include "cluster_triplets.h"
#include "plate_surface.h"
#include "rigid_motion.h"

#include <mid/registration/triplet_match.h>
#include <mid/segmentation/compound_splitting.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <memory>
#include <random>
#include <set>
#include <utility>

namespace {

constexpr int kPoints = 40;

/** Copies of one carton-like object (40 keypoints on a 6 x 1 x 18 cm slab, long along the
  * viewing direction), placed by the caller, and triplet matches between copies.
  */
struct Copies
{
  /** Add a copy at `pose` (object frame -> camera); returns its number. */
  int
  add (const Eigen::Isometry3f& pose)
  {
    std::mt19937 rng (5);
    std::uniform_real_distribution<float> x (0.005f, 0.065f), y (-0.005f, 0.005f),
        z (-0.09f, 0.09f);
    for (int i = 0; i < kPoints; ++i) {
      Eigen::Vector3f local;
      // One draw per statement: the same points with every compiler.
      local.x() = x (rng);
      local.y() = y (rng);
      local.z() = z (rng);
      pcl::PointNormal point;
      point.getVector3fMap() = pose * local;
      keypoints->push_back (point);
    }
    poses.push_back (pose);
    return static_cast<int> (poses.size()) - 1;
  }

  /** Keypoint i of copy k. */
  static int
  index (int k, int i)
  {
    return k * kPoints + i;
  }

  /** The copy a keypoint lies on. */
  static int
  copyOf (pcl::index_t k)
  {
    return static_cast<int> (k) / kPoints;
  }

  /** Triplets linking points i, i+1, i+2 of copy `from` to the same points of copy `to`
    * (every second one stored the other way round, as self-matches come either way), added
    * to `cluster` (its point sets and pose are left to finish()). If `middle` names two
    * copies, the middle point of each triplet is taken from copy middle.first and matched to
    * copy middle.second instead: a triangle across two copies (with {to, from}, one that a
    * half turn swapping them maps onto itself).
    */
  void
  link (int from,
        int to,
        mid::TripletCluster& cluster,
        std::pair<int, int> middle = {-1, -1})
  {
    const Eigen::Matrix4f motion = (poses[to] * poses[from].inverse()).matrix();
    for (int i = 0; i + 2 < kPoints; ++i) {
      mid::TripletMatch triplet;
      for (int c = 0; c < 3; ++c) {
        const bool across = middle.first >= 0 && c == 1;
        const int a = index (across ? middle.first : from, i + c),
                  b = index (across ? middle.second : to, i + c);
        triplet.correspondences[static_cast<std::size_t> (c)] =
            i % 2 == 0 ? pcl::Correspondence (a, b, 0.0f)
                       : pcl::Correspondence (b, a, 0.0f);
      }
      triplet.transformation = i % 2 == 0 ? motion : Eigen::Matrix4f (motion.inverse());
      cluster.triplets.push_back (triplets->size());
      cluster.reversed.push_back (i % 2 != 0);
      cluster.transformation = motion;
      triplets->push_back (triplet);
    }
  }

  /** Fill a cluster's point sets from its triplets. */
  void
  finish (mid::TripletCluster& cluster) const
  {
    std::set<pcl::index_t> sources, targets;
    for (std::size_t m = 0; m < cluster.triplets.size(); ++m)
      for (const auto& c : (*triplets)[cluster.triplets[m]].correspondences) {
        sources.insert (cluster.reversed[m] ? c.index_match : c.index_query);
        targets.insert (cluster.reversed[m] ? c.index_query : c.index_match);
      }
    cluster.source_indices.assign (sources.begin(), sources.end());
    cluster.target_indices.assign (targets.begin(), targets.end());
  }

  mid::KeypointCloud::Ptr keypoints = pcl::make_shared<mid::KeypointCloud>();
  std::shared_ptr<mid::TripletMatches> triplets =
      std::make_shared<mid::TripletMatches>();
  std::vector<Eigen::Isometry3f, Eigen::aligned_allocator<Eigen::Isometry3f>> poses;
};

/** The copies a point set lies on. */
std::set<int>
copiesOf (const pcl::Indices& points)
{
  std::set<int> copies;
  for (const auto k : points)
    copies.insert (Copies::copyOf (k));
  return copies;
}

/** The copies the sources and the targets of a half-turn cluster's triplets lie on once
  * oriented (dropped triplets left out).
  */
std::pair<std::set<int>, std::set<int>>
orientedCopies (const Copies& scene,
                const mid::TripletCluster& cluster,
                const std::vector<mid::TripletOrientation>& orientation)
{
  std::pair<std::set<int>, std::set<int>> copies;
  for (std::size_t m = 0; m < orientation.size(); ++m) {
    if (orientation[m] == mid::TripletOrientation::drop)
      continue;
    const bool reversed =
        cluster.reversed[m] != (orientation[m] == mid::TripletOrientation::reverse);
    for (const auto& c : (*scene.triplets)[cluster.triplets[m]].correspondences) {
      copies.first.insert (Copies::copyOf (reversed ? c.index_match : c.index_query));
      copies.second.insert (Copies::copyOf (reversed ? c.index_query : c.index_match));
    }
  }
  return copies;
}

/** The copies each cluster's source and target sets lie on. */
using Links = std::set<std::pair<std::set<int>, std::set<int>>>;

/** The links of the clusters the clusterer makes of all the scene's triplets. */
Links
clusteredLinks (const Copies& scene)
{
  Links links;
  for (const auto& cluster :
       mid::test::clusterTriplets (scene.keypoints, scene.triplets))
    links.emplace (copiesOf (cluster.source_indices),
                   copiesOf (cluster.target_indices));
  return links;
}

/** The frame the camera sees of `plates` above a floor at height floor_y (renderPlates()),
  * with the pixel of each of the scene's keypoints.
  */
mid::KeypointSurface
seenOnPlates (const Copies& scene,
              const std::vector<mid::test::Plate>& plates,
              float floor_y)
{
  mid::KeypointSurface seen{mid::test::renderPlates (plates, floor_y), {}};
  for (const auto& k : *scene.keypoints)
    seen.keypoint_pixels.push_back (mid::test::plateSurfacePixel (k.getVector3fMap()));
  return seen;
}

/** Copy 0 lying at 0.9 m, copy 1 turned about the vertical through its long edge: the two lie
  * side by side, head to tail, and the half turn maps each onto the other.
  */
const Eigen::Isometry3f kFirst =
    mid::test::rigidMotion (Eigen::Vector3f (0.0f, 0.1f, 0.9f));
const Eigen::Isometry3f kHalfTurn =
    kFirst * mid::test::rigidMotion (Eigen::Vector3f::Zero(),
                                     static_cast<float> (M_PI),
                                     Eigen::Vector3f::UnitY());
/** A third copy 30 cm to the side of copy 0, same heading. */
const Eigen::Isometry3f kThird =
    mid::test::rigidMotion (Eigen::Vector3f (0.3f, 0.1f, 0.9f));

/** Copies 0 and 1 head to tail side by side (kHalfTurn), copy 2 further to the side. */
Copies
headToTail ()
{
  Copies scene;
  scene.add (kFirst);
  scene.add (kHalfTurn);
  scene.add (kThird);
  return scene;
}

/** Copies 0 and 1 touching side by side, and 2 and 3 the same pair 30 cm further. */
Copies
pairOfPairs ()
{
  Copies scene;
  const Eigen::Isometry3f next =
      mid::test::rigidMotion (Eigen::Vector3f (0.07f, 0.0f, 0.0f));
  const Eigen::Isometry3f further =
      mid::test::rigidMotion (Eigen::Vector3f (0.3f, 0.0f, 0.0f));
  scene.add (kFirst);
  scene.add (next * kFirst);
  scene.add (further * kFirst);
  scene.add (further * next * kFirst);
  return scene;
}

} // namespace

TEST (CompoundSplitting, OrientsAHalfTurnFromOneCopyToTheOther)
{
  Copies scene = headToTail();
  mid::TripletCluster half_turn, anchor;
  scene.link (0, 1, half_turn);
  scene.link (1, 0, half_turn);
  const std::size_t straight = half_turn.triplets.size();
  scene.link (0, 1, half_turn, {1, 0});
  scene.finish (half_turn);
  scene.link (0, 2, anchor);
  scene.finish (anchor);
  // The paper's cluster: each point set spans both copies.
  ASSERT_EQ (copiesOf (half_turn.source_indices), (std::set<int>{0, 1}));

  // The anchor (copy 0's points matched to copy 2) is needed: a plane across both cartons
  // agrees with the half turn too (and cuts fewer links between neighbouring keypoints).
  const auto orientation = mid::orientHalfTurnCluster (
      half_turn, {anchor.source_indices}, *scene.triplets, *scene.keypoints);
  ASSERT_EQ (orientation.size(), half_turn.triplets.size());
  for (std::size_t m = 0; m < orientation.size(); ++m)
    EXPECT_EQ (orientation[m] == mid::TripletOrientation::drop, m >= straight) << m;
  const auto [source_copies, target_copies] =
      orientedCopies (scene, half_turn, orientation);
  EXPECT_EQ (source_copies.size(), 1u);
  EXPECT_EQ (target_copies.size(), 1u);
  EXPECT_NE (source_copies, target_copies);
}

/** Two copies 20 cm apart: copy 1 is copy 0 turned about a vertical axis 10 cm beside it (no
  * keypoint of one is a neighbour of the other, so the plane between them cuts no link), and
  * the half-turn cluster between them with no third copy to anchor it.
  */
struct CopiesApart
{
  CopiesApart()
  {
    scene.add (kFirst);
    scene.add (mid::test::rigidMotion (Eigen::Vector3f (-0.2f, 0.0f, 0.0f)) *
               kHalfTurn);
    scene.link (0, 1, half_turn);
    scene.link (1, 0, half_turn);
    scene.finish (half_turn);
  }

  /** The keypoints seen on `plates` (their tops at the copies' upper face, y = 9.5 cm) above
    * a floor 2.5 cm lower.
    */
  mid::KeypointSurface
  surface (const std::vector<mid::test::Plate>& plates) const
  {
    return seenOnPlates (scene, plates, 0.12f);
  }

  /** The copies' upper faces: 1 cm wider on each side than their keypoints (x in [0.5, 6.5]
    * cm and z in [81, 99] cm for copy 0, 20 cm to the left for copy 1), so that every
    * keypoint's pixel shows its own copy.
    */
  static constexpr mid::test::Plate kCopy0{-0.005f, 0.075f, 0.80f, 1.0f, 0.095f},
      kCopy1{-0.275f, -0.195f, 0.80f, 1.0f, 0.095f};

  Copies scene;
  mid::TripletCluster half_turn;
};

TEST (CompoundSplitting, OrientsAHalfTurnBetweenCopiesApartWithoutAnAnchor)
{
  // The surface shows the floor between the copies: no third copy is needed to tell them
  // apart.
  const CopiesApart apart;
  ASSERT_EQ (copiesOf (apart.half_turn.source_indices), (std::set<int>{0, 1}));
  const mid::KeypointSurface surface =
      apart.surface ({CopiesApart::kCopy0, CopiesApart::kCopy1});
  ASSERT_TRUE (mid::isValidKeypointSurface (surface, apart.scene.keypoints->size()));

  const auto orientation = mid::orientHalfTurnCluster (
      apart.half_turn, {}, *apart.scene.triplets, *apart.scene.keypoints, &surface);
  ASSERT_EQ (orientation.size(), apart.half_turn.triplets.size());
  EXPECT_EQ (std::count (
                 orientation.begin(), orientation.end(), mid::TripletOrientation::drop),
             0);
  const auto [source_copies, target_copies] =
      orientedCopies (apart.scene, apart.half_turn, orientation);
  EXPECT_EQ (source_copies.size(), 1u);
  EXPECT_EQ (target_copies.size(), 1u);
  EXPECT_NE (source_copies, target_copies);

  // Without a surface only an anchor could confirm the plane.
  EXPECT_TRUE (mid::orientHalfTurnCluster (
                   apart.half_turn, {}, *apart.scene.triplets, *apart.scene.keypoints)
                   .empty());
}

TEST (CompoundSplitting, LeavesTwoPatchesOfOneSurfaceAlone)
{
  // The same keypoints on one object: its print repeats after a half turn, in two patches
  // with 21 cm free of keypoints between them. Its surface runs on between the patches.
  const CopiesApart patches;
  const mid::KeypointSurface one_object = patches.surface (
      {{CopiesApart::kCopy1.x_min, CopiesApart::kCopy0.x_max, 0.80f, 1.0f, 0.095f}});
  EXPECT_TRUE (mid::orientHalfTurnCluster (patches.half_turn,
                                           {},
                                           *patches.scene.triplets,
                                           *patches.scene.keypoints,
                                           &one_object)
                   .empty());
}

TEST (CompoundSplitting, LeavesAHalfTurnWithoutAnAnchorOnOneSideAlone)
{
  // Copies 0 and 1 as the two halves of one symmetric object, matched whole to the same
  // object elsewhere (copies 2 and 3): the anchor spans both sides of every plane.
  Copies scene;
  scene.add (kFirst);
  scene.add (kHalfTurn);
  const Eigen::Isometry3f away =
      mid::test::rigidMotion (Eigen::Vector3f (0.3f, 0.0f, 0.0f));
  scene.add (away * kFirst);
  scene.add (away * kHalfTurn);
  mid::TripletCluster half_turn, whole;
  scene.link (0, 1, half_turn);
  scene.link (1, 0, half_turn);
  scene.finish (half_turn);
  scene.link (0, 2, whole);
  scene.link (1, 3, whole);
  scene.finish (whole);
  EXPECT_TRUE (mid::orientHalfTurnCluster (
                   half_turn, {whole.source_indices}, *scene.triplets, *scene.keypoints)
                   .empty());
  // Without any anchor nothing tells the copies apart either.
  EXPECT_TRUE (
      mid::orientHalfTurnCluster (half_turn, {}, *scene.triplets, *scene.keypoints)
          .empty());
}

TEST (CompoundSplitting, DropsTripletsOutsideTheClustersPointSets)
{
  // A cluster whose point sets do not list all its triplets' keypoints (not what the clusterer
  // makes): those triplets take no side and are dropped, nothing throws.
  Copies scene = headToTail();
  mid::TripletCluster half_turn, anchor;
  scene.link (0, 1, half_turn);
  scene.link (1, 0, half_turn);
  scene.finish (half_turn);
  scene.link (0, 2, anchor);
  scene.finish (anchor);
  const pcl::index_t missing = half_turn.source_indices.front();
  for (auto* set : {&half_turn.source_indices, &half_turn.target_indices})
    set->erase (std::remove (set->begin(), set->end(), missing), set->end());
  const auto orientation = mid::orientHalfTurnCluster (
      half_turn, {anchor.source_indices}, *scene.triplets, *scene.keypoints);
  ASSERT_EQ (orientation.size(), half_turn.triplets.size());
  for (std::size_t m = 0; m < orientation.size(); ++m) {
    bool uses_missing = false;
    for (const auto& c : (*scene.triplets)[half_turn.triplets[m]].correspondences)
      uses_missing =
          uses_missing || c.index_query == missing || c.index_match == missing;
    if (uses_missing) {
      EXPECT_EQ (orientation[m], mid::TripletOrientation::drop) << m;
    }
  }
}

TEST (CompoundSplitting, LeavesOtherClustersAlone)
{
  Copies scene = headToTail();
  // A translation, and a half turn seen in one direction only (its point sets are disjoint).
  mid::TripletCluster translation, one_way;
  scene.link (0, 2, translation);
  scene.finish (translation);
  scene.link (0, 1, one_way);
  scene.finish (one_way);
  for (const auto& cluster : {translation, one_way})
    EXPECT_TRUE (
        mid::orientHalfTurnCluster (cluster, {}, *scene.triplets, *scene.keypoints)
            .empty());
}

TEST (CompoundSplitting, SplitsAPairOfPairsAlongTheOtherCluster)
{
  Copies scene = pairOfPairs();
  mid::TripletCluster neighbours, pairs, single;
  scene.link (0, 1, neighbours);
  scene.finish (neighbours);
  scene.link (0, 2, pairs);
  scene.link (1, 3, pairs);
  scene.finish (pairs);
  scene.link (0, 2, single);
  scene.finish (single);

  const auto parts = mid::splitStraddlingCluster (
      pairs, neighbours, *scene.triplets, *scene.keypoints);
  ASSERT_EQ (parts.size(), 2u);
  std::set<std::set<int>> found;
  for (const auto& part : parts) {
    std::set<int> copies;
    for (const std::size_t m : part)
      for (const auto& c : (*scene.triplets)[pairs.triplets[m]].correspondences)
        copies.insert (
            {Copies::copyOf (c.index_query), Copies::copyOf (c.index_match)});
    found.insert (copies);
  }
  EXPECT_EQ (found, (std::set<std::set<int>>{{0, 2}, {1, 3}}));
  // A keypoint missing from the point set (not what the clusterer makes): its triplets take
  // no side, the others split as before, nothing throws.
  mid::TripletCluster incomplete = pairs;
  incomplete.source_indices.erase (incomplete.source_indices.begin());
  const auto incomplete_parts = mid::splitStraddlingCluster (
      incomplete, neighbours, *scene.triplets, *scene.keypoints);
  ASSERT_EQ (incomplete_parts.size(), 2u);
  EXPECT_LT (incomplete_parts[0].size() + incomplete_parts[1].size(),
             parts[0].size() + parts[1].size());
  // A cluster between two single copies is left whole.
  EXPECT_EQ (mid::splitStraddlingCluster (
                 single, neighbours, *scene.triplets, *scene.keypoints)
                 .size(),
             1u);
}

TEST (CompoundSplitting, DropsAPairOfPairsWhoseTrianglesSpanBothCopies)
{
  // Lying cans touching in pairs: every triangle of the cluster 0, 1 -> 2, 3 has a corner on
  // each copy of its pair, so no part of it lies on one copy.
  Copies scene = pairOfPairs();
  mid::TripletCluster neighbours, across;
  scene.link (0, 1, neighbours);
  scene.finish (neighbours);
  scene.link (0, 2, across, {1, 3});
  scene.finish (across);
  ASSERT_EQ (copiesOf (across.source_indices), (std::set<int>{0, 1}));
  EXPECT_TRUE (mid::splitStraddlingCluster (
                   across, neighbours, *scene.triplets, *scene.keypoints)
                   .empty());
  // The clusterer drops it, after it has split the pair of pairs 0, 2 -> 1, 3 along it.
  mid::TripletCluster unused;
  scene.link (2, 3, unused);
  EXPECT_EQ (clusteredLinks (scene), (Links{{{0}, {1}}, {{2}, {3}}}));
}

TEST (CompoundSplitting, LeavesAStraddlerWithWholeTrianglesOnOneSideOnlyWhole)
{
  // Copy 0 -> 2 plus triangles across copies 0, 1 -> 2, 3: only copy 0's side holds whole
  // triangles. Such a set may be one object whose print repeats (the other cluster's two sets
  // then lie on it): nothing is cut.
  Copies scene = pairOfPairs();
  mid::TripletCluster neighbours, mixed;
  scene.link (0, 1, neighbours);
  scene.finish (neighbours);
  scene.link (0, 2, mixed);
  scene.link (0, 2, mixed, {1, 3});
  scene.finish (mixed);
  const auto parts = mid::splitStraddlingCluster (
      mixed, neighbours, *scene.triplets, *scene.keypoints);
  ASSERT_EQ (parts.size(), 1u);
  EXPECT_EQ (parts.front().size(), mixed.triplets.size());
}

TEST (CompoundSplitting, TheClustererLeavesEachPointSetOnOneCopy)
{
  Copies scene = headToTail();
  mid::TripletCluster unused;
  scene.link (0, 1, unused);
  scene.link (1, 0, unused);
  scene.link (0, 2, unused);
  for (const bool split : {false, true}) {
    const mid::TripletClusters clusters =
        mid::test::clusterTriplets (scene.keypoints, scene.triplets, true, split);
    ASSERT_EQ (clusters.size(), 2u);
    std::size_t compound = 0;
    for (const auto& cluster : clusters) {
      // Every triplet stays: 38 each way between copies 0 and 1, 38 from 0 to 2.
      EXPECT_EQ (cluster.triplets.size(),
                 static_cast<std::size_t> (copiesOf (cluster.target_indices).count (2)
                                               ? kPoints - 2
                                               : 2 * (kPoints - 2)));
      if (copiesOf (cluster.source_indices).size() > 1 ||
          copiesOf (cluster.target_indices).size() > 1)
        ++compound;
    }
    // The paper's clusterer keeps the half turn's point sets on both copies.
    EXPECT_EQ (compound, split ? 0u : 1u) << "split " << split;
  }
}

TEST (CompoundSplitting, TheClustererSplitsAPairOfPairs)
{
  // The clusters 0, 1 -> 2, 3 and 0, 2 -> 1, 3 each link two copies to two, and split each
  // other.
  Copies scene = pairOfPairs();
  mid::TripletCluster unused;
  scene.link (0, 1, unused);
  scene.link (2, 3, unused);
  scene.link (0, 2, unused);
  scene.link (1, 3, unused);
  EXPECT_EQ (clusteredLinks (scene),
             (Links{{{0}, {1}}, {{2}, {3}}, {{0}, {2}}, {{1}, {3}}}));
}

namespace {

/** Four copies in a row along x, 12 cm apart, 30 cm below the camera (seen from above at
  * about 18 degrees), and what the camera sees of them.
  */
struct RowApart
{
  RowApart()
  {
    for (int k = 0; k < 4; ++k)
      scene.add (mid::test::rigidMotion (
          Eigen::Vector3f (step * static_cast<float> (k) - 0.18f, 0.3f, 0.9f)));
  }

  /** The keypoints seen on `plates` (at the copies' upper face, y = 29.5 cm) above a floor
    * 5 cm lower.
    */
  mid::KeypointSurface
  surface (const std::vector<mid::test::Plate>& plates) const
  {
    return seenOnPlates (scene, plates, 0.345f);
  }

  /** The upper face under copies first to last, 1.5 cm wider on each side than their
    * keypoints (every keypoint's pixel shows its own copy; 3 cm of floor between neighbours
    * on two faces).
    */
  static mid::test::Plate
  face (int first, int last)
  {
    return {step * static_cast<float> (first) - 0.19f,
            step * static_cast<float> (last) - 0.10f,
            0.75f,
            1.05f,
            0.295f};
  }

  /** Each copy on its own face. */
  mid::KeypointSurface
  copiesApart () const
  {
    return surface ({face (0, 0), face (1, 1), face (2, 2), face (3, 3)});
  }

  /** One face under all four: the same keypoints on a single object. */
  mid::KeypointSurface
  oneObject () const
  {
    return surface ({face (0, 3)});
  }

  /** The cluster 0, 1 -> 2, 3: one pose, each point set on two copies. */
  mid::TripletCluster
  everySecondCopy ()
  {
    mid::TripletCluster pairs;
    scene.link (0, 2, pairs);
    scene.link (1, 3, pairs);
    scene.finish (pairs);
    return pairs;
  }

  /** The copies each part's sources and targets lie on. */
  std::set<std::pair<std::set<int>, std::set<int>>>
  partCopies (const mid::TripletCluster& cluster,
              const std::vector<std::vector<std::size_t>>& parts) const
  {
    std::set<std::pair<std::set<int>, std::set<int>>> found;
    for (const auto& part : parts) {
      std::pair<std::set<int>, std::set<int>> copies;
      for (const std::size_t m : part)
        for (const auto& c : (*scene.triplets)[cluster.triplets[m]].correspondences) {
          const bool reversed = cluster.reversed[m];
          copies.first.insert (
              Copies::copyOf (reversed ? c.index_match : c.index_query));
          copies.second.insert (
              Copies::copyOf (reversed ? c.index_query : c.index_match));
        }
      found.insert (copies);
    }
    return found;
  }

  /** What the parts of everySecondCopy() link: 0 -> 2 and 1 -> 3. */
  static inline const std::set<std::pair<std::set<int>, std::set<int>>>
      kEverySecondCopy{{{0}, {2}}, {{1}, {3}}};

  static constexpr float step = 0.12f;
  Copies scene;
};

} // namespace

TEST (CompoundSplitting, SplitsEverySecondCopyOfARowApartAtTheSurfaceGaps)
{
  // Copies 0, 1 -> 2, 3: one pose, each point set on two copies with the floor between them.
  RowApart row;
  const mid::TripletCluster pairs = row.everySecondCopy();
  ASSERT_EQ (copiesOf (pairs.source_indices), (std::set<int>{0, 1}));
  const mid::KeypointSurface apart = row.copiesApart();
  ASSERT_TRUE (mid::isValidKeypointSurface (apart, row.scene.keypoints->size()));

  const auto parts = mid::splitClusterAtSurfaceGaps (pairs, *row.scene.triplets, apart);
  ASSERT_EQ (parts.size(), 2u);
  EXPECT_EQ (parts[0].size() + parts[1].size(), pairs.triplets.size());
  EXPECT_EQ (row.partCopies (pairs, parts), RowApart::kEverySecondCopy);

  // The same keypoints on one object: no gap, nothing is cut.
  const auto whole =
      mid::splitClusterAtSurfaceGaps (pairs, *row.scene.triplets, row.oneObject());
  ASSERT_EQ (whole.size(), 1u);
  EXPECT_EQ (whole.front().size(), pairs.triplets.size());

  // A cluster between two single copies is left whole.
  mid::TripletCluster single;
  row.scene.link (0, 2, single);
  row.scene.finish (single);
  const auto single_parts =
      mid::splitClusterAtSurfaceGaps (single, *row.scene.triplets, apart);
  ASSERT_EQ (single_parts.size(), 1u);
  EXPECT_EQ (single_parts.front().size(), single.triplets.size());
}

TEST (CompoundSplitting, DropsAClusterWhoseTrianglesSpanCopiesApart)
{
  // Every triangle has a corner on each copy of a pair: nothing of it lies on one copy. A few
  // whole triangles (fewer than three) do not make a part either.
  RowApart row;
  mid::TripletCluster across;
  row.scene.link (0, 2, across, {1, 3});
  row.scene.finish (across);
  ASSERT_TRUE (
      mid::isValidKeypointSurface (row.copiesApart(), row.scene.keypoints->size()));
  EXPECT_TRUE (
      mid::splitClusterAtSurfaceGaps (across, *row.scene.triplets, row.copiesApart())
          .empty());

  mid::TripletCluster mostly_across = across;
  const auto add_whole = [&row, &mostly_across] (int first) {
    mostly_across.triplets.push_back (row.scene.triplets->size());
    mostly_across.reversed.push_back (false);
    mid::TripletMatch whole;
    for (int c = 0; c < 3; ++c)
      whole.correspondences[static_cast<std::size_t> (c)] = pcl::Correspondence (
          Copies::index (0, first + c), Copies::index (2, first + c), 0.0f);
    row.scene.triplets->push_back (whole);
    row.scene.finish (mostly_across);
  };
  add_whole (0);
  add_whole (1);
  EXPECT_TRUE (mid::splitClusterAtSurfaceGaps (
                   mostly_across, *row.scene.triplets, row.copiesApart())
                   .empty());
  // With a third whole triangle, that part stays, alone.
  add_whole (2);
  const auto parts = mid::splitClusterAtSurfaceGaps (
      mostly_across, *row.scene.triplets, row.copiesApart());
  ASSERT_EQ (parts.size(), 1u);
  EXPECT_EQ (parts.front(),
             (std::vector<std::size_t>{across.triplets.size(),
                                       across.triplets.size() + 1,
                                       across.triplets.size() + 2}));
}

TEST (CompoundSplitting, TheClustererSplitsEverySecondCopyOfARowApartGivenTheSurface)
{
  // No cluster links neighbours (their triplets lie elsewhere on the print, or were not
  // found): only the surface tells the copies of each point set apart.
  RowApart row;
  mid::TripletCluster unused;
  row.scene.link (0, 2, unused);
  row.scene.link (1, 3, unused);
  const auto links = [&row] (const mid::KeypointSurface* surface) {
    Links found;
    for (const auto& cluster : mid::test::clusterTriplets (
             row.scene.keypoints, row.scene.triplets, true, true, surface))
      found.emplace (copiesOf (cluster.source_indices),
                     copiesOf (cluster.target_indices));
    return found;
  };
  EXPECT_EQ (links (nullptr), (Links{{{0, 1}, {2, 3}}}));
  const mid::KeypointSurface apart = row.copiesApart();
  EXPECT_EQ (links (&apart), (Links{{{0}, {2}}, {{1}, {3}}}));
  const mid::KeypointSurface one_object = row.oneObject();
  EXPECT_EQ (links (&one_object), (Links{{{0, 1}, {2, 3}}}));
}

TEST (CompoundSplitting, SplitsAtAGapThatOnlyOnePointSetShows)
{
  // Copies 2 and 3 on one face (one object to the surface), 0 and 1 apart: the sources tell
  // the two pairs apart.
  RowApart row;
  const mid::TripletCluster pairs = row.everySecondCopy();
  const auto parts = mid::splitClusterAtSurfaceGaps (
      pairs,
      *row.scene.triplets,
      row.surface (
          {RowApart::face (0, 0), RowApart::face (1, 1), RowApart::face (2, 3)}));
  EXPECT_EQ (row.partCopies (pairs, parts), RowApart::kEverySecondCopy);
}

TEST (CompoundSplitting, LeavesAClusterWithTwoKeypointsAcrossAGapWhole)
{
  // Copy 0 -> 2, and one triangle with two corners on copy 1 (apart): two keypoints make no
  // group, so no set holds two and nothing is cut.
  RowApart row;
  mid::TripletCluster cluster;
  row.scene.link (0, 2, cluster);
  mid::TripletMatch stray;
  for (int c = 0; c < 3; ++c)
    stray.correspondences[static_cast<std::size_t> (c)] = pcl::Correspondence (
        Copies::index (c == 0 ? 0 : 1, c), Copies::index (c == 0 ? 2 : 3, c), 0.0f);
  cluster.triplets.push_back (row.scene.triplets->size());
  cluster.reversed.push_back (false);
  row.scene.triplets->push_back (stray);
  row.scene.finish (cluster);
  ASSERT_EQ (copiesOf (cluster.source_indices), (std::set<int>{0, 1}));
  const auto parts =
      mid::splitClusterAtSurfaceGaps (cluster, *row.scene.triplets, row.copiesApart());
  ASSERT_EQ (parts.size(), 1u);
  EXPECT_EQ (parts.front().size(), cluster.triplets.size());
}

TEST (CompoundSplitting, LeavesKeypointsWithoutDepthOutOfTheSurfaceGroups)
{
  // A keypoint of copy 0 whose pixel has no depth would show no drop towards any other: it
  // takes no group, and its three triangles go; the split is the same.
  RowApart row;
  const mid::TripletCluster pairs = row.everySecondCopy();
  mid::KeypointSurface surface = row.copiesApart();
  auto holed = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>> (*surface.organized);
  const auto pixel =
      static_cast<std::size_t> (surface.keypoint_pixels[Copies::index (0, 5)]);
  (*holed)[pixel].x = (*holed)[pixel].y = (*holed)[pixel].z =
      std::numeric_limits<float>::quiet_NaN();
  surface.organized = holed;
  ASSERT_TRUE (mid::isValidKeypointSurface (surface, row.scene.keypoints->size()));
  const auto parts =
      mid::splitClusterAtSurfaceGaps (pairs, *row.scene.triplets, surface);
  EXPECT_EQ (row.partCopies (pairs, parts), RowApart::kEverySecondCopy);
  std::size_t kept = 0;
  for (const auto& part : parts)
    kept += part.size();
  EXPECT_EQ (kept, pairs.triplets.size() - 3);
}
