#include "simulation_test_utils.h"
#include "temporary_folder.h"

#include <mid/simulation/frame_io.h>
#include <mid/simulation/ground_truth_json.h>
#include <mid/simulation/scene_renderer.h>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <pcl/point_types.h>

#include <cmath>
#include <limits>

using namespace mid::simulation;
using mid::simulation::test::facingPlanePose;
using mid::simulation::test::makeColoredBox;
using mid::simulation::test::makeFacingPlane;
using mid::simulation::test::makePose;

namespace {

struct BoxScene
{
  Scene scene;
  BoxShape::Ptr box;
  Eigen::Isometry3d pose;
  RenderedFrame frame;
};

BoxScene
renderBox ()
{
  BoxScene result;
  result.box = makeColoredBox (0.15, 0.1, 0.07);
  result.box->setName ("test \"box\"");
  result.pose =
      makePose (Eigen::Vector3d (0.03, -0.02, 0.8), 0.9, Eigen::Vector3d (1, 1, 0));
  result.scene.addObject (result.box, result.pose);
  result.scene.addBackgroundObject (makeFacingPlane(), facingPlanePose (1.2));
  SceneRenderer renderer;
  EXPECT_TRUE (renderer.render (result.scene, result.frame));
  return result;
}

} // namespace

TEST (SimulationFrameIO, QuantizeDepthRoundsAndDropsWhatCannotBeStored)
{
  cv::Mat depth = (cv::Mat_<float> (1, 6) << 0.0f,
                   0.4004f,
                   1.2346f,
                   -1.0f,
                   70.0f,
                   std::numeric_limits<float>::quiet_NaN());
  cv::Mat depth_16u;
  ASSERT_TRUE (quantizeDepth (depth, MILLIMETRE_DEPTH_SCALE, depth_16u));
  ASSERT_EQ (depth_16u.type(), CV_16UC1);
  EXPECT_EQ (depth_16u.at<std::uint16_t> (0, 0), 0);
  EXPECT_EQ (depth_16u.at<std::uint16_t> (0, 1), 400);
  EXPECT_EQ (depth_16u.at<std::uint16_t> (0, 2), 1235);
  EXPECT_EQ (depth_16u.at<std::uint16_t> (0, 3), 0);
  EXPECT_EQ (depth_16u.at<std::uint16_t> (0, 4), 0); // beyond 65.535 m
  EXPECT_EQ (depth_16u.at<std::uint16_t> (0, 5), 0);
  EXPECT_FALSE (quantizeDepth (depth, 0.0, depth_16u));
  EXPECT_TRUE (depth_16u.empty());
  EXPECT_FALSE (quantizeDepth (cv::Mat (2, 2, CV_16UC1), 0.001, depth_16u));
}

TEST (SimulationFrameIO, CloudPointsLieOnTheSurfaceWithinTheQuantization)
{
  const BoxScene data = renderBox();
  const double scale =
      0.00002; // 20 micrometres: 1.31 m of range, enough for this scene
  pcl::PointCloud<pcl::PointXYZRGB> cloud;
  ASSERT_TRUE (frameToCloud (data.frame, scale, cloud));
  ASSERT_EQ (cloud.width, 640u);
  ASSERT_EQ (cloud.height, 480u);
  const Eigen::Isometry3d camera_to_model = data.pose.inverse();
  int on_box = 0;
  for (int v = 0; v < 480; ++v)
    for (int u = 0; u < 640; ++u) {
      const pcl::PointXYZRGB& point = cloud.at (u, v);
      const cv::Vec3b color = data.frame.color.at<cv::Vec3b> (v, u);
      EXPECT_EQ (point.b, color[0]);
      EXPECT_EQ (point.r, color[2]);
      if (data.frame.instances.at<int> (v, u) != 0) {
        EXPECT_NEAR (point.z, 1.2, 0.5 * scale + 1e-6); // the wall
        continue;
      }
      const Eigen::Vector3d p (point.x, point.y, point.z);
      // z is off by at most half a unit; x and y follow z along the pixel ray.
      EXPECT_NEAR (point.z, data.frame.depth.at<float> (v, u), 0.5 * scale + 1e-6);
      EXPECT_NEAR (data.box->signedDistance (camera_to_model * p), 0.0, scale + 2e-6);
      ++on_box;
    }
  EXPECT_EQ (on_box, data.frame.instance_stats[0].visible_pixels);
}

