// pcl_multi_instance_detect with a model discovered by pcl_multi_instance_discovery.

#include "app_runner.h"
#include "rendered_objects_scene.h"
#include "tabletop_frame.h"
#include "temporary_folder.h"
#include "two_copies_scene.h"

#include <Eigen/Core>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <pcl/io/pcd_io.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <utility>
#include <vector>

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

/** A 4x4 matrix from a row-major nested JSON list. */
Eigen::Matrix4f
matrixOf (const nlohmann::json& rows)
{
  Eigen::Matrix4f matrix;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      matrix (r, c) = rows.at (static_cast<std::size_t> (r))
                          .at (static_cast<std::size_t> (c))
                          .get<float>();
  return matrix;
}

/** The print of the cookie boxes. */
const char* const kCookies = "bastoncini_cookie_box.png";

/** Three cookie boxes of 0.12 x 0.09 x 0.04 m lying apart on a table (folder/seen.pcd),
  * discovered into folder/model_0.json (with the box all three agree on); false after a test
  * failure if discovery failed.
  */
bool
discoverCookieBoxes (const mid::test::TemporaryFolder& folder)
{
  const auto seen = mid::test::boxesLyingOnATable ({kCookies, kCookies, kCookies});
  EXPECT_EQ (
      pcl::io::savePCDFileBinaryCompressed (folder.file ("seen.pcd"), *seen.cloud), 0);
  const auto discovered =
      mid::test::runCommand (discoveryApp() + " " + folder.file ("seen.pcd") +
                             " -models " + folder.file ("model_"));
  EXPECT_EQ (discovered.exit_code, 0) << discovered.output;
  return discovered.exit_code == 0;
}

/** The header of a model file. */
nlohmann::json
modelHeader (const std::string& path)
{
  return nlohmann::json::parse (std::ifstream (path));
}

/** The poses of the instances of the one object of a detect app's JSON result (none if no
  * object was found).
  */
std::vector<Eigen::Matrix4f>
detectedPoses (const std::string& path)
{
  const auto result = nlohmann::json::parse (std::ifstream (path));
  std::vector<Eigen::Matrix4f> poses;
  for (const auto& object : result.at ("objects"))
    for (const auto& instance : object.at ("instances"))
      poses.push_back (matrixOf (instance.at ("pose")));
  return poses;
}

} // namespace

