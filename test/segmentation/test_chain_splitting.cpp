#include "cluster_triplets.h"
#include "plate_surface.h"
#include "rigid_motion.h"

#include <mid/registration/triplet_match.h>
#include <mid/segmentation/chain_splitting.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <set>

namespace {

constexpr int kPoints = 12;

/** 12 points in a 6 x 4 x 3 cm box centred at the origin. */
std::vector<Eigen::Vector3f>
randomBox ()
{
  std::mt19937 rng (3);
  std::uniform_real_distribution<float> x (-0.03f, 0.03f), y (-0.02f, 0.02f),
      z (-0.015f, 0.015f);
  std::vector<Eigen::Vector3f> object;
  object.reserve (kPoints);
  for (int i = 0; i < kPoints; ++i)
    object.emplace_back (x (rng), y (rng), z (rng));
  return object;
}

/** `copies` copies of 12 object points (by default randomBox()) in a row: copy k is copy 0
  * moved by k * step, optionally rotated by `angle` about the vertical per step. Triplets
  * link every copy k to copy k + 1 (every second one stored reversed, k + 1 -> k, as a
  * self-match may come in either direction); `cluster` holds them. With `skip`, triplets also
  * link every copy k to copy k + 2 (not in `cluster`).
  */
struct Row
{
  Row (int copies,
       const Eigen::Vector3f& step,
       float angle = 0.0f,
       bool skip = false,
       const std::vector<Eigen::Vector3f>& object = randomBox(),
       const Eigen::Vector3f& origin = Eigen::Vector3f (-0.2f, 0.0f, 0.9f))
  {
    for (int k = 0; k < copies; ++k) {
      const Eigen::Isometry3f pose =
          mid::test::rigidMotion (origin + static_cast<float> (k) * step,
                                  static_cast<float> (k) * angle,
                                  Eigen::Vector3f::UnitY());
      for (const auto& p : object) {
        pcl::PointNormal point;
        point.getVector3fMap() = pose * p;
        keypoints->push_back (point);
      }
    }
    // The pose of copy k -> k + 1 in the camera frame (rotation about each copy's origin).
    const Eigen::Isometry3f first = mid::test::rigidMotion (origin);
    cluster.transformation =
        (first * mid::test::rigidMotion (step, angle, Eigen::Vector3f::UnitY()) *
         first.inverse())
            .matrix();
    for (int stride = 1; stride <= (skip ? 2 : 1); ++stride)
      for (int k = 0; k + stride < copies; ++k)
        addTriplets (k, stride, first, step, angle);
    for (int k = 0; k + 1 < copies; ++k)
      for (int i = 0; i < kPoints; ++i) {
        cluster.source_indices.push_back (k * kPoints + i);
        cluster.target_indices.push_back ((k + 1) * kPoints + i);
      }
  }

  /** Triplets linking copy k to copy k + stride (added to `cluster` for stride 1). */
  void
  addTriplets (int k,
               int stride,
               const Eigen::Isometry3f& first,
               const Eigen::Vector3f& step,
               float angle)
  {
    const Eigen::Matrix4f motion =
        (first *
         mid::test::rigidMotion (static_cast<float> (stride) * step,
                                 static_cast<float> (stride) * angle,
                                 Eigen::Vector3f::UnitY()) *
         first.inverse())
            .matrix();
    for (int i = 0; i + 2 < kPoints; ++i) {
      mid::TripletMatch triplet;
      for (int c = 0; c < 3; ++c) {
        const int a = k * kPoints + i + c, b = (k + stride) * kPoints + i + c;
        triplet.correspondences[static_cast<std::size_t> (c)] =
            i % 2 == 0 ? pcl::Correspondence (a, b, 0.0f)
                       : pcl::Correspondence (b, a, 0.0f);
      }
      triplet.transformation = i % 2 == 0 ? motion : Eigen::Matrix4f (motion.inverse());
      if (stride == 1) {
        cluster.triplets.push_back (triplets->size());
        cluster.reversed.push_back (i % 2 != 0);
        copy_of.push_back (k);
      }
      triplets->push_back (triplet);
    }
  }

