#include "temporary_folder.h"

#include <mid/discovery/result_json.h>
#include <mid/evaluation/detection_result.h>
#include <mid/evaluation/ground_truth.h>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include <fstream>

TEST (EvaluationIO, ReadsBopGroundTruthWithMasks)
{
  const mid::test::TemporaryFolder folder;
  std::ofstream (folder.file ("scene_gt.json"))
      << R"({"0": [{"cam_R_m2c": [1, 0, 0, 0, 0, -1, 0, 1, 0], "cam_t_m2c": [10, -20, 800], "obj_id": 4},
                    {"cam_R_m2c": [1, 0, 0, 0, 1, 0, 0, 0, 1], "cam_t_m2c": [0, 0, 900], "obj_id": 4}],
              "3": [{"cam_R_m2c": [1, 0, 0, 0, 1, 0, 0, 0, 1], "cam_t_m2c": [0, 0, 700], "obj_id": 2}]})";
  std::ofstream (folder.file ("scene_gt_info.json"))
      << R"({"0": [{"bbox_visib": [10, 20, 30, 40], "px_count_visib": 900},
                    {"bbox_visib": [100, 100, 5, 5], "px_count_visib": 25}],
              "3": [{"bbox_visib": [0, 0, 10, 10], "px_count_visib": 100}]})";
  std::filesystem::create_directories (folder.path() / "mask_visib");
  cv::Mat mask = cv::Mat::zeros (120, 160, CV_8UC1);
  mask (cv::Rect (10, 20, 30, 40)).setTo (255);
  mask.at<unsigned char> (25, 15) = 0; // a hole inside the box
  ASSERT_TRUE (cv::imwrite (
      (folder.path() / "mask_visib" / "000000_000000.png").string(), mask));

  mid::evaluation::GroundTruthScene scene;
  ASSERT_TRUE (mid::evaluation::loadBopScene (folder.path().string(), scene));
  ASSERT_EQ (scene.size(), 2u);
  const auto& frame = scene.at (0);
  ASSERT_EQ (frame.instances.size(), 2u);
  EXPECT_EQ (frame.instances[0].object_id, 4);
  EXPECT_FLOAT_EQ (frame.instances[0].pose (2, 3), 0.8f); // millimetres -> metres
  EXPECT_FLOAT_EQ (frame.instances[0].pose (1, 2), -1.0f);
  EXPECT_EQ (frame.instances[0].visible_pixels, 900);
  EXPECT_TRUE (frame.contains (0, 12.0f, 22.0f));
  EXPECT_FALSE (frame.contains (0, 15.0f, 25.0f));  // the mask decides, not the box
  EXPECT_TRUE (frame.contains (1, 102.0f, 101.0f)); // no mask: the box decides
  EXPECT_FALSE (frame.contains (1, 99.0f, 101.0f));
  EXPECT_EQ (scene.at (3).instances.front().object_id, 2);
}

TEST (EvaluationIO, RefusesMissingOrMalformedGroundTruth)
{
  const mid::test::TemporaryFolder folder;
  mid::evaluation::GroundTruthScene scene;
  EXPECT_FALSE (mid::evaluation::loadBopScene (folder.path().string(), scene));
  std::ofstream (folder.file ("scene_gt.json"))
      << R"({"0": [{"cam_R_m2c": [1, 0], "cam_t_m2c": [0, 0, 1], "obj_id": 1}]})";
  EXPECT_FALSE (mid::evaluation::loadBopScene (folder.path().string(), scene));
  std::ofstream (folder.file ("scene_gt.json")) << "{ not json";
  EXPECT_FALSE (mid::evaluation::loadBopScene (folder.path().string(), scene));
  EXPECT_TRUE (scene.empty());
}

TEST (EvaluationIO, ReadsBackTheResultJsonTheAppsWrite)
{
  mid::DiscoveryResult result;
  result.keypoints = pcl::make_shared<mid::KeypointCloud> (3, 1);
  result.image_keypoints = {{10.5f, 20.25f}, {30.0f, 40.0f}, {50.0f, 60.0f}};
  result.timing_ms = {{"features", 12.5}, {"total", 20.0}};
  mid::ObjectModel model;
  model.landmarks.resize (3);
  mid::ModelInstance instance;
  instance.pose (0, 3) = 0.25f;
  instance.pose (1, 1) = -1.0f;
  instance.keypoints = {0, 2};
  instance.landmarks = {0, 1};
  model.instances.push_back (instance);
  result.models.push_back (model);
  // The second object's two instances share no landmark: two groups.
  mid::ModelInstance apart = instance;
  apart.keypoints = {1};
  apart.landmarks = {2};
  model.instances.push_back (apart);
  result.models.push_back (model);
  // The first object's box was measured on two copies, the second's not at all.
  mid::ModelSize box;
  box.valid = true;
  box.agreeing = 2;
  box.size = Eigen::Vector3f (0.05f, 0.11f, 0.16f);
  result.model_sizes = {box, mid::ModelSize()};

  const mid::test::TemporaryFolder folder;
  std::ofstream (folder.file ("result.json"))
      << mid::formatDiscoveryJson (result, "scene.pcd");
  mid::evaluation::DetectionResult read;
  ASSERT_TRUE (
      mid::evaluation::readDetectionResult (folder.file ("result.json"), read));
  ASSERT_EQ (read.objects.size(), 2u);
  EXPECT_EQ (read.objects[0].box_size, box.size);
  EXPECT_EQ (read.objects[0].box_copies, 2);
  EXPECT_EQ (read.objects[1].box_size, Eigen::Vector3f::Zero());
  EXPECT_EQ (read.objects[1].box_copies, 0);
  ASSERT_EQ (read.objects[0].instances.size(), 1u);
  EXPECT_EQ (read.objects[0].instances[0].pose, instance.pose);
  ASSERT_EQ (read.objects[0].instances[0].keypoints.size(), 2u);
  EXPECT_EQ (read.objects[0].instances[0].keypoints[1], Eigen::Vector2f (50.0f, 60.0f));
  EXPECT_DOUBLE_EQ (read.total_ms, 20.0);
  EXPECT_DOUBLE_EQ (read.features_ms, 12.5);
  EXPECT_EQ (read.objects[0].instances[0].group, 0);
  ASSERT_EQ (read.objects[1].instances.size(), 2u);
  EXPECT_EQ (read.objects[1].instances[0].group, 0);
  EXPECT_EQ (read.objects[1].instances[1].group, 1);
  // Written without groups (the detect app), they read as none.
  std::ofstream (folder.file ("detected.json"))
      << mid::formatDiscoveryJson (result, "scene.pcd", false);
  ASSERT_TRUE (
      mid::evaluation::readDetectionResult (folder.file ("detected.json"), read));
  ASSERT_EQ (read.objects.size(), 2u);
  EXPECT_EQ (read.objects[1].instances[1].group, -1);

  std::ofstream (folder.file ("other.json"))
      << R"({"format": "mid-discovery-result", "version": 9})";
  EXPECT_FALSE (
      mid::evaluation::readDetectionResult (folder.file ("other.json"), read));
  EXPECT_FALSE (
      mid::evaluation::readDetectionResult (folder.file ("missing.json"), read));
  EXPECT_TRUE (read.objects.empty());
}
