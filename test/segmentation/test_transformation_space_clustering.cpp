#include "rigid_motion.h"
#include "two_copies_scene.h"

#include <mid/features/self_matcher.h>
#include <mid/features/sift_keypoint_extractor.h>
#include <mid/registration/rigid_transform.h>
#include <mid/segmentation/transformation_space_clustering.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

namespace {

using mid::test::poseError;

constexpr int kPoints = 30; // keypoints of the object
constexpr int kInstances = 3;

/** Three instances of a random oriented point set at known poses, then random clutter. */
struct ThreeInstances
{
  mid::KeypointCloud::Ptr keypoints = pcl::make_shared<mid::KeypointCloud>();
  std::vector<Eigen::Isometry3f, Eigen::aligned_allocator<Eigen::Isometry3f>> poses;
  int clutter_begin = kPoints * kInstances;
};

ThreeInstances
makeThreeInstances (unsigned seed = 9)
{
  ThreeInstances s;
  std::mt19937 rng (seed);
  std::uniform_real_distribution<float> unit (-0.5f, 0.5f);
  s.poses.push_back (mid::test::rigidMotion ({-0.25f, 0.0f, 0.9f}, 0.3f, {0, 0, 1}));
  s.poses.push_back (mid::test::rigidMotion ({0.0f, 0.1f, 1.0f}, 2.0f, {1, 1, 0}));
  s.poses.push_back (mid::test::rigidMotion ({0.25f, -0.05f, 0.95f}, -1.2f, {0, 1, 1}));
  std::vector<Eigen::Vector3f> model;
  model.reserve (kPoints);
  for (int k = 0; k < kPoints; ++k)
    model.emplace_back (unit (rng) * 0.1f, unit (rng) * 0.1f, unit (rng) * 0.1f);
  for (const auto& pose : s.poses)
    for (const auto& m : model) {
      pcl::PointNormal p;
      p.getVector3fMap() = pose * m;
      p.getNormalVector3fMap() = Eigen::Vector3f::UnitZ();
      s.keypoints->push_back (p);
    }
  for (int k = 0; k < 60; ++k) {
    pcl::PointNormal p;
    p.getVector3fMap() = Eigen::Vector3f (unit (rng), unit (rng), 1.0f + unit (rng));
    p.getNormalVector3fMap() = Eigen::Vector3f::UnitZ();
    s.keypoints->push_back (p);
  }
  return s;
}

mid::TripletMatch
makeTriplet (const mid::KeypointCloud& cloud,
             const std::array<int, 3>& p,
             const std::array<int, 3>& q)
{
  mid::TripletMatch t;
  Eigen::Matrix3Xf from (3, 3), to (3, 3);
  for (std::size_t k = 0; k < 3; ++k) {
    t.correspondences[k] = pcl::Correspondence (p[k], q[k], 100.0f);
    from.col (static_cast<Eigen::Index> (k)) =
        cloud[static_cast<std::size_t> (p[k])].getVector3fMap();
    to.col (static_cast<Eigen::Index> (k)) =
        cloud[static_cast<std::size_t> (q[k])].getVector3fMap();
  }
  t.transformation = mid::estimateRigidTransform (from, to, &t.rms_error);
  return t;
}

/** 25 triplets per instance pair (i -> j), some pairs also in the reverse direction, and 40
  * random triplets of clutter.
  */
mid::TripletMatches
makeTriplets (const ThreeInstances& s, bool with_reverse, unsigned seed = 4)
{
  std::mt19937 rng (seed);
  std::uniform_int_distribution<int> keypoint (0, kPoints - 1),
      clutter (s.clutter_begin, static_cast<int> (s.keypoints->size()) - 1);
  mid::TripletMatches triplets;
  auto add_pair = [&] (int i, int j, int count) {
    for (int n = 0; n < count;) {
      const std::array<int, 3> k{keypoint (rng), keypoint (rng), keypoint (rng)};
      if (k[0] == k[1] || k[1] == k[2] || k[0] == k[2])
        continue;
      triplets.push_back (
          makeTriplet (*s.keypoints,
                       {i * kPoints + k[0], i * kPoints + k[1], i * kPoints + k[2]},
                       {j * kPoints + k[0], j * kPoints + k[1], j * kPoints + k[2]}));
      ++n;
    }
  };
  add_pair (0, 1, 25);
  add_pair (0, 2, 25);
  add_pair (1, 2, 25);
  if (with_reverse)
    add_pair (1, 0, 20); // the pair (0, 1) once more, the other way round
  for (int n = 0; n < 40; ++n)
    triplets.push_back (makeTriplet (*s.keypoints,
                                     {clutter (rng), clutter (rng), clutter (rng)},
                                     {clutter (rng), clutter (rng), clutter (rng)}));
  return triplets;
}

mid::TripletClusters
runClustering (mid::TransformationSpaceClustering& clustering,
               const ThreeInstances& s,
               const mid::TripletMatches& triplets)
{
  clustering.setInputCloud (s.keypoints);
  clustering.setSceneCloud (s.keypoints);
  clustering.setInputTriplets (std::make_shared<const mid::TripletMatches> (triplets));
  mid::TransformationSpaceClustering::Transformations poses;
  std::vector<pcl::Correspondences> groups;
  clustering.recognize (poses, groups);
  EXPECT_EQ (poses.size(), clustering.getClusters().size());
  EXPECT_EQ (groups.size(), clustering.getClusters().size());
  return clustering.getClusters();
}

int
instanceOf (pcl::index_t keypoint)
{
  return keypoint < kPoints * kInstances ? keypoint / kPoints : -1;
}

} // namespace