  mid::KeypointCloud::Ptr keypoints = pcl::make_shared<mid::KeypointCloud>();
  std::shared_ptr<mid::TripletMatches> triplets =
      std::make_shared<mid::TripletMatches>();
  mid::TripletCluster cluster;
  std::vector<int> copy_of; ///< the source copy of each triplet
};

constexpr float kMaxRotation = static_cast<float> (20.0 * M_PI / 180.0);

/** Whether the parts are one per pair of neighbours, in copy order, each with all of its
  * triplets.
  */
bool
areNeighbourPairs (const Row& row, const std::vector<std::vector<std::size_t>>& parts)
{
  if (parts.size() != static_cast<std::size_t> (
                          *std::max_element (row.copy_of.begin(), row.copy_of.end())) +
                          1u)
    return false;
  for (std::size_t part = 0; part < parts.size(); ++part) {
    if (parts[part].size() != static_cast<std::size_t> (kPoints - 2))
      return false;
    for (const std::size_t m : parts[part])
      if (row.copy_of[m] != static_cast<int> (part))
        return false;
  }
  return true;
}

/** The row's cluster comes out as one part holding every triplet. */
void
expectWhole (const Row& row)
{
  const auto parts =
      mid::splitChainCluster (row.cluster, *row.triplets, *row.keypoints, kMaxRotation);
  ASSERT_EQ (parts.size(), 1u);
  EXPECT_EQ (parts.front().size(), row.triplets->size());
}

/** The row's cluster comes out as one part per pair of neighbours, in copy order, each with
  * all of its triplets.
  */
void
expectNeighbourPairs (const Row& row)
{
  ASSERT_FALSE (row.copy_of.empty());
  EXPECT_TRUE (areNeighbourPairs (
      row,
      mid::splitChainCluster (
          row.cluster, *row.triplets, *row.keypoints, kMaxRotation)));
}

} // namespace

TEST (ChainSplitting, SplitsARowIntoNeighbourPairs)
{
  // Four copies 8 cm apart along the row (the box is 6 cm long): three pairs.
  const Row row (4, Eigen::Vector3f (0.08f, 0.0f, 0.01f));
  expectNeighbourPairs (row);
}

TEST (ChainSplitting, CutsTouchingCopiesBetweenThemNotInsideTheirPrint)
{
  // 6 cm boxes 6.1 cm apart whose keypoints leave a 2 cm band without keypoints in every box
  // (x from -2 to 0 cm): the largest empty interval of the phases lies inside the boxes, the
  // 1 mm between them is the only cut that puts the row on the fewest copies.
  std::vector<Eigen::Vector3f> object;
  const float xs[kPoints] = {-0.03f,
                             -0.026f,
                             -0.022f,
                             -0.02f,
                             0.0f,
                             0.005f,
                             0.01f,
                             0.015f,
                             0.02f,
                             0.025f,
                             0.028f,
                             0.03f};
  for (int i = 0; i < kPoints; ++i) {
    const auto t = static_cast<float> (i);
    object.emplace_back (
        xs[i], 0.02f * std::sin (1.7f * t), 0.015f * std::cos (2.3f * t));
  }
  const Row row (4, Eigen::Vector3f (0.061f, 0.0f, 0.0f), 0.0f, false, object);
  expectNeighbourPairs (row);
}

TEST (ChainSplitting, CutsWhereTheSurfaceShowsAGapNotInsideAWiderEmptyBand)
{
  // Five flat 6 cm plates 1 cm apart, 30 cm below the camera above a floor 10 cm lower, whose
  // keypoints leave a 2.4 cm band without keypoints in every plate; the first link misses
  // its left half (as when those keypoints of the first copies find no match). A cut in the
  // band then puts the keypoints on as few copies as the cut in the 1 cm gap, and the band
  // is wider: without the surface the row is cut inside the plates. The surface shows the
  // floor through the gaps.
  const float xs[kPoints] = {-0.03f,
                             -0.027f,
                             -0.025f,
                             -0.022f,
                             -0.017f,
                             -0.012f,
                             0.012f,
                             0.016f,
                             0.02f,
                             0.024f,
                             0.027f,
                             0.03f};
  std::vector<Eigen::Vector3f> object;
  object.reserve (kPoints);
  for (int i = 0; i < kPoints; ++i)
    object.emplace_back (
        xs[i], 0.0f, 0.018f * std::sin (1.7f * static_cast<float> (i)));
  const Eigen::Vector3f origin (-0.15f, 0.3f, 0.9f);
  const Eigen::Vector3f step (0.07f, 0.0f, 0.0f);
  Row row (5, step, 0.0f, false, object, origin);
  const auto left_half = [] (pcl::Indices& indices, int copy) {
    indices.erase (std::remove_if (indices.begin(),
                                   indices.end(),
                                   [copy] (pcl::index_t k) {
                                     return k / kPoints == copy && k % kPoints < 6;
                                   }),
                   indices.end());
  };
  left_half (row.cluster.source_indices, 0);
  left_half (row.cluster.target_indices, 1);

  std::vector<mid::test::Plate> plates;
  for (int k = 0; k < 5; ++k) {
    const float x = origin.x() + step.x() * static_cast<float> (k);
    plates.push_back ({x - 0.03f, x + 0.03f, 0.87f, 0.93f, origin.y()});
  }
  mid::KeypointSurface surface;
  surface.organized = mid::test::renderPlates (plates, 0.4f);
  for (const auto& keypoint : *row.keypoints)
    surface.keypoint_pixels.push_back (
        mid::test::plateSurfacePixel (keypoint.getVector3fMap()));
  ASSERT_TRUE (mid::isValidKeypointSurface (surface, row.keypoints->size()));

  EXPECT_FALSE (areNeighbourPairs (
      row,
      mid::splitChainCluster (
          row.cluster, *row.triplets, *row.keypoints, kMaxRotation)));
  EXPECT_TRUE (areNeighbourPairs (row,
                                  mid::splitChainCluster (row.cluster,
                                                          *row.triplets,
                                                          *row.keypoints,
                                                          kMaxRotation,
                                                          Eigen::Vector3f::Zero(),
                                                          &surface)));
}

