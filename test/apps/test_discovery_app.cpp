// pcl_multi_instance_discovery on good and bad input: a clear one-line error and a non-zero exit
// for every unusable input, never a crash; counts for a scene with a known repeated pattern.

#include "app_runner.h"
#include "two_copies_scene.h"

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <pcl/io/pcd_io.h>

#include <filesystem>
#include <fstream>
#include <regex>

namespace {

namespace fs = std::filesystem;

class DiscoveryApp : public ::testing::Test
{
protected:
  void
  SetUp () override
  {
    const auto* info = ::testing::UnitTest::GetInstance ()->current_test_info ();
    dir_ = fs::temp_directory_path () / ("mid_test_app_" + std::string (info->name ()));
    fs::remove_all (dir_);
    fs::create_directories (dir_);
  }
  void
  TearDown () override { fs::remove_all (dir_); }

  std::string
  path (const std::string& name) const { return (dir_ / name).string (); }

  static mid::test::RunResult
  run (const std::string& arguments)
  {
    return mid::test::runCommand (std::string (MID_DISCOVERY_APP) + " " + arguments);
  }

  /** The app must refuse the input: non-zero exit, no crash, one error line naming it. */
  static void
  expectRefused (const std::string& arguments, const std::string& message)
  {
    const auto result = run (arguments);
    EXPECT_FALSE (result.crashed) << result.output;
    EXPECT_NE (result.exit_code, 0) << result.output;
    EXPECT_NE (result.output.find (message), std::string::npos)
        << "expected '" << message << "' in:\n" << result.output;
    EXPECT_EQ (std::count (result.output.begin (), result.output.end (), '\n'), 1)
        << result.output;
  }

  fs::path dir_;
};

} // namespace

TEST_F (DiscoveryApp, CountsKeypointsAndMatchesOfARepeatedPattern)
{
  const auto scene = mid::test::makeTwoCopiesScene ();
  ASSERT_EQ (pcl::io::savePCDFileBinaryCompressed (path ("scene.pcd"), *scene.cloud), 0);
  const auto result = run (path ("scene.pcd"));
  ASSERT_EQ (result.exit_code, 0) << result.output;
  std::smatch keypoints, matches;
  ASSERT_TRUE (std::regex_search (result.output, keypoints, std::regex ("keypoints: (\\d+)")));
  ASSERT_TRUE (std::regex_search (result.output, matches, std::regex ("matches: +(\\d+)")));
  // Two copies of one texture: nearly every keypoint finds its twin.
  EXPECT_GT (std::stoi (keypoints[1]), 100);
  EXPECT_GT (std::stoi (matches[1]), std::stoi (keypoints[1]) * 7 / 10);
  EXPECT_NE (result.output.find ("timing_ms"), std::string::npos);
}

TEST_F (DiscoveryApp, ReadsColorAndDepthPngsWithIntrinsics)
{
  const auto scene = mid::test::makeTwoCopiesScene ();
  cv::Mat color (480, 640, CV_8UC3), depth (480, 640, CV_16UC1);
  for (int v = 0; v < 480; ++v)
    for (int u = 0; u < 640; ++u) {
      const auto& p = scene.cloud->at (u, v);
      color.at<cv::Vec3b> (v, u) = cv::Vec3b (p.b, p.g, p.r);
      depth.at<std::uint16_t> (v, u) = static_cast<std::uint16_t> (std::lround (p.z * 1000.0f));
    }
  ASSERT_TRUE (cv::imwrite (path ("rgb.png"), color));
  ASSERT_TRUE (cv::imwrite (path ("depth.png"), depth));
  const auto result = run ("-rgb " + path ("rgb.png") + " -depth " + path ("depth.png") +
                           " -fx 525 -fy 525 -cx 319.5 -cy 239.5");
  ASSERT_EQ (result.exit_code, 0) << result.output;
  EXPECT_NE (result.output.find ("640 x 480"), std::string::npos) << result.output;

  cv::imwrite (path ("small_depth.png"), cv::Mat (depth, cv::Rect (0, 0, 320, 240)));
  expectRefused ("-rgb " + path ("rgb.png") + " -depth " + path ("small_depth.png") +
                     " -fx 525 -fy 525 -cx 319.5 -cy 239.5",
                 "sizes differ");
  expectRefused ("-rgb " + path ("rgb.png") + " -depth " + path ("depth.png"), "intrinsics");
  expectRefused ("-rgb " + path ("rgb.png") + " -depth " + path ("depth.png") +
                     " -fx 0 -fy 525 -cx 319.5 -cy 239.5",
                 "focal");
}

TEST_F (DiscoveryApp, RefusesUnusableFiles)
{
  expectRefused (path ("missing.pcd"), "cannot open");
  std::ofstream (path ("empty.pcd")).flush ();
  expectRefused (path ("empty.pcd"), "is empty");
  std::ofstream (path ("garbage.pcd")) << "garbage\n";
  expectRefused (path ("garbage.pcd"), "not a valid PCD");

  auto cloud = mid::test::makeTwoCopiesScene ().cloud;
  pcl::PointCloud<pcl::PointXYZ> xyz;
  pcl::copyPointCloud (*cloud, xyz);
  ASSERT_EQ (pcl::io::savePCDFileBinary (path ("xyz.pcd"), xyz), 0);
  expectRefused (path ("xyz.pcd"), "no color field");

  cloud->width = static_cast<std::uint32_t> (cloud->size ());
  cloud->height = 1;
  ASSERT_EQ (pcl::io::savePCDFileBinary (path ("flat.pcd"), *cloud), 0);
  expectRefused (path ("flat.pcd"), "not organized");

  cloud->width = 640;
  cloud->height = 480;
  for (auto& p : *cloud)
    p.z = std::numeric_limits<float>::quiet_NaN ();
  ASSERT_EQ (pcl::io::savePCDFileBinary (path ("nan.pcd"), *cloud), 0);
  expectRefused (path ("nan.pcd"), "no valid depth");
}

TEST_F (DiscoveryApp, RefusesBadArguments)
{
  expectRefused ("a.pcd b.pcd", "exactly one input");
  expectRefused ("-rgb x.png", "together");
  const auto scene = mid::test::makeTwoCopiesScene ();
  ASSERT_EQ (pcl::io::savePCDFileBinaryCompressed (path ("scene.pcd"), *scene.cloud), 0);
  expectRefused (path ("scene.pcd") + " -max_desc_dist -5", "Invalid parameter");
  expectRefused (path ("scene.pcd") + " -normal_radius 0", "Invalid parameter");
  const auto usage = run ("");
  EXPECT_NE (usage.exit_code, 0);
  EXPECT_NE (usage.output.find ("Usage"), std::string::npos);
}
