// Off-screen screenshots of the scene viewer, under a virtual X display (CTest runs this program
// with xvfb-run -a, label "rendering"): the picture is not blank, and each instance's model
// landmarks, projected with the camera model, appear in their object's color.

#include "app_runner.h"
#include "boxes_on_a_table.h"
#include "temporary_folder.h"
#include "two_copies_scene.h"

#include <mid/discovery/multi_instance_discovery.h>
#include <mid/io/organized_cloud_io.h>
#include <mid/visualization/discovery_viewer.h>
#include <mid/visualization/object_colors.h>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <pcl/io/pcd_io.h>

#include <algorithm>
#include <cstdlib>

namespace {

/** The camera of makeTwoCopiesScene (test/common/two_copies_scene.cpp). */
constexpr double kFocal = 525.0, kCx = 319.5, kCy = 239.5;
constexpr int kImageWidth = 640, kImageHeight = 480;

/** True if two colors differ by at most 30 (sum over the channels). */
bool
similar (const cv::Vec3b& a, const cv::Vec3b& b)
{
  return std::abs (a[0] - b[0]) + std::abs (a[1] - b[1]) + std::abs (a[2] - b[2]) <= 30;
}

/** True if a pixel within `radius` of `at` has (about) `color`, BGR. */
bool
colorNear (const cv::Mat& image,
           const cv::Point2d& at,
           const cv::Vec3b& color,
           int radius)
{
  const int u0 = cvRound (at.x), v0 = cvRound (at.y);
  for (int v = std::max (0, v0 - radius); v <= std::min (image.rows - 1, v0 + radius);
       ++v)
    for (int u = std::max (0, u0 - radius); u <= std::min (image.cols - 1, u0 + radius);
         ++u)
      if (similar (image.at<cv::Vec3b> (v, u), color))
        return true;
  return false;
}

/** The share of the result's posed landmarks that appear in their object's color where the
  * camera sees them, in a scene viewport `scene_width` x `height` pixels at the screenshot's
  * left, the camera's image fitted in it whole and centred.
  */
double
shareOfLandmarksSeen (const cv::Mat& image,
                      const mid::DiscoveryResult& result,
                      int scene_width)
{
  const double scale = std::min (static_cast<double> (scene_width) / kImageWidth,
                                 static_cast<double> (image.rows) / kImageHeight);
  const double offset_u = 0.5 * (scene_width - scale * kImageWidth);
  const double offset_v = 0.5 * (image.rows - scale * kImageHeight);
  std::size_t seen = 0, total = 0;
  for (std::size_t m = 0; m < result.models.size(); ++m) {
    const auto color = mid::visualization::objectColor (m);
    const cv::Vec3b bgr (color.b, color.g, color.r);
    for (const auto& instance : result.models[m].instances)
      for (const auto& landmark : result.models[m].landmarks) {
        const Eigen::Vector3f p =
            instance.pose.topLeftCorner<3, 3>() * landmark.getVector3fMap() +
            instance.pose.topRightCorner<3, 1>();
        const double u = kFocal * p.x() / p.z() + kCx, v = kFocal * p.y() / p.z() + kCy;
        const cv::Point2d pixel (offset_u + (u + 0.5) * scale - 0.5,
                                 offset_v + (v + 0.5) * scale - 0.5);
        seen += colorNear (image, pixel, bgr, 1) ? 1 : 0;
        ++total;
      }
  }
  return total > 0 ? static_cast<double> (seen) / static_cast<double> (total) : 0.0;
}

/** Pixels of (about) the given color, BGR, in a column range. */
std::size_t
countColor (const cv::Mat& image, const cv::Vec3b& color, int u_begin, int u_end)
{
  std::size_t count = 0;
  for (int v = 0; v < image.rows; ++v)
    for (int u = u_begin; u < u_end; ++u)
      count += similar (image.at<cv::Vec3b> (v, u), color) ? 1 : 0;
  return count;
}

cv::Vec3b
objectBgr (std::size_t object)
{
  const auto color = mid::visualization::objectColor (object);
  return {color.b, color.g, color.r};
}

/** Not blank: many different gray levels. */
void
expectNotBlank (const cv::Mat& image)
{
  cv::Scalar mean, deviation;
  cv::meanStdDev (image, mean, deviation);
  EXPECT_GT (deviation[0] + deviation[1] + deviation[2], 30.0);
  EXPECT_GT (mean[0] + mean[1] + mean[2], 30.0);
}

class Rendering : public ::testing::Test
{
protected:
  void
  SetUp () override
  {
    ASSERT_NE (std::getenv ("DISPLAY"), nullptr) << "run this test under xvfb-run -a";
    scene_ = mid::test::makeTwoCopiesScene();
    mid::MultiInstanceDiscovery<pcl::PointXYZRGB> discovery;
    discovery.setInputCloud (scene_.cloud);
    ASSERT_TRUE (discovery.discover (result_));
    ASSERT_EQ (result_.models.size(), 1u);
    ASSERT_EQ (result_.models[0].instances.size(), 2u);
    viewer_.setInputCloud (scene_.cloud);
    viewer_.setResult (result_);
  }

