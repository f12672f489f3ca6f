// renderOverlay on a scene with a known repeated pattern: every instance's box is drawn in its
// object's color, and the rest of the image is the scene's color image, untouched; on boxes
// lying on a table, each object's box is drawn where the true boxes are.

#include "boxes_on_a_table.h"
#include "rendered_objects_scene.h"
#include "temporary_folder.h"
#include "two_copies_scene.h"

#include <mid/discovery/multi_instance_discovery.h>
#include <mid/visualization/intrinsics_estimation.h>
#include <mid/visualization/object_colors.h>
#include <mid/visualization/overlay.h>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace {

struct Box
{
  int u_min, v_min, u_max, v_max;
};

/** The rectangle of an instance's keypoints, rounded as the overlay draws it. */
Box
boxOf (const mid::DiscoveryResult& result, const mid::ModelInstance& instance)
{
  float u_min = std::numeric_limits<float>::max(), v_min = u_min;
  float u_max = std::numeric_limits<float>::lowest(), v_max = u_max;
  for (const auto k : instance.keypoints) {
    const auto& keypoint = result.image_keypoints[static_cast<std::size_t> (k)];
    u_min = std::min (u_min, keypoint.u);
    v_min = std::min (v_min, keypoint.v);
    u_max = std::max (u_max, keypoint.u);
    v_max = std::max (v_max, keypoint.v);
  }
  return {cvRound (u_min), cvRound (v_min), cvRound (u_max), cvRound (v_max)};
}

cv::Vec3b
bgr (const mid::visualization::ObjectColor& color)
{
  return {color.b, color.g, color.r};
}

class Overlay : public ::testing::Test
{
protected:
  void
  SetUp () override
  {
    scene_ = mid::test::makeTwoCopiesScene();
    mid::MultiInstanceDiscovery<pcl::PointXYZRGB> discovery;
    discovery.setInputCloud (scene_.cloud);
    ASSERT_TRUE (discovery.discover (result_));
    ASSERT_EQ (result_.models.size(), 1u);
    ASSERT_EQ (result_.models[0].instances.size(), 2u);
  }

  mid::test::TwoCopiesScene scene_;
  mid::DiscoveryResult result_;
};

} // namespace

TEST_F (Overlay, DrawsEachInstanceBoxInItsObjectColorAndKeepsTheScene)
{
  cv::Mat image;
  ASSERT_TRUE (mid::visualization::renderOverlay (*scene_.cloud, result_, image));
  ASSERT_EQ (image.type(), CV_8UC3);
  ASSERT_EQ (image.cols, 640);
  ASSERT_EQ (image.rows, 480);

  // Where the overlay may draw: each box, its keypoint circles and its label, with a margin.
  cv::Mat drawn (image.size(), CV_8UC1, cv::Scalar (0));
  for (std::size_t m = 0; m < result_.models.size(); ++m) {
    const cv::Vec3b color = bgr (mid::visualization::objectColor (m));
    for (const auto& instance : result_.models[m].instances) {
      const Box box = boxOf (result_, instance);
      EXPECT_GT (box.u_max - box.u_min, 50);
      EXPECT_GT (box.v_max - box.v_min, 50);
      for (int u = box.u_min; u <= box.u_max; ++u) {
        EXPECT_EQ (image.at<cv::Vec3b> (box.v_min, u), color) << "top edge, u " << u;
        EXPECT_EQ (image.at<cv::Vec3b> (box.v_max, u), color) << "bottom edge, u " << u;
      }
      for (int v = box.v_min; v <= box.v_max; ++v) {
        EXPECT_EQ (image.at<cv::Vec3b> (v, box.u_min), color) << "left edge, v " << v;
        EXPECT_EQ (image.at<cv::Vec3b> (v, box.u_max), color) << "right edge, v " << v;
      }
      constexpr int kMargin = 30;
      cv::rectangle (drawn,
                     cv::Point (box.u_min - kMargin, box.v_min - kMargin),
                     cv::Point (box.u_max + kMargin, box.v_max + kMargin),
                     cv::Scalar (255),
                     cv::FILLED);
    }
  }
  std::size_t kept = 0, changed = 0;
  for (int v = 0; v < image.rows; ++v)
    for (int u = 0; u < image.cols; ++u) {
      if (drawn.at<uchar> (v, u) != 0)
        continue;
      const auto& point = scene_.cloud->at (u, v);
      (image.at<cv::Vec3b> (v, u) == cv::Vec3b (point.b, point.g, point.r) ? kept
                                                                           : changed) +=
          1;
    }
  EXPECT_EQ (changed, 0u);
  EXPECT_GT (kept, 640u * 480u / 2);
}

