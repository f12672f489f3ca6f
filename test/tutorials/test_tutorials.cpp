// The tutorial programs on the shipped sample scene, checked against its ground truth.

#include "app_runner.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <regex>
#include <set>

namespace {

const std::string kScene = std::string (MID_TEST_DATA_DIR) + "/sample_scene/scene.pcd";

/** The annotated instances of the sample scene: object name, pose and box (x, y, w, h). */
struct Annotated
{
  std::string object;
  Eigen::Matrix4f pose;
  std::vector<int> bbox;
};

std::vector<Annotated>
annotations ()
{
  std::ifstream file (std::string (MID_TEST_DATA_DIR) +
                      "/sample_scene/ground_truth.json");
  nlohmann::json document;
  file >> document;
  std::vector<Annotated> result;
  for (const auto& entry : document.at ("instances")) {
    Annotated a;
    a.object = entry.at ("object").get<std::string>();
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c)
        a.pose (r, c) = entry.at ("pose")
                            .at (static_cast<std::size_t> (r))
                            .at (static_cast<std::size_t> (c))
                            .get<float>();
    a.bbox = entry.at ("bbox").get<std::vector<int>>();
    result.push_back (a);
  }
  return result;
}

} // namespace

TEST (Tutorials, ThePipelineFindsCartonsOfTheSampleScene)
{
  const auto run =
      mid::test::runCommand (std::string (MID_TUTORIAL_PIPELINE) + " " + kScene);
  ASSERT_EQ (run.exit_code, 0) << run.output;
  const auto truth = annotations();
  std::set<std::size_t> found;
  const std::regex line (
      "object 0 instance \\d+ keypoints \\d+ centre_pixel ([0-9.]+) ([0-9.]+)");
  for (auto it = std::sregex_iterator (run.output.begin(), run.output.end(), line);
       it != std::sregex_iterator();
       ++it) {
    const double u = std::stod ((*it)[1]), v = std::stod ((*it)[2]);
    std::size_t on = truth.size();
    for (std::size_t k = 0; k < truth.size(); ++k)
      if (u >= truth[k].bbox[0] && v >= truth[k].bbox[1] &&
          u < truth[k].bbox[0] + truth[k].bbox[2] &&
          v < truth[k].bbox[1] + truth[k].bbox[3] && truth[k].object == "juice_carton")
        on = k;
    ASSERT_LT (on, truth.size())
        << "an instance off every carton at " << u << ", " << v;
    found.insert (on);
  }
  EXPECT_GE (found.size(), 2u) << run.output; // distinct cartons
  EXPECT_NE (run.output.find ("objects 1"), std::string::npos) << run.output;
}

TEST (Tutorials, ShotCorrespondencesClusterIntoAPairOfCartons)
{
  const auto run =
      mid::test::runCommand (std::string (MID_TUTORIAL_SHOT) + " " + kScene);
  ASSERT_EQ (run.exit_code, 0) << run.output;
  std::smatch match;
  ASSERT_TRUE (std::regex_search (
      run.output,
      match,
      std::regex ("cluster 0: \\d+ keypoint pairs, pose((?: [-0-9.e]+){16})")))
      << run.output;
  std::istringstream values (match[1].str());
  Eigen::Matrix4f pose;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      values >> pose (r, c);
  // The cluster maps one carton onto another: its pose is some G_j * G_i^-1 of the truth.
  const auto truth = annotations();
  double best = 1e9;
  for (std::size_t i = 0; i < truth.size(); ++i)
    for (std::size_t j = 0; j < truth.size(); ++j) {
      if (i == j || truth[i].object != "juice_carton" ||
          truth[j].object != "juice_carton")
        continue;
      const Eigen::Matrix4f expected = truth[j].pose * truth[i].pose.inverse();
      const Eigen::Vector4f centre = truth[i].pose.col (3);
      const Eigen::Matrix3f relative =
          pose.topLeftCorner<3, 3>().transpose() * expected.topLeftCorner<3, 3>();
      const double angle = Eigen::AngleAxisf (relative).angle() * 180.0 / M_PI;
      if (angle < 5.0)
        best = std::min (
            best, static_cast<double> (((pose - expected) * centre).head<3>().norm()));
    }
  EXPECT_LT (best, 0.01) << run.output; // within 1 cm at the carton's centre
}
