// The result JSON of pcl_multi_instance_discovery against a scene with known truth, and its
// all-or-nothing writing.

#include "app_runner.h"
#include "pipeline_stages.h"
#include "temporary_folder.h"
#include "two_copies_scene.h"

#include <gtest/gtest.h>
#include <pcl/io/pcd_io.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

std::string
readFile (const fs::path& path)
{
  std::ifstream file (path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

/** The numbers of every "bbox": [u_min, v_min, u_max, v_max] in the JSON. */
std::vector<std::vector<double>>
boxes (const std::string& json)
{
  std::vector<std::vector<double>> result;
  const std::regex pattern (
      R"("bbox": \[([-0-9.e]+), ([-0-9.e]+), ([-0-9.e]+), ([-0-9.e]+)\])");
  for (auto it = std::sregex_iterator (json.begin(), json.end(), pattern);
       it != std::sregex_iterator();
       ++it)
    result.push_back ({std::stod ((*it)[1]),
                       std::stod ((*it)[2]),
                       std::stod ((*it)[3]),
                       std::stod ((*it)[4])});
  return result;
}

bool
inside (const std::vector<double>& box, const cv::Rect& rect, double margin)
{
  return box[0] >= rect.x - margin && box[1] >= rect.y - margin &&
         box[2] <= rect.br().x + margin && box[3] <= rect.br().y + margin;
}

} // namespace

TEST (DiscoveryAppJson, DescribesTheTwoCopiesAsOneObjectWithTwoInstances)
{
  const mid::test::TemporaryFolder folder;
  const fs::path& dir = folder.path();
  const auto scene = mid::test::makeTwoCopiesScene();
  ASSERT_EQ (
      pcl::io::savePCDFileBinaryCompressed ((dir / "scene.pcd").string(), *scene.cloud),
      0);
  const auto result = mid::test::runCommand (std::string (MID_DISCOVERY_APP) + " " +
                                             (dir / "scene.pcd").string() + " -json " +
                                             (dir / "result.json").string());
  ASSERT_EQ (result.exit_code, 0) << result.output;
  const std::string json = readFile (dir / "result.json");
  EXPECT_NE (json.find ("\"format\": \"mid-discovery-result\""), std::string::npos);
  EXPECT_NE (json.find ("\"version\": 1"), std::string::npos);
  EXPECT_NE (json.find ("\"objects\": 1, \"instances\": 2"), std::string::npos) << json;
  // Two copies of one print: the verification confirms the cluster between them, and their
  // relative pose rests on the landmarks both observe (one group).
  EXPECT_NE (json.find ("\"rejected_clusters\": 0,"), std::string::npos) << json;
  const std::regex group (R"("group": 0, "pose")");
  EXPECT_EQ (std::distance (std::sregex_iterator (json.begin(), json.end(), group),
                            std::sregex_iterator()),
             2)
      << json;
  std::vector<std::string> stages = mid::test::pipelineStages();
  stages.emplace_back ("total");
  for (const auto& stage : stages)
    EXPECT_NE (json.find ("\"" + stage + "\": "), std::string::npos) << stage;
  EXPECT_NE (json.find ("\"box\": "), std::string::npos)
      << json; // an object's box, or null
  // One instance on each copy: its keypoints' box within the copy (plus SIFT's outline margin).
  const auto found = boxes (json);
  ASSERT_EQ (found.size(), 2u);
  const bool first_is_a = inside (found[0], scene.rect_a, 12.0);
  EXPECT_TRUE (first_is_a || inside (found[0], scene.rect_b, 12.0));
  EXPECT_TRUE (inside (found[1], first_is_a ? scene.rect_b : scene.rect_a, 12.0));
}

TEST (DiscoveryAppJson, AMissingOutputFolderFailsBeforeTheWorkAndWritesNothing)
{
  const mid::test::TemporaryFolder folder;
  const fs::path& dir = folder.path();
  const auto scene = mid::test::makeTwoCopiesScene();
  ASSERT_EQ (
      pcl::io::savePCDFileBinaryCompressed ((dir / "scene.pcd").string(), *scene.cloud),
      0);
  const auto result = mid::test::runCommand (
      std::string (MID_DISCOVERY_APP) + " " + (dir / "scene.pcd").string() + " -json " +
      (dir / "no_such_folder" / "result.json").string());
  EXPECT_FALSE (result.crashed);
  EXPECT_NE (result.exit_code, 0);
  EXPECT_NE (result.output.find ("missing or not writable"), std::string::npos)
      << result.output;
  EXPECT_EQ (result.output.find ("keypoints:"), std::string::npos); // no work was done
  EXPECT_EQ (folder.entries(), 1u);
}