TEST (SimulationFrameIO, CloudInMillimetresMatchesTheWrittenPngPair)
{
  const BoxScene data = renderBox();
  pcl::PointCloud<pcl::PointXYZRGBA> cloud;
  ASSERT_TRUE (frameToCloud (data.frame, MILLIMETRE_DEPTH_SCALE, cloud));
  const mid::test::TemporaryFolder folder;
  const std::string color_path = folder.file ("rgb.png");
  const std::string depth_path = folder.file ("depth.png");
  ASSERT_TRUE (writeFrameImages (data.frame, color_path, depth_path));
  EXPECT_EQ (folder.entries(), 2u); // no temporary file left
  const cv::Mat color = cv::imread (color_path, cv::IMREAD_UNCHANGED);
  const cv::Mat depth = cv::imread (depth_path, cv::IMREAD_UNCHANGED);
  ASSERT_EQ (color.type(), CV_8UC3);
  ASSERT_EQ (depth.type(), CV_16UC1);
  EXPECT_EQ (cv::norm (color, data.frame.color, cv::NORM_INF), 0.0);
  for (int v = 0; v < 480; v += 5)
    for (int u = 0; u < 640; u += 5) {
      const std::uint16_t millimetres = depth.at<std::uint16_t> (v, u);
      EXPECT_EQ (millimetres,
                 static_cast<std::uint16_t> (
                     std::lround (data.frame.depth.at<float> (v, u) * 1000.0)));
      EXPECT_FLOAT_EQ (cloud.at (u, v).z, static_cast<float> (millimetres * 0.001));
    }
}

TEST (SimulationFrameIO, FailedWriteLeavesNoFile)
{
  const BoxScene data = renderBox();
  const mid::test::TemporaryFolder folder;
  // The depth file must be a PNG: nothing at all is written.
  EXPECT_FALSE (writeFrameImages (
      data.frame, folder.file ("rgb.png"), folder.file ("depth.jpg")));
  // An unknown colour extension makes the first write fail.
  EXPECT_FALSE (writeFrameImages (
      data.frame, folder.file ("rgb.unknown"), folder.file ("depth.png")));
  EXPECT_EQ (folder.entries(), 0u);
}

TEST (SimulationFrameIO, GroundTruthJsonHoldsCameraPosesAndStatistics)
{
  const BoxScene data = renderBox();
  const std::string json =
      formatGroundTruthJSON (data.scene, data.frame, 0.001, {{"seed", 42}});
  EXPECT_NE (
      json.find (
          "\"camera\": {\"width\": 640, \"height\": 480, \"fx\": 538, \"fy\": 538, "
          "\"cx\": 319.5, \"cy\": 239.5}"),
      std::string::npos)
      << json;
  EXPECT_NE (json.find ("\"depth_scale\": 0.001"), std::string::npos);
  EXPECT_NE (json.find ("\"seed\": 42"), std::string::npos);
  EXPECT_NE (json.find ("\"object\": \"test \\\"box\\\"\", \"type\": \"box\""),
             std::string::npos)
      << json;
  EXPECT_NE (
      json.find (
          "\"dimensions\": {\"size_x\": 0.15, \"size_y\": 0.1, \"size_z\": 0.07}"),
      std::string::npos);
  EXPECT_NE (json.find ("\"visible_pixels\": " +
                        std::to_string (data.frame.instance_stats[0].visible_pixels)),
             std::string::npos);
  const cv::Rect& bbox = data.frame.instance_stats[0].bbox;
  EXPECT_NE (json.find ("\"bbox\": [" + std::to_string (bbox.x) + ", " +
                        std::to_string (bbox.y) + ", " + std::to_string (bbox.width) +
                        ", " + std::to_string (bbox.height) + "]"),
             std::string::npos);
  EXPECT_NE (json.find ("\"type\": \"table_plane\""), std::string::npos);
  // The translation is the last column of the pose.
  EXPECT_NE (json.find ("0.03], ["), std::string::npos) << json;
  EXPECT_NE (json.find ("[0, 0, 0, 1]]"), std::string::npos);
  // Balanced brackets and braces.
  int braces = 0, brackets = 0;
  for (const char c : json) {
    braces += c == '{' ? 1 : (c == '}' ? -1 : 0);
    brackets += c == '[' ? 1 : (c == ']' ? -1 : 0);
  }
  EXPECT_EQ (braces, 0);
  EXPECT_EQ (brackets, 0);
}
