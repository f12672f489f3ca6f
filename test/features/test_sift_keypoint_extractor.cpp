#include "two_copies_scene.h"

#include <mid/features/sift_keypoint_extractor.h>

#include <gtest/gtest.h>

#include <limits>

namespace {

using Extractor = mid::SIFTKeypointExtractor<pcl::PointXYZRGB>;

bool
inside (const cv::Rect& rect, const mid::ImageKeypoint& kp, int margin = 0)
{
  const cv::Rect grown (rect.x - margin,
                        rect.y - margin,
                        rect.width + 2 * margin,
                        rect.height + 2 * margin);
  return grown.contains (cv::Point (static_cast<int> (std::lround (kp.u)),
                                    static_cast<int> (std::lround (kp.v))));
}

/** Keypoints on a patch's outline may round to a wall pixel just outside it. */
constexpr int kOutline = 3;

} // namespace

TEST (SIFTKeypointExtractor, LiftsKeypointsOntoTheSurfaceWithCameraFacingNormals)
{
  const auto scene = mid::test::makeTwoCopiesScene();
  Extractor extractor;
  extractor.setInputCloud (scene.cloud);
  mid::KeypointCloud keypoints;
  mid::SIFTDescriptorCloud descriptors;
  ASSERT_TRUE (extractor.compute (keypoints, descriptors));
  ASSERT_GT (keypoints.size(), 60u);
  ASSERT_EQ (descriptors.size(), keypoints.size());
  ASSERT_EQ (extractor.getImageKeypoints().size(), keypoints.size());

  std::size_t in_a = 0, in_b = 0;
  for (std::size_t i = 0; i < keypoints.size(); ++i) {
    const auto& image_kp = extractor.getImageKeypoints()[i];
    EXPECT_EQ (keypoints[i].getVector3fMap(),
               (*scene.cloud)[static_cast<std::size_t> (image_kp.pixel_index)]
                   .getVector3fMap());
    // Every point here lies on a fronto-parallel plane: the normal faces the camera exactly.
    EXPECT_NEAR (keypoints[i].normal_z, -1.0f, 1e-4f);
    EXPECT_NEAR (keypoints[i].curvature, 0.0f, 1e-4f);
    // A coarse-scale blob on a patch's corner may be centred up to its radius outside it.
    const int reach = std::max (kOutline, static_cast<int> (image_kp.size / 2));
    in_a += inside (scene.rect_a, image_kp, reach) ? 1 : 0;
    in_b += inside (scene.rect_b, image_kp, reach) ? 1 : 0;
    float norm = 0.0f;
    for (const float value : descriptors[i].histogram)
      norm += value * value;
    EXPECT_NEAR (std::sqrt (norm), 512.0f, 30.0f);
  }
  // The wall is untextured; the two copies hold (nearly) the same keypoints.
  EXPECT_EQ (in_a + in_b, keypoints.size());
  EXPECT_NEAR (static_cast<double> (in_a),
               static_cast<double> (in_b),
               0.15 * static_cast<double> (in_a));
}

TEST (SIFTKeypointExtractor, KeepsOnlyKeypointsWithValidDepth)
{
  const auto scene = mid::test::makeTwoCopiesScene();
  for (int v = scene.rect_b.y; v < scene.rect_b.br().y; ++v)
    for (int u = scene.rect_b.x; u < scene.rect_b.br().x; ++u)
      scene.cloud->at (u, v).z = std::numeric_limits<float>::quiet_NaN();
  Extractor extractor;
  extractor.setInputCloud (scene.cloud);
  mid::KeypointCloud keypoints;
  mid::SIFTDescriptorCloud descriptors;
  ASSERT_TRUE (extractor.compute (keypoints, descriptors));
  std::size_t in_a = 0;
  for (const auto& kp : extractor.getImageKeypoints()) {
    EXPECT_FALSE (inside (scene.rect_b, kp)) << kp.u << ", " << kp.v;
    in_a += inside (scene.rect_a, kp, kOutline) ? 1 : 0;
  }
  EXPECT_GT (in_a, 100u);
}

TEST (SIFTKeypointExtractor, HonoursIndicesAndTheKeypointCap)
{
  const auto scene = mid::test::makeTwoCopiesScene();
  auto indices = pcl::make_shared<pcl::Indices>();
  for (int v = scene.rect_a.y; v < scene.rect_a.br().y; ++v)
    for (int u = scene.rect_a.x; u < scene.rect_a.br().x; ++u)
      indices->push_back (v * static_cast<int> (scene.cloud->width) + u);
  Extractor extractor;
  extractor.setInputCloud (scene.cloud);
  extractor.setIndices (indices);
  mid::KeypointCloud keypoints;
  mid::SIFTDescriptorCloud descriptors;
  ASSERT_TRUE (extractor.compute (keypoints, descriptors));
  ASSERT_GT (keypoints.size(), 30u);
  for (const auto& kp : extractor.getImageKeypoints())
    EXPECT_TRUE (inside (scene.rect_a, kp));

  extractor.setMaxKeypoints (10);
  ASSERT_TRUE (extractor.compute (keypoints, descriptors));
  ASSERT_EQ (keypoints.size(), 10u);
  for (std::size_t i = 1; i < 10; ++i)
    EXPECT_GE (extractor.getImageKeypoints()[i - 1].response,
               extractor.getImageKeypoints()[i].response);
}

TEST (SIFTKeypointExtractor, IsDeterministic)
{
  const auto scene = mid::test::makeTwoCopiesScene();
  Extractor extractor;
  extractor.setInputCloud (scene.cloud);
  mid::KeypointCloud first, second;
  mid::SIFTDescriptorCloud first_descriptors, second_descriptors;
  ASSERT_TRUE (extractor.compute (first, first_descriptors));
  ASSERT_TRUE (extractor.compute (second, second_descriptors));
  ASSERT_EQ (first.size(), second.size());
  for (std::size_t i = 0; i < first.size(); ++i) {
    EXPECT_EQ (first[i].getVector3fMap(), second[i].getVector3fMap());
    EXPECT_TRUE (std::equal (first_descriptors[i].histogram,
                             first_descriptors[i].histogram + 128,
                             second_descriptors[i].histogram));
  }
}

TEST (SIFTKeypointExtractor, RefusesBadInputWithClearedOutputs)
{
  Extractor extractor;
  mid::KeypointCloud keypoints (3, 1);
  mid::SIFTDescriptorCloud descriptors (3, 1);
  EXPECT_FALSE (extractor.compute (keypoints, descriptors));
  EXPECT_TRUE (keypoints.empty());
  EXPECT_TRUE (descriptors.empty());

  auto flat = pcl::make_shared<pcl::PointCloud<pcl::PointXYZRGB>> (100, 1);
  extractor.setInputCloud (flat);
  EXPECT_FALSE (extractor.compute (keypoints, descriptors));

  extractor.setInputCloud (mid::test::makeTwoCopiesScene().cloud);
  extractor.setNormalRadius (0.0f);
  EXPECT_FALSE (extractor.compute (keypoints, descriptors));
  extractor.setNormalRadius (0.015f);
  extractor.setMaxKeypoints (-1);
  EXPECT_FALSE (extractor.compute (keypoints, descriptors));
  EXPECT_TRUE (keypoints.empty());
}