TEST (TransformationSpaceClustering, FindsEachInstancePairWithItsTruePose)
{
  const ThreeInstances s = makeThreeInstances();
  mid::TransformationSpaceClustering clustering;
  const auto clusters = runClustering (clustering, s, makeTriplets (s, true));
  ASSERT_EQ (clusters.size(), 3u); // (0,1) in both directions merged into one
  std::set<std::pair<int, int>> pairs;
  for (const auto& c : clusters) {
    const int from = instanceOf (c.source_indices.front()),
              to = instanceOf (c.target_indices.front());
    ASSERT_GE (from, 0);
    ASSERT_GE (to, 0);
    for (const auto i : c.source_indices)
      EXPECT_EQ (instanceOf (i), from); // no clutter, no other instance
    for (const auto i : c.target_indices)
      EXPECT_EQ (instanceOf (i), to);
    pairs.insert ({std::min (from, to), std::max (from, to)});
    const Eigen::Isometry3f truth = s.poses[static_cast<std::size_t> (to)] *
                                    s.poses[static_cast<std::size_t> (from)].inverse();
    const auto error = poseError (c.transformation, truth.matrix());
    EXPECT_LT (error.first, 1e-5);
    EXPECT_LT (error.second, 1e-5);
    EXPECT_LT (c.rms_error, 1e-5f);
    EXPECT_GE (c.triplets.size(), 25u);
  }
  EXPECT_EQ (pairs, (std::set<std::pair<int, int>>{{0, 1}, {0, 2}, {1, 2}}));
  // The clutter triplets are noise: no cluster holds one.
  std::size_t clustered = 0;
  for (const auto& c : clusters)
    clustered += c.triplets.size();
  EXPECT_EQ (clustered, 3u * 25u + 20u);
}

TEST (TransformationSpaceClustering, MergesInverseClustersOnlyWhenAsked)
{
  const ThreeInstances s = makeThreeInstances();
  mid::TransformationSpaceClustering clustering;
  clustering.setMergeInverseClusters (false);
  const auto clusters = runClustering (clustering, s, makeTriplets (s, true));
  ASSERT_EQ (clusters.size(), 4u);
  bool found_reverse = false;
  for (const auto& c : clusters)
    if (instanceOf (c.source_indices.front()) == 1 &&
        instanceOf (c.target_indices.front()) == 0) {
      found_reverse = true;
      EXPECT_EQ (c.triplets.size(), 20u);
    }
  EXPECT_TRUE (found_reverse);

  clustering.setMergeInverseClusters (true);
  const auto merged = runClustering (clustering, s, makeTriplets (s, true));
  ASSERT_EQ (merged.size(), 3u);
  EXPECT_EQ (merged.front().triplets.size(),
             45u); // the largest: (0,1) with its reverse
  EXPECT_EQ (
      std::count (merged.front().reversed.begin(), merged.front().reversed.end(), true),
      20);
}

TEST (TransformationSpaceClustering, DoesNotDependOnTheInputOrder)
{
  const ThreeInstances s = makeThreeInstances();
  auto triplets = makeTriplets (s, true);
  mid::TransformationSpaceClustering clustering;
  const auto first = runClustering (clustering, s, triplets);
  std::shuffle (triplets.begin(), triplets.end(), std::mt19937 (3));
  const auto second = runClustering (clustering, s, triplets);
  ASSERT_EQ (first.size(), second.size());
  for (std::size_t i = 0; i < first.size(); ++i) {
    EXPECT_EQ (first[i].source_indices, second[i].source_indices);
    EXPECT_EQ (first[i].target_indices, second[i].target_indices);
    EXPECT_LT (
        (first[i].transformation - second[i].transformation).cwiseAbs().maxCoeff(),
        1e-6f);
  }
}