TEST (DetectApp, ExtendedModelFindsACopyShowingAnotherFace)
{
  // Cookie boxes (0.12 x 0.09 x 0.07 m) with an orange-juice print on one side face. Seen from
  // above, three copies give a model of the cookie print only, which misses a copy lying on
  // that print, its side face towards an oblique camera. A copy seen obliquely with both faces
  // is detected by its top, and -extend adds its side face to the model, which then finds the
  // copy on its top, at its true pose.
  mid::test::BoxSpec box;
  box.texture = kCookies;
  box.side_texture = "god_morgon_orange_juice_front.jpg";
  box.size = Eigen::Vector3d (0.12, 0.09, 0.07);
  const double tilt = 40.0;
  const auto from_above =
      mid::test::renderBoxes (mid::test::boxesLyingApart (box, {0, 1, 3}), 0.95);
  const auto both_faces =
      mid::test::renderBoxes (mid::test::boxesLyingApart (box, {0}), 0.95, tilt);
  auto upside_down = mid::test::boxesLyingApart (box, {0});
  upside_down[0].pose =
      upside_down[0].pose * Eigen::AngleAxisd (M_PI, Eigen::Vector3d::UnitY());
  const auto side_only = mid::test::renderBoxes (upside_down, 0.95, tilt);

  const mid::test::TemporaryFolder folder;
  for (const auto& [name, scene] : {std::pair{"above.pcd", &from_above},
                                    std::pair{"both.pcd", &both_faces},
                                    std::pair{"side.pcd", &side_only}})
    ASSERT_EQ (pcl::io::savePCDFileBinaryCompressed (folder.file (name), *scene->cloud),
               0);
  const auto discovered = mid::test::runCommand (
      discoveryApp() + " " + folder.file ("above.pcd") + " -models " +
      folder.file ("model_") + " -json " + folder.file ("above.json"));
  ASSERT_EQ (discovered.exit_code, 0) << discovered.output;
  ASSERT_TRUE (modelHeader (folder.file ("model_0.json")).at ("box").is_object());
  // The model frame, tied to the box's own through a copy discovered: X = G^-1 P, with G the
  // true pose of the copy nearest to the instance.
  const auto seen = detectedPoses (folder.file ("above.json"));
  ASSERT_FALSE (seen.empty());
  const auto nearest = std::min_element (
      from_above.boxes.begin(),
      from_above.boxes.end(),
      [&seen] (const mid::test::BoxSpec& a, const mid::test::BoxSpec& b) {
        const Eigen::Vector3f at = seen[0].topRightCorner<3, 1>();
        return (a.pose.translation().cast<float>() - at).norm() <
               (b.pose.translation().cast<float>() - at).norm();
      });
  const Eigen::Matrix4f model_in_box =
      nearest->pose.matrix().cast<float>().inverse() * seen[0];
  const auto expect_at = [&model_in_box] (const Eigen::Matrix4f& found,
                                          const mid::test::BoxSpec& copy) {
    const Eigen::Matrix4f error =
        (copy.pose.matrix().cast<float>() * model_in_box).inverse() * found;
    EXPECT_LT (
        Eigen::AngleAxisf (Eigen::Matrix3f (error.topLeftCorner<3, 3>())).angle() *
            180.0f / static_cast<float> (M_PI),
        2.0f);
    const Eigen::Vector3f shift = error.topRightCorner<3, 1>();
    EXPECT_LT (shift.norm(), 0.005f);
  };

  // Each run writes a result of its own: a failed run leaves none to read.
  const auto detect = [&] (const std::string& model,
                           const std::string& scene,
                           const std::string& out,
                           const std::string& more) {
    const auto run = mid::test::runCommand (detectApp() + " " + folder.file (model) +
                                            " " + folder.file (scene) + " -json " +
                                            folder.file (out) + more);
    EXPECT_EQ (run.exit_code, 0) << run.output;
    return detectedPoses (folder.file (out));
  };
  ASSERT_TRUE (detect ("model_0.json", "side.pcd", "before.json", "").empty())
      << "the model seen from above holds nothing of the side face";

  const auto anchor = detect ("model_0.json",
                              "both.pcd",
                              "both.json",
                              " -extend " + folder.file ("extended.json"));
  ASSERT_EQ (anchor.size(), 1u);
  expect_at (anchor[0], both_faces.boxes[0]);
  const auto original = modelHeader (folder.file ("model_0.json"));
  const auto extended = modelHeader (folder.file ("extended.json"));
  EXPECT_GT (extended.at ("landmarks").get<int>(),
             original.at ("landmarks").get<int>());
  EXPECT_EQ (extended.at ("box"), original.at ("box")) << "the box is kept";

  const auto found = detect ("extended.json", "side.pcd", "after.json", "");
  ASSERT_EQ (found.size(), 1u);
  expect_at (found[0], side_only.boxes[0]);
}

TEST (DetectApp, ExtendRefusesAModelWithoutBox)
{
  // Without the object's box nothing tells which keypoints belong to the object.
  const mid::test::TemporaryFolder folder;
  ASSERT_TRUE (discoverCookieBoxes (folder));
  auto header = modelHeader (folder.file ("model_0.json"));
  ASSERT_TRUE (header.at ("box").is_object());
  header["box"] = nullptr;
  std::ofstream (folder.file ("no_box.json")) << header.dump();
  std::filesystem::copy_file (folder.file ("model_0.pcd"), folder.file ("no_box.pcd"));
  const std::string command =
      detectApp() + " " + folder.file ("no_box.json") + " " + folder.file ("seen.pcd");
  const auto result =
      mid::test::runCommand (command + " -extend " + folder.file ("extended.json"));
  EXPECT_FALSE (result.crashed);
  EXPECT_NE (result.exit_code, 0);
  EXPECT_NE (result.output.find ("holds no box of the object"), std::string::npos)
      << result.output;
  EXPECT_FALSE (std::filesystem::exists (folder.file ("extended.json")));
  // The same runs without -extend, and with the box.
  EXPECT_EQ (mid::test::runCommand (command).exit_code, 0);
  EXPECT_EQ (mid::test::runCommand (detectApp() + " " + folder.file ("model_0.json") +
                                    " " + folder.file ("seen.pcd") + " -extend " +
                                    folder.file ("extended.json"))
                 .exit_code,
             0);
  EXPECT_TRUE (std::filesystem::exists (folder.file ("extended.json")));
}

