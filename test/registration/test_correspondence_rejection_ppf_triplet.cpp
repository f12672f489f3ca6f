#include "rigid_motion.h"
#include "two_copies_scene.h"

#include <mid/features/self_matcher.h>
#include <mid/features/sift_keypoint_extractor.h>
#include <mid/registration/correspondence_rejection_ppf_triplet.h>

#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <pcl/conversions.h>

#include <algorithm>
#include <map>
#include <random>
#include <set>

namespace {

using Rejector = mid::CorrespondenceRejectorPPFTriplet;

/** Two copies of a random oriented point set: keypoint i and n + i are the same surface point
  * seen on two instances, related by `motion`; then random outlier keypoints.
  */
struct TwoInstances
{
  mid::KeypointCloud::Ptr keypoints = pcl::make_shared<mid::KeypointCloud>();
  pcl::Correspondences true_matches;
  pcl::Correspondences
      all_matches; // true matches and outliers, each with its own distance
  Eigen::Isometry3f motion = Eigen::Isometry3f::Identity();
  int n = 0;
};

/** Points in a cube of side `size` at 0.8 m, with normals within 60 deg of facing the camera. */
TwoInstances
makeTwoInstances (const Eigen::Isometry3f& motion,
                  int n = 40,
                  float size = 0.08f,
                  int outliers = 30,
                  unsigned seed = 3,
                  bool mirror = false)
{
  TwoInstances s;
  s.motion = motion;
  s.n = n;
  std::mt19937 rng (seed);
  std::uniform_real_distribution<float> unit (-0.5f, 0.5f);
  Eigen::Matrix3f linear = motion.linear();
  if (mirror)
    linear = linear * Eigen::Vector3f (-1, 1, 1).asDiagonal();
  std::vector<pcl::PointNormal> first;
  for (int i = 0; i < n; ++i) {
    pcl::PointNormal p;
    p.getVector3fMap() = Eigen::Vector3f (unit (rng), unit (rng), unit (rng)) * size +
                         Eigen::Vector3f (0, 0, 0.8f);
    p.getNormalVector3fMap() =
        Eigen::Vector3f (unit (rng), unit (rng), -1.0f).normalized();
    first.push_back (p);
  }
  for (const auto& p : first)
    s.keypoints->push_back (p);
  const Eigen::Vector3f center (0, 0, 0.8f);
  for (const auto& p : first) {
    pcl::PointNormal q;
    q.getVector3fMap() =
        linear * (p.getVector3fMap() - center) + center + motion.translation();
    q.getNormalVector3fMap() = linear * p.getNormalVector3fMap();
    s.keypoints->push_back (q);
  }
  for (int i = 0; i < outliers; ++i) {
    pcl::PointNormal o;
    o.getVector3fMap() = Eigen::Vector3f (unit (rng), unit (rng), unit (rng)) * 0.4f +
                         Eigen::Vector3f (0, 0, 0.9f);
    o.getNormalVector3fMap() =
        Eigen::Vector3f (unit (rng), unit (rng), -1.0f).normalized();
    s.keypoints->push_back (o);
  }
  const int total = static_cast<int> (s.keypoints->size());
  for (int i = 0; i < n; ++i)
    s.true_matches.emplace_back (i, n + i, 100.0f + static_cast<float> (i));
  s.all_matches = s.true_matches;
  std::uniform_int_distribution<int> any (0, total - 1);
  for (int i = 0; i < outliers * 2; ++i) {
    const int a = any (rng), b = any (rng);
    if (a != b)
      s.all_matches.emplace_back (a, b, 150.0f + static_cast<float> (i));
  }
  return s;
}

/** The motion as it acts on the points built by makeTwoInstances (about the set's centre). */
Eigen::Isometry3f
aboutCenter (const Eigen::Isometry3f& motion)
{
  const Eigen::Vector3f center (0, 0, 0.8f);
  Eigen::Isometry3f about = motion;
  about.translation() = center + motion.translation() - motion.linear() * center;
  return about;
}

const Eigen::Isometry3f kMotion =
    mid::test::rigidMotion ({0.30f, 0.05f, 0.10f}, 1.2f, {0.3f, 1.0f, 0.2f});

using mid::test::poseError;

mid::TripletMatches
run (Rejector& rejector,
     const TwoInstances& s,
     const pcl::Correspondences& matches,
     pcl::Correspondences* remaining = nullptr)
{
  rejector.setInputSource (s.keypoints);
  pcl::Correspondences kept;
  rejector.getRemainingCorrespondences (matches, kept);
  if (remaining != nullptr)
    *remaining = kept;
  return rejector.getTripletMatches();
}

} // namespace