TEST (TransformationSpaceClustering, StoredAndRecomputedNeighboursGiveTheSameClusters)
{
  const ThreeInstances s = makeThreeInstances();
  const auto triplets = makeTriplets (s, true);
  mid::TransformationSpaceClustering stored, recomputed;
  recomputed.setMaxStoredNeighbors (0);
  const auto a = runClustering (stored, s, triplets);
  const auto b = runClustering (recomputed, s, triplets);
  ASSERT_EQ (a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ (a[i].triplets, b[i].triplets);
    EXPECT_EQ (a[i].transformation, b[i].transformation);
  }
}

TEST (TransformationSpaceClustering, RespectsTheMinimumClusterSize)
{
  const ThreeInstances s = makeThreeInstances();
  mid::TransformationSpaceClustering clustering;
  clustering.setMinClusterSize (
      26); // each direction of each pair has 25 or 20 triplets
  clustering.setMergeInverseClusters (false);
  EXPECT_TRUE (runClustering (clustering, s, makeTriplets (s, true)).empty());
}

TEST (TransformationSpaceClustering, GroupsTheSelfMatchesOfTwoTexturedCopies)
{
  const auto scene = mid::test::makeTwoCopiesScene();
  mid::SIFTKeypointExtractor<pcl::PointXYZRGB> extractor;
  extractor.setInputCloud (scene.cloud);
  auto keypoints = pcl::make_shared<mid::KeypointCloud>();
  auto descriptors = pcl::make_shared<mid::SIFTDescriptorCloud>();
  ASSERT_TRUE (extractor.compute (*keypoints, *descriptors));
  mid::SelfMatcher matcher;
  matcher.setInputKeypoints (keypoints);
  matcher.setInputDescriptors (descriptors);
  auto matches = pcl::make_shared<pcl::Correspondences>();
  ASSERT_TRUE (matcher.match (*matches));

  // The correspondence path: the clusterer runs the triplet rejector itself.
  mid::TransformationSpaceClustering clustering;
  clustering.setInputCloud (keypoints);
  clustering.setSceneCloud (keypoints);
  clustering.setModelSceneCorrespondences (matches);
  mid::TransformationSpaceClustering::Transformations poses;
  clustering.recognize (poses);
  ASSERT_EQ (poses.size(), 1u);
  const auto forward = poseError (poses.front(), scene.a_to_b.matrix());
  const auto backward = poseError (poses.front(), scene.a_to_b.inverse().matrix());
  const auto& error = forward.second < backward.second ? forward : backward;
  EXPECT_LT (error.first, 1.0 * M_PI / 180.0);
  EXPECT_LT (error.second, 0.002);
  EXPECT_GT (clustering.getClusters().front().correspondences.size(), 30u);
}

TEST (TransformationSpaceClustering, BadInputGivesAnEmptyResult)
{
  const ThreeInstances s = makeThreeInstances();
  mid::TransformationSpaceClustering clustering;
  EXPECT_TRUE (
      runClustering (clustering, s, {}).empty()); // no triplets: nothing to find

  auto triplets = makeTriplets (s, false);
  triplets[3].transformation (0, 0) = NAN;
  EXPECT_TRUE (runClustering (clustering, s, triplets).empty());

  triplets = makeTriplets (s, false);
  for (const float eps : {0.0f, -1.0f, NAN}) {
    clustering.setClusterDistance (eps);
    EXPECT_TRUE (runClustering (clustering, s, triplets).empty());
  }
  clustering.setClusterDistance (0.035f);
  EXPECT_EQ (runClustering (clustering, s, triplets).size(), 3u);

  triplets.back().correspondences[0].index_match = 100000; // outside the cloud
  EXPECT_TRUE (runClustering (clustering, s, triplets).empty());

  // A keypoint surface must give each keypoint a pixel inside an organized cloud.
  triplets = makeTriplets (s, false);
  const auto organized = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>> (4, 4);
  const std::size_t n = s.keypoints->size();
  clustering.setKeypointSurface ({organized, pcl::Indices (n, 15)});
  EXPECT_EQ (runClustering (clustering, s, triplets).size(), 3u);
  clustering.setKeypointSurface ({organized, pcl::Indices (n - 1, 0)});
  EXPECT_TRUE (runClustering (clustering, s, triplets).empty());
  clustering.setKeypointSurface ({organized, pcl::Indices (n, 16)});
  EXPECT_TRUE (runClustering (clustering, s, triplets).empty());

  mid::TransformationSpaceClustering no_scene;
  no_scene.setInputCloud (s.keypoints);
  no_scene.setInputTriplets (
      std::make_shared<const mid::TripletMatches> (makeTriplets (s, false)));
  std::vector<pcl::Correspondences> groups (2);
  no_scene.cluster (groups);
  EXPECT_TRUE (groups.empty());
  EXPECT_TRUE (no_scene.getClusters().empty());
}