  cv::Mat
  screenshot (int width, int height)
  {
    EXPECT_TRUE (viewer_.saveScreenshot (folder_.file ("shot.png"), width, height));
    return cv::imread (folder_.file ("shot.png"), cv::IMREAD_COLOR);
  }

  mid::test::TemporaryFolder folder_;
  mid::test::TwoCopiesScene scene_;
  mid::DiscoveryResult result_;
  mid::visualization::DiscoveryViewer<pcl::PointXYZRGB> viewer_;
};

} // namespace

TEST_F (Rendering, CameraViewShowsTheLandmarksWhereTheCameraSeesThem)
{
  viewer_.setShowModelPanel (false);
  const cv::Mat image = screenshot (kImageWidth, kImageHeight);
  ASSERT_EQ (image.cols, kImageWidth);
  ASSERT_EQ (image.rows, kImageHeight);
  expectNotBlank (image);
  EXPECT_GT (shareOfLandmarksSeen (image, result_, kImageWidth), 0.9);
  // Far from both copies: the wall, gray 90, seen through the camera.
  EXPECT_TRUE (colorNear (image, cv::Point2d (20, 20), cv::Vec3b (90, 90, 90), 0));
  EXPECT_TRUE (colorNear (image, cv::Point2d (600, 450), cv::Vec3b (90, 90, 90), 0));
}

TEST_F (Rendering, ModelPanelOnTheRightLeavesTheCameraViewFitted)
{
  const cv::Mat image = screenshot (800, 480);
  ASSERT_EQ (image.cols, 800);
  expectNotBlank (image);
  const int scene_width = static_cast<int> (
      std::lround (800 * (1.0 - mid::visualization::MODEL_PANEL_WIDTH)));
  EXPECT_GT (shareOfLandmarksSeen (image, result_, scene_width), 0.9);
  EXPECT_GT (countColor (image, objectBgr (0), scene_width, image.cols), 50u);
}

TEST_F (Rendering, MatchLinesAndAnotherViewpointChangeThePicture)
{
  viewer_.setShowModelPanel (false);
  const cv::Mat plain = screenshot (320, 240);
  viewer_.setShowMatches (true);
  const cv::Mat matches = screenshot (320, 240);
  viewer_.setShowMatches (false);
  viewer_.setViewpoint (Eigen::Vector3f (0.4f, -0.3f, 0.0f));
  const cv::Mat turned = screenshot (320, 240);
  expectNotBlank (turned);
  EXPECT_GT (cv::norm (plain, matches, cv::NORM_L1), 1000.0);
  EXPECT_GT (cv::norm (plain, turned, cv::NORM_L1), 1000.0);
  EXPECT_GT (countColor (turned, objectBgr (0), 0, turned.cols), 20u);
}