TEST_F (Overlay, SavesAPng)
{
  const mid::test::TemporaryFolder folder;
  ASSERT_TRUE (mid::visualization::saveOverlay (
      folder.file ("overlay.png"), *scene_.cloud, result_));
  cv::Mat expected,
      written = cv::imread (folder.file ("overlay.png"), cv::IMREAD_COLOR);
  ASSERT_TRUE (mid::visualization::renderOverlay (*scene_.cloud, result_, expected));
  ASSERT_EQ (written.size(), expected.size());
  EXPECT_EQ (cv::norm (written, expected, cv::NORM_INF), 0.0);
  EXPECT_FALSE (mid::visualization::saveOverlay (
      folder.file ("missing/overlay.png"), *scene_.cloud, result_));
}

TEST_F (Overlay, RefusesAnUnorganizedCloudOrAKeypointWithoutPixel)
{
  cv::Mat image (2, 2, CV_8UC3);
  pcl::PointCloud<pcl::PointXYZRGB> flat (100, 1);
  EXPECT_FALSE (mid::visualization::renderOverlay (flat, result_, image));
  EXPECT_TRUE (image.empty());

  mid::DiscoveryResult broken = result_;
  broken.models[0].instances[1].keypoints.push_back (
      static_cast<pcl::index_t> (broken.image_keypoints.size()));
  image = cv::Mat (2, 2, CV_8UC3);
  EXPECT_FALSE (mid::visualization::renderOverlay (*scene_.cloud, broken, image));
  EXPECT_TRUE (image.empty());
}

TEST (OverlayWithoutObjects, IsTheColorImage)
{
  const auto scene = mid::test::makeTwoCopiesScene();
  cv::Mat image;
  ASSERT_TRUE (
      mid::visualization::renderOverlay (*scene.cloud, mid::DiscoveryResult(), image));
  for (int v = 0; v < image.rows; v += 7)
    for (int u = 0; u < image.cols; u += 7) {
      const auto& point = scene.cloud->at (u, v);
      ASSERT_EQ (image.at<cv::Vec3b> (v, u), cv::Vec3b (point.b, point.g, point.r));
    }
}

TEST (OverlayBoxes, DrawsEachObjectsBoxOnEveryCopy)
{
  // Three copies of one box lying apart on a table: the result gives the object's box, agreed
  // on by all three, and the overlay draws it at each instance's pose. The true boxes' edges,
  // projected by the cloud's camera, are where the drawn edges are: most of their pixels (the
  // visible and the hidden edges alike) lie within 3 pixels of one in the object's color.
  mid::test::RenderedObjectsScene scene;
  mid::DiscoveryResult result;
  ASSERT_NO_FATAL_FAILURE (mid::test::discoverBoxesOnATable (scene, result));
  cv::Mat image;
  ASSERT_TRUE (mid::visualization::renderOverlay (*scene.cloud, result, image));
  for (const double share : mid::test::boxOutlinesShown (
           image, bgr (mid::visualization::objectColor (0)), 0, scene))
    EXPECT_GT (share, 0.8);
  // Without the boxes in the result no edge is drawn, nor for a box one copy alone gives.
  mid::DiscoveryResult without = result;
  without.model_sizes.clear();
  cv::Mat plain;
  ASSERT_TRUE (mid::visualization::renderOverlay (*scene.cloud, without, plain));
  EXPECT_GT (cv::norm (image, plain, cv::NORM_L1), 0.0);
  mid::DiscoveryResult one_copy = result;
  one_copy.model_sizes[0].agreeing = 1;
  cv::Mat unsure;
  ASSERT_TRUE (mid::visualization::renderOverlay (*scene.cloud, one_copy, unsure));
  EXPECT_EQ (cv::norm (unsure, plain, cv::NORM_L1), 0.0);
}