TEST (CorrespondenceRejectorPPFTriplet, EveryTripletPoseIsTheKnownMotion)
{
  const TwoInstances s = makeTwoInstances (kMotion);
  Rejector rejector;
  pcl::Correspondences remaining;
  const auto triplets = run (rejector, s, s.all_matches, &remaining);
  ASSERT_GT (triplets.size(), 20u);
  const Eigen::Matrix4f forward = aboutCenter (kMotion).matrix();
  const Eigen::Matrix4f backward = aboutCenter (kMotion).inverse().matrix();
  for (const auto& t : triplets) {
    // A triplet may map the first instance onto the second or, reversed, the second onto the first.
    const bool reversed = t.correspondences[0].index_query >= s.n;
    const auto error = poseError (t.transformation, reversed ? backward : forward);
    EXPECT_LT (error.first, 1e-5);
    EXPECT_LT (error.second, 1e-5);
    EXPECT_LT (t.rms_error, 1e-5f);
    for (const auto& c : t.correspondences)
      EXPECT_EQ (std::abs (c.index_match - c.index_query), s.n);
  }
  // Only true matches remain.
  for (const auto& c : remaining)
    EXPECT_EQ (c.index_match - c.index_query, s.n);
  EXPECT_GT (remaining.size(), static_cast<std::size_t> (s.n / 2));
}

TEST (CorrespondenceRejectorPPFTriplet, RejectsMirroredTooSmallAndTooAcuteTriplets)
{
  Rejector rejector;
  // A mirror image passes the point pair features but not sidedness.
  const TwoInstances mirrored = makeTwoInstances (kMotion, 40, 0.08f, 0, 3, true);
  EXPECT_TRUE (run (rejector, mirrored, mirrored.true_matches).empty());

  // Every edge shorter than 10 mm.
  const TwoInstances tiny = makeTwoInstances (kMotion, 40, 0.005f, 0);
  EXPECT_TRUE (run (rejector, tiny, tiny.true_matches).empty());
  rejector.setMinEdgeLength (0.001f);
  EXPECT_FALSE (run (rejector, tiny, tiny.true_matches).empty());
  rejector.setMinEdgeLength (0.010f);

  // All points on a thin line: every triangle is too acute.
  TwoInstances line = makeTwoInstances (kMotion, 40, 0.08f, 0);
  for (int i = 0; i < 2 * line.n; ++i) {
    auto& p = (*line.keypoints)[static_cast<std::size_t> (i)];
    const Eigen::Vector3f local =
        i < line.n ? Eigen::Vector3f (p.getVector3fMap())
                   : aboutCenter (kMotion).inverse() * p.getVector3fMap();
    const Eigen::Vector3f squeezed (
        local.x(), 0.001f * local.y(), 0.8f + 0.001f * (local.z() - 0.8f));
    p.getVector3fMap() =
        i < line.n ? squeezed : Eigen::Vector3f (aboutCenter (kMotion) * squeezed);
  }
  EXPECT_TRUE (run (rejector, line, line.true_matches).empty());
  rejector.setMinTriangleAngle (0.0f);
  rejector.setMaxDistanceDifference (0.01f);
  EXPECT_FALSE (run (rejector, line, line.true_matches).empty());
}

TEST (CorrespondenceRejectorPPFTriplet, RejectsOverlappingTriangles)
{
  // The "second instance" is the first moved by 3 mm: its triangles lie on the first one's.
  const Eigen::Isometry3f nudge = mid::test::rigidMotion ({0.003f, 0.0f, 0.0f});
  const TwoInstances s = makeTwoInstances (nudge, 40, 0.08f, 0);
  Rejector rejector;
  EXPECT_TRUE (run (rejector, s, s.true_matches).empty());
  rejector.setOverlapDistance (-1.0f);
  EXPECT_FALSE (run (rejector, s, s.true_matches).empty());
}

TEST (CorrespondenceRejectorPPFTriplet, EachKeypointTakesPartInAtMostLTriplets)
{
  const TwoInstances s = makeTwoInstances (kMotion);
  for (const int limit : {1, 3, 10}) {
    Rejector rejector;
    rejector.setMaxTripletsPerKeypoint (limit);
    const auto triplets = run (rejector, s, s.all_matches);
    ASSERT_FALSE (triplets.empty());
    std::map<pcl::index_t, int> uses;
    for (const auto& t : triplets)
      for (const auto& c : t.correspondences) {
        ++uses[c.index_query];
        ++uses[c.index_match];
      }
    for (const auto& entry : uses)
      EXPECT_LE (entry.second, limit) << "keypoint " << entry.first;
    if (limit == 1) {
      EXPECT_LE (triplets.size(), static_cast<std::size_t> (2 * s.n / 6));
    }
  }
  Rejector capped;
  capped.setMaxTriplets (5);
  EXPECT_EQ (run (capped, s, s.all_matches).size(), 5u);
}

TEST (CorrespondenceRejectorPPFTriplet, OutputDependsOnlyOnTheInputNotItsOrder)
{
  const TwoInstances s = makeTwoInstances (kMotion);
  Rejector rejector;
  const auto first = run (rejector, s, s.all_matches);
  const auto again = run (rejector, s, s.all_matches);
  pcl::Correspondences shuffled = s.all_matches;
  std::shuffle (shuffled.begin(), shuffled.end(), std::mt19937 (11));
  const auto reordered = run (rejector, s, shuffled);
  ASSERT_EQ (first.size(), again.size());
  ASSERT_EQ (first.size(), reordered.size());
  for (std::size_t i = 0; i < first.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ (first[i].correspondences[k].index_query,
                 reordered[i].correspondences[k].index_query);
      EXPECT_EQ (first[i].correspondences[k].index_match,
                 reordered[i].correspondences[k].index_match);
      EXPECT_EQ (first[i].transformation, again[i].transformation);
    }
}

