#include "two_copies_scene.h"

#include <mid/features/self_matcher.h>
#include <mid/features/sift_keypoint_extractor.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace {

/** Keypoints far apart on a line and descriptors filled by the test. */
struct Fixture
{
  mid::KeypointCloud::Ptr keypoints = pcl::make_shared<mid::KeypointCloud>();
  mid::SIFTDescriptorCloud::Ptr descriptors =
      pcl::make_shared<mid::SIFTDescriptorCloud>();
  std::mt19937 rng{42};

  /** A random descriptor of norm about 512, like OpenCV's SIFT. */
  mid::SIFTDescriptor
  randomDescriptor ()
  {
    std::uniform_real_distribution<float> value (0.0f, 80.0f);
    mid::SIFTDescriptor d;
    for (float& v : d.histogram)
      v = value (rng);
    return d;
  }

  /** d moved by exactly `distance` along one axis. */
  static mid::SIFTDescriptor
  moved (mid::SIFTDescriptor d, float distance, int axis = 0)
  {
    d.histogram[axis] += distance;
    return d;
  }

  void
  add (const mid::SIFTDescriptor& d, float x = -1.0f)
  {
    pcl::PointNormal p;
    p.x = x >= 0.0f ? x : 0.1f * static_cast<float> (keypoints->size());
    p.y = p.z = 0.0f;
    p.normal_x = p.normal_y = 0.0f;
    p.normal_z = -1.0f;
    keypoints->push_back (p);
    descriptors->push_back (d);
  }

  pcl::Correspondences
  match (mid::SelfMatcher& matcher) const
  {
    matcher.setInputKeypoints (keypoints);
    matcher.setInputDescriptors (descriptors);
    pcl::Correspondences matches;
    EXPECT_TRUE (matcher.match (matches));
    return matches;
  }
};

int
matchOf (const pcl::Correspondences& matches, int query)
{
  for (const auto& m : matches)
    if (m.index_query == query)
      return m.index_match;
  return -1;
}

} // namespace

TEST (SelfMatcher, MatchesEachKeypointToItsNearestOtherWithinTheThreshold)
{
  Fixture f;
  const auto a = f.randomDescriptor(), b = f.randomDescriptor();
  f.add (a);                      // 0
  f.add (b);                      // 1
  f.add (f.randomDescriptor());   // 2: unique
  f.add (Fixture::moved (a, 50)); // 3: like 0
  f.add (Fixture::moved (b, 90)); // 4: like 1
  mid::SelfMatcher matcher;
  matcher.setMaxDescriptorDistance (100.0f);
  const auto matches = f.match (matcher);
  ASSERT_EQ (matches.size(), 4u);
  EXPECT_EQ (matchOf (matches, 0), 3);
  EXPECT_EQ (matchOf (matches, 3), 0);
  EXPECT_EQ (matchOf (matches, 1), 4);
  EXPECT_EQ (matchOf (matches, 4), 1);
  EXPECT_EQ (matchOf (matches, 2), -1);
  EXPECT_FLOAT_EQ (matches[0].distance, 50.0f);
  for (std::size_t i = 1; i < matches.size(); ++i)
    EXPECT_LT (matches[i - 1].index_query, matches[i].index_query);

  matcher.setMaxDescriptorDistance (80.0f);
  EXPECT_EQ (f.match (matcher).size(), 2u);
}

TEST (SelfMatcher, SkipsCandidatesInTheQuerysOwnNeighbourhood)
{
  Fixture f;
  const auto a = f.randomDescriptor();
  f.add (a, 0.0f);                       // 0
  f.add (Fixture::moved (a, 1), 0.005f); // 1: same spot, other orientation
  f.add (Fixture::moved (a, 40), 0.5f);  // 2: the other instance
  mid::SelfMatcher matcher;
  const auto matches = f.match (matcher);
  EXPECT_EQ (matchOf (matches, 0), 2);
  EXPECT_EQ (matchOf (matches, 1), 2);
  EXPECT_EQ (matchOf (matches, 2), 1);

  matcher.setMinKeypointDistance (0.0f);
  EXPECT_EQ (matchOf (f.match (matcher), 0), 1);
}

TEST (SelfMatcher, RatioTestAndMutualCheck)
{
  Fixture f;
  const auto a = f.randomDescriptor();
  f.add (a);                         // 0
  f.add (Fixture::moved (a, 30));    // 1: best of 0
  f.add (Fixture::moved (a, 35, 1)); // 2: a close second
  mid::SelfMatcher matcher;
  EXPECT_EQ (f.match (matcher).size(), 3u);
  matcher.setMaxDistanceRatio (0.8f);
  EXPECT_EQ (matchOf (f.match (matcher), 0), -1);

  // 2's best is 0 but 0's best is 1: the mutual check drops 2 -> 0.
  matcher.setMaxDistanceRatio (1.0f);
  matcher.setMutualCheck (true);
  const auto mutual = f.match (matcher);
  EXPECT_EQ (matchOf (mutual, 0), 1);
  EXPECT_EQ (matchOf (mutual, 1), 0);
  EXPECT_EQ (matchOf (mutual, 2), -1);
}