TEST (ChainSplitting, LeavesLinksBetweenNonConsecutiveCopiesWhole)
{
  // Six touching boxes in a row of which only copies 0 -> 1 and 4 -> 5 are linked: the sources
  // span four steps, but lie on copies 0 and 4 only. No shared keypoint shows a chain; the
  // cluster may be two pairs of touching copies that stand apart, and is left whole.
  const Row row (6, Eigen::Vector3f (0.061f, 0.0f, 0.0f));
  mid::TripletCluster pairs;
  pairs.transformation = row.cluster.transformation;
  std::set<pcl::index_t> sources, targets;
  for (std::size_t m = 0; m < row.cluster.triplets.size(); ++m) {
    if (row.copy_of[m] != 0 && row.copy_of[m] != 4)
      continue;
    pairs.triplets.push_back (row.cluster.triplets[m]);
    pairs.reversed.push_back (row.cluster.reversed[m]);
    for (const auto& c : (*row.triplets)[row.cluster.triplets[m]].correspondences) {
      sources.insert (row.cluster.reversed[m] ? c.index_match : c.index_query);
      targets.insert (row.cluster.reversed[m] ? c.index_query : c.index_match);
    }
  }
  pairs.source_indices.assign (sources.begin(), sources.end());
  pairs.target_indices.assign (targets.begin(), targets.end());
  const auto parts =
      mid::splitChainCluster (pairs, *row.triplets, *row.keypoints, kMaxRotation);
  ASSERT_EQ (parts.size(), 1u);
  EXPECT_EQ (parts.front().size(), pairs.triplets.size());
}

TEST (ChainSplitting, LeavesAPairOfCopiesWhole)
{
  const Row row (2, Eigen::Vector3f (0.0f, 0.0f, 0.09f));
  expectWhole (row);
}

TEST (ChainSplitting, LeavesTwoTouchingCopiesWhole)
{
  // 6 cm boxes 6.1 cm apart: the largest gap between the phases of the keypoints may lie inside
  // a box, but a pair of copies is no chain (no keypoint is both a source and a target).
  const Row row (2, Eigen::Vector3f (0.061f, 0.0f, 0.0f));
  expectWhole (row);
}

TEST (ChainSplitting, LeavesARotatedChainWhole)
{
  // Copies turned by 30 degrees each: not a row of translated copies.
  const Row row (
      4, Eigen::Vector3f (0.08f, 0.0f, 0.0f), static_cast<float> (30.0 * M_PI / 180.0));
  expectWhole (row);
}

TEST (ChainSplitting, TheClustererGivesOneClusterPerPairOfNeighbours)
{
  const Row row (5, Eigen::Vector3f (0.075f, 0.0f, 0.0f));
  const mid::TripletClusters clusters =
      mid::test::clusterTriplets (row.keypoints, row.triplets);
  ASSERT_EQ (clusters.size(), 4u);
  for (const auto& cluster : clusters) {
    // Every pair of a cluster links copy k to copy k + 1 for one k, and the pose is the step.
    const int k = cluster.correspondences.front().index_query / kPoints;
    for (const auto& c : cluster.correspondences) {
      EXPECT_EQ (c.index_query / kPoints, k);
      EXPECT_EQ (c.index_match / kPoints, k + 1);
    }
    EXPECT_LT (mid::test::poseError (cluster.transformation, row.cluster.transformation)
                   .second,
               1e-5);
  }
  EXPECT_EQ (mid::test::clusterTriplets (row.keypoints, row.triplets, false).size(),
             1u);
}

TEST (ChainSplitting, SplitsEverySecondCopyAlongTheRowsStep)
{
  // Copies k -> k + 2 form a chain of their own (copies 0, 2, 4 and 1, 3, 5): numbered in its
  // own step, copies 0 and 1 would be one unit, and its parts would link pairs of copies.
  const Row row (6, Eigen::Vector3f (0.075f, 0.0f, 0.0f), 0.0f, true);
  std::multiset<int> strides;
  for (const auto& cluster :
       mid::test::clusterTriplets (row.keypoints, row.triplets, true, false)) {
    const int k = cluster.correspondences.front().index_query / kPoints,
              stride = cluster.correspondences.front().index_match / kPoints - k;
    for (const auto& c : cluster.correspondences) {
      EXPECT_EQ (c.index_query / kPoints, k);
      EXPECT_EQ (c.index_match / kPoints, k + stride);
    }
    strides.insert (stride);
  }
  EXPECT_EQ (strides, (std::multiset<int>{1, 1, 1, 1, 1, 2, 2, 2, 2}));
}
