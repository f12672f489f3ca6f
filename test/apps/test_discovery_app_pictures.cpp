// The picture options of pcl_multi_instance_discovery without a display: -overlay works, and
// -screenshot, -view and unusable picture options are refused with one line before any work,
// leaving no file behind. (Screenshots under a virtual display: test/visualization.)

#include "app_runner.h"
#include "temporary_folder.h"
#include "two_copies_scene.h"

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <pcl/io/pcd_io.h>

#include <algorithm>
#include <filesystem>

namespace {

class DiscoveryAppPictures : public ::testing::Test
{
protected:
  void
  SetUp () override
  {
    const auto scene = mid::test::makeTwoCopiesScene();
    ASSERT_EQ (
        pcl::io::savePCDFileBinaryCompressed (folder_.file ("scene.pcd"), *scene.cloud),
        0);
  }

  /** Run the app on the scene with no display at all. */
  mid::test::RunResult
  run (const std::string& arguments) const
  {
    return mid::test::runCommand ("env -u DISPLAY " + std::string (MID_DISCOVERY_APP) +
                                  " " + folder_.file ("scene.pcd") + " " + arguments);
  }

  void
  expectRefused (const std::string& arguments, const std::string& message) const
  {
    const auto result = run (arguments);
    EXPECT_FALSE (result.crashed) << result.output;
    EXPECT_NE (result.exit_code, 0) << result.output;
    EXPECT_NE (result.output.find (message), std::string::npos)
        << "expected '" << message << "' in:\n"
        << result.output;
    EXPECT_EQ (std::count (result.output.begin(), result.output.end(), '\n'), 1)
        << result.output;
    EXPECT_EQ (folder_.entries(), 1u) << "only the scene may be in the folder";
  }

  mid::test::TemporaryFolder folder_;
};

} // namespace

TEST_F (DiscoveryAppPictures, WritesTheOverlayWithoutADisplay)
{
  const auto result = run ("-overlay " + folder_.file ("overlay.png") + " -json " +
                           folder_.file ("result.json"));
  ASSERT_EQ (result.exit_code, 0) << result.output;
  const cv::Mat overlay = cv::imread (folder_.file ("overlay.png"), cv::IMREAD_COLOR);
  EXPECT_EQ (overlay.size(), cv::Size (640, 480));
  EXPECT_TRUE (std::filesystem::exists (folder_.file ("result.json")));
  EXPECT_EQ (folder_.entries(), 3u); // nothing partial left
}

TEST_F (DiscoveryAppPictures, RefusesAScreenshotOrAWindowWithoutADisplay)
{
  expectRefused ("-screenshot " + folder_.file ("shot.png"), "needs an X display");
  expectRefused ("-screenshot " + folder_.file ("shot.png") + " -json " +
                     folder_.file ("result.json"),
                 "xvfb-run");
  expectRefused ("-view", "-view needs an X display");
}

TEST_F (DiscoveryAppPictures, RefusesUnusablePictureOptions)
{
  expectRefused ("-overlay " + folder_.file ("overlay.jpg"), "must end in .png");
  expectRefused ("-overlay " + folder_.file ("missing/overlay.png"),
                 "missing or not writable");
  expectRefused ("-overlay " + folder_.file ("overlay.png") + " -size 640",
                 "-size needs 2 values");
  expectRefused ("-overlay " + folder_.file ("overlay.png") + " -size 0 480",
                 "Invalid parameter");
  expectRefused ("-overlay " + folder_.file ("overlay.png") + " -viewpoint 1 2",
                 "-viewpoint needs 3 values");
  expectRefused ("-overlay " + folder_.file ("overlay.png") + " -size 640.5 480",
                 "whole number");
  expectRefused ("-overlay " + folder_.file ("overlay.png") + " -viewpoint nan 0 0",
                 "-viewpoint needs 3 numbers");
}