TEST (RenderingBoxes, DrawsEachObjectsBoxOnEveryCopy)
{
  // Three copies of one box lying apart on a table: the view through the camera draws the
  // object's box, which all three agree on, at each instance in the object's colour in front
  // of the scene. Most points along the true boxes' projected edges then lie within 3 pixels
  // of that colour; without the boxes in the result, or with a box one copy alone gives, few
  // do (the landmarks, in that colour too, lie inside the boxes' outlines).
  ASSERT_NE (std::getenv ("DISPLAY"), nullptr) << "run this test under xvfb-run -a";
  mid::test::RenderedObjectsScene scene;
  mid::DiscoveryResult result;
  ASSERT_NO_FATAL_FAILURE (mid::test::discoverBoxesOnATable (scene, result));
  const mid::test::TemporaryFolder folder;
  const auto edgesShown = [&] (const mid::DiscoveryResult& shown) {
    mid::visualization::DiscoveryViewer<pcl::PointXYZRGBA> viewer;
    viewer.setInputCloud (scene.cloud);
    viewer.setResult (shown);
    viewer.setShowModelPanel (false);
    EXPECT_TRUE (
        viewer.saveScreenshot (folder.file ("boxes.png"), kImageWidth, kImageHeight));
    const cv::Mat image = cv::imread (folder.file ("boxes.png"), cv::IMREAD_COLOR);
    expectNotBlank (image);
    return mid::test::boxOutlinesShown (image, objectBgr (0), 30, scene);
  };
  for (const double share : edgesShown (result))
    EXPECT_GT (share, 0.8);
  mid::DiscoveryResult without = result;
  without.model_sizes.clear();
  for (const double share : edgesShown (without))
    EXPECT_LT (share, 0.5);
  mid::DiscoveryResult one_copy = result;
  one_copy.model_sizes[0].agreeing = 1;
  for (const double share : edgesShown (one_copy))
    EXPECT_LT (share, 0.5);
}

TEST_F (Rendering, RefusesAnUnwritableFile)
{
  EXPECT_FALSE (viewer_.saveScreenshot (folder_.file ("missing/shot.png"), 320, 240));
  EXPECT_FALSE (viewer_.saveScreenshot (folder_.file ("shot.png"), 0, 240));
}

TEST (RenderingApp, ScreenshotOfTheDiscoveryApp)
{
  ASSERT_NE (std::getenv ("DISPLAY"), nullptr) << "run this test under xvfb-run -a";
  const mid::test::TemporaryFolder folder;
  const auto scene = mid::test::makeTwoCopiesScene();
  ASSERT_EQ (
      pcl::io::savePCDFileBinaryCompressed (folder.file ("scene.pcd"), *scene.cloud),
      0);
  const auto run = mid::test::runCommand (std::string (MID_DISCOVERY_APP) + " " +
                                          folder.file ("scene.pcd") + " -screenshot " +
                                          folder.file ("shot.png") + " -overlay " +
                                          folder.file ("overlay.png"));
  ASSERT_EQ (run.exit_code, 0) << run.output;
  const cv::Mat image = cv::imread (folder.file ("shot.png"), cv::IMREAD_COLOR);
  ASSERT_EQ (image.cols, 640); // the default size
  ASSERT_EQ (image.rows, 480);
  expectNotBlank (image);
  EXPECT_EQ (cv::imread (folder.file ("overlay.png")).size(), cv::Size (640, 480));
  EXPECT_EQ (folder.entries(), 3u); // scene, screenshot, overlay: nothing partial left

  // The app's result, recomputed here: the pipeline is deterministic.
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZRGBA>>();
  ASSERT_TRUE (mid::io::loadOrganizedPCD (folder.file ("scene.pcd"), *cloud));
  mid::MultiInstanceDiscovery<pcl::PointXYZRGBA> discovery;
  discovery.setInputCloud (cloud);
  mid::DiscoveryResult result;
  ASSERT_TRUE (discovery.discover (result));
  ASSERT_EQ (result.models.size(), 1u);
  const int scene_width = static_cast<int> (
      std::lround (640 * (1.0 - mid::visualization::MODEL_PANEL_WIDTH)));
  EXPECT_GT (shareOfLandmarksSeen (image, result, scene_width), 0.9);
  EXPECT_GT (countColor (image, objectBgr (0), scene_width, image.cols), 50u);

  const auto sized = mid::test::runCommand (
      std::string (MID_DISCOVERY_APP) + " " + folder.file ("scene.pcd") +
      " -screenshot " + folder.file ("big.png") +
      " -size 1024 600 -viewpoint 0.3 -0.2 0.1 -draw_matches");
  ASSERT_EQ (sized.exit_code, 0) << sized.output;
  const cv::Mat big = cv::imread (folder.file ("big.png"), cv::IMREAD_COLOR);
  EXPECT_EQ (big.size(), cv::Size (1024, 600));
  expectNotBlank (big);
}
