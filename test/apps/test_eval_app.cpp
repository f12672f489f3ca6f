// pcl_multi_instance_eval on a hand-built BOP dataset and results whose scores are known.

#include "app_runner.h"
#include "temporary_folder.h"

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include <filesystem>
#include <fstream>

namespace {

const char* kTruth =
    R"({"0": [{"cam_R_m2c": [1, 0, 0, 0, 1, 0, 0, 0, 1], "cam_t_m2c": [0, 0, 800], "obj_id": 1},
                               {"cam_R_m2c": [1, 0, 0, 0, 1, 0, 0, 0, 1], "cam_t_m2c": [200, 0, 800], "obj_id": 1}],
                         "1": [{"cam_R_m2c": [1, 0, 0, 0, 1, 0, 0, 0, 1], "cam_t_m2c": [0, 0, 800], "obj_id": 1},
                               {"cam_R_m2c": [1, 0, 0, 0, 1, 0, 0, 0, 1], "cam_t_m2c": [200, 0, 800], "obj_id": 1}]})";
const char* kInfo =
    R"({"0": [{"bbox_visib": [0, 0, 100, 100]}, {"bbox_visib": [200, 0, 100, 100]}],
                        "1": [{"bbox_visib": [0, 0, 100, 100]}, {"bbox_visib": [200, 0, 100, 100]}]})";

/** A result with one object whose instances are at the two annotated boxes. */
const char* kPerfect =
    R"({"format": "mid-discovery-result", "version": 1, "timing_ms": {"features": 50, "total": 80},
  "objects": [{"instances": [
    {"pose": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0.8], [0, 0, 0, 1]], "keypoints": [[10, 10], [20, 20]]},
    {"pose": [[1, 0, 0, 0.2], [0, 1, 0, 0], [0, 0, 1, 0.8], [0, 0, 0, 1]], "keypoints": [[210, 10], [220, 20]]}]}]})";

/** kPerfect with a grouping stage of 10 + 2 ms. */
const char* kPerfectTimed =
    R"({"format": "mid-discovery-result", "version": 1,
  "timing_ms": {"features": 50, "triplets": 10, "clustering": 2, "total": 80},
  "objects": [{"instances": [
    {"pose": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0.8], [0, 0, 0, 1]], "keypoints": [[10, 10], [20, 20]]},
    {"pose": [[1, 0, 0, 0.2], [0, 1, 0, 0], [0, 0, 1, 0.8], [0, 0, 0, 1]], "keypoints": [[210, 10], [220, 20]]}]}]})";

/** A peer that finds one instance on the annotated box and one in between, in 0 + 3 ms. */
const char* kHalfTimed =
    R"({"format": "mid-discovery-result", "version": 1,
  "timing_ms": {"features": 50, "triplets": 0, "clustering": 3, "total": 71},
  "objects": [{"instances": [
    {"pose": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0.8], [0, 0, 0, 1]], "keypoints": [[10, 10], [20, 20]]},
    {"pose": [[1, 0, 0, 0.1], [0, 1, 0, 0], [0, 0, 1, 0.8], [0, 0, 0, 1]], "keypoints": [[150, 10], [160, 20]]}]}]})";

/** Writes the hand-built dataset (one scene folder, 000000, with kTruth and kInfo) to
  * `folder`/dataset and returns that folder.
  */
std::filesystem::path
writeDataset (const mid::test::TemporaryFolder& folder)
{
  auto dataset = folder.path() / "dataset";
  std::filesystem::create_directories (dataset / "000000");
  std::ofstream (dataset / "000000" / "scene_gt.json") << kTruth;
  std::ofstream (dataset / "000000" / "scene_gt_info.json") << kInfo;
  return dataset;
}

} // namespace

TEST (EvalApp, ScoresAPerfectAndAMissingResult)
{
  const mid::test::TemporaryFolder folder;
  const auto dataset = writeDataset (folder), results = folder.path() / "results";
  std::filesystem::create_directories (results / "000000");
  std::ofstream (dataset / "scenarios.json") << R"({"000000": "S_ez"})";
  std::ofstream (results / "000000" / "000000.json")
      << kPerfect; // frame 1 has no result
  const auto run = mid::test::runCommand (std::string (MID_EVAL_APP) + " " +
                                          dataset.string() + " " + results.string() +
                                          " -report " + folder.file ("report.md"));
  ASSERT_EQ (run.exit_code, 0) << run.output;
  // Instances: 2 TP, 0 FP, 2 FN -> P 1, R 0.5; pairs (both frames hold only pairs): 1 TP, 1 FN.
  EXPECT_NE (
      run.output.find ("| S_ez       |    2 | 1.000 | 0.500 | 0.667 |    2 | 1.000 | "
                       "0.500 | 0.667 |   0.00 |   0.00 |    80.0 |    50.0 |"),
      std::string::npos)
      << run.output;
  EXPECT_NE (run.output.find ("1 frames had no result file"), std::string::npos);
  EXPECT_TRUE (std::filesystem::exists (folder.file ("report.md")));
}

