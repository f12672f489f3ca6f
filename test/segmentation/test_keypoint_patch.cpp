#include <mid/segmentation/keypoint_patch.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace {

/** A keypoint at (x, y, z) metres. */
pcl::PointNormal
at (float x, float y, float z)
{
  pcl::PointNormal p;
  p.x = x;
  p.y = y;
  p.z = z;
  p.normal_x = p.normal_y = 0.0f;
  p.normal_z = -1.0f;
  return p;
}

/** Ten keypoints within 2 cm of (0, 0, 1) (indices 0, 2, ..., 18), six within 2 cm of
  * (0.3, 0, 1) (indices 1, 3, ..., 11) and four far apart from everything (13, 15, 17, 19).
  */
mid::KeypointCloud
twoGroups ()
{
  mid::KeypointCloud keypoints;
  for (int i = 0; i < 20; ++i) {
    const float t = 0.6f * static_cast<float> (i),
                r = 0.002f * static_cast<float> (i % 9);
    if (i % 2 == 0)
      keypoints.push_back (at (r * std::cos (t), r * std::sin (t), 1.0f));
    else if (i < 12)
      keypoints.push_back (at (0.3f + r * std::cos (t), r * std::sin (t), 1.0f));
    else
      keypoints.push_back (at (-0.5f + 0.2f * static_cast<float> (i - 13), 0.4f, 1.2f));
  }
  return keypoints;
}

} // namespace

TEST (KeypointPatch, TakesTheDensestGroupOfFreeKeypoints)
{
  const mid::KeypointCloud keypoints = twoGroups();
  std::vector<bool> free (keypoints.size(), true);
  pcl::Indices patch;
  ASSERT_TRUE (mid::densestKeypointPatch (keypoints, free, 0.05f, 5, patch));
  ASSERT_EQ (patch.size(), 10u);
  EXPECT_EQ (patch.front(),
             0); // every member sees all ten: ties go to the lowest index
  pcl::Indices sorted = patch;
  std::sort (sorted.begin(), sorted.end());
  EXPECT_EQ (sorted, (pcl::Indices{0, 2, 4, 6, 8, 10, 12, 14, 16, 18}));

  // The first group taken: the second; a keypoint that is not free never joins.
  for (int i = 0; i < 20; i += 2)
    free[static_cast<std::size_t> (i)] = false;
  free[5] = false;
  ASSERT_TRUE (mid::densestKeypointPatch (keypoints, free, 0.05f, 5, patch));
  EXPECT_EQ (patch, (pcl::Indices{1, 3, 7, 9, 11}));

  // Fewer free keypoints together than the minimum: no patch.
  ASSERT_TRUE (mid::densestKeypointPatch (keypoints, free, 0.05f, 6, patch));
  EXPECT_TRUE (patch.empty());
  // A radius too small to hold two keypoints of a group.
  ASSERT_TRUE (mid::densestKeypointPatch (keypoints, free, 0.0001f, 2, patch));
  EXPECT_TRUE (patch.empty());
}

TEST (KeypointPatch, IgnoresKeypointsWithoutAPosition)
{
  mid::KeypointCloud keypoints = twoGroups();
  keypoints[0].x = std::nanf ("");
  const std::vector<bool> free (keypoints.size(), true);
  pcl::Indices patch;
  ASSERT_TRUE (mid::densestKeypointPatch (keypoints, free, 0.05f, 5, patch));
  ASSERT_EQ (patch.size(), 9u);
  EXPECT_EQ (patch.front(), 2);
  EXPECT_EQ (std::count (patch.begin(), patch.end(), 0), 0);
}

TEST (KeypointPatch, RefusesBadInputWithClearedOutput)
{
  const mid::KeypointCloud keypoints = twoGroups();
  const std::vector<bool> free (keypoints.size(), true);
  pcl::Indices patch{7};
  EXPECT_FALSE (mid::densestKeypointPatch (
      keypoints, std::vector<bool> (3, true), 0.05f, 5, patch));
  EXPECT_TRUE (patch.empty());
  for (const float radius : {0.0f, -1.0f, std::nanf ("")}) {
    patch = {7};
    EXPECT_FALSE (mid::densestKeypointPatch (keypoints, free, radius, 5, patch));
    EXPECT_TRUE (patch.empty());
  }
  patch = {7};
  EXPECT_FALSE (mid::densestKeypointPatch (keypoints, free, 0.05f, 0, patch));
  EXPECT_TRUE (patch.empty());
  ASSERT_TRUE (mid::densestKeypointPatch (mid::KeypointCloud(), {}, 0.05f, 1, patch));
  EXPECT_TRUE (patch.empty());
}