TEST (SelfMatcher, KeepsTheKMostSimilarKeypointsEachPairOnce)
{
  // Three copies of a feature (0, 1, 2) and a fourth keypoint that matches nothing.
  Fixture f;
  const auto a = f.randomDescriptor();
  f.add (a);                         // 0
  f.add (Fixture::moved (a, 20));    // 1: best of 0
  f.add (Fixture::moved (a, 30, 1)); // 2: 30 from 0, 36 from 1
  f.add (f.randomDescriptor());      // 3
  mid::SelfMatcher matcher;
  matcher.setMaxDescriptorDistance (100.0f);
  EXPECT_EQ (f.match (matcher).size(),
             3u); // 0->1, 1->0, 2->1: pair (0, 2) never matched
  matcher.setMaxMatchesPerKeypoint (2);
  const auto matches = f.match (matcher);
  // The three best matches first, then 1->2 (1's second), the only pair still missing; 0's
  // and 2's second candidates form pairs already matched.
  ASSERT_EQ (matches.size(), 4u);
  EXPECT_EQ (matches[3].index_query, 1);
  EXPECT_EQ (matches[3].index_match, 2);
  EXPECT_NEAR (matches[3].distance, std::sqrt (20.0f * 20.0f + 30.0f * 30.0f), 1e-3f);
  matcher.setMaxMatchesPerKeypoint (0);
  pcl::Correspondences refused{pcl::Correspondence (0, 1, 0.0f)};
  EXPECT_FALSE (matcher.match (refused));
  EXPECT_TRUE (refused.empty());
}

TEST (SelfMatcher, RefusesBadInputWithClearedOutput)
{
  Fixture f;
  f.add (f.randomDescriptor());
  f.add (f.randomDescriptor());
  mid::SelfMatcher matcher;
  pcl::Correspondences matches (3);
  EXPECT_FALSE (matcher.match (matches));
  EXPECT_TRUE (matches.empty());

  matcher.setInputKeypoints (f.keypoints);
  matcher.setInputDescriptors (f.descriptors);
  f.descriptors->push_back (f.randomDescriptor());
  matches.resize (3);
  EXPECT_FALSE (matcher.match (matches));
  EXPECT_TRUE (matches.empty());
  f.descriptors->resize (2);

  for (const float bad : {0.0f, -1.0f, NAN}) {
    matcher.setMaxDescriptorDistance (bad);
    EXPECT_FALSE (matcher.match (matches));
  }
  matcher.setMaxDescriptorDistance (200.0f);
  matcher.setMaxDistanceRatio (1.5f);
  EXPECT_FALSE (matcher.match (matches));
  matcher.setMaxDistanceRatio (1.0f);
  matcher.setMinKeypointDistance (-0.1f);
  EXPECT_FALSE (matcher.match (matches));
  matcher.setMinKeypointDistance (0.01f);
  EXPECT_TRUE (matcher.match (matches));
}

TEST (SelfMatcher, MatchesBetweenTwoCopiesAgreeWithTheKnownRigidMotion)
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

  const auto& image = extractor.getImageKeypoints();
  auto in_a = [&] (pcl::index_t i) {
    return scene.rect_a.contains (cv::Point (
        static_cast<int> (std::lround (image[static_cast<std::size_t> (i)].u)),
        static_cast<int> (std::lround (image[static_cast<std::size_t> (i)].v))));
  };
  std::size_t across = 0, consistent = 0;
  for (const auto& m : matches) {
    const bool query_in_a = in_a (m.index_query), match_in_a = in_a (m.index_match);
    if (query_in_a == match_in_a)
      continue;
    ++across;
    const Eigen::Vector3f p =
        (*keypoints)[static_cast<std::size_t> (m.index_query)].getVector3fMap();
    const Eigen::Vector3f q =
        (*keypoints)[static_cast<std::size_t> (m.index_match)].getVector3fMap();
    const Eigen::Vector3f predicted =
        query_in_a ? scene.a_to_b * p : scene.a_to_b.inverse() * p;
    // One pixel at 0.8 m is 1.5 mm; keypoints are rounded to pixels on both sides.
    if ((predicted - q).norm() < 0.004f)
      ++consistent;
  }
  EXPECT_GT (across, 0.6 * static_cast<double> (keypoints->size()));
  EXPECT_GE (consistent,
             static_cast<std::size_t> (0.95 * static_cast<double> (across)));
  EXPECT_GE (across,
             static_cast<std::size_t> (0.9 * static_cast<double> (matches.size())));
}