TEST (EvalApp, SplitsThePairsByGroupsWhenTheResultGivesThem)
{
  const mid::test::TemporaryFolder folder;
  const auto dataset = writeDataset (folder), results = folder.path() / "results";
  std::filesystem::create_directories (results / "000000");
  std::ofstream (dataset / "scenarios.json") << R"({"000000": "S_ez"})";
  const std::string command =
      std::string (MID_EVAL_APP) + " " + dataset.string() + " " + results.string();
  std::ofstream (results / "000000" / "000000.json") << kPerfect;
  const auto without = mid::test::runCommand (command);
  ASSERT_EQ (without.exit_code, 0) << without.output;
  EXPECT_EQ (without.output.find ("pairs in one group"), std::string::npos)
      << without.output;

  // The same instances, both in group 0: their one pair is counted within one group.
  std::string grouped = kPerfect;
  for (std::size_t at = grouped.find ("{\"pose\""); at != std::string::npos;
       at = grouped.find ("{\"pose\"", at + 2))
    grouped.insert (at + 1, "\"group\": 0, ");
  std::ofstream (results / "000000" / "000000.json") << grouped;
  const auto with = mid::test::runCommand (command);
  ASSERT_EQ (with.exit_code, 0) << with.output;
  EXPECT_NE (with.output.find ("pairs in one group"), std::string::npos) << with.output;
  EXPECT_NE (with.output.find ("| S_ez       |     1 |"), std::string::npos)
      << with.output;
}

TEST (EvalApp, RefusesUnusableFolders)
{
  const mid::test::TemporaryFolder folder;
  const auto run =
      mid::test::runCommand (std::string (MID_EVAL_APP) + " " + folder.file ("none") +
                             " " + folder.path().string());
  EXPECT_FALSE (run.crashed);
  EXPECT_NE (run.exit_code, 0);
  EXPECT_NE (run.output.find ("is not a folder"), std::string::npos) << run.output;
  const auto empty =
      mid::test::runCommand (std::string (MID_EVAL_APP) + " " + folder.path().string() +
                             " " + folder.path().string());
  EXPECT_NE (empty.exit_code, 0);
  EXPECT_NE (empty.output.find ("no BOP scene folder"), std::string::npos)
      << empty.output;
}

TEST (EvalApp, RefusesUnknownOptionsAndMissingValues)
{
  const mid::test::TemporaryFolder folder;
  const auto dataset = writeDataset (folder), results = folder.path() / "results";
  std::filesystem::create_directories (results / "000000");
  const std::string command =
      std::string (MID_EVAL_APP) + " " + dataset.string() + " " + results.string();
  for (const auto& [options, message] :
       {std::pair<std::string, std::string>{" -reprot out.md",
                                            "Unknown argument '-reprot'"},
        {" -report", "-report needs 1 value"},
        {" -report -frames", "-report needs 1 value"},
        {" -frames " + results.string(), "Unknown argument"},
        {" -min_inside +0.5", "-min_inside must be a number, got '+0.5'"},
        {" -max_tilt 0.5", "-max_tilt 0.5 (must be 1 or more)"}}) {
    SCOPED_TRACE (options);
    const auto run = mid::test::runCommand (command + options);
    EXPECT_FALSE (run.crashed);
    EXPECT_NE (run.exit_code, 0);
    EXPECT_NE (run.output.find (message), std::string::npos) << run.output;
  }
  const auto valid =
      mid::test::runCommand (command + " -frames -report " + folder.file ("report.md"));
  EXPECT_EQ (valid.exit_code, 0) << valid.output;
  EXPECT_TRUE (std::filesystem::exists (folder.file ("report.md")));
}

TEST (EvalApp, PutsMethodsSideBySide)
{
  const mid::test::TemporaryFolder folder;
  const auto dataset = writeDataset (folder);
  for (const char* method : {"ours", "peer"}) {
    std::filesystem::create_directories (folder.path() / method / "000000");
    for (const char* image : {"000000.json", "000001.json"})
      std::ofstream (folder.path() / method / "000000" / image)
          << (method[0] == 'o' ? kPerfectTimed : kHalfTimed);
  }
  const std::string command = std::string (MID_EVAL_APP) + " " + dataset.string() +
                              " " + folder.file ("ours") + " " + folder.file ("peer");
  const auto run = mid::test::runCommand (command + " -names triplets,gcg");
  ASSERT_EQ (run.exit_code, 0) << run.output;
  // Ours: 4 TP. The peer: per frame 1 TP, 1 FP (no annotated box holds 90 % of its
  // keypoints), 1 FN -> P 0.5, R 0.5; pairs: no valid object with two TP -> 0 TP, 1 FP, 1 FN.
  // Grouping time 12 ms against 3 ms: ratio 4.
  EXPECT_NE (
      run.output.find ("| 000000     | triplets   | 1.000 | 1.000 | 1.000 | 1.000 | "
                       "1.000 | 1.000 |   0.00 |   0.00 |   12.00 |  1.00 |"),
      std::string::npos)
      << run.output;
  EXPECT_NE (
      run.output.find ("| 000000     | gcg        | 0.500 | 0.500 | 0.500 | 0.000 | "
                       "0.000 | 0.000 |    nan |    nan |    3.00 |  4.00 |"),
      std::string::npos)
      << run.output;
  const auto wrong_names = mid::test::runCommand (command + " -names one");
  EXPECT_NE (wrong_names.exit_code, 0);
  EXPECT_NE (wrong_names.output.find ("-names gives 1 names for 2"), std::string::npos)
      << wrong_names.output;
}

