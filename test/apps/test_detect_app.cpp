// pcl_multi_instance_detect with a model discovered by pcl_multi_instance_discovery.

#include "app_runner.h"
#include "temporary_folder.h"
#include "two_copies_scene.h"

#include <gtest/gtest.h>
#include <pcl/io/pcd_io.h>

#include <filesystem>
#include <fstream>

namespace {

std::string
discoveryApp ()
{
  return MID_DISCOVERY_APP;
}

std::string
detectApp ()
{
  return MID_DETECT_APP;
}

/** Discover the two-copies scene into folder/model_0.json and return the scene path. */
std::string
discoverModel (const mid::test::TemporaryFolder& folder,
               const mid::test::TwoCopiesScene& scene)
{
  std::string path = folder.file ("scene.pcd");
  EXPECT_EQ (pcl::io::savePCDFileBinaryCompressed (path, *scene.cloud), 0);
  const auto result = mid::test::runCommand (discoveryApp() + " " + path + " -models " +
                                             folder.file ("model_"));
  EXPECT_EQ (result.exit_code, 0) << result.output;
  return path;
}

} // namespace

TEST (DetectApp, FindsTheInstancesOfADiscoveredModel)
{
  const mid::test::TemporaryFolder folder;
  const auto scene = mid::test::makeTwoCopiesScene();
  const std::string scene_path = discoverModel (folder, scene);
  const auto result =
      mid::test::runCommand (detectApp() + " " + folder.file ("model_0.json") + " " +
                             scene_path + " -json " + folder.file ("detected.json"));
  ASSERT_EQ (result.exit_code, 0) << result.output;
  std::ifstream json (folder.file ("detected.json"));
  const std::string text ((std::istreambuf_iterator<char> (json)),
                          std::istreambuf_iterator<char>());
  EXPECT_NE (text.find ("\"objects\": 1, \"instances\": 2"), std::string::npos) << text;
}

TEST (DetectApp, FindsASingleInstanceToo)
{
  const mid::test::TemporaryFolder folder;
  const auto scene = mid::test::makeTwoCopiesScene();
  discoverModel (folder, scene);
  // The same frame with copy B blanked: one instance left.
  auto single = *scene.cloud;
  for (int v = scene.rect_b.y; v < scene.rect_b.br().y; ++v)
    for (int u = scene.rect_b.x; u < scene.rect_b.br().x; ++u)
      single.at (u, v).r = single.at (u, v).g = single.at (u, v).b = 90;
  ASSERT_EQ (pcl::io::savePCDFileBinaryCompressed (folder.file ("single.pcd"), single),
             0);
  const auto result =
      mid::test::runCommand (detectApp() + " " + folder.file ("model_0.json") + " " +
                             folder.file ("single.pcd"));
  ASSERT_EQ (result.exit_code, 0) << result.output;
  EXPECT_NE (result.output.find ("object 0: 1 instances"), std::string::npos)
      << result.output;
}

TEST (DetectApp, RefusesMissingTruncatedOrForeignModels)
{
  const mid::test::TemporaryFolder folder;
  const auto scene = mid::test::makeTwoCopiesScene();
  const std::string scene_path = discoverModel (folder, scene);
  auto expect_refused = [&] (const std::string& model, const std::string& message) {
    const auto result =
        mid::test::runCommand (detectApp() + " " + model + " " + scene_path);
    EXPECT_FALSE (result.crashed);
    EXPECT_NE (result.exit_code, 0);
    EXPECT_NE (result.output.find (message), std::string::npos) << result.output;
  };
  expect_refused (folder.file ("missing.json"), "cannot open");
  std::filesystem::resize_file (folder.file ("model_0.pcd"), 100);
  expect_refused (folder.file ("model_0.json"), "model_0.pcd");
  std::ofstream (folder.file ("other.json"))
      << R"({"format": "mid-object-model", "version": 7})";
  expect_refused (folder.file ("other.json"), "version");
}

TEST (DetectApp, RefusesUnknownArgumentsAndMalformedNumbers)
{
  const mid::test::TemporaryFolder folder;
  const auto scene = mid::test::makeTwoCopiesScene();
  std::string command = detectApp() + " " + folder.file ("model_0.json");
  command += " " + discoverModel (folder, scene);
  for (const auto& [extra, message] :
       {std::pair<std::string, std::string>{" -iteratoins 10", "Unknown argument"},
        {" -iterations 1e3", "-iterations must be an integer"},
        {" -inlier 5mm", "-inlier must be a number, got '5mm'"},
        // strtod alone reads these as 5, 8 and 0.
        {" -inlier +5", "-inlier must be a number, got '+5'"},
        {" -inlier 0x8", "-inlier must be a number, got '0x8'"},
        {" -min_ratio 1e-50", "-min_ratio must be a number, got '1e-50'"},
        {" -min_spread -0.001", "min_spread is -0.001, must be >= 0"},
        // A second model would be ignored.
        {" " + folder.file ("model_0.json"),
         "Give exactly one model file MODEL.json (got 2)"},
        {" " + folder.file ("other.JSON"),
         "Give exactly one model file MODEL.json (got 2)"}}) {
    SCOPED_TRACE (extra);
    const auto result = mid::test::runCommand (command + extra);
    EXPECT_FALSE (result.crashed);
    EXPECT_NE (result.exit_code, 0);
    EXPECT_NE (result.output.find (message), std::string::npos) << result.output;
  }
  // The same command without the bad option runs.
  EXPECT_EQ (mid::test::runCommand (command).exit_code, 0);
}