TEST (DetectApp, ReportsEachCopyOnce)
{
  // The juice cartons of the tabletop recipe: the model of a frame with five, detected in
  // another frame with five. A detection takes only its inliers out of the matches, so the rest
  // of a carton's keypoints can detect it a second time (seed 13: six detections on five
  // cartons before overlapping ones were dropped); every instance must lie on a carton of its
  // own.
  const mid::test::TemporaryFolder folder;
  mid::test::TabletopFrame seen, other;
  ASSERT_TRUE (mid::test::renderTabletopFrame (5, 2, seen));
  ASSERT_TRUE (mid::test::renderTabletopFrame (5, 13, other));
  ASSERT_EQ (
      pcl::io::savePCDFileBinaryCompressed (folder.file ("seen.pcd"), *seen.cloud), 0);
  ASSERT_EQ (
      pcl::io::savePCDFileBinaryCompressed (folder.file ("other.pcd"), *other.cloud),
      0);
  const auto discovered =
      mid::test::runCommand (discoveryApp() + " " + folder.file ("seen.pcd") +
                             " -models " + folder.file ("model_"));
  ASSERT_EQ (discovered.exit_code, 0) << discovered.output;
  const auto detected = mid::test::runCommand (
      detectApp() + " " + folder.file ("model_0.json") + " " +
      folder.file ("other.pcd") + " -json " + folder.file ("out.json"));
  ASSERT_EQ (detected.exit_code, 0) << detected.output;
  const auto result = nlohmann::json::parse (std::ifstream (folder.file ("out.json")));
  ASSERT_EQ (result.at ("objects").size(), 1u);
  std::set<int> cartons;
  std::size_t instances = 0;
  for (const auto& instance : result.at ("objects").at (0).at ("instances")) {
    // Each detection rests on the model by its own matches: no discovery group.
    EXPECT_FALSE (instance.contains ("group"));
    std::vector<Eigen::Vector2f> pixels;
    for (const auto& uv : instance.at ("keypoints"))
      pixels.emplace_back (uv.at (0).get<float>(), uv.at (1).get<float>());
    const int carton = mid::test::objectUnderPixels (other, pixels);
    EXPECT_GE (carton, 0) << "an instance on the background";
    EXPECT_LT (carton, 5) << "an instance on a distractor";
    EXPECT_EQ (cartons.count (carton), 0u) << "carton " << carton << " twice";
    cartons.insert (carton);
    ++instances;
  }
  EXPECT_GE (instances, 4u);
}

TEST (DetectApp, ReportsTheObjectsBoxAtEachInstance)
{
  // Three cookie boxes of 0.12 x 0.09 x 0.04 m lying apart on a table: discovery measures the
  // object's box, which all three agree on, and saves it with the model. In another frame,
  // with copies at a new place and at an old one, the detection reports that box, and placed
  // at each instance it lies on that copy's box.
  const mid::test::TemporaryFolder folder;
  ASSERT_TRUE (discoverCookieBoxes (folder));
  const auto other = mid::test::boxesLyingOnATable ({kCookies, kCookies}, {3, 0});
  ASSERT_EQ (
      pcl::io::savePCDFileBinaryCompressed (folder.file ("other.pcd"), *other.cloud),
      0);
  const auto detected = mid::test::runCommand (
      detectApp() + " " + folder.file ("model_0.json") + " " +
      folder.file ("other.pcd") + " -json " + folder.file ("out.json"));
  ASSERT_EQ (detected.exit_code, 0) << detected.output;
  EXPECT_NE (detected.output.find ("(agreed by 3 copies)"), std::string::npos)
      << detected.output;

  const auto result = nlohmann::json::parse (std::ifstream (folder.file ("out.json")));
  ASSERT_EQ (result.at ("objects").size(), 1u);
  const auto& object = result.at ("objects").at (0);
  ASSERT_TRUE (object.at ("box").is_object()) << object.dump();
  const auto& box = object.at ("box");
  EXPECT_EQ (box.at ("copies").get<int>(), 3);
  const Eigen::Vector3f size (box.at ("size").at (0).get<float>(),
                              box.at ("size").at (1).get<float>(),
                              box.at ("size").at (2).get<float>());
  EXPECT_LT ((size - Eigen::Vector3f (0.04f, 0.09f, 0.12f)).cwiseAbs().maxCoeff(),
             0.006f)
      << size.transpose();
  const Eigen::Matrix4f box_in_model = matrixOf (box.at ("pose"));
  ASSERT_EQ (object.at ("instances").size(), 2u);
  std::set<std::size_t> copies;
  for (const auto& instance : object.at ("instances")) {
    const Eigen::Matrix4f placed = matrixOf (instance.at ("pose")) * box_in_model;
    for (std::size_t b = 0; b < other.boxes.size(); ++b) {
      const Eigen::Vector3f centre = other.boxes[b].pose.translation().cast<float>();
      if ((placed.topRightCorner<3, 1>() - centre).norm() < 0.005f)
        copies.insert (b);
    }
  }
  EXPECT_EQ (copies, (std::set<std::size_t>{0, 1}));
}

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
        {" -extend " + folder.file ("extended.txt"),
         "The extended model's file must end in .json"},
        {" -extend " + folder.file ("extended.JSON"),
         "The extended model's file must end in .json"},
        {" -extend " + folder.file ("out.json") + " -json " + folder.file ("out.json"),
         "would write over the -json result"},
        {" -extend " + folder.file ("scene.json"), "would write over the scene"},
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