TEST (EvalApp, ReportsRecallAgainstTheSharedSurfaceWhenTheDatasetHasDepth)
{
  const mid::test::TemporaryFolder folder;
  const auto dataset = writeDataset (folder), results = folder.path() / "results";
  std::filesystem::create_directories (results / "000000");
  std::ofstream (results / "000000" / "000000.json") << kPerfect;
  const std::string command =
      std::string (MID_EVAL_APP) + " " + dataset.string() + " " + results.string();
  const auto without = mid::test::runCommand (command);
  ASSERT_EQ (without.exit_code, 0) << without.output;
  EXPECT_NE (without.output.find ("no shared-surface table"), std::string::npos)
      << without.output;
  EXPECT_EQ (without.output.find ("R (sharing >="), std::string::npos)
      << without.output;

  // A wall 0.8 m away, seen head-on: the boxes lie 297 mm apart on it (200 pixels), the poses
  // 200 mm, so in the model frame the two boxes overlap by 50 x 147 mm: 30 to 99 cubes of
  // 10 mm. Frame 0's two instances are found, frame 1's missed.
  const auto scene = dataset / "000000";
  std::ofstream (scene / "scene_camera.json")
      << R"({"0": {"cam_K": [538, 0, 319.5, 0, 538, 239.5, 0, 0, 1], "depth_scale": 0.1},
             "1": {"cam_K": [538, 0, 319.5, 0, 538, 239.5, 0, 0, 1], "depth_scale": 0.1}})";
  std::filesystem::create_directories (scene / "depth");
  const cv::Mat wall (480, 640, CV_16UC1, cv::Scalar (8000));
  for (const char* image : {"000000.png", "000001.png"})
    ASSERT_TRUE (cv::imwrite ((scene / "depth" / image).string(), wall));
  const auto with = mid::test::runCommand (command + " -findable 0");
  ASSERT_EQ (with.exit_code, 0) << with.output;
  EXPECT_NE (
      with.output.find ("| 000000     |   0 /   0 |   0 /   0 |   0 /   0 |   2 /   "
                        "4 |   0 /   0 | 1.000 | 0.500 | 0.667 |"),
      std::string::npos)
      << with.output;
  const auto frames = mid::test::runCommand (command + " -frames");
  EXPECT_NE (
      frames.output.find ("000000/000001: 0 objects, instances TP 0 FP 0 FN 2\n"
                          "  missed instance 0: obj_id 1, 0 pixels visible, shares "),
      std::string::npos)
      << frames.output;
  // Without rgb/ the cubes are not tested for texture, and the lines say so.
  EXPECT_EQ (frames.output.find ("textured cubes"), std::string::npos) << frames.output;
  const auto none = mid::test::runCommand (command + " -shared_cell 0");
  EXPECT_EQ (none.output.find ("R (sharing >="), std::string::npos) << none.output;
}

TEST (EvalApp, ReadsTheShapesSymmetriesAndRefusesABadModelsInfo)
{
  const mid::test::TemporaryFolder folder;
  const auto dataset = writeDataset (folder), results = folder.path() / "results";
  std::filesystem::create_directories (results / "000000");
  std::ofstream (results / "000000" / "000000.json") << kPerfect;
  const std::string command = std::string (MID_EVAL_APP) + " " + dataset.string() +
                              " " + results.string() + " -shared_cell 0";
  const auto without = mid::test::runCommand (command);
  ASSERT_EQ (without.exit_code, 0) << without.output;
  EXPECT_NE (without.output.find ("has no models_info.json"), std::string::npos)
      << without.output;
  EXPECT_NE (without.output.find ("rot. err. > 45 deg mod. symmetry"),
             std::string::npos)
      << without.output;

  std::ofstream (dataset / "models_info.json")
      << R"({"1": {"diameter": 100, "symmetries_continuous": [{"axis": [0, 0, 1], "offset": [0, 0, 0]}]}})";
  const auto with = mid::test::runCommand (command);
  ASSERT_EQ (with.exit_code, 0) << with.output;
  EXPECT_EQ (with.output.find ("has no models_info.json"), std::string::npos)
      << with.output;

  std::ofstream (dataset / "models_info.json")
      << R"({"1": {"symmetries_discrete": [[1, 0, 0]]}})";
  const auto bad = mid::test::runCommand (command);
  EXPECT_NE (bad.exit_code, 0);
  EXPECT_NE (bad.output.find ("models_info.json"), std::string::npos) << bad.output;
  EXPECT_NE (bad.output.find ("16 numbers"), std::string::npos) << bad.output;
}