TEST (CorrespondenceRejectorPPFTriplet, WorksAsAPlainPclRejector)
{
  const TwoInstances s = makeTwoInstances (kMotion);
  pcl::registration::CorrespondenceRejector::Ptr rejector =
      pcl::make_shared<Rejector>();
  ASSERT_TRUE (rejector->requiresSourcePoints());
  // The way pcl::Registration hands clouds to its rejectors: as PCLPointCloud2.
  auto blob = pcl::make_shared<pcl::PCLPointCloud2>();
  pcl::toPCLPointCloud2 (*s.keypoints, *blob);
  rejector->setSourcePoints (blob);
  rejector->setSourceNormals (blob);
  rejector->setInputCorrespondences (
      pcl::make_shared<pcl::Correspondences> (s.all_matches));
  pcl::Correspondences remaining;
  rejector->getCorrespondences (remaining);
  ASSERT_FALSE (remaining.empty());
  for (const auto& c : remaining)
    EXPECT_EQ (c.index_match - c.index_query, s.n);
  pcl::Indices rejected;
  rejector->getRejectedQueryIndices (remaining, rejected);
  EXPECT_EQ (rejected.size() + remaining.size(), s.all_matches.size());
  EXPECT_EQ (rejector->getClassName(), "CorrespondenceRejectorPPFTriplet");
}

TEST (CorrespondenceRejectorPPFTriplet, FindsTheKnownMotionBetweenTwoTexturedCopies)
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
  pcl::Correspondences matches;
  ASSERT_TRUE (matcher.match (matches));

  Rejector rejector;
  rejector.setInputSource (keypoints);
  pcl::Correspondences remaining;
  rejector.getRemainingCorrespondences (matches, remaining);
  const auto& triplets = rejector.getTripletMatches();
  ASSERT_GT (triplets.size(), 30u);
  std::size_t consistent = 0;
  for (const auto& t : triplets) {
    const auto forward = poseError (t.transformation, scene.a_to_b.matrix());
    const auto backward = poseError (t.transformation, scene.a_to_b.inverse().matrix());
    const auto& best = forward.second < backward.second ? forward : backward;
    // Keypoints are whole pixels (1.5 mm at 0.8 m) on flat copies.
    if (best.first < 5.0 * M_PI / 180.0 && best.second < 0.008)
      ++consistent;
  }
  EXPECT_GE (consistent, triplets.size() * 95 / 100);
}

TEST (CorrespondenceRejectorPPFTriplet, RefusesBadInputWithAnEmptyResult)
{
  TwoInstances s = makeTwoInstances (kMotion);
  Rejector rejector;
  pcl::Correspondences remaining (3);
  rejector.getRemainingCorrespondences (s.all_matches, remaining); // no source
  EXPECT_TRUE (remaining.empty());

  auto expectEmpty = [&] (const pcl::Correspondences& matches) {
    remaining.resize (3);
    rejector.getRemainingCorrespondences (matches, remaining);
    EXPECT_TRUE (remaining.empty());
    EXPECT_TRUE (rejector.getTripletMatches().empty());
  };
  rejector.setInputSource (pcl::make_shared<mid::KeypointCloud>());
  expectEmpty (s.all_matches);
  rejector.setInputSource (s.keypoints);
  pcl::Correspondences out_of_range = s.true_matches;
  out_of_range.emplace_back (0, static_cast<pcl::index_t> (s.keypoints->size()), 1.0f);
  expectEmpty (out_of_range);
  out_of_range.back() = pcl::Correspondence (-1, 0, 1.0f);
  expectEmpty (out_of_range);
  // A separate target that is too small for the indices.
  rejector.setInputTarget (pcl::make_shared<mid::KeypointCloud> (5, 1));
  expectEmpty (s.true_matches);
  rejector.setInputTarget (nullptr);

  auto no_normals = pcl::make_shared<mid::KeypointCloud> (*s.keypoints);
  for (auto& p : *no_normals)
    p.getNormalVector3fMap().setZero();
  rejector.setInputSource (no_normals);
  expectEmpty (s.true_matches);
  rejector.setInputSource (s.keypoints);

  rejector.setMinEdgeLength (0.2f); // above the max edge
  expectEmpty (s.true_matches);
  rejector.setMinEdgeLength (0.01f);
  rejector.setMaxTripletsPerKeypoint (0);
  expectEmpty (s.true_matches);
  rejector.setMaxTripletsPerKeypoint (10);
  rejector.setMaxAngleDifference (NAN);
  expectEmpty (s.true_matches);
  rejector.setMaxAngleDifference (0.6f);
  expectEmpty ({});
  rejector.getRemainingCorrespondences (s.true_matches, remaining);
  EXPECT_FALSE (remaining.empty());
}
